"""The ``jaxtow`` command line.

Subcommands:

* ``jaxtow calm --out DIR``: the without-waves stability study of thesis section 6.1 for
  Barge 2a and 2b (equilibria vs x_p', max Re λ vs l0', a (x_p', l0') stability map, and
  time-domain runs from the thesis's initial condition, figs 6.5-6.7): PNG figures,
  NetCDF datasets and a JSON summary in DIR.
* ``jaxtow equilibria``: the equilibria of one configuration and their eigenvalues.
* ``jaxtow map``: any sweep over named parameters, saved as NetCDF (and a figure for 1-D
  and 2-D sweeps).
* ``jaxtow drift``: the waterline drift methods compared (thesis chapters 4-5, figs
  4.3-4.6, 5.6-5.7) for Barge 1, Barge 2 or a waterline file, with relative MSE per zone.
* ``jaxtow bifurcation``: equilibrium branches in one parameter with pitchfork, fold and
  Hopf points (first Lyapunov coefficient) and limit cycles (path width, Floquet multipliers).
* ``jaxtow bem``: panel-method (Capytaine, optional extra) RAOs and far-/near-field drift
  QTF databases for Barge 1, Barge 2 or a mesh file, and the mesh-convergence study.
* ``jaxtow simulate``: time-domain runs (time traces, phase portraits, force history,
  fishtailing metrics).

Run ``jaxtow SUBCOMMAND --help`` for the options.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
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
            raise SystemExit(f"error: --set {k}: {v!r} is not a number")
    return out


def _model(args, vessel_name=None, overrides=None):
    import jaxtow as jt

    vname = vessel_name or args.vessel
    if vname not in jt.presets.VESSELS:
        raise SystemExit(f"error: unknown vessel {vname!r}; choose from {sorted(jt.presets.VESSELS)}")
    vessel = jt.presets.VESSELS[vname]()
    EA = args.EA if args.EA is not None else jt.presets.steel_wire_EA_nd(u_tug=args.u_tug)
    try:
        model = jt.TowModel(vessel=vessel, towline=jt.Towline(l0=args.l0, xp=args.xp, EA=EA))
        sets = dict(overrides or {})
        from jaxtow.parameters import check_values

        for k, v in sets.items():
            check_values(model, k, v)
        return jt.with_parameters(model, **sets) if sets else model
    except ValueError as e:
        raise SystemExit(f"error: {e}")


def _common(p):
    p.add_argument("--u-tug", type=float, default=2.0,
                   help="tug speed U_tug [m/s]; sets EA' of the default steel towline (default 2.0)")
    p.add_argument("--EA", type=float, default=None,
                   help="towline stiffness EA' (non-dimensional); default: the documented steel wire")
    p.add_argument("--l0", type=float, default=2.5, help="unstretched towline length l0' [L] (default 2.5)")
    p.add_argument("--xp", type=float, default=0.5, help="attachment point x_p' ahead of CoG [L] (default 0.5)")
    p.add_argument("--set", action="append", metavar="NAME=VALUE",
                   help="override any model parameter, e.g. --set a22=0.3 (repeatable)")


def cmd_calm(args):
    import jaxtow as jt
    from jaxtow.io import save_dataset
    from jaxtow.plotting.calm import plot_equilibria_vs, plot_max_real_vs, plot_stability_map, save

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sets = _parse_sets(args.set)
    summary = {}
    opts = dict(method="numerical", progress=not args.quiet, chunk_size=args.chunk_size)
    for vname in args.vessels:
        model = _model(args, vname, sets)
        c = float(model.vessel.stability_coefficient())
        ds_xp = jt.sweep(model, {"xp": _grid(args.xp_grid, "xp-grid")}, **opts)
        ds_l0 = jt.sweep(model, {"l0": _grid(args.l0_grid, "l0-grid")}, **opts)
        ds_map = jt.sweep(model, {"xp": _grid(args.map_xp, "map-xp"), "l0": _grid(args.map_l0, "map-l0")}, **opts)
        for tag, ds in (("equilibria_vs_xp", ds_xp), ("max_real_vs_l0", ds_l0), ("map_xp_l0", ds_map)):
            save_dataset(ds, out / f"{vname}_{tag}.nc")
        save(plot_equilibria_vs(ds_xp, "xp", title=f"{model.vessel.name}: equilibria (fig. 6.3), l0'={args.l0}"),
             out / f"{vname}_equilibria_vs_xp.png")
        save(plot_max_real_vs(ds_l0, "l0", title=f"{model.vessel.name}: max Re(lambda), xp'={args.xp} (fig. 6.4)"),
             out / f"{vname}_max_real_vs_l0.png")
        save(plot_stability_map(ds_map, "xp", "l0"), out / f"{vname}_map_xp_l0.png")
        # Summary numbers at the configured (xp, l0).
        eqs = jt.equilibria(model)
        st = jt.stability(model, eqs.state)
        straight = ds_l0["max_real"].where(ds_l0["valid"] & (ds_l0["branch"] == 0)).max("equilibrium")
        summary[vname] = dict(
            stability_coefficient_c=c,
            course_stable=c > 0,
            xp=args.xp, l0=args.l0, EA=float(model.towline.EA),
            equilibria_psi_deg=[float(np.degrees(p)) for p in eqs.psi],
            equilibria_max_real=[float(v) for v in st["max_real"]],
            equilibria_stability=[jt.STABILITY_LABELS[int(s)] for s in st["stability"]],
            straight_behind_max_real_range_over_l0=[float(straight.min()), float(straight.max())],
            assumed_values=dict(model.assumed),
        )
        if not args.no_time_domain:
            summary[vname]["time_domain"] = _time_domain(model, vname, args, out)
    (out / "summary.json").write_text(json.dumps(summary, indent=2, default=float))
    for vname, s in summary.items():
        print(f"{vname}: c = {s['stability_coefficient_c']:+.4f} ({'course stable' if s['course_stable'] else 'course unstable'})")
        for p, mr, lab in zip(s["equilibria_psi_deg"], s["equilibria_max_real"], s["equilibria_stability"]):
            print(f"   psi = {p:+8.3f} deg   max Re(lambda) = {mr:+.5f}   {lab}")
        lo, hi = s["straight_behind_max_real_range_over_l0"]
        print(f"   straight behind, max Re(lambda) over l0' grid: [{lo:+.4f}, {hi:+.4f}]")
    print("note: draft, added masses and EA' are documented estimates (jaxtow.presets.ASSUMPTIONS)")
    print(f"wrote figures, NetCDF datasets and summary.json to {out}")


def cmd_equilibria(args):
    import jaxtow as jt

    model = _model(args, overrides=_parse_sets(args.set))
    eqs = jt.equilibria(model)
    st = jt.stability(model, eqs.state)
    print(f"{model.vessel.name}: xp'={float(model.towline.xp)}, l0'={float(model.towline.l0)}, "
          f"EA'={float(model.towline.EA):.2f}")
    print(f"{'psi [deg]':>10} {'gamma [deg]':>12} {'T_prime':>9} {'l_prime':>8} {'max Re':>10} "
          f"{'verdict':>9} {'R-H':>5} {'valid':>5} {'|f|':>9}")
    for i in range(len(eqs)):
        print(f"{math.degrees(eqs.psi[i]):10.4f} {math.degrees(eqs.gamma[i]):12.4f} "
              f"{float(eqs.tension[i]):9.5f} {float(eqs.length[i]):8.4f} {float(st['max_real'][i]):+10.5f} "
              f"{jt.STABILITY_LABELS[int(st['stability'][i])]:>9} {str(bool(st['routh_hurwitz'][i])):>5} "
              f"{str(bool(eqs.valid[i])):>5} {float(eqs.residual[i]):9.1e}")
        if args.eigenvalues:
            lam = np.asarray(st["eigenvalues"][i])
            print("      eigenvalues: " + ", ".join(f"{z.real:+.4f}{z.imag:+.4f}j" for z in lam))


def cmd_map(args):
    import jaxtow as jt
    from jaxtow.io import save_dataset
    from jaxtow.plotting.calm import plot_equilibria_vs, plot_max_real_vs, plot_stability_map, save

    if not args.param:
        raise SystemExit("error: give at least one --param NAME LO HI N")
    model = _model(args, overrides=_parse_sets(args.set))
    grid = {}
    for name, lo, hi, n in args.param:
        grid[name] = _grid((lo, hi, n), f"param {name}")
    try:
        ds = jt.sweep(model, grid, method=args.method, progress=not args.quiet,
                      chunk_size=args.chunk_size, max_roots=args.max_roots)
    except ValueError as e:
        raise SystemExit(f"error: {e}")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    stem = args.vessel + "_" + "_".join(grid)
    save_dataset(ds, out / f"{stem}.nc")
    names = list(grid)
    if len(names) == 1:
        save(plot_equilibria_vs(ds, names[0]), out / f"{stem}_equilibria.png")
        save(plot_max_real_vs(ds, names[0]), out / f"{stem}_max_real.png")
    elif len(names) == 2:
        save(plot_stability_map(ds, names[0], names[1]), out / f"{stem}_map.png")
    n_unstable = int(((ds["stability"] > 0) & ds["valid"]).sum())
    print(f"{ds.sizes}: {n_unstable} unstable equilibria; wrote {out / (stem + '.nc')}")


def _time_domain(model, vname, args, out: Path) -> dict:
    """Run from the thesis's initial condition, write figures and the run; return metrics."""
    from jaxtow.metrics import fishtail_metrics, force_history, trajectory
    from jaxtow.plotting.calm import save
    from jaxtow.plotting.timedomain import plot_force_history, plot_phase_portraits, plot_time_traces
    from jaxtow.simulate import initial_state, simulate

    try:
        y0 = initial_state(model, psi0=math.radians(args.psi0), y0=args.y0)
        sim = simulate(model, y0, t1=args.t1, n_save=args.n_save, solver=args.solver)
    except ValueError as e:
        raise SystemExit(f"error: {e}")
    met = fishtail_metrics(model, sim)
    traj = trajectory(model, sim)
    title = (f"{model.vessel.name}: xp'={float(model.towline.xp)}, l0'={float(model.towline.l0)}, "
             f"psi0={args.psi0} deg, y0'={args.y0}")
    save(plot_time_traces(traj, title), out / f"{vname}_time_traces.png")
    save(plot_phase_portraits(traj, title), out / f"{vname}_phase_portraits.png")
    save(plot_force_history(force_history(model, sim), title), out / f"{vname}_forces.png")
    np.savez(out / f"{vname}_run.npz", t=np.asarray(sim.ts), y=np.asarray(sim.ys))
    w = met["path_width"]
    print(f"{vname} time domain: {met['outcome']}; path width {w if w is None else round(w, 3)} L, "
          f"yaw range {tuple(round(a, 2) for a in met['yaw_range']) if met['yaw_range'] else None} deg, "
          f"slewing period {met['slewing_period'] and round(met['slewing_period'], 2)}, "
          f"heading damping {met['damping']['zeta'] and round(met['damping']['zeta'], 4)} ({met['damping']['method']})"
          + ("; ENDED EARLY at t'=%.1f" % met["t_end"] if met["ended_early"] else ""))
    return met | dict(n_steps=int(sim.n_steps))


def cmd_simulate(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    summary = {}
    for vname in args.vessels:
        model = _model(args, vname, _parse_sets(args.set))
        summary[vname] = _time_domain(model, vname, args, out) | dict(assumed_values=dict(model.assumed))
    (out / "simulate_summary.json").write_text(json.dumps(summary, indent=2, default=float))
    print(f"wrote figures, runs and simulate_summary.json to {out}")


def _time_domain_options(p, t1_default=400.0):
    p.add_argument("--psi0", type=float, default=0.0, help="initial heading [deg] (default 0)")
    p.add_argument("--y0", type=float, default=0.3, help="initial sway offset of the CoG [L] (default 0.3)")
    p.add_argument("--t1", type=float, default=t1_default, help="run length, non-dimensional (by L/U_tug)")
    p.add_argument("--n-save", type=int, default=4001, help="saved samples")
    p.add_argument("--solver", default="auto", choices=("auto", "tsit5", "kvaerno5"))


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="jaxtow",
        description="Towing stability of a barge on an elastic towline (JAX). "
        "Non-dimensional inputs use the thesis scales: lengths by L, stiffness by 0.5*rho*T*L*U_tug^2.",
    )
    sub = p.add_subparsers(dest="command", required=True)

    c = sub.add_parser("calm", help="reproduce the without-waves stability study (thesis 6.1)")
    c.add_argument("--out", default="results", help="output folder (default: results)")
    c.add_argument("--vessels", nargs="+", default=["barge_2a", "barge_2b"], help="vessel presets")
    c.add_argument("--xp-grid", nargs=3, default=(0.0, 0.6, 121), metavar=("LO", "HI", "N"),
                   help="x_p' grid for the equilibria figure (default 0 0.6 121)")
    c.add_argument("--l0-grid", nargs=3, default=(0.2, 2.5, 116), metavar=("LO", "HI", "N"),
                   help="l0' grid for the max Re(lambda) figure (default 0.2 2.5 116)")
    c.add_argument("--map-xp", nargs=3, default=(0.0, 0.6, 61), metavar=("LO", "HI", "N"))
    c.add_argument("--map-l0", nargs=3, default=(0.2, 2.5, 47), metavar=("LO", "HI", "N"))
    c.add_argument("--chunk-size", type=int, default=16384, help="points per vmapped chunk")
    c.add_argument("--quiet", action="store_true", help="no progress bar")
    c.add_argument("--no-time-domain", action="store_true",
                   help="skip the runs from the thesis's initial condition (figs 6.5-6.7)")
    _time_domain_options(c)
    _common(c)
    c.set_defaults(func=cmd_calm, vessel=None)

    e = sub.add_parser("equilibria", help="equilibria of one configuration and their stability")
    e.add_argument("--vessel", default="barge_2a", help="vessel preset (barge_2a, barge_2b)")
    e.add_argument("--eigenvalues", action="store_true", help="print all eigenvalues")
    _common(e)
    e.set_defaults(func=cmd_equilibria)

    s = sub.add_parser("simulate", help="time-domain run(s) from the thesis's initial condition")
    s.add_argument("--vessels", nargs="+", default=["barge_2a", "barge_2b"], help="vessel presets")
    _time_domain_options(s)
    s.add_argument("--out", default="results", help="output folder")
    _common(s)
    s.set_defaults(func=cmd_simulate, vessel=None)

    m = sub.add_parser("map", help="sweep any parameters; NetCDF + figure")
    m.add_argument("--vessel", default="barge_2a", help="vessel preset (barge_2a, barge_2b)")
    m.add_argument("--param", nargs=4, action="append", metavar=("NAME", "LO", "HI", "N"),
                   help="swept parameter and its grid, e.g. --param l0 0.2 2.5 100 (repeatable)")
    m.add_argument("--method", choices=("numerical", "analytic"), default="numerical",
                   help="equilibrium solver (analytic: calm water, elastic line only)")
    m.add_argument("--max-roots", type=int, default=4, help="equilibrium slots per point")
    m.add_argument("--out", default="results", help="output folder")
    m.add_argument("--chunk-size", type=int, default=16384, help="points per vmapped chunk")
    m.add_argument("--quiet", action="store_true", help="no progress bar")
    _common(m)
    m.set_defaults(func=cmd_map)

    from ._cli_drift import add_parser as add_drift

    add_drift(sub)
    from ._cli_bifurcation import add_parser as add_bifurcation

    add_bifurcation(sub)
    from ._cli_resistance import add_parser as add_resistance

    add_resistance(sub)
    from ._cli_report import add_parser as add_report

    add_report(sub)
    from ._cli_bem import add_parser as add_bem

    add_bem(sub)
    return p


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    args.func(args)
    return 0


if __name__ == "__main__":
    sys.exit(main())
