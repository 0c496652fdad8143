"""Benchmark: a calm (x_p', l0') map on a Dask ``LocalCluster`` against one process.

The same sweep (`jaxtow.sweep`, analytic equilibria, max Re λ, the Routh-Hurwitz check) is
run in this process and as Dask tasks (`jaxtow.distributed.sweep`, one task a chunk) on
``--workers`` worker processes of one thread each. Each side's kernel is compiled before
the clock starts (the compile times are printed separately: each worker compiles its own).
A plain NumPy/SciPy loop (`baseline_numpy.stability_map`: the same analytic equilibria, a
finite-difference Jacobian, `numpy.linalg.eigvals`) is timed on the first ``--numpy-points``
points and its cost per point printed beside the others.

Run: ``python benchmarks/bench_distributed.py`` (``--points 1000000 --workers 2``).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(__file__))
from baseline_numpy import stability_map  # noqa: E402

import jaxtow as jt  # noqa: E402


def _compile_here(model, grid, chunk, options):
    """Compile (and run once) the chunk kernel as `jaxtow.sweep` calls it: a sweep of one
    chunk of the same shape; its wall time."""
    xp, l0 = grid["xp"], grid["l0"]
    rows = -(-chunk // xp.size)  # enough l0 values for one full chunk
    t = time.perf_counter()
    jt.sweep_arrays(
        model, {"xp": xp, "l0": l0[:rows]}, *jt.sweep_options(chunk_size=chunk, **options)
    )
    return time.perf_counter() - t


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--chunk", type=int, default=65536)
    ap.add_argument("--numpy-points", type=int, default=20_000)
    ap.add_argument(
        "--model",
        choices=("calm", "waves"),
        default="calm",
        help="calm: the analytic calm map; waves: the (l0', ω) map of Barge 2a in regular head "
        "waves (the shipped near-field database; about 20x the work a point)",
    )
    ap.add_argument("--json", default=None, help="write the results here")
    ap.add_argument("--md", default=None, help="write the results as a Markdown table here")
    args = ap.parse_args(argv)
    from dask.distributed import Client, LocalCluster

    side = int(round(np.sqrt(args.points)))
    if args.model == "calm":
        model = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())
        grid = {
            "xp": np.linspace(0.0, 0.6, side),
            "l0": np.linspace(0.2, 2.5, args.points // side),
        }
        options = dict(method="analytic")
    else:
        from jaxtow.presets import barge2_wave_model

        model = barge2_wave_model("2a", l0=1.0, xp=0.5, omega=1.0, zeta_a=1.25)
        grid = {
            "xp": np.linspace(0.1, 0.9, side),
            "l0": np.linspace(0.3, 3.0, args.points // side),
        }
        options = dict(method="numerical", n_grid=401)
    npts = grid["xp"].size * grid["l0"].size

    compile_here = _compile_here(model, grid, args.chunk, options)
    r0, t = resource.getrusage(resource.RUSAGE_SELF), time.perf_counter()
    ref = jt.sweep(model, grid, chunk_size=args.chunk, **options)
    t_one = time.perf_counter() - t
    r1 = resource.getrusage(resource.RUSAGE_SELF)
    cores_one = (r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime) / t_one
    print(
        f"one process: compile + first chunk {compile_here:.1f} s; {npts} points {t_one:.2f} s, "
        f"using {cores_one:.2f} cores on average (XLA's own threads)"
    )

    with (
        LocalCluster(
            n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        Client(cluster) as client,
    ):
        t = time.perf_counter()
        jt.distributed.compile_on_workers(client, model, grid, chunk_size=args.chunk, **options)
        compile_workers = time.perf_counter() - t
        t = time.perf_counter()
        ds = jt.distributed.sweep(model, grid, client=client, chunk_size=args.chunk, **options)
        ds = ds.compute()
        t_dask = time.perf_counter() - t
    print(
        f"Dask, {args.workers} workers: compile on every worker {compile_workers:.1f} s; "
        f"{npts} points {t_dask:.2f} s"
    )
    identical = all(
        np.array_equal(ds[k].values, ref[k].values, equal_nan=ds[k].dtype.kind == "f")
        for k in ref.data_vars
    )

    us_numpy, n_numpy = float("nan"), 0
    if args.model == "calm":  # the NumPy/SciPy loop of the same work (benchmarks/baseline_numpy)
        params = {n: float(getattr(model.vessel, n)) for n in jt.VESSEL_PARAMETERS}
        params["EA"] = float(model.towline.EA)
        axes = np.meshgrid(*grid.values(), indexing="ij")
        xp, l0 = (m.ravel()[: args.numpy_points] for m in axes)
        t = time.perf_counter()
        stability_map(params, xp, l0)
        n_numpy = int(xp.size)
        us_numpy = (time.perf_counter() - t) / n_numpy * 1e6

    res = dict(
        points=npts,
        workers=args.workers,
        chunk=args.chunk,
        one_process_s=t_one,
        dask_s=t_dask,
        speedup=t_one / t_dask,
        identical=bool(identical),
        compile_one_process_s=compile_here,
        compile_workers_s=compile_workers,
        us_per_point_one_process=t_one / npts * 1e6,
        us_per_point_dask=t_dask / npts * 1e6,
        us_per_point_numpy=us_numpy,
        numpy_points=n_numpy,
        model=args.model,
        cpu_count=os.cpu_count(),
        cores_used_one_process=cores_one,
    )
    print(
        f"speed-up of Dask over one process: {res['speedup']:.2f}x "
        f"(identical results: {identical}); µs a point: one process "
        f"{res['us_per_point_one_process']:.2f}, Dask {res['us_per_point_dask']:.2f}, "
        f"NumPy/SciPy loop {us_numpy:.0f} ({us_numpy / res['us_per_point_dask']:.0f}x Dask)"
    )
    if args.json:
        with open(args.json, "w") as f:
            json.dump(res, f, indent=2)
    if args.md:
        with open(args.md, "w") as f:
            f.write(markdown(res))
    return res


def markdown(res: dict) -> str:
    return (
        f"| {res['model']} map, {res['points']} points, {res['cpu_count']} cores | wall time | µs a point | "
        "compile |\n|---|---|---|---|\n"
        f"| one process | {res['one_process_s']:.2f} s | {res['us_per_point_one_process']:.2f} | "
        f"{res['compile_one_process_s']:.1f} s |\n"
        f"| Dask, {res['workers']} workers | {res['dask_s']:.2f} s | "
        f"{res['us_per_point_dask']:.2f} | {res['compile_workers_s']:.1f} s (each worker) |\n"
        + (
            f"| NumPy/SciPy loop (first {res['numpy_points']} points) | | "
            f"{res['us_per_point_numpy']:.0f} | |\n"
            if res["numpy_points"]
            else ""
        )
        + "\n"
        f"Speed-up of Dask over one process: **{res['speedup']:.2f}x**; results identical: "
        f"{res['identical']}. Chunks of {res['chunk']} points. The one process used "
        f"{res['cores_used_one_process']:.2f} of the {res['cpu_count']} cores on average "
        "(XLA runs a vmapped kernel on its own threads).\n"
    )


if __name__ == "__main__":
    main()
