"""``jaxtow study TOW --out DIR``: the whole assessment of one tow, as NetCDF, JSON and one
self-contained HTML report."""

from __future__ import annotations

import dataclasses
import re
import sys
from pathlib import Path

import msgspec

import jaxtow as jt

from ._common import ea_arguments, ea_option, finite_float, positive_float
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
    ea = ea_option(args, "study")
    changes = {
        key: getattr(args, attr)
        for attr, key in (
            ("l0", "l0"),
            ("length", "length"),
            ("xp", "xp"),
            ("EA_nd", "EA_nd"),
            ("u_tug", "speed"),
        )
        if getattr(args, attr) is not None
    }
    if ea is not None:
        changes["EA_N"] = ea
    if not changes:
        return tow
    try:
        return jt.tow.with_changes(tow, **changes)
    except ValueError as e:
        raise SystemExit(f"jaxtow study: error: {e}") from None


def _stem(args) -> str:
    """The file stem of a study's outputs: the tow's name, made safe for a file name."""
    return safe_name(_tow(args).name)


def _with_risk_options(tow, args):
    """The tow with the command line's --risk and --risk-budget in its [study] options."""
    given = {
        k: v for k, v in (("risk", args.risk), ("risk_budget_s", args.risk_budget)) if v is not None
    }
    if not given:
        return tow
    return dataclasses.replace(tow, study=dataclasses.replace(tow.study, **given))


def cmd_study(args):
    tow = _with_risk_options(_tow(args), args)
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
    options = dict(kw, n_save=2001, risk=[tow.study.risk, tow.study.risk_budget_s])
    store = jt.io.StepStore(
        out / f".{stem}_steps",
        jt.io.fingerprint(dict(tow=tow.resolved, options=options, version=jt.__version__)),
        resume=args.resume,
    )
    study = jt.studies.tow_study(tow, progress=not args.quiet, store=store, **kw)
    report = _write(study, out, stem, quiet=args.quiet)
    _print_summary(study.summary, report, out)
    stopped = study.summary.incomplete
    if stopped is None:
        store.clear()
        return
    print(
        f"jaxtow study: the study stopped at the step '{stopped.step}' ({stopped.error}); "
        f"the report of what finished, marked incomplete, is {report} (a complete report "
        f"of an earlier run in {out} is left as it was); the finished steps are kept in "
        f"{store.folder}: run the same command with --resume to continue",
        file=sys.stderr,
    )
    if stopped.interrupted:
        raise KeyboardInterrupt
    raise SystemExit(1)


#: The suffix of an incomplete study's files, so that they never replace a complete study's.
INCOMPLETE = "_INCOMPLETE"


def _write(study, out: Path, stem: str, *, quiet: bool) -> Path:
    """The study's NetCDF, PNG, JSON and HTML files; a figure that fails is named in the
    summary (``figure_errors``) and the report is written without it. An incomplete study
    writes its files under ``<tow>_INCOMPLETE_*`` and leaves a complete study's alone; a
    complete one removes the incomplete files of an earlier run."""
    if not quiet:
        print("[report] figures and files ...", file=sys.stderr)
    incomplete = study.summary.incomplete is not None
    name = stem + (INCOMPLETE if incomplete else "")
    if not incomplete:
        for old in out.glob(f"{stem}{INCOMPLETE}_*"):
            old.unlink()
    for key, ds in study.datasets.items():
        jt.io.save_dataset(ds, out / f"{name}_{safe_name(key)}.nc")
    figs, errors = {}, {}
    for k, make in jt.plotting.tow.study_figure_makers(study).items():
        try:
            figs[k] = jt.plotting.tow.png_bytes(make())
        except Exception as e:  # noqa: BLE001 - one figure never costs the report
            errors[k] = f"{type(e).__name__}: {e}"
    summary = study.summary
    if errors:
        summary = msgspec.structs.replace(summary, figure_errors=errors)
    for k, b in figs.items():
        jt.io.write_file(out / f"{name}_{safe_name(k)}.png", b)
    jt.io.write_file(out / f"{name}_summary.json", jt.studies.to_json(summary))
    report = out / f"{name}_report.html"
    jt.io.write_file(report, jt.reports.tow_report_html(summary, figs, version=jt.__version__))
    return report


def _print_summary(s, report: Path, out: Path) -> None:
    print(f"{s.tow}: {s.description}")
    for c in s.conditions:
        print(f"  {c.name}: {c.verdict_text}")
    for r in s.resistance:
        sp = r.operating_speed if r.status == "successful" else None
        print(
            f"  {r.sea_state}: required bollard pull {r.required / jt.TONNE_FORCE:.1f} t (the "
            "worst over Tp)"
            + (
                f", operating speed {sp:.2f} m/s ({sp / jt.KNOT:.1f} kn)"
                if sp is not None
                else f"; {r.message}"
            )
        )
    for line in jt.reports.criteria_lines(s):
        print(f"  {line}")
    for k, why in s.skipped.items():
        print(f"  not assessed: {k} ({why})")
    for k, why in s.figure_errors.items():
        print(f"  figure {k} failed: {why}")
    if s.assessment is not None:
        print(f"VERDICT {s.assessment.reason}")
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
    ea_arguments(p)
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
    p.add_argument(
        "--risk",
        choices=("auto", "always", "never"),
        default=None,
        help="the irregular-sea Monte Carlo: auto (where a yaw criterion is not determined; "
        "the default of [study] risk), always, never",
    )
    p.add_argument(
        "--risk-budget",
        type=positive_float,
        default=None,
        metavar="S",
        help="its wall-time budget in seconds (default [study] risk_budget_s, 300)",
    )
    p.add_argument("--quiet", action="store_true", help="no progress output")
    p.add_argument(
        "--resume",
        action="store_true",
        help="continue a study that failed or was interrupted, from the steps it finished "
        "(kept in OUT/.TOW_steps until the study completes)",
    )
    p.set_defaults(func=cmd_study, manifest_name=lambda args: f"{_stem(args)}_run.json")
