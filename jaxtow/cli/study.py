"""``jaxtow study TOW --out DIR``: the whole assessment of one tow, as NetCDF, JSON and one
self-contained HTML report."""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import jaxtow as jt

from ..io._atomic import write_file
from ._common import check_ea_newtons, finite_float, positive_float
from .tow import load_tow


def safe_name(text: str) -> str:
    """``text`` as a portable file-name part: letters, digits, '.', '-' and '_' kept, every
    other run of characters (a '/', spaces, brackets) one '_'."""
    return re.sub(r"[^A-Za-z0-9._-]+", "_", text).strip("_") or "_"


def _tow(args):
    """The tow of ``jaxtow study TOW`` or ``--tow TOW``, with the command line's changes in
    the tow file's units (`jaxtow.tow.with_changes`)."""
    if args.tow_positional and args.tow_flag and args.tow_positional != args.tow_flag:
        raise SystemExit("jaxtow study: error: give the tow once (TOW or --tow TOW)")
    tow = load_tow(args.tow_positional or args.tow_flag or "barge2a", "study")
    if args.EA is not None:
        check_ea_newtons(args.EA, "study")
    changes = {
        key: getattr(args, attr)
        for attr, key in (
            ("l0", "l0"),
            ("length", "length"),
            ("xp", "xp"),
            ("EA", "EA"),
            ("EA_nd", "EA_nd"),
            ("u_tug", "speed"),
        )
        if getattr(args, attr) is not None
    }
    if not changes:
        return tow
    try:
        return jt.tow.with_changes(tow, **changes)
    except ValueError as e:
        raise SystemExit(f"jaxtow study: error: {e}") from None


def cmd_study(args):
    tow = _tow(args)
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
    stem = safe_name(tow.name)
    options = dict(kw, n_save=2001)
    store = jt.io.StepStore(
        out / f".{stem}_steps",
        jt.io.study_fingerprint(tow.resolved, options, jt.__version__),
        resume=args.resume,
    )
    study = jt.studies.tow_study(tow, progress=not args.quiet, store=store, **kw)
    report = _write(study, out, stem, quiet=args.quiet)
    _print_summary(study.summary, report, out)
    stopped = study.summary.get("incomplete")
    if stopped is None:
        store.clear()
        return
    print(
        f"jaxtow study: the study stopped at the step '{stopped['step']}' ({stopped['error']}); "
        f"the report of what finished, marked incomplete, is {report}; the finished steps are "
        f"kept in {store.folder}: run the same command with --resume to continue",
        file=sys.stderr,
    )
    if stopped["interrupted"]:
        raise KeyboardInterrupt
    raise SystemExit(1)


def _write(study, out: Path, stem: str, *, quiet: bool) -> Path:
    """The study's NetCDF, PNG, JSON and HTML files; a figure that fails is named in the
    summary (``figure_errors``) and the report is written without it."""
    if not quiet:
        print("[report] figures and files ...", file=sys.stderr)
    for name, ds in study.datasets.items():
        jt.io.save_dataset(ds, out / f"{stem}_{safe_name(name)}.nc")
    figs, errors = {}, {}
    for k, make in jt.plotting.tow.study_figure_makers(study).items():
        try:
            figs[k] = jt.plotting.tow.png_bytes(make())
        except Exception as e:  # noqa: BLE001 - one figure never costs the report
            errors[k] = f"{type(e).__name__}: {e}"
    if errors:
        study.summary["figure_errors"] = errors
    for k, b in figs.items():
        write_file(out / f"{stem}_{safe_name(k)}.png", b)
    write_file(out / f"{stem}_summary.json", json.dumps(study.summary, indent=2, default=float))
    report = out / f"{stem}_report.html"
    write_file(report, jt.reports.tow_report_html(study.summary, figs, version=jt.__version__))
    return report


def _print_summary(s: dict, report: Path, out: Path) -> None:
    print(f"{s['tow']}: {s.get('description', '')}")
    if "calm" in s:
        print(f"  calm water: {s['calm']['verdict_text']}")
    for name, r in s.get("sea_states", {}).items():
        print(f"  sea state {name}: {r['verdict_text']}")
    for r in s.get("resistance", []):
        worst = max(r["required_bollard_pull"], r.get("worst_required_bollard_pull", 0.0))
        sp = r.get("operating_speed") if r["status"] == "successful" else None
        print(
            f"  {r['sea_state']}: required bollard pull {worst / 9.80665e3:.1f} t (the worst "
            "over Tp)"
            + (
                f", operating speed {sp:.2f} m/s ({sp / 0.514444:.1f} kn)"
                if sp is not None
                else f"; {r['message']}"
            )
        )
    for line in jt.reports.criteria_lines(s):
        print(f"  {line}")
    for k, why in s.get("skipped", {}).items():
        print(f"  not assessed: {k} ({why})")
    for k, why in s.get("figure_errors", {}).items():
        print(f"  figure {k} failed: {why}")
    print(f"wrote {report} (and NetCDF, JSON, PNG) to {out}")


def add_parser(sub):
    p = sub.add_parser(
        "study",
        help="the whole assessment of one tow: resistance, speed, stability, time domain; "
        "one HTML report",
    )
    p.add_argument(
        "tow_positional",
        metavar="TOW",
        nargs="?",
        help="tow file, or a built-in tow: barge1, barge2a, barge2b (default barge2a)",
    )
    p.add_argument("--tow", dest="tow_flag", metavar="TOW", help="the tow, as TOW")
    p.add_argument("--l0", type=positive_float, help="towline length l0' [L] (tow file: l0)")
    p.add_argument("--length", type=positive_float, help="towline length [m] (tow file: length)")
    p.add_argument("--xp", type=finite_float, help="attachment point x_p' [L] (tow file: xp)")
    p.add_argument("--EA", type=positive_float, help="towline axial stiffness [N] (tow file: EA)")
    p.add_argument(
        "--EA-nd", dest="EA_nd", type=positive_float, help="non-dimensional EA' (tow file: EA_nd)"
    )
    p.add_argument(
        "--u-tug", type=positive_float, help="design tow speed [m/s] (tow file: [tow] speed)"
    )
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
    p.add_argument(
        "--resume",
        action="store_true",
        help="continue a study that failed or was interrupted, from the steps it finished "
        "(kept in OUT/.TOW_steps until the study completes)",
    )
    p.set_defaults(func=cmd_study)
