"""Every Python block of README.md and docs/howto/*.md runs as written: the blocks of one
page run in order in one namespace, as a reader pastes them into one session, in a
temporary working folder. A block that needs an optional extra says so in its first line
(``# needs: capytaine``) and is skipped where the extra is not installed."""

from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import matplotlib
import pytest

ROOT = Path(__file__).resolve().parents[1]
#: The README's examples are small and run in the default suite; the how-tos run real
#: studies (minutes together) and run in the slow suite.
PAGES = [
    pytest.param(ROOT / "README.md", id="README.md"),
    *(
        pytest.param(
            p,
            id=p.name,
            # waves.md runs the thesis's wave study and bem.md a 1 m panel solve (minutes
            # each on 2 cores): with the heavy tests
            marks=[pytest.mark.slow]
            + ([pytest.mark.heavy] if p.name in ("waves.md", "bem.md") else []),
        )
        for p in sorted((ROOT / "docs" / "howto").glob("*.md"))
    ),
]
BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def python_blocks(text: str) -> list[str]:
    return [m.group(1) for m in BLOCK.finditer(text)]


def test_the_block_reader_finds_each_python_block():
    text = "a\n```python\nx = 1\n```\n```bash\nls\n```\n```python\ny = x\n```\n"
    assert python_blocks(text) == ["x = 1\n", "y = x\n"]


@pytest.mark.parametrize("page", PAGES)
def test_every_python_block_runs(page, tmp_path, monkeypatch):
    matplotlib.use("Agg")
    monkeypatch.chdir(tmp_path)
    blocks = python_blocks(page.read_text(encoding="utf-8"))
    if not blocks:
        pytest.skip(f"{page.name} holds no Python block")
    namespace: dict = {"__name__": "__doc_example__"}
    for i, code in enumerate(blocks):
        needs = re.match(r"#\s*needs:\s*(\w+)", code)
        if needs and importlib.util.find_spec(needs.group(1)) is None:
            pytest.skip(f"{page.name} block {i + 1} needs {needs.group(1)}")
        try:
            exec(compile(code, f"{page.name} block {i + 1}", "exec"), namespace)
        except Exception as e:  # the page and block in the failure, then the error
            raise AssertionError(f"{page.name}, Python block {i + 1} fails: {e!r}\n{code}") from e
