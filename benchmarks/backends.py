"""Benchmark: the same work on every backend of this machine, in one process.

For each backend JAX finds (the CPU always; a GPU where there is one), in float64:

* ``calm_map``: the calm-water (x_p', l0') stability map of Barge 2a (analytic equilibria,
  autodiff Jacobians), max Re λ by the Routh kernel (the sweeps' default), and the same map
  with every eigenvalue by the backend's default eigenvalue method
  (`jaxtow.default_eig_method`: LAPACK on the CPU, the characteristic polynomial elsewhere);
* ``wave_map``: the (l0', ω) map in regular head waves on the shipped near-field panel
  database (every equilibrium by the heading scan, Routh kernel);
* ``time_domain``: a batch of time-domain runs of 100 L/U (diffrax, Tsit5);
* ``strip_table``: strip theory's added-resistance table of the 21-section box (40 ω × 13 β
  at 2 m/s);
* ``study``: ``jaxtow study barge2a`` in a subprocess on that backend, with a fresh
  compile cache (cold) and again (warm).

Each item records its run time (the second call), its compile time (first call minus
second), µs per point or runs per second, and the eigenvalue method used. The plain
NumPy/SciPy loops of the same work (``baseline_numpy``: the calm map; ``baseline_numpy_waves``:
the wave map; SciPy's ``solve_ivp``: the time domain) run once, on a subset, on the CPU.

    python benchmarks/backends.py --json benchmarks/data/perf/backends.json [--label NAME]
    python benchmarks/backends.py --table benchmarks/data/perf/backends.json   # docs table

``--json`` appends this run (one entry per backend) to the file's list of runs; ``--table``
writes the table of every run in the file into docs/benchmarks.md.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import platform as host
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import jax
import numpy as np

sys.path.insert(0, str(Path(__file__).parent))

import jaxtow as jt  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs" / "benchmarks.md"
BEGIN, END = (
    "<!-- backends table: python benchmarks/backends.py --table -->",
    "<!-- end of backends table -->",
)

#: Work sizes per backend: the CPU sizes keep a 2-core run to minutes.
SIZES = {
    "cpu": dict(calm=65_536, wave=96, runs=256, numpy_calm=2_000, numpy_wave=12, numpy_runs=8),
    "gpu": dict(calm=4_194_304, wave=400, runs=16_384),
}


def _timed(fn):
    t = time.perf_counter()
    out = fn()
    jax.block_until_ready(out)
    return out, time.perf_counter() - t


def _twice(fn):
    """(result, run seconds, compile seconds): the first call compiles, the second runs."""
    _, first = _timed(fn)
    out, second = _timed(fn)
    return out, second, max(first - second, 0.0)


def calm_map(device, n):
    model = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())
    side = int(round(np.sqrt(n)))
    grid = {"xp": np.linspace(0.0, 0.6, side), "l0": np.linspace(0.2, 2.5, n // side)}
    npts = side * (n // side)
    out = {}
    for key, opts in (
        ("routh", dict(eig_method="routh")),
        ("default_eigenvalues", dict(eigenvalues=True)),
    ):
        solver, execution = jt.sweep_options(
            method="analytic",
            routh_hurwitz=False,
            chunk_size=min(npts, 262_144),
            devices=[device],
            **opts,
        )
        arrays, run, comp = _twice(lambda: jt.sweep_arrays(model, grid, solver, execution))
        out[key] = dict(
            points=npts,
            run_s=run,
            compile_s=comp,
            us_per_point=1e6 * run / npts,
            eig_method=str(arrays["_eig_method"]),
        )
    out["default_over_routh"] = out["default_eigenvalues"]["run_s"] / out["routh"]["run_s"]
    return out


def wave_map(device, n):
    model = jt.presets.barge2_wave_model("2a", l0=1.0, xp=0.5, omega=1.0, zeta_a=1.25)
    grid = {"l0": np.linspace(0.3, 3.0, n), "external.omega": np.linspace(0.3, 2.0, n)}
    solver, execution = jt.sweep_options(
        n_grid=401,
        max_roots=4,
        routh_hurwitz=False,
        chunk_size=8192,
        devices=[device],
        specialise=True,
    )
    arrays, run, comp = _twice(lambda: jt.sweep_arrays(model, grid, solver, execution))
    return dict(
        points=n * n,
        run_s=run,
        compile_s=comp,
        us_per_point=1e6 * run / (n * n),
        eig_method=str(arrays["_eig_method"]),
    )


def _starts(model, runs):
    rng = np.random.default_rng(0)
    psi0 = np.radians(rng.uniform(-20, 20, runs))
    yoff = rng.uniform(-0.4, 0.4, runs)
    return np.stack([np.asarray(jt.initial_state(model, psi0=p, y0=y)) for p, y in zip(psi0, yoff)])


def time_domain(device, runs):
    model = jt.TowModel(
        vessel=jt.presets.barge_2b(), towline=jt.presets.default_towline(l0=2.5, xp=0.5)
    )
    y0s = jax.device_put(_starts(model, runs), device)
    batch = None if device.platform != "cpu" else 64
    sims, run, comp = _twice(
        lambda: jt.simulate_batch(model, y0s, t1=100.0, n_save=2, batch_size=batch).ys
    )
    return dict(
        runs=runs, t1=100.0, run_s=run, compile_s=comp, runs_per_s=runs / run, batch_size=batch
    )


def strip_table(device):
    hull = jt.strip.box(76.2, 24.4, 5.0, n_stations=21)
    omega = np.linspace(0.2, 2.0, 40)
    beta = np.radians(np.linspace(0.0, 180.0, 13))
    loading = jt.Loading(z_g=5.0)

    def call():
        return jt.strip.added_resistance(hull, omega, beta, 2.0, loading=loading).resistance

    _, run, comp = _twice(call)
    return dict(frequencies=40, headings=13, sections=21, run_s=run, compile_s=comp)


def study(platform, timeout):
    """``jaxtow study barge2a`` in a subprocess on ``platform``: cold (a fresh compile cache),
    then warm (the same cache)."""
    out = {}
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(
            os.environ, JAX_PLATFORMS=platform, JAXTOW_COMPILE_CACHE=str(Path(tmp) / "cache")
        )
        for key in ("cold", "warm"):
            folder = Path(tmp) / key
            t = time.perf_counter()
            r = subprocess.run(
                [
                    sys.executable,
                    "-c",
                    "import sys; from jaxtow.cli import main; sys.exit(main())",
                    "study",
                    "barge2a",
                    "--out",
                    str(folder),
                    "--quiet",
                ],
                env=env,
                capture_output=True,
                text=True,
                timeout=timeout,
            )
            out[f"{key}_s"] = time.perf_counter() - t
            if r.returncode != 0:
                out["error"] = (r.stderr or r.stdout)[-500:]
                break
            shutil.rmtree(folder, ignore_errors=True)
    return out


def numpy_baselines(sizes):
    """The plain NumPy/SciPy loops of the same work, on a subset of points (CPU)."""
    from baseline_numpy import stability_map, vector_field as np_field
    from scipy.integrate import solve_ivp

    out = {}
    model = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())
    vessel = model.vessel
    params = {k: float(getattr(vessel, k)) for k in jt.VESSEL_PARAMETERS}
    params["EA"] = float(model.towline.EA)
    rng = np.random.default_rng(1)
    n = sizes["numpy_calm"]
    xp, l0 = rng.uniform(0.0, 0.6, n), rng.uniform(0.2, 2.5, n)
    _, t = _timed(lambda: stability_map(params, xp, l0))
    out["calm_map"] = dict(points=n, run_s=t, us_per_point=1e6 * t / n)

    from baseline_numpy_waves import NumpyQTF, stability_map as wave_map_np

    wm = jt.presets.barge2_wave_model("2a", l0=1.0, xp=0.5, omega=1.0, zeta_a=1.25)
    q = wm.external.qtf
    sc = jt.presets.barge2_scales()
    wp = {k: float(getattr(wm.vessel, k)) for k in jt.VESSEL_PARAMETERS}
    wp.update(
        EA=float(wm.towline.EA),
        xp=float(wm.towline.xp),
        zeta_a=1.25,
        u_tug=float(sc.u_tug),
        force=float(sc.force),
        moment=float(sc.moment),
        length=float(sc.length),
        qtf=NumpyQTF(np.asarray(q.omega), np.asarray(q.beta), np.asarray(q.values), q.periodic),
        moments=NumpyQTF(
            np.asarray(q.omega), np.asarray(q.beta), np.asarray(q.sectional), q.periodic
        )
        if q.has_sectional
        else None,
    )
    n = sizes["numpy_wave"]
    _, t = _timed(lambda: wave_map_np(wp, rng.uniform(0.3, 3.0, n), rng.uniform(0.3, 2.0, n)))
    out["wave_map"] = dict(points=n, run_s=t, us_per_point=1e6 * t / n)

    tm = jt.TowModel(
        vessel=jt.presets.barge_2b(), towline=jt.presets.default_towline(l0=2.5, xp=0.5)
    )
    tp = {k: float(getattr(tm.vessel, k)) for k in jt.VESSEL_PARAMETERS}
    tp.update(EA=float(tm.towline.EA), xp=0.5, l0=2.5)
    y0s = _starts(tm, sizes["numpy_runs"])

    def loop():
        for y0 in y0s:
            solve_ivp(lambda t, y: np_field(y, tp), (0.0, 100.0), y0, rtol=1e-8, atol=1e-8)

    _, t = _timed(loop)
    out["time_domain"] = dict(runs=len(y0s), run_s=t, runs_per_s=len(y0s) / t)
    return out


def backends():
    found = []
    for name in ("cpu", "gpu"):
        with contextlib.suppress(RuntimeError):
            found.append((name, jax.devices(name)[0]))
    return found


def run(args):
    if not jax.config.jax_enable_x64:
        raise SystemExit("float64 is off: unset JAXTOW_ENABLE_X64=0")
    entry = dict(
        label=args.label,
        date=time.strftime("%Y-%m-%d"),
        machine=f"{host.node()} ({os.cpu_count()} CPU cores)",
        jax=jax.__version__,
        float64=True,
        backends=[],
    )
    for name, device in backends():
        if args.backends and name not in args.backends:
            continue
        sizes = SIZES[name] if name in SIZES else SIZES["gpu"]
        rec = dict(platform=name, device=str(getattr(device, "device_kind", device)), work={})
        items = dict(
            calm_map=lambda: calm_map(device, sizes["calm"]),
            wave_map=lambda: wave_map(device, sizes["wave"]),
            time_domain=lambda: time_domain(device, sizes["runs"]),
            strip_table=lambda: strip_table(device),
        )
        if not args.no_study:
            items["study"] = lambda: study("cuda" if name == "gpu" else name, args.study_timeout)
        for key, fn in items.items():
            if args.only and key not in args.only:
                continue
            t = time.perf_counter()
            try:
                with jax.default_device(device):
                    rec["work"][key] = fn()
            except Exception as e:  # a failed item is a result too: say what failed
                rec["work"][key] = dict(error=f"{type(e).__name__}: {e}"[:500])
            print(
                f"[{name}] {key} ({time.perf_counter() - t:.1f} s): {json.dumps(rec['work'][key])}",
                flush=True,
            )
        entry["backends"].append(rec)
    if not args.no_numpy:
        entry["numpy"] = numpy_baselines(SIZES["cpu"])
        print(f"[numpy] {json.dumps(entry['numpy'])}", flush=True)
    if args.json:
        path = Path(args.json)
        runs = json.loads(path.read_text()) if path.exists() else []
        runs = [r for r in runs if r.get("label") != args.label] + [entry]
        path.write_text(json.dumps(runs, indent=2) + "\n")
    return entry


def _cell(w, key):
    if not w or "error" in w:
        return "failed" if w else "—"
    if key == "time_domain":
        return f"{w['runs_per_s']:.0f} runs/s ({w['runs']} runs; compile {w['compile_s']:.1f} s)"
    if key == "strip_table":
        return f"{w['run_s']:.2f} s (compile {w['compile_s']:.1f} s)"
    if key == "study":
        return f"cold {w['cold_s']:.0f} s, warm {w.get('warm_s', float('nan')):.0f} s"
    return f"{w['us_per_point']:.3g} µs/point ({w['points']:,} points; compile {w['compile_s']:.1f} s; {w['eig_method']})"


def table(path) -> str:
    runs = json.loads(Path(path).read_text())
    cols, rows = [], {}
    works = [
        ("calm map, Routh kernel", "calm_map", "routh"),
        ("calm map, every eigenvalue (backend default)", "calm_map", "default_eigenvalues"),
        ("wave map, near-field database, Routh", "wave_map", None),
        ("time domain, 100 L/U per run", "time_domain", None),
        ("strip added-resistance table, 40 ω × 13 β", "strip_table", None),
        ("`jaxtow study barge2a`", "study", None),
    ]
    numpy = {}
    for r in runs:
        for b in r["backends"]:
            cols.append(f"{r['label']}: {b['platform']} ({b['device']})")
            for title, key, sub in works:
                w = b["work"].get(key)
                if w is not None and sub is not None and "error" not in w:
                    w = w[sub]
                rows.setdefault(title, []).append(_cell(w, key))
        numpy = r.get("numpy", numpy) or numpy
    head = "| work | " + " | ".join(cols) + " | NumPy/SciPy loop (CPU) |"
    lines = [head, "|" + " --- |" * (len(cols) + 2)]
    for title, key, sub in works:
        n = numpy.get(key)
        if n and key == "time_domain":
            ncell = f"{n['runs_per_s']:.2g} runs/s"
        elif n:
            ncell = f"{n['us_per_point']:.3g} µs/point"
        else:
            ncell = "—"
        lines.append(f"| {title} | " + " | ".join(rows[title]) + f" | {ncell} |")
    return "\n".join(lines)


def write_table(path):
    from _docs_block import write_block  # beside this script

    write_block(DOCS, BEGIN, END, table(path))


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--json", default=None, help="append this run to this file's list of runs")
    ap.add_argument("--label", default=host.node(), help="this run's name in the table")
    ap.add_argument(
        "--backends", nargs="*", default=None, help="cpu, gpu (default: every one found)"
    )
    ap.add_argument("--only", nargs="*", default=None, help="work items to run (default: all)")
    ap.add_argument("--no-study", action="store_true")
    ap.add_argument("--no-numpy", action="store_true")
    ap.add_argument("--study-timeout", type=float, default=900.0)
    ap.add_argument("--table", default=None, help="write the docs table of this JSON and stop")
    args = ap.parse_args(argv)
    if args.table:
        write_table(args.table)
        print(table(args.table))
        return None
    return run(args)


if __name__ == "__main__":
    main()
