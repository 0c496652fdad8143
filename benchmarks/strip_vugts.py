"""Vugts's (1968) heaving semicircle against jaxtow's section solver and Ursell's exact theory.

The measured points (``benchmarks/data/strip/vugts1968_circle.json``: Vugts's heave added
mass and damping of a semicircular cylinder, as digitised in public notes, with the reading
described there) are recomputed at the same frequencies by `jaxtow.strip.section_coefficients`
(32 and 64 panels on the quarter circle, the rigid lid on) and by Ursell's (1949) multipole
solution (``tests/ursell.py``, SciPy quadrature, independent of jaxtow's code).

The summary is the statistic the open strip code michell publishes for the same experiments:
the median of |computed − measured| over the points, relative to the largest measured value
of the quantity. Its own figures (read from another digitisation of Vugts's measurements)
are in the table beside jaxtow's. Writes ``benchmarks/data/strip/vugts1968_compared.json``
and, with ``--docs``, the table into docs/strip.md.

    python benchmarks/strip_vugts.py --docs
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import time
from pathlib import Path

import numpy as np

import jaxtow as jt
from jaxtow.strip import section_coefficients

HERE = Path(__file__).parent
MEASURED = HERE / "data" / "strip" / "vugts1968_circle.json"
OUT = HERE / "data" / "strip" / "vugts1968_compared.json"
DOCS = HERE.parent / "docs" / "strip.md"
URSELL = HERE.parent / "tests" / "ursell.py"
BEGIN = "<!-- vugts table: python benchmarks/strip_vugts.py --docs -->"
END = "<!-- end of vugts table -->"
G, RHO = 9.80665, 1025.0
PANELS = (32, 64)
#: Below this ω√(R/g) the measured added mass falls far below the potential-flow theory
#: (four points at 0.13-0.25 read 0.76-1.34 where Ursell's solution gives 1.75-2.83), a
#: deviation of the experiment every potential-flow code shares; the table also gives the
#: medians above it.
LOW = 0.3


def semicircle(n: int, r: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """Half offsets of a semicircle of radius r, waterline to keel, n panels."""
    th = np.linspace(0.0, np.pi / 2, n + 1)
    return r * np.cos(th), -r * np.sin(th)


def ursell():
    spec = importlib.util.spec_from_file_location("ursell", URSELL)
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod.ursell_heave


def jaxtow_heave(x: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(a33/(ρπR²/2), b33√(R/g)/(ρπR²/2)) of the unit semicircle at ω√(R/g) = x."""
    y, z = semicircle(n)
    c = section_coefficients(y, z, x * np.sqrt(G), water=jt.Water(rho=RHO, g=G))
    m = RHO * np.pi / 2
    a = np.asarray(c.added_mass)[:, 1, 1] / m
    b = np.asarray(c.damping)[:, 1, 1] / m / np.sqrt(G)
    return a, b


def compare(data) -> dict:
    exact = ursell()
    out = {}
    for index, key in enumerate(("added_mass", "damping")):
        pts = np.asarray(data[key]["points"], float)
        x, measured = pts[:, 0], pts[:, 1]
        rows = dict(
            omega_nd=x.tolist(),
            measured=measured.tolist(),
            ursell=[float(exact(float(w))[index]) for w in x],
        )
        for n in PANELS:
            rows[f"jaxtow_{n}"] = jaxtow_heave(x, n)[index].tolist()
        out[key] = rows
    return out


def medians(rows: dict, column: str, low: float = 0.0) -> float:
    """Median |column − measured| over the points at ω√(R/g) ≥ low, relative to the largest
    measured value (the whole set's)."""
    x = np.asarray(rows["omega_nd"])
    m = np.asarray(rows["measured"])
    d = np.abs(np.asarray(rows[column]) - m)[x >= low]
    return float(np.median(d) / np.max(np.abs(m)))


def table(res: dict, data: dict) -> str:
    names = {"added_mass": "a₃₃/(ρπR²/2)", "damping": "b₃₃√(R/g)/(ρπR²/2)"}
    lines = [
        "| quantity | points | largest measured | jaxtow, 32 / 64 panels | Ursell's exact "
        "theory | michell (anchor) |",
        "|---|---|---|---|---|---|",
    ]
    for key, rows in res.items():
        m = np.asarray(rows["measured"])
        n_hi = int(np.sum(np.asarray(rows["omega_nd"]) >= LOW))
        cells = []
        for low in (0.0, LOW):
            j = " / ".join(f"{100 * medians(rows, f'jaxtow_{n}', low):.1f} %" for n in PANELS)
            u = f"{100 * medians(rows, 'ursell', low):.1f} %"
            cells.append((j, u))
        lines.append(
            f"| {names[key]} | {len(m)} ({n_hi} at ω√(R/g) ≥ {LOW}) | {np.max(m):.3f} | "
            f"{cells[0][0]} ({cells[1][0]}) | {cells[0][1]} ({cells[1][1]}) | "
            f"{100 * data['anchor'][key]:.0f} % |"
        )
    return "\n".join(lines)


def write_docs(text: str) -> None:
    from _docs_block import write_block  # beside this script

    write_block(DOCS, BEGIN, END, text)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--json", default=str(OUT))
    ap.add_argument("--docs", action="store_true", help="write the table into docs/strip.md")
    args = ap.parse_args(argv)
    data = json.loads(MEASURED.read_text())
    t0 = time.perf_counter()
    res = compare(data)
    Path(args.json).write_text(
        json.dumps(
            dict(res, command="python benchmarks/strip_vugts.py --docs", jaxtow=jt.__version__),
            indent=1,
        )
        + "\n"
    )
    text = table(res, data)
    print(text)
    print(f"\n{time.perf_counter() - t0:.0f} s")
    if args.docs:
        write_docs(text)


if __name__ == "__main__":
    main()
