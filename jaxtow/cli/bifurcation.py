"""``jaxtow bifurcation``: equilibrium branches, pitchfork/fold/Hopf points, limit cycles."""

from __future__ import annotations

import json
from pathlib import Path

import jaxtow as jt

from ._common import positive_float, tow_model, tow_option


def cmd_bifurcation(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    model, tow_name = tow_model(args, command="bifurcation")
    lo, hi = args.range
    try:
        study = jt.studies.bifurcation_study(
            model, args.param, (lo, hi), ds=args.ds, cycles=args.cycles
        )
    except (KeyError, ValueError) as e:
        raise SystemExit(f"error: {e}") from None
    if study.note:
        print(f"note: {study.note}")
    stem = out / f"bifurcation_{tow_name}_{args.param}"
    jt.plotting.save(
        jt.plotting.bifurcation.plot_branch(
            study.branch,
            orbits=study.orbits,
            title=f"{model.vessel.name}, l0'={args.l0}, xp'={args.xp} (fixed ones)",
        ),
        stem.with_suffix(".png"),
    )
    record = dict(
        tow=tow_name,
        parameter=args.param,
        range=[lo, hi],
        special_points=study.special,
        limit_cycles=study.cycles,
        assumed_values=dict(model.assumed),
    )
    jt.io.write_file(stem.with_suffix(".json"), json.dumps(record, indent=2, default=float))
    _print(model.vessel.name, args.param, lo, hi, study)
    print(f"wrote figure and JSON to {out}")


def _print(name: str, param: str, lo: float, hi: float, study) -> None:
    print(f"{name}: continuation in {param}' over [{lo}, {hi}]")
    for s in study.special:
        extra = (
            f"  omega = {s['frequency']:.4f}, l1 = {s['lyapunov']:+.4g} ({s['criticality']})"
            if s["kind"] == "hopf"
            else ""
        )
        print(
            f"  {s['kind']:15s} {param}' = {s['parameter']:.10f}  psi = {s['psi_deg']:+8.3f} deg{extra}"
        )
    for c in study.cycles:
        print(
            f"  limit cycle {param}' = {c['parameter']:.4f}: period {c['period']:.3f}, path width "
            f"{c['path_width']:.4f} L, yaw +-{c['yaw_range_deg']:.2f} deg, {'stable' if c['stable'] else 'unstable'}"
        )


def add_parser(sub):
    b = sub.add_parser(
        "bifurcation", help="equilibrium branches, pitchfork/fold/Hopf points, limit cycles"
    )
    tow_option(b)
    b.add_argument(
        "--param", default="xp", help="continuation parameter (xp, l0, EA, any vessel coefficient)"
    )
    b.add_argument("--range", nargs=2, type=float, default=(0.0, 1.0), metavar=("LO", "HI"))
    b.add_argument("--xp", type=float, default=0.5, help="x_p' when not the continuation parameter")
    b.add_argument("--l0", type=float, default=0.5, help="l0' when not the continuation parameter")
    b.add_argument("--ds", type=positive_float, default=0.01, help="initial arclength step")
    b.add_argument(
        "--cycles", type=int, default=0, help="limit cycles to continue across the unstable range"
    )
    b.add_argument("--out", default="results/bifurcation", help="output folder")
    b.set_defaults(func=cmd_bifurcation)
