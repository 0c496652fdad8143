"""Benchmark: peak memory and time against grid size, chunked against one call.

Three jobs, each size in a fresh process (peak resident memory, ``ru_maxrss``, is a
per-process high-water mark):

* ``calm``: the (x_p', l0') stability map of Barge 2a (analytic equilibria, max Re λ),
  10³ … 10⁶ points, by `jaxtow.sweep_arrays` in chunks of 16 384 points and, as the
  baseline, in one chunk holding every point (up to 10⁵: beyond it the one call needs more
  memory than a 2-core CI machine has);
* ``waves``: the (l0', ω) map of Barge 2a in head waves on the shipped near-field database,
  10³ … 10⁵ points, chunks of 4 096 against one chunk (up to 10⁴);
* ``simulate``: batched time-domain runs of Barge 2b (`jaxtow.simulate_batch`, t' ≤ 50,
  two saved times), 10² … 10⁴ runs, in vmapped groups of 64 against one vmap over all.

Each row gives the time (the first call of the size, compile included, and a second,
timed call), the peak memory, the bytes of the results themselves and the rest (the
working memory). The persistent compilation cache is on, so the wave kernel is compiled
once for the whole benchmark.

    python benchmarks/bench_memory.py [--jobs calm waves simulate] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time

SIZES = {
    "calm": ([1_000, 10_000, 100_000, 1_000_000], 100_000),
    "waves": ([1_000, 10_000, 100_000], 10_000),
    "simulate": ([100, 1_000, 10_000], 10_000),
}
CHUNK = {"calm": 16384, "waves": 4096, "simulate": 64}


def one(job: str, size: int, chunked: bool) -> dict:
    import jax
    import numpy as np

    import jaxtow as jt

    jt.enable_compile_cache()
    side = int(round(np.sqrt(size)))
    if job == "calm":
        m = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())
        grid = {"xp": np.linspace(0.0, 0.6, side), "l0": np.linspace(0.2, 2.5, size // side)}
        chunk = CHUNK[job] if chunked else size

        def work():
            return jt.sweep_arrays(
                m, grid, jt.SweepSolver(method="analytic"), jt.SweepExecution(chunk_size=chunk)
            )
    elif job == "waves":
        m = jt.presets.barge2_wave_model("2a")
        grid = {
            "l0": np.linspace(0.3, 3.0, side),
            "external.omega": np.linspace(0.3, 2.0, size // side),
        }
        chunk = CHUNK[job] if chunked else size

        def work():
            return jt.sweep_arrays(
                m,
                grid,
                jt.SweepSolver(n_grid=201, routh_hurwitz=False),
                jt.SweepExecution(chunk_size=chunk),
            )
    else:
        from jaxtow._simulate import initial_state

        m = jt.TowModel(vessel=jt.presets.barge_2b(), towline=jt.presets.default_towline())
        rng = np.random.default_rng(0)
        y0 = np.asarray(initial_state(m, psi0=0.2, y0=0.1))
        y0s = y0 + 0.01 * rng.normal(size=(size, 6)) * np.array([0, 0, 1, 0, 1, 1])
        bs = CHUNK[job] if chunked else None

        def work():
            s = jt.simulate_batch(m, y0s, t1=50.0, n_save=2, batch_size=bs)
            return {"ys": np.asarray(s.ys), "ok": np.asarray(s.success)}

    t = time.perf_counter()
    work()
    first = time.perf_counter() - t
    t = time.perf_counter()
    out = work()
    second = time.perf_counter() - t
    jax.clear_caches()
    nbytes = sum(v.nbytes for v in out.values() if hasattr(v, "nbytes"))
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # kB -> MiB (Linux)
    return dict(
        job=job,
        size=size,
        chunked=chunked,
        first_s=first,
        second_s=second,
        peak_mib=peak,
        results_mib=nbytes / 2**20,
        working_mib=peak - nbytes / 2**20,
    )


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--jobs", nargs="+", default=list(SIZES))
    ap.add_argument("--one", nargs=3, metavar=("JOB", "SIZE", "CHUNKED"), help=argparse.SUPPRESS)
    ap.add_argument("--json", default=None)
    args = ap.parse_args(argv)
    if args.one:
        job, size, chunked = args.one
        print(json.dumps(one(job, int(size), chunked == "1")))
        return None
    rows = []
    for job in args.jobs:
        sizes, one_call_max = SIZES[job]
        for size in sizes:
            for chunked in (True, False):
                if not chunked and size > one_call_max:
                    continue
                res = subprocess.run(
                    [sys.executable, __file__, "--one", job, str(size), "1" if chunked else "0"],
                    capture_output=True,
                    text=True,
                    check=True,
                )
                row = json.loads(res.stdout.strip().splitlines()[-1])
                rows.append(row)
                print(
                    f"{job:>8} {size:>8d} {'chunked' if chunked else 'one call':>8}: "
                    f"{row['second_s']:7.2f} s (first {row['first_s']:6.2f} s) | peak "
                    f"{row['peak_mib']:7.0f} MiB = results {row['results_mib']:6.1f} + "
                    f"working {row['working_mib']:7.0f} MiB",
                    flush=True,
                )
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=2)
    return rows


if __name__ == "__main__":
    main()
