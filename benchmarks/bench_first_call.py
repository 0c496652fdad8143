"""Benchmark: a public function called eagerly, as in a notebook or the README's examples.

Each function is called twice in a fresh process (its first call includes every compile; the
next is the median of five more calls with new values of the same shapes), two ways in the
same run:

* ``op by op``: under `jax.disable_jit` (every operation compiled on its first use and
  dispatched one at a time: how these functions ran before they became programs);
* ``program``: as jaxtow runs them now (`jaxtow._program_cache.host_program`: one compiled
  program per static options and argument shapes).

Beside them, where ``benchmarks/baseline_numpy*.py`` has the same work, the plain NumPy/SciPy
call (the calm vector field; a central-difference Jacobian and ``numpy.linalg.eigvals`` for the
eigenvalues; the QTF look-up and Aranha's finite form for the sailing drift), and how many
times longer the program's call takes: for one call, plain Python and NumPy dispatch faster
than a compiled program plus jaxtow's parameter checks; the programs' speed is in batches
(``benchmarks/backends.py``).

    python benchmarks/bench_first_call.py [--json benchmarks/data/perf/first_call.json] [--docs]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
OUT = HERE / "data" / "perf" / "first_call.json"
DOCS = HERE.parent / "docs" / "benchmarks.md"
BEGIN = "<!-- first-call table: python benchmarks/bench_first_call.py --docs -->"
END = "<!-- end of first-call table -->"

SETUP = """
import numpy as np
import jaxtow as jt
model = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.Towline(l0=2.5, xp=0.5, EA=100.0))
y = np.array([1.0, 0.0, 0.0, 2.5, 0.0, 0.0])
q = jt.presets.database("barge2")
w = np.linspace(0.2, 3.0, 400)
S = jt.waves.Jonswap(hs=2.4, tp=7.0)(w)
"""

#: name -> the call, with ``k`` a small number that changes between calls (new values, same
#: shapes)
CALLS = {
    "vector_field": "jt.vector_field(0.0, y + 0.01 * k, model)",
    "jacobian": "jt.jacobian(model, y + 0.01 * k)",
    "eigenvalues": "jt.eigenvalues(model, y + 0.01 * k)",
    "stability": "jt.stability(model, (y + 0.01 * k)[None])",
    "analytic_equilibria": "jt.analytic_equilibria(jt.with_parameters(model, xp=0.5 + 0.01 * k))",
    "heading_residual": "jt.heading_residual(0.1 + 0.01 * k, model)",
    "Jonswap spectrum": "jt.waves.Jonswap(hs=2.4, tp=7.0 + 0.01 * k)(w[:300])",  # not the setup's shape
    "QTF (one look-up)": "q(0.9 + 0.01 * k, 0.1 * k)",
    "sailing_drift": "jt.drift.sailing_drift(q, 0.9 + 0.01 * k, 0.0, u=2.0)",
    "wave_drift_damping": "jt.drift.wave_drift_damping(q, omega=0.9 + 0.01 * k, beta=0.0)",
    "irregular_sailing_drift": "jt.drift.irregular_sailing_drift(q, w, S, 0.0, 2.0 + 0.01 * k)",
}

CHILD = """
import contextlib, statistics, sys, time, json
import jax
{setup}
mode = sys.argv[1]
ctx = jax.disable_jit() if mode == "op by op" else contextlib.nullcontext()
with ctx:
    k = 0
    t = time.perf_counter()
    jax.block_until_ready({call})
    first = time.perf_counter() - t
    nxt = []
    for k in range(1, 6):
        t = time.perf_counter()
        jax.block_until_ready({call})
        nxt.append(time.perf_counter() - t)
print(json.dumps(dict(first_s=first, next_s=statistics.median(nxt))))
"""


def child(call: str, mode: str) -> dict:
    code = CHILD.format(setup=SETUP, call=call)
    r = subprocess.run(
        [sys.executable, "-c", code, mode], capture_output=True, text=True, check=True
    )
    return json.loads(r.stdout.strip().splitlines()[-1])


def numpy_calls() -> dict:
    """Seconds per call of the NumPy baselines (median of 20 calls)."""
    sys.path.insert(0, str(HERE))
    import numpy as np
    from baseline_numpy import fd_jacobian, vector_field as np_field
    from baseline_numpy_waves import NumpyQTF, sailing_drift as np_sailing

    import jaxtow as jt

    model = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.Towline(l0=2.5, xp=0.5, EA=100.0))
    p = {k: float(getattr(model.vessel, k)) for k in jt.VESSEL_PARAMETERS}
    p.update(EA=float(model.towline.EA), l0=2.5, xp=0.5)
    y = np.array([1.0, 0.0, 0.0, 2.5, 0.0, 0.0])
    q = jt.presets.database("barge2")
    nq = NumpyQTF(np.asarray(q.omega), np.asarray(q.beta), np.asarray(q.values), q.periodic)
    work = {
        "vector_field": lambda: np_field(y, p),
        "eigenvalues": lambda: np.linalg.eigvals(fd_jacobian(y, p)),
        "QTF (one look-up)": lambda: nq(0.9, 0.1),
        "sailing_drift": lambda: np_sailing(nq, 0.9, 0.0, 2.0, 0.0),
    }
    out = {}
    for name, f in work.items():
        times = []
        for _ in range(20):
            t = time.perf_counter()
            f()
            times.append(time.perf_counter() - t)
        out[name] = statistics.median(times)
    return out


def table(res: dict) -> str:
    ms = lambda s: f"{1e3 * s:.2f}" if s < 0.1 else f"{1e3 * s:.0f}"  # noqa: E731
    lines = [
        "| function | first call, op by op | first call, program | next call, op by op | "
        "next call, program | NumPy/SciPy call (program ÷ NumPy) |",
        "|---|---|---|---|---|---|",
    ]
    for name, r in res["calls"].items():
        a, b = r["op by op"], r["program"]
        npy = res["numpy_s"].get(name)
        lines.append(
            f"| `{name}` | {a['first_s']:.2f} s | {b['first_s']:.2f} s "
            f"({a['first_s'] / b['first_s']:.1f}x) | {ms(a['next_s'])} ms | "
            f"{ms(b['next_s'])} ms ({a['next_s'] / b['next_s']:.0f}x) | "
            + (f"{ms(npy)} ms ({b['next_s'] / npy:.0f}x) |" if npy else "– |")
        )
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--json", default=str(OUT))
    ap.add_argument("--docs", action="store_true", help="write the table into docs")
    args = ap.parse_args(argv)
    res = dict(cpu_count=os.cpu_count(), calls={}, numpy_s=numpy_calls())
    for name, call in CALLS.items():
        res["calls"][name] = {mode: child(call, mode) for mode in ("op by op", "program")}
        r = res["calls"][name]
        print(
            f"{name:26s} first {r['op by op']['first_s']:6.2f} s -> {r['program']['first_s']:5.2f} s"
            f"   next {1e3 * r['op by op']['next_s']:7.2f} ms -> "
            f"{1e3 * r['program']['next_s']:6.3f} ms",
            flush=True,
        )
    text = table(res)
    print(text)
    Path(args.json).write_text(json.dumps(res, indent=1) + "\n")
    if args.docs:
        sys.path.insert(0, str(HERE))
        from _docs_block import write_block

        write_block(DOCS, BEGIN, END, text)


if __name__ == "__main__":
    main()
