"""Helpers shared by the subcommands: grids, --set overrides, the preset model, time-domain runs."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np


def _grid(spec, name):
    lo, hi, n = spec
    n = int(n)
    if n < 1:
        raise SystemExit(f"error: --{name} needs a positive number of points")
    return np.linspace(float(lo), float(hi), n)


def _parse_sets(items):
    out = {}
    for item in items or []:
        if "=" not in item:
            raise SystemExit(f"error: --set expects NAME=VALUE, got {item!r}")
        k, v = item.split("=", 1)
        try:
            out[k.strip()] = float(v)
        except ValueError:
            raise SystemExit(f"error: --set {k}: {v!r} is not a number") from None
    return out


def _model(args, vessel_name=None, overrides=None):
    import jaxtow as jt

    vname = vessel_name or args.vessel
    if vname not in jt.presets.VESSELS:
        raise SystemExit(
            f"error: unknown vessel {vname!r}; choose from {sorted(jt.presets.VESSELS)}"
        )
    vessel = jt.presets.VESSELS[vname]()
    EA = args.EA if args.EA is not None else jt.presets.steel_wire_EA_nd(u_tug=args.u_tug)
    try:
        model = jt.TowModel(vessel=vessel, towline=jt.Towline(l0=args.l0, xp=args.xp, EA=EA))
        sets = dict(overrides or {})
        from .._parameters import check_values

        for k, v in sets.items():
            check_values(model, k, v)
        return jt.with_parameters(model, **sets) if sets else model
    except ValueError as e:
        raise SystemExit(f"error: {e}") from None


def _common(p):
    p.add_argument(
        "--u-tug",
        type=float,
        default=2.0,
        help="tug speed U_tug [m/s]; sets EA' of the default steel towline (default 2.0)",
    )
    p.add_argument(
        "--EA",
        type=float,
        default=None,
        help="towline stiffness EA' (non-dimensional); default: the documented steel wire",
    )
    p.add_argument(
        "--l0", type=float, default=2.5, help="unstretched towline length l0' [L] (default 2.5)"
    )
    p.add_argument(
        "--xp", type=float, default=0.5, help="attachment point x_p' ahead of CoG [L] (default 0.5)"
    )
    p.add_argument(
        "--set",
        action="append",
        metavar="NAME=VALUE",
        help="override any model parameter, e.g. --set a22=0.3 (repeatable)",
    )


def _time_domain(model, vname, args, out: Path) -> dict:
    """Run from the thesis's initial condition, write figures and the run; return metrics."""
    from .._metrics import fishtail_metrics, force_history, trajectory
    from .._simulate import initial_state, simulate
    from ..plotting.calm import save
    from ..plotting.timedomain import plot_force_history, plot_phase_portraits, plot_time_traces

    try:
        y0 = initial_state(model, psi0=math.radians(args.psi0), y0=args.y0)
        sim = simulate(model, y0, t1=args.t1, n_save=args.n_save, solver=args.solver)
    except ValueError as e:
        raise SystemExit(f"error: {e}") from None
    met = fishtail_metrics(model, sim)
    traj = trajectory(model, sim)
    title = (
        f"{model.vessel.name}: xp'={float(model.towline.xp)}, l0'={float(model.towline.l0)}, "
        f"psi0={args.psi0} deg, y0'={args.y0}"
    )
    save(plot_time_traces(traj, title), out / f"{vname}_time_traces.png")
    save(plot_phase_portraits(traj, title), out / f"{vname}_phase_portraits.png")
    save(plot_force_history(force_history(model, sim), title), out / f"{vname}_forces.png")
    flags = {k: np.asarray(v) for k, v in sim.validity.items()}
    np.savez(
        out / f"{vname}_run.npz",
        t=np.asarray(sim.ts),
        y=np.asarray(sim.ys),
        **{f"validity_{k}": v for k, v in flags.items()},
    )
    finite = np.all(np.isfinite(np.asarray(sim.ys)), axis=-1)
    share = {
        k: float(np.mean(v[finite])) for k, v in flags.items() if v.dtype == bool and finite.any()
    }
    w = met["path_width"]
    print(
        f"{vname} time domain: {met['outcome']}; path width {w if w is None else round(w, 3)} L, "
        f"yaw range {tuple(round(a, 2) for a in met['yaw_range']) if met['yaw_range'] else None} deg, "
        f"slewing period {met['slewing_period'] and round(met['slewing_period'], 2)}, "
        f"heading damping {met['damping']['zeta'] and round(met['damping']['zeta'], 4)} ({met['damping']['method']})"
        + (f"; ENDED EARLY at t'={met['t_end']:.1f}" if met["ended_early"] else "")
    )
    return met | dict(n_steps=int(sim.n_steps), validity_share_of_run=share)


def _time_domain_options(p, t1_default=400.0):
    p.add_argument("--psi0", type=float, default=0.0, help="initial heading [deg] (default 0)")
    p.add_argument(
        "--y0", type=float, default=0.3, help="initial sway offset of the CoG [L] (default 0.3)"
    )
    p.add_argument(
        "--t1", type=float, default=t1_default, help="run length, non-dimensional (by L/U_tug)"
    )
    p.add_argument("--n-save", type=int, default=4001, help="saved samples")
    p.add_argument("--solver", default="auto", choices=("auto", "tsit5", "kvaerno5"))
