"""``jaxtow study TOW --out DIR``: the whole assessment of one tow, as NetCDF, JSON and one
self-contained HTML report."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import jaxtow as jt

from ..io._atomic import write_file
from ._common import positive_float
from .tow import load_tow


def cmd_study(args):
    tow = load_tow(args.tow, "study")
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise SystemExit(f"jaxtow study: error: --out {out} exists and is not a folder")
    out.mkdir(parents=True, exist_ok=True)
    kw = {}
    for k in ("map_xp", "map_l0", "speeds"):
        if getattr(args, k) is not None:
            kw[k] = [float(x) for x in getattr(args, k)]
    if args.t1 is not None:
        kw["t1"] = args.t1
    if args.no_time_domain:
        kw["time_domain"] = False
    try:
        study = jt.studies.tow_study(tow, progress=not args.quiet, **kw)
    except ValueError as e:
        raise SystemExit(f"jaxtow study: error: {e}") from None
    if not args.quiet:
        print("[report] figures and files ...", file=sys.stderr)
    for name, ds in study.datasets.items():
        jt.io.save_dataset(ds, out / f"{tow.name}_{name}.nc")
    figs = {
        k: jt.plotting.tow.png_bytes(f) for k, f in jt.plotting.tow.study_figures(study).items()
    }
    for k, b in figs.items():
        write_file(out / f"{tow.name}_{k}.png", b)
    write_file(out / f"{tow.name}_summary.json", json.dumps(study.summary, indent=2, default=float))
    report = out / f"{tow.name}_report.html"
    write_file(report, jt.reports.tow_report_html(study.summary, figs, version=jt.__version__))
    s = study.summary
    print(f"{tow.name}: {s.get('description', '')}")
    if "calm" in s:
        print(f"  calm water: {s['calm']['verdict_text']}")
    for name, r in s.get("sea_states", {}).items():
        print(f"  sea state {name}: {r['verdict_text']}")
    for r in s.get("resistance", []):
        sp = r.get("operating_speed")
        print(
            f"  {r['sea_state']}: required bollard pull {r['required_bollard_pull'] / 9.80665e3:.1f} t"
            + (f", operating speed {sp:.2f} m/s" if sp is not None else f"; {r['message']}")
        )
    for k, why in s.get("skipped", {}).items():
        print(f"  not assessed: {k} ({why})")
    print(f"wrote {report} (and NetCDF, JSON, PNG) to {out}")


def add_parser(sub):
    p = sub.add_parser(
        "study",
        help="the whole assessment of one tow: resistance, speed, stability, time domain; "
        "one HTML report",
    )
    p.add_argument("tow", help="tow file, or a built-in tow: barge1, barge2a, barge2b")
    p.add_argument("--out", default="results", help="output folder (default results)")
    p.add_argument(
        "--map-xp", nargs=3, default=None, metavar=("LO", "HI", "N"), help="override [study] map_xp"
    )
    p.add_argument(
        "--map-l0", nargs=3, default=None, metavar=("LO", "HI", "N"), help="override [study] map_l0"
    )
    p.add_argument(
        "--speeds",
        nargs=3,
        default=None,
        metavar=("LO", "HI", "N"),
        help="override [study] speeds [m/s]",
    )
    p.add_argument("--t1", type=positive_float, default=None, help="override [study] t1")
    p.add_argument("--no-time-domain", action="store_true", help="skip the time-domain check")
    p.add_argument("--quiet", action="store_true", help="no progress output")
    p.set_defaults(func=cmd_study)
