"""Benchmark: the calm-water (x_p', l0') stability map, jaxtow vs plain NumPy/SciPy.

Both compute, at every grid point, the analytic equilibria (thesis eqs 6.7-6.13), the
Jacobian (jaxtow: autodiff; baseline: central finite differences) and max Re λ per
equilibrium (baseline: `numpy.linalg.eigvals`; jaxtow: the pure-JAX spectral abscissa,
``--eig-method routh``, the sweeps' default, or LAPACK's eigenvalues, ``lapack``; both by
default). Run: ``python benchmarks/bench_stability_map.py`` (``--sizes 10000 100000``).
Prints run times (JIT compile reported separately), the speed-up ratio and the largest
difference between the two results.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time

import jax
import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from baseline_numpy import stability_map  # noqa: E402

import jaxtow as jt  # noqa: E402
from jaxtow._sweep import point_kernel  # noqa: E402


def grid(n):
    side = int(round(np.sqrt(n)))
    xp, l0 = np.meshgrid(
        np.linspace(0.0, 0.6, side), np.linspace(0.2, 2.5, n // side), indexing="ij"
    )
    return xp.ravel(), l0.ravel()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--sizes", type=int, nargs="+", default=[10_000, 100_000])
    ap.add_argument("--vessel", default="barge_2a")
    ap.add_argument("--chunk", type=int, default=16384)
    ap.add_argument("--eig-method", nargs="+", default=["routh", "lapack"])
    ap.add_argument("--json", default=None, help="write the results here")
    args = ap.parse_args(argv)
    results = []
    for eig in args.eig_method:
        results += run(args, eig)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)
    return results


def run(args, eig_method):

    vessel = jt.presets.VESSELS[args.vessel]()
    model = jt.TowModel(vessel=vessel, towline=jt.presets.default_towline())
    params = {n: float(getattr(vessel, n)) for n in jt.VESSEL_PARAMETERS}
    params["EA"] = float(model.towline.EA)

    # The same work as the baseline: analytic equilibria, Jacobian, eigenvalues, max Re λ
    # (the Routh-Hurwitz cross-check of the sweep kernel is left out, as in the baseline).
    @jax.jit
    def kernel(xp, l0):
        return jax.vmap(
            lambda a, b: point_kernel(
                model,
                {"xp": a, "l0": b},
                method="analytic",
                routh_hurwitz=False,
                eig_method=eig_method,
            )
        )(xp, l0)

    def run_jax(xp, l0):
        outs = []
        for s in range(0, xp.size, args.chunk):  # chunks of a fixed shape: one compilation
            a = np.resize(xp[s : s + args.chunk], args.chunk)
            b = np.resize(l0[s : s + args.chunk], args.chunk)
            out = kernel(a, b)
            mr = np.asarray(jax.device_get(out["max_real"]))
            found = np.asarray(out["found"])
            outs.append(np.where(found, mr, np.nan)[: min(args.chunk, xp.size - s)])
        return np.concatenate(outs)

    xp0, l00 = (a[: args.chunk] for a in grid(args.chunk))
    t = time.perf_counter()
    jax.block_until_ready(kernel.lower(xp0, l00).compile())
    compile_s = time.perf_counter() - t
    print(
        f"jaxtow JIT compile: {compile_s:.2f} s (chunk {args.chunk}, device {jax.devices()[0].platform}, "
        f"max Re λ by {eig_method!r})"
    )

    results = []
    for n in args.sizes:
        xp, l0 = grid(n)
        run_jax(xp[:10], l0[:10])  # warm
        t = time.perf_counter()
        r_jax = run_jax(xp, l0)
        t_jax = time.perf_counter() - t
        t = time.perf_counter()
        r_np = stability_map(params, xp, l0)
        t_np = time.perf_counter() - t
        same_nan = np.array_equal(np.isnan(r_jax), np.isnan(r_np))
        diff = float(np.nanmax(np.abs(r_jax - r_np)))
        res = dict(
            points=int(xp.size),
            jaxtow_s=t_jax,
            numpy_s=t_np,
            speedup=t_np / t_jax,
            max_abs_diff=diff,
            same_equilibria=bool(same_nan),
            compile_s=compile_s,
            eig_method=eig_method,
        )
        results.append(res)
        print(
            f"[{eig_method}] {xp.size:>7d} points: jaxtow {t_jax:8.3f} s | NumPy/SciPy loop {t_np:8.2f} s | "
            f"speed-up {t_np / t_jax:7.1f}x | max |diff| {diff:.1e} | same equilibria: {same_nan}"
        )
    return results


if __name__ == "__main__":
    main()
