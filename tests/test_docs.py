"""The documentation in docs/ matches the code it describes."""

import re
from pathlib import Path

import jaxtow as jt

ROOT = Path(__file__).parent.parent
DOCS = ROOT / "docs"


def test_every_documented_estimate_is_in_the_estimates_page():
    text = (DOCS / "estimates.md").read_text()
    for key in jt.presets.ASSUMPTIONS:
        assert f"`{key}`" in text, f"docs/estimates.md does not describe the estimate {key!r}"


def test_code_cites_only_documents_inside_the_repository():
    cited = set()
    for path in list((ROOT / "jaxtow").rglob("*.py")) + list((ROOT / "notebooks").glob("*.ipynb")):
        text = path.read_text()
        assert "MODEL.md" not in text and "shared/" not in text, path
        cited |= set(re.findall(r"docs/([\w/-]+\.md)", text))
    for doc in cited:
        assert (DOCS / doc).is_file(), f"the code cites docs/{doc}, which does not exist"


def test_model_sections_cited_by_the_code_exist():
    sections = set(re.findall(r"^## (\d+)\.", (DOCS / "model.md").read_text(), re.M))
    for path in (ROOT / "jaxtow").rglob("*.py"):
        for a, b in re.findall(r"docs/model\.md sections? (\d+)(?:-(\d+))?", path.read_text()):
            for s in filter(None, (a, b)):
                assert s in sections, f"{path} cites docs/model.md section {s}"


def test_architecture_lists_every_numerical_owner():
    text = (DOCS / "architecture.md").read_text()
    for owner in (
        "_roots.brackets",
        "_roots.bisect",
        "_roots.newton",
        "matrix_eigenvalues",
        "classify",
        "_simulate.integrate",
        "_interp",
        "Scales.nondimensional",
        "spectral_integral",
    ):
        assert owner in text
