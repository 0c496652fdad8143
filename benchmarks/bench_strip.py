"""Benchmark: what a researcher waits for in `jaxtow.strip`, in one fresh process.

* ``first_motions_s`` / ``next_motions_s``: `strip.motions` of Journée's Wigley model I
  (21 stations) at 3 frequencies in head seas at Fn 0.2, the first call (trace and compile
  included) and the next (another speed: the same shapes, a new value);
* ``grad_first_s`` / ``grad_next_s``: `jax.jit(jax.grad(f))` of the heave response with
  respect to the beam, the hull built by `strip.wigley` inside f, first and next call;
* ``numpy_table_s`` is not given: strip theory has no NumPy twin in this repository (its
  cross-check is the panel method, `benchmarks/strip_drift_vs_panel.py`).

Writes one JSON entry per run (``--json``, appended with ``--label``).

    python benchmarks/bench_strip.py --json benchmarks/data/perf/strip.json --label after
"""

from __future__ import annotations

import argparse
import json
import os
import time
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

import jaxtow as jt
import jaxtow.strip as strip

L, B, T = 3.0, 0.3, 0.1875
OMEGA = np.sqrt(2 * np.pi * 9.81 / (np.array([1.0, 1.25, 1.5]) * L))
U = 0.2 * np.sqrt(9.81 * L)


def timed(f):
    t0 = time.perf_counter()
    out = jax.block_until_ready(f())
    return out, time.perf_counter() - t0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", default=None)
    ap.add_argument("--label", default="run")
    ap.add_argument("--no-grad", action="store_true", help="motions only")
    args = ap.parse_args(argv)
    loading = jt.Loading(z_g=0.0, radii=(0.35 * B, 0.25 * L, 0.25 * L))
    hull = strip.wigley(L, B, T)
    res = dict(label=args.label, jax=jax.__version__, cpu_count=os.cpu_count())
    _, res["first_motions_s"] = timed(
        lambda: strip.motions(hull, OMEGA, [0.0], U, loading=loading).rao
    )
    _, res["next_motions_s"] = timed(
        lambda: strip.motions(hull, OMEGA, [0.0], 1.1 * U, loading=loading).rao
    )
    if not args.no_grad:

        def heave(b):
            m = strip.motions(strip.wigley(L, b, T), OMEGA, [0.0], U, loading=loading)
            return jnp.sum(jnp.abs(m.rao[:, 0, 1]) ** 2)

        g = jax.jit(jax.grad(heave))
        _, res["grad_first_s"] = timed(lambda: g(B))
        _, res["grad_next_s"] = timed(lambda: g(1.05 * B))
    print(json.dumps(res, indent=1))
    if args.json:
        path = Path(args.json)
        runs = json.loads(path.read_text()) if path.exists() else []
        runs = [r for r in runs if r.get("label") != args.label] + [res]
        path.write_text(json.dumps(runs, indent=1) + "\n")


if __name__ == "__main__":
    main()
