"""Benchmark: the irregular-sea Monte Carlo of Barge 2a in the survival sea state, 1,024
three-hour runs (`jaxtow.risk.irregular_sea`, the built-in tow barge2a: slow drift by
Newman's approximation from the shipped near-field panel database with its forward-speed
form, NPD gusts on the 20 m/s wind), against a plain NumPy/SciPy loop of the same model
(``baseline_numpy.vector_field`` with the mean forces frozen at the equilibrium is not the
same work, so the loop here integrates jaxtow's own vector field, one run at a time, with
SciPy's ``solve_ivp`` RK45 through a NumPy callback: the cost of a Python time-stepper on
the same right-hand side), timed on a few runs and extrapolated.

The first chunk compiles; the compile time is reported apart (the same chunk run again).
Writes a JSON with the wall time, runs per second and the backend.

    python benchmarks/bench_risk.py --json benchmarks/data/perf/risk_cpu.json
    python benchmarks/bench_risk.py --runs 16384 --chunk 4096 --json risk_gpu.json   # a GPU
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time
from pathlib import Path

import jax
import jax.numpy as jnp
import numpy as np

import jaxtow as jt
from jaxtow import risk


def numpy_loop(tow, sea, settings, n: int) -> float:
    """Seconds per run of SciPy's RK45 on jaxtow's right-hand side (jitted, called from
    Python at every stage): the Monte Carlo written as a plain loop."""
    from scipy.integrate import solve_ivp

    model, _ = risk.risk_model(tow.sea_model(sea), settings)
    mean = tow.sea_model(sea)
    eqs = jt.equilibria(mean)
    y0 = np.asarray(eqs.state)[
        int(np.argmin(np.where(np.asarray(eqs.valid), np.abs(np.asarray(eqs.psi)), np.inf)))
    ]
    f = jax.jit(lambda t, y: jt.vector_field(t, y, model, throw=False))
    f(0.0, jnp.asarray(y0)).block_until_ready()
    t1 = settings.duration * float(tow.scales.u_tug) / float(tow.scales.length)
    t = time.perf_counter()
    for k in range(n):
        y = y0.copy()
        y[5] += np.radians(1.0 * (k + 1) / n)
        solve_ivp(
            lambda tt, yy: np.asarray(f(tt, jnp.asarray(yy))), (0.0, t1), y, rtol=1e-6, atol=1e-6
        )
    return (time.perf_counter() - t) / n


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--runs", type=int, default=1024)
    ap.add_argument("--chunk", type=int, default=64)
    ap.add_argument("--hours", type=float, default=3.0)
    ap.add_argument("--numpy-runs", type=int, default=2, help="runs of the SciPy loop (0: none)")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    tow = jt.tow.load("barge2a")
    sea = tow.sea_states[0]  # survival
    s = risk.RiskSettings(chunk_size=args.chunk)
    duration = args.hours * 3600.0
    # compile: one chunk, then the same chunk again (compile time = first - second)
    t = time.perf_counter()
    risk.irregular_sea(tow, sea, n_runs=args.chunk, duration=duration, settings=s)
    first = time.perf_counter() - t
    t = time.perf_counter()
    risk.irregular_sea(tow, sea, n_runs=args.chunk, duration=duration, settings=s)
    chunk_s = time.perf_counter() - t
    t = time.perf_counter()
    r = risk.irregular_sea(tow, sea, n_runs=args.runs, duration=duration, settings=s, seed=1)
    wall = time.perf_counter() - t
    out = dict(
        backend=jax.default_backend(),
        device=str(jax.devices()[0].device_kind),
        cpu_cores=os.cpu_count(),
        machine=platform.node(),
        jax=jax.__version__,
        runs=args.runs,
        hours=args.hours,
        chunk=args.chunk,
        wall_s=wall,
        runs_per_s=args.runs / wall,
        compile_s=max(first - chunk_s, 0.0),
        fishtail_probability=r.fishtail_probability,
        interval=list(r.confidence_interval),
        mpm_tension_kN=r.mpm_tension / 1e3,
        completed=r.n,
    )
    if args.numpy_runs:
        per = numpy_loop(tow, sea, s, args.numpy_runs)
        out.update(scipy_loop_s_per_run=per, speedup=per / (wall / args.runs))
    print(json.dumps(out, indent=2))
    if args.json:
        Path(args.json).write_text(json.dumps(out, indent=2) + "\n")
    return out


if __name__ == "__main__":
    main()
