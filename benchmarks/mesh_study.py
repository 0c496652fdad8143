"""Mesh study of the stability verdict, and the shipped panel databases (docs/bem.md,
"Shipped databases").

    # 1. the panel solves (background; about 10 / 20 / 60 min on 2 cores at 2 / 1.5 / 1 m):
    for p in 2 1.5 1; do jaxtow bem barge2a --panel-size $p --out RUNS/barge2_p$p; done
    jaxtow bem barge1 --panel-size 1.5 --out RUNS/barge1_p1.5
    # 2. the verdict study and the table (docs/data/mesh_study.{json,md}):
    python benchmarks/mesh_study.py --runs RUNS [--n 41] [--write]
    # 3. ship the chosen mesh (jaxtow/data/qtf/{barge1,barge2}_{far,near}_field.nc):
    python benchmarks/mesh_study.py --runs RUNS --ship barge2=1 --ship barge1=1.5

For every Barge 2 mesh of RUNS and each drift method, the four maps of the wave study
(`jaxtow.studies.verdict_maps`: 2a and 2b over (l0', ω) and (l0', Tp)); between successive
meshes, the fraction of map points whose verdict changes and the largest change of max Re λ.
The QTF representation is compared the same way on the finest mesh: the tensor Hermite
interpolant with three-point slopes (the default) against the same table smoothed in heading
by a least-squares Fourier fit (`jaxtow.drift.QTF.smoothed`). Barge 1: the head-sea surge in
short waves against Faltinsen's wall limit ½ρgζa²B, and near field vs far field per zone.
"""

from __future__ import annotations

import argparse
import json
import re
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "jaxtow" / "data" / "qtf"
DOCS = ROOT / "docs" / "data"
METHODS = ("near_field", "far_field")


def runs_of(runs: Path, hull: str, only=None) -> dict:
    """{panel size: run folder} of the ``jaxtow bem`` outputs for ``hull`` under ``runs``."""
    out = {}
    for d in sorted(runs.glob(f"{hull}_p*")):
        m = re.fullmatch(rf"{hull}_p([0-9.]+)", d.name)
        if m and (d / "summary.json").exists() and (only is None or float(m.group(1)) in only):
            out[float(m.group(1))] = d
    return dict(sorted(out.items(), reverse=True))


def verdict_study(runs: dict, n: int, smooth: int, rep_size=None, methods=METHODS) -> dict:
    from jaxtow.io import load_qtf
    from jaxtow.studies import MAP_NAMES, verdict_change, verdict_maps

    rows, maps = [], {}
    t0 = time.perf_counter()

    def cached(d, tag, make):
        f = d / f"verdict_maps_{tag}_n{n}.npz"
        if f.exists():
            return dict(np.load(f))
        out = {k: v for k, v in make().items() if k in MAP_NAMES}
        np.savez(f, **out)
        return out

    for size, d in runs.items():
        summ = json.loads((d / "summary.json").read_text())
        for method in methods:
            q = load_qtf(d / f"qtf_{method}.nc")
            maps[(size, method)] = cached(d, method, lambda q=q: verdict_maps(q, n=n))
            print(f"maps done: {size:g} m {method} ({time.perf_counter() - t0:.0f} s)", flush=True)
        rows.append(dict(panel_size=size, n_panels=summ["n_panels"]))
    sizes = list(runs)
    for i, size in enumerate(sizes):
        for method in methods:
            r = rows[i].setdefault(method, {})
            if i == 0:
                continue
            prev = maps[(sizes[i - 1], method)]
            cur = maps[(size, method)]
            per = {k: verdict_change(prev[k], cur[k]) for k in MAP_NAMES}
            r["per_map"] = per
            r["fraction_changed"] = float(np.mean([v["fraction_changed"] for v in per.values()]))
            # of all map points together (the maps have different sizes)
            r["fraction_of_points_changed"] = float(
                sum(v["fraction_changed"] * v["points"] for v in per.values())
                / sum(v["points"] for v in per.values())
            )
            r["max_abs_change"] = float(np.nanmax([v["max_abs_change"] for v in per.values()]))
    finest = sizes[-1] if rep_size is None else rep_size
    rep = {}
    for method in methods:
        q = load_qtf(runs[finest] / f"qtf_{method}.nc")
        sm = cached(
            runs[finest],
            f"{method}_smoothed{smooth}",
            lambda q=q: verdict_maps(q.smoothed(smooth), n=n),
        )
        per = {k: verdict_change(maps[(finest, method)][k], sm[k]) for k in MAP_NAMES}
        rep[method] = dict(
            per_map=per,
            fraction_changed=float(np.mean([v["fraction_changed"] for v in per.values()])),
            max_abs_change=float(np.nanmax([v["max_abs_change"] for v in per.values()])),
        )
    stable = {
        f"{size}_{method}": {k: float(np.nanmean(maps[(size, method)][k] < 0)) for k in MAP_NAMES}
        for size in sizes
        for method in methods
    }
    return dict(
        n=n,
        rows=rows,
        methods=list(methods),
        representation=dict(panel_size=finest, harmonics=smooth, **rep),
        stable_fraction=stable,
        wall_s=time.perf_counter() - t0,
    )


def barge1_checks(runs: dict) -> dict:
    """Head-sea surge at the highest frequency over ½ρgB (per ζa²) and near vs far per zone."""
    out = {}
    for size, d in runs.items():
        s = json.loads((d / "summary.json").read_text())
        out[str(size)] = dict(
            n_panels=s["n_panels"],
            short_wave_surge_over_wall_limit={
                k: v / -0.5 for k, v in s["short_wave_surge_head_seas"].items()
            },
            near_vs_far_fx=s["near_vs_far_fx"],
            near_vs_far_fy=s["near_vs_far_fy"],
        )
    return out


def table(study: dict, b1: dict) -> str:
    lines = [
        "| panel size [m] | hull panels | method | verdict changes vs previous mesh: all points "
        "(mean of the four maps) | per map: 2a (l0', ω), 2b (l0', ω), 2a (l0', Tp), 2b (l0', Tp) "
        "| max Δ max Re λ |",
        "|---|---|---|---|---|---|",
    ]
    for r in study["rows"]:
        for method in study["methods"]:
            m = r[method]
            if "fraction_changed" in m:
                pooled = m.get("fraction_of_points_changed", m["fraction_changed"])
                ch = f"{100 * pooled:.2f} % ({100 * m['fraction_changed']:.2f} %)"
                per = ", ".join(
                    f"{100 * v['fraction_changed']:.2f} %" for v in m["per_map"].values()
                )
            else:
                ch = per = "-"
            mx = f"{m['max_abs_change']:.4f}" if "max_abs_change" in m else "-"
            lines.append(
                f"| {r['panel_size']:g} | {r['n_panels']} | {method} | {ch} | {per} | {mx} |"
            )
    rep = study["representation"]
    lines += [
        "",
        f"Representation ({rep['panel_size']:g} m mesh): Hermite three-point slopes against the "
        f"table smoothed in heading ({rep['harmonics']} Fourier harmonics):",
        "",
        "| method | verdict changes | max Δ max Re λ |",
        "|---|---|---|",
    ]
    for method in study["methods"]:
        m = rep[method]
        lines.append(
            f"| {method} | {100 * m['fraction_changed']:.2f} % | {m['max_abs_change']:.4f} |"
        )
    if b1:
        lines += [
            "",
            "Barge 1, head-sea surge at 2.5 rad/s over Faltinsen's wall limit ½ρgζa²B, and "
            "near vs far field (relative MSE of F_x per zone):",
            "",
            "| panel size [m] | hull panels | far field / limit | near field / limit | NF vs FF, F_x by zone |",
            "|---|---|---|---|---|",
        ]
        for size, r in b1.items():
            s = r["short_wave_surge_over_wall_limit"]
            z = ", ".join(f"{k} {v:.3f}" for k, v in r["near_vs_far_fx"].items())
            lines.append(
                f"| {float(size):g} | {r['n_panels']} | {s['far_field']:.3f} | {s['near_field']:.3f} | {z} |"
            )
    return "\n".join(lines) + "\n"


def ship(run: Path, hull: str, size: float, study: dict | None) -> None:
    """Copy a run's QTFs into the package data, compressed, with the provenance."""
    import xarray as xr

    DATA.mkdir(parents=True, exist_ok=True)
    for method in METHODS:
        ds = xr.load_dataset(run / f"qtf_{method}.nc")
        ds.attrs.update(
            database=f"{hull}_{method}",
            reproduce=(
                f"jaxtow bem {hull} --panel-size {size:g} --out RUNS/{hull}_p{size:g}; "
                f"python benchmarks/mesh_study.py --runs RUNS --ship {hull}={size:g}"
            ),
            mesh_study=(
                "docs/bem.md, Shipped databases"
                if study is None
                else json.dumps(
                    [{k: r[k] for k in ("panel_size", "n_panels")} for r in study["rows"]]
                )
            ),
        )
        enc = {v: {"zlib": True, "complevel": 6} for v in ds.data_vars}
        ds.to_netcdf(DATA / f"{hull}_{method}.nc", encoding=enc)
        print(f"shipped {hull} {method} from {run} -> {DATA / f'{hull}_{method}.nc'}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", required=True, help="folder of jaxtow bem outputs HULL_pSIZE")
    ap.add_argument("--n", type=int, default=41, help="points per map axis")
    ap.add_argument(
        "--harmonics", type=int, default=8, help="Fourier harmonics of the smoothed table"
    )
    ap.add_argument("--ship", action="append", default=[], help="HULL=SIZE to ship")
    ap.add_argument("--no-study", action="store_true", help="only ship")
    ap.add_argument(
        "--sizes", type=float, nargs="*", default=None, help="only these Barge 2 meshes"
    )
    ap.add_argument("--methods", nargs="+", default=list(METHODS), choices=METHODS)
    ap.add_argument(
        "--representation-size",
        type=float,
        default=None,
        help="mesh of the representation comparison (default the finest)",
    )
    ap.add_argument("--write", action="store_true", help="write docs/data/mesh_study.{json,md}")
    args = ap.parse_args(argv)
    runs = Path(args.runs)
    study = None
    if not args.no_study:
        b2 = runs_of(runs, "barge2", args.sizes)
        study = verdict_study(
            b2, args.n, args.harmonics, args.representation_size, tuple(args.methods)
        )
        b1 = barge1_checks(runs_of(runs, "barge1"))
        study["barge1"] = b1
        md = table(study, b1)
        print(md)
        if args.write:
            DOCS.mkdir(parents=True, exist_ok=True)
            (DOCS / "mesh_study.json").write_text(json.dumps(study, indent=1))
            (DOCS / "mesh_study.md").write_text(md)
    for spec in args.ship:
        hull, size = spec.split("=")
        ship(runs_of(runs, hull)[float(size)], hull, float(size), study)


if __name__ == "__main__":
    main()
