"""``jaxtow drift``: the waterline drift-method comparison of thesis chapters 4-5."""

from __future__ import annotations

import json
from pathlib import Path

import jaxtow as jt

from ._common import positive_int, tow_names, tow_option
from .tow import load_tow


def _waterline(args):
    """The waterline of ``--waterline FILE`` or of the tow (``--tow``; ``--draft`` overrides
    its draft)."""

    if args.waterline:
        return jt.io.read_waterline(args.waterline, draft=args.draft or 5.0)
    name = tow_names(args, "drift")[0]
    tow = load_tow(name, "drift")
    if args.draft is None:
        return tow.waterline
    spec = tow.resolved["hull"]["waterline"]
    if spec == "box":
        return jt.presets.box_waterline(
            tow.scales.length, tow.resolved["vessel"]["breadth"], args.draft
        )
    if spec == "barge2":
        return jt.presets.barge2_waterline(draft=args.draft)
    return jt.io.read_waterline(spec, draft=args.draft)


def cmd_drift(args):
    if args.base not in jt.drift.WATERLINE_METHODS:
        raise SystemExit(
            f"error: --base {args.base!r} is not a drift method; choose from {sorted(jt.drift.WATERLINE_METHODS)}"
        )
    wl = _waterline(args)
    study = jt.studies.drift_methods_study(
        wl,
        base=args.base,
        omega_max=args.omega_max,
        n_omega=args.n_omega,
        sway_heading_deg=args.sway_heading,
        hs=args.hs,
        speeds=args.speeds,
    )
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    jt.io.save_dataset(study.head, out / "stationary_head_seas.nc")
    jt.io.save_dataset(study.oblique, out / "stationary_oblique.nc")
    for stem, ax in jt.plotting.drift.drift_study_figures(study).items():
        jt.plotting.save(ax, out / f"{stem}.png")
    summary = study.summary
    jt.io.write_file(out / "summary.json", json.dumps(summary, indent=2, default=float))
    print(
        f"{wl.name}: L = {summary['length']:g} m, B = {summary['breadth']:g} m, "
        f"T = {summary['draft']:g} m, C_B = {summary['block_coefficient']:.3f}"
    )
    print(f"relative MSE against {args.base!r} (regular waves, surge beta = 0) per zone:")
    print(f"  {'method':18s} {'motion':>10s} {'transition':>11s} {'reflection':>11s}")
    for m, z in summary["regular_relative_mse_by_zone"]["surge"].items():
        cells = [
            f"{z[k]:10.3g}" if z[k] is not None else f"{'-':>10s}"
            for k in ("motion", "transition", "reflection")
        ]
        print(f"  {m:18s} {cells[0]} {cells[1]:>11s} {cells[2]:>11s}")
    print(f"wrote figures, NetCDF datasets and summary.json to {out}")


def add_parser(sub):
    d = sub.add_parser("drift", help="compare the waterline drift methods (thesis chapters 4-5)")
    tow_option(d, default=("barge1",))
    d.add_argument(
        "--waterline", help="half-waterline text file instead (see jaxtow.io.read_waterline)"
    )
    d.add_argument(
        "--draft",
        type=float,
        default=None,
        help="draft [m] (default: the documented 5.0 m estimate)",
    )
    d.add_argument(
        "--base", default="faltinsen", help="base method for the relative MSE (default faltinsen)"
    )
    d.add_argument(
        "--sway-heading", type=float, default=-15.0, help="heading for the sway figures [deg]"
    )
    d.add_argument(
        "--hs", type=float, default=5.0, help="Hs of the irregular comparison [m] (default 5)"
    )
    d.add_argument(
        "--speeds", type=float, nargs="+", default=[0.0, 1.0, 2.0, 3.0], help="speeds [m/s]"
    )
    d.add_argument(
        "--omega-max", type=float, default=2.1, help="highest wave frequency [rad/s] (default 2.1)"
    )
    d.add_argument(
        "--n-omega",
        type=positive_int,
        default=191,
        help="frequencies from 0.2 rad/s to --omega-max",
    )
    d.add_argument("--out", default="results/drift", help="output folder")
    d.set_defaults(func=cmd_drift)
