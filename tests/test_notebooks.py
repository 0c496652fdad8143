"""The notebooks run top to bottom (executed with nbclient) and print what they claim."""

from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

NOTEBOOKS = sorted((Path(__file__).parent.parent / "notebooks").glob("*.ipynb"))

#: Text each notebook must print: its results, not only "it ran" (a cell that raises makes
#: nbclient raise CellExecutionError before these are looked at).
EXPECTED = {
    "01_getting_started.ipynb": ["float64 enabled: True", "c = -0.072", "max Re lambda:"],
    "02_bifurcations.ipynb": ["branch_point", "hopf", "path width"],
    "03_towline_design.ipynb": ["(> 0: fishtails)", "evaluations:", "path width"],
    "04_new_force.ipynb": [
        "drogue ['psi=+0.00 deg: unstable",
        "drogue: converged",
        "constructor:      parameter 'coefficient' must be >= 0",
        "with_parameters:  parameter 'coefficient' must be >= 0",
        "traced:           parameter 'coefficient' must be >= 0",
    ],
    "05_strip_bow_rake.ipynb": [
        "dR/d(bow rake): autodiff",
        "central difference",
        "bow rake 5.49 m ->",
    ],
    "06_risk.ipynb": ["Hs 3.5 m: P(fishtail) =", "MPM tension", "McNemar p ="],
    "07_strip_wigley_form.ipynb": [
        "gradient (central difference):",
        "BFGS: ",
        "result True",
        "optimum: B 0.39",
        "re-run, 41 stations, 80 frequencies:",
    ],
}


def test_every_notebook_has_expectations():
    assert {p.name for p in NOTEBOOKS} == set(EXPECTED)


# the notebooks (~40-90 s each) run with the slow tests (`pytest -m slow`) to keep CI short;
# the test suite covers every API they use
@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=[p.name for p in NOTEBOOKS])
def test_notebook_executes(path):
    nb = nbformat.read(path, as_version=4)
    NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}
    ).execute()
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert all(c.get("execution_count") for c in code), "a code cell did not run"
    text = "".join(
        o.get("text", "")
        for c in code
        for o in c.get("outputs", [])
        if o.get("output_type") == "stream"
    )
    for expected in EXPECTED[path.name]:
        assert expected in text, f"{path.name} did not print {expected!r}"
