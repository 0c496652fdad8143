"""Benchmark: the (l0', ω) stability map of Barge 2a in regular head waves (thesis figs
6.17-6.19), jaxtow's one vmapped sweep against a plain NumPy/SciPy loop of the same work
(`baseline_numpy_waves`: fsolve equilibria, finite-difference Jacobian, eigvals).

jaxtow computes the whole map (default 200 × 200 points) in one call: every equilibrium by
bracketing the heading residual, Jacobians by autodiff, LAPACK eigenvalues. The NumPy loop
is timed on a random subset of the same points (it would take hours on the full map) and the
per-point costs are compared; on that subset the two must agree. JIT compile time is
reported separately. Drift forces: the shipped Barge 2 near-field panel database
(`jaxtow.presets.database`, with its sectional moments, so the yaw-rate column of the
wave-drift damping is on in both codes) with Aranha's finite form for the forward speed;
``--qtf standin`` for the Kashiwagi-waterline stand-in.

    python benchmarks/bench_wave_map.py [--n 200] [--subset 60] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))


from baseline_numpy_waves import NumpyQTF, stability_map  # noqa: E402

import jaxtow as jt  # noqa: E402
from jaxtow._sweep import make_specialised_kernel, sweep_arrays, sweep_options  # noqa: E402
from jaxtow.presets import barge2_wave_model
from jaxtow.studies import nearest_straight  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--n", type=int, default=200, help="points per axis (n × n map)")
    ap.add_argument("--subset", type=int, default=60, help="points timed with the NumPy/SciPy loop")
    ap.add_argument(
        "--n-grid",
        type=int,
        default=401,
        help="heading-scan points over ±90° (401: 0.45° brackets, each root refined to machine precision)",
    )
    ap.add_argument("--qtf", default=None, help="drift source (default: the shipped near field)")
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)

    model = barge2_wave_model("2a", l0=1.0, xp=0.5, omega=1.0, zeta_a=1.25, qtf=args.qtf)
    qtf = model.external.qtf
    l0 = np.linspace(0.3, 3.0, args.n)
    omega = np.linspace(0.3, 2.0, args.n)
    kopts = dict(n_grid=args.n_grid, max_roots=4, routh_hurwitz=False, eig_method="lapack")
    opts = dict(
        kopts, chunk_size=8192, kernel=make_specialised_kernel(model, method="numerical", **kopts)
    )

    grid = {"l0": l0, "external.omega": omega}
    t = time.perf_counter()
    sweep_arrays(
        model, grid, *sweep_options(**opts)
    )  # the first call compiles (specialised to this model)
    first = time.perf_counter() - t
    t = time.perf_counter()
    arrays = sweep_arrays(model, grid, *sweep_options(**opts))
    t_jax = time.perf_counter() - t
    compile_s = first - t_jax
    mr = nearest_straight(arrays)
    npts = args.n * args.n
    print(
        f"jaxtow: {npts} points in {t_jax:.2f} s ({1e3 * t_jax / npts:.3f} ms/point); "
        f"JIT compile ≈ {compile_s:.1f} s (first call minus second)"
    )

    ves = model.vessel
    params = {n: float(getattr(ves, n)) for n in jt.VESSEL_PARAMETERS}
    sc = jt.presets.barge2_scales()
    params.update(
        EA=float(model.towline.EA),
        xp=float(model.towline.xp),
        zeta_a=1.25,
        u_tug=float(sc.u_tug),
        force=float(sc.force),
        moment=float(sc.moment),
        length=float(sc.length),
        qtf=NumpyQTF(
            np.asarray(qtf.omega), np.asarray(qtf.beta), np.asarray(qtf.values), qtf.periodic
        ),
        moments=(
            NumpyQTF(
                np.asarray(qtf.omega), np.asarray(qtf.beta), np.asarray(qtf.sectional), qtf.periodic
            )
            if qtf.has_sectional
            else None
        ),
    )
    rng = np.random.default_rng(0)
    idx = rng.choice(npts, size=args.subset, replace=False)
    L0, W = np.meshgrid(l0, omega, indexing="ij")
    t = time.perf_counter()
    r_np = stability_map(params, L0.ravel()[idx], W.ravel()[idx])
    t_np = time.perf_counter() - t
    r_jax = mr.ravel()[idx]
    both = np.isfinite(r_np) & np.isfinite(r_jax)
    diff = float(np.max(np.abs(r_np[both] - r_jax[both]))) if both.any() else float("nan")
    per_np, per_jax = t_np / args.subset, t_jax / npts
    res = dict(
        points=npts,
        jaxtow_s=t_jax,
        compile_s=compile_s,
        numpy_subset=args.subset,
        numpy_s=t_np,
        numpy_s_per_point=per_np,
        jaxtow_s_per_point=per_jax,
        speedup=per_np / per_jax,
        numpy_extrapolated_full_map_s=per_np * npts,
        max_abs_diff_subset=diff,
        both_found=int(both.sum()),
        numpy_missed=int(np.sum(np.isnan(r_np) & np.isfinite(r_jax))),
    )
    print(
        f"NumPy/SciPy loop: {args.subset} points in {t_np:.2f} s ({1e3 * per_np:.1f} ms/point; "
        f"the full map would take {per_np * npts / 60:.0f} min)"
    )
    print(
        f"speed-up per point: {per_np / per_jax:.0f}x | max |diff| of max Re lambda on the subset: {diff:.1e} "
        f"({int(both.sum())} points found by both; fsolve missed {res['numpy_missed']})"
    )
    if args.json:
        Path(args.json).write_text(json.dumps(res, indent=2))
    return res


if __name__ == "__main__":
    main()
