"""``jaxtow bifurcation``: equilibrium branches, pitchfork/fold/Hopf points, limit cycles."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ..io._atomic import write_file
from ._common import _model, _tow_option, positive_float


def cmd_bifurcation(args):
    import jaxtow as jt

    from .. import continuation as ct
    from ..plotting.bifurcation import plot_branch
    from ..plotting.calm import save

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    model, tow_name = _model(args, command="bifurcation")
    vessel = model.vessel
    lo, hi = args.range
    try:
        p0 = min(max(float(jt.get_parameter(model, args.param)), lo), hi)
        model = jt.with_parameters(model, **{args.param: p0})
        branch = ct.equilibrium_branch(model, args.param, p_range=(lo, hi), ds=args.ds)
    except (KeyError, ValueError) as e:
        raise SystemExit(f"error: {e}") from None
    orbits = []
    # limit cycles across the oscillatory-unstable stretch of the straight-behind branch: the
    # contiguous unstable run next to a Hopf point there
    hopf = sorted(sp.parameter for sp in branch.points("hopf") if sp.psi == 0.0)
    straight = branch.psi == 0.0
    runs, cur = [], []
    for k in np.argsort(branch.p):
        if straight[k] and branch.max_real[k] > 0:
            cur.append(branch.p[k])
        elif cur:
            runs.append(cur)
            cur = []
    if cur:
        runs.append(cur)
    span = max(args.ds * 3, 1e-3)
    runs = [r for r in runs if any(min(abs(r[0] - h), abs(r[-1] - h)) < span for h in hopf)]
    if args.cycles > 0 and runs:
        r = max(runs, key=len)
        values = np.linspace(r[0], r[-1], args.cycles + 2)[1:-1]
        mid = len(values) // 2
        try:
            first = ct.limit_cycle_from_simulation(
                jt.with_parameters(model, **{args.param: float(values[mid])})
            )
            first.parameter = float(values[mid])
            up = ct.limit_cycle_branch(model, args.param, values[mid + 1 :], start=first)
            down = ct.limit_cycle_branch(model, args.param, values[:mid][::-1], start=first)
            orbits = sorted([first, *up, *down], key=lambda o: o.parameter)
        except RuntimeError as e:
            print(f"note: limit cycles not computed: {e}")
    save(
        plot_branch(
            branch, orbits=orbits, title=f"{vessel.name}, l0'={args.l0}, xp'={args.xp} (fixed ones)"
        ),
        out / f"bifurcation_{tow_name}_{args.param}.png",
    )
    special = [
        dict(
            kind=s.kind,
            parameter=s.parameter,
            psi_deg=float(np.degrees(s.psi)),
            frequency=s.frequency,
            lyapunov=s.lyapunov,
            criticality=s.criticality,
        )
        for b in [branch, *branch.children]
        for s in b.special
    ]
    cycles = [
        dict(
            parameter=o.parameter,
            period=o.period,
            path_width=o.path_width,
            yaw_range_deg=float(np.degrees(o.yaw_range)),
            stable=o.stable,
            floquet_abs=sorted(np.abs(o.floquet).tolist()),
        )
        for o in orbits
    ]
    write_file(
        out / f"bifurcation_{tow_name}_{args.param}.json",
        json.dumps(
            dict(
                tow=tow_name,
                parameter=args.param,
                range=[lo, hi],
                special_points=special,
                limit_cycles=cycles,
                assumed_values=dict(model.assumed),
            ),
            indent=2,
            default=float,
        ),
    )
    print(f"{vessel.name}: continuation in {args.param}' over [{lo}, {hi}]")
    for s in special:
        extra = (
            f"  omega = {s['frequency']:.4f}, l1 = {s['lyapunov']:+.4g} ({s['criticality']})"
            if s["kind"] == "hopf"
            else ""
        )
        print(
            f"  {s['kind']:15s} {args.param}' = {s['parameter']:.10f}  psi = {s['psi_deg']:+8.3f} deg{extra}"
        )
    for c in cycles:
        print(
            f"  limit cycle {args.param}' = {c['parameter']:.4f}: period {c['period']:.3f}, path width "
            f"{c['path_width']:.4f} L, yaw +-{c['yaw_range_deg']:.2f} deg, {'stable' if c['stable'] else 'unstable'}"
        )
    print(f"wrote figure and JSON to {out}")


def add_parser(sub):
    b = sub.add_parser(
        "bifurcation", help="equilibrium branches, pitchfork/fold/Hopf points, limit cycles"
    )
    _tow_option(b)
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
