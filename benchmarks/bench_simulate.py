"""Benchmark: 1024 time-domain runs, jaxtow (diffrax, batched) vs a SciPy solve_ivp loop.

Both integrate the same model (thesis eqs 6.1-6.6, Barge 2b on the documented steel
towline) from 1024 initial conditions (heading ψ0 and sway offset y0' spread around the
thesis's l0' = 2.5, x_p' = 0.5 case) over t' ∈ [0, T1] with the same tolerances
(RK45/Dopri5 in SciPy, Tsit5 in jaxtow; rtol = 1e-8, atol = 1e-8), and the final states are
compared. jaxtow is timed for several ``batch_size`` values of `simulate_batch` to show the
lockstep cost of vmapped adaptive solves; compile time is reported separately.

Run: ``python benchmarks/bench_simulate.py [--runs 1024] [--t1 100]``.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

import jax
import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.dirname(__file__))
from baseline_numpy import vector_field  # noqa: E402

import jaxtow as jt  # noqa: E402
from jaxtow._simulate import initial_state, simulate_batch  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--runs", type=int, default=1024)
    ap.add_argument("--t1", type=float, default=100.0)
    ap.add_argument("--vessel", default="barge_2b")
    ap.add_argument(
        "--batch-sizes",
        type=int,
        nargs="+",
        default=[0, 64, 16, 1],
        help="simulate_batch batch_size values (0 = one vmap over all runs)",
    )
    args = ap.parse_args(argv)
    rtol = atol = 1e-8

    vessel = jt.presets.VESSELS[args.vessel]()
    model = jt.TowModel(vessel=vessel, towline=jt.presets.default_towline(l0=2.5, xp=0.5))
    rng = np.random.default_rng(0)
    psi0 = np.radians(rng.uniform(-20, 20, args.runs))
    yoff = rng.uniform(-0.4, 0.4, args.runs)
    y0s = np.stack([np.asarray(initial_state(model, psi0=p, y0=y)) for p, y in zip(psi0, yoff)])

    results = {}
    for bs in args.batch_sizes:
        b = None if bs == 0 else bs
        t = time.perf_counter()
        sims = simulate_batch(model, y0s[: max(bs, 1)], t1=args.t1, n_save=2, batch_size=b)
        jax.block_until_ready(sims.ys)
        t_small = time.perf_counter() - t
        t = time.perf_counter()
        sims = simulate_batch(model, y0s, t1=args.t1, n_save=2, batch_size=b)
        jax.block_until_ready(sims.ys)
        t_full = time.perf_counter() - t  # includes one compile for the full batch shape
        t = time.perf_counter()
        sims = simulate_batch(model, y0s, t1=args.t1, n_save=2, batch_size=b)
        jax.block_until_ready(sims.ys)
        t_run = time.perf_counter() - t
        results[bs] = (t_run, t_full - t_run, sims)
        steps = np.asarray(sims.n_steps)
        print(
            f"jaxtow batch_size={'all' if bs == 0 else bs:>4}: run {t_run:7.3f} s, compile ~{t_full - t_run:5.2f} s "
            f"(first small call {t_small:.2f} s); steps per run {steps.min()}..{steps.max()}; "
            f"all succeeded: {bool(np.all(sims.success))}"
        )

    params = {n: float(getattr(vessel, n)) for n in jt.VESSEL_PARAMETERS}
    params.update(EA=float(model.towline.EA), l0=2.5, xp=0.5)
    t = time.perf_counter()
    finals = []
    for y0 in y0s:  # the baseline's Python loop over runs
        sol = solve_ivp(
            lambda t, y: vector_field(y, params),
            (0.0, args.t1),
            y0,
            method="RK45",
            rtol=rtol,
            atol=atol,
        )
        finals.append(sol.y[:, -1])
    t_np = time.perf_counter() - t
    finals = np.array(finals)
    print(f"SciPy solve_ivp (RK45) loop: {t_np:.2f} s for {args.runs} runs")
    for bs, (t_run, t_comp, sims) in results.items():
        diff = float(np.max(np.abs(np.asarray(sims.ys[:, -1]) - finals)))
        print(
            f"speed-up with batch_size={'all' if bs == 0 else bs:>4}: {t_np / t_run:7.1f}x   "
            f"max |final-state difference| {diff:.1e}"
        )


if __name__ == "__main__":
    main()
