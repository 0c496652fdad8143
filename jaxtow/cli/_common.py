"""Helpers shared by the subcommands: grids, --set overrides, the preset model, time-domain runs."""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

import jaxtow as jt

from .tow import load_tow


def grid_option(spec, name):
    """LO HI N from the command line: N points from LO to HI (messages name the option)."""
    lo, hi, n = spec
    try:
        lo, hi = float(lo), float(hi)
    except ValueError:
        raise SystemExit(
            f"error: --{name}: LO and HI must be numbers, got {spec[0]!r} {spec[1]!r}"
        ) from None
    try:
        n = int(n)
    except ValueError:
        raise SystemExit(
            f"error: --{name}: N must be a whole number of points, got {n!r}"
        ) from None
    if n < 1:
        raise SystemExit(f"error: --{name} needs a positive number of points, got {n}")
    if not (math.isfinite(lo) and math.isfinite(hi)):
        raise SystemExit(f"error: --{name}: LO and HI must be finite, got {lo} {hi}")
    return np.linspace(lo, hi, n)


def parse_sets(items):
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


def tow_names(args, command: str) -> list:
    """The tow names or files of a subcommand (``--tow``/``--tows``; the old ``--vessel`` /
    ``--vessels`` flags and spellings are accepted with a deprecation message)."""

    old = getattr(args, "vessel_old", None) or getattr(args, "vessels_old", None)
    if old:
        flag = "--vessel" if getattr(args, "vessel_old", None) else "--vessels"
        new = "--tow" if flag == "--vessel" else "--tows"
        print(
            f"jaxtow {command}: warning: {flag} is deprecated and will be removed; use {new}",
            file=sys.stderr,
        )
    names = old or getattr(args, "tows", None) or getattr(args, "tow", None) or "barge2a"
    return list(names) if isinstance(names, (list, tuple)) else [names]


def tow_model(args, tow_name=None, overrides=None, command: str = ""):
    """(model, tow name): the tow's calm-water model with the command line's overrides
    (``--u-tug`` rescales EA' as `jaxtow.at_tug_speed`; ``--l0``, ``--xp``, ``--EA-N`` and
    ``--set NAME=VALUE`` set parameters)."""

    command = command or getattr(args, "command", "")
    name = tow_name or tow_names(args, command)[0]
    tow = load_tow(name, command)
    if tow.vessel is None or tow.towline is None:
        raise SystemExit(
            f"jaxtow {command}: error: tow {tow.name!r} has no manoeuvring model "
            "([vessel] derivatives or preset, and [towline])"
        )
    try:
        model = tow.model()
        if getattr(args, "u_tug", None) is not None:
            model = jt.at_tug_speed(model, args.u_tug)
        sets = {k: getattr(args, k) for k in ("l0", "xp") if getattr(args, k, None) is not None}
        EA = ea_nondimensional(args, model.reference_scales, command)
        if EA is not None:
            sets["EA"] = EA
        sets.update(overrides or {})
        # with_parameters checks each value by its parameter's rule first
        return (jt.with_parameters(model, **sets) if sets else model), tow.name
    except ValueError as e:
        raise SystemExit(f"error: {e}") from None


#: The least axial stiffness [N] `--EA-N` takes: real towlines are 1e6-1e9 N; a smaller value
#: is almost surely the non-dimensional EA' given to the wrong flag.
EA_MIN_N = 1e3


def ea_arguments(p) -> None:
    """``--EA-N`` (newtons), ``--EA-nd`` (the non-dimensional EA') and the deprecated
    ``--EA`` (read as ``--EA-N``, with a warning): one unambiguous name for each unit."""
    p.add_argument(
        "--EA-N",
        dest="EA_N",
        type=positive_float,
        default=None,
        help="towline axial stiffness EA [N] (tow file: EA_N)",
    )
    p.add_argument(
        "--EA-nd",
        dest="EA_nd",
        type=positive_float,
        default=None,
        help="towline stiffness EA' = EA/(rho T L U^2/2), non-dimensional (tow file: EA_nd)",
    )
    p.add_argument("--EA", dest="EA_old", type=positive_float, help=argparse.SUPPRESS)


def ea_option(args, command: str = "") -> float | None:
    """The stiffness in newtons given on the command line (``--EA-N``, or the deprecated
    ``--EA`` with a warning), checked against `EA_MIN_N`; None when not given. Refuses
    ``--EA-N`` together with ``--EA-nd``."""
    prefix = f"jaxtow {command}: " if command else ""
    EA = getattr(args, "EA_N", None)
    old = getattr(args, "EA_old", None)
    if old is not None:
        if EA is not None:
            raise SystemExit(f"{prefix}error: give --EA-N only (--EA is its deprecated spelling)")
        print(
            f"{prefix}warning: --EA is deprecated: it is read as --EA-N (newtons)", file=sys.stderr
        )
        EA = old
    if EA is not None and getattr(args, "EA_nd", None) is not None:
        raise SystemExit(
            f"{prefix}error: give --EA-N (in N) or --EA-nd (non-dimensional), not both"
        )
    if EA is not None and EA < EA_MIN_N:
        raise SystemExit(
            f"{prefix}error: argument --EA-N: the axial stiffness in N, got {EA:g}; for the "
            "non-dimensional EA' use --EA-nd"
        )
    return EA


def ea_nondimensional(args, scales, command: str = ""):
    """EA' from ``--EA-N`` [N] (EA' = EA/(½ρTLU²) with the model's scales) or ``--EA-nd``;
    None when neither is given."""
    EA = ea_option(args, command)
    if EA is None:
        return getattr(args, "EA_nd", None)
    if scales is None:
        raise SystemExit(
            "error: argument --EA-N: the model has no scales to convert N; use --EA-nd"
        )
    return EA / float(scales.force)


def tow_option(p, multiple: bool = False, default=("barge2a",)):
    """``--tow TOW`` (or ``--tows TOW ...``) and the hidden deprecated ``--vessel(s)``."""

    if multiple:
        p.add_argument(
            "--tow",
            "--tows",
            dest="tows",
            nargs="+",
            default=list(default),
            help="tow files or built-in tows (barge2a, barge2b) (default: "
            + " ".join(default)
            + ")",
        )
        p.add_argument("--vessels", dest="vessels_old", nargs="+", help=argparse.SUPPRESS)
    else:
        p.add_argument(
            "--tow",
            default=default[0],
            help=f"tow file or built-in tow (barge1, barge2a, barge2b) (default {default[0]})",
        )
        p.add_argument("--vessel", dest="vessel_old", help=argparse.SUPPRESS)


def model_options(p):
    p.add_argument(
        "--u-tug",
        type=positive_float,
        default=None,
        help="tug speed U_tug [m/s]; rescales EA' (default: the tow file's speed)",
    )
    ea_arguments(p)
    p.add_argument(
        "--l0",
        type=float,
        default=None,
        help="unstretched towline length l0' [L] (default: the tow file's)",
    )
    p.add_argument(
        "--xp",
        type=float,
        default=None,
        help="attachment point x_p' ahead of CoG [L] (default: the tow file's)",
    )
    p.add_argument(
        "--set",
        action="append",
        metavar="NAME=VALUE",
        help="override any model parameter, e.g. --set a22=0.3 (repeatable)",
    )


def time_domain_settings(args) -> dict:
    """The keywords of `jaxtow.studies.time_domain_run` from the command line's options."""
    return dict(psi0_deg=args.psi0, y0=args.y0, t1=args.t1, n_save=args.n_save, solver=args.solver)


def write_time_domain(model, vname, run, args, out: Path) -> None:
    """The figures, the run's arrays and one line of a `jaxtow.studies.TimeDomainRun`."""
    title = (
        f"{model.vessel.name}: xp'={float(model.towline.xp)}, l0'={float(model.towline.l0)}, "
        f"psi0={args.psi0} deg, y0'={args.y0}"
    )
    td = jt.plotting.timedomain
    jt.plotting.save(td.plot_time_traces(run.trajectory, title), out / f"{vname}_time_traces.png")
    jt.plotting.save(
        td.plot_phase_portraits(run.trajectory, title), out / f"{vname}_phase_portraits.png"
    )
    jt.plotting.save(td.plot_force_history(run.forces, title), out / f"{vname}_forces.png")
    sim = run.simulation
    flags = {k: np.asarray(v) for k, v in sim.validity.items()}
    np.savez(
        out / f"{vname}_run.npz",
        t=np.asarray(sim.ts),
        y=np.asarray(sim.ys),
        **{f"validity_{k}": v for k, v in flags.items()},
    )
    met = run.metrics
    w = met.path_width
    print(
        f"{vname} time domain: {met.outcome}; path width {w if w is None else round(w, 3)} L, "
        f"yaw range {tuple(round(a, 2) for a in met.yaw_range) if met.yaw_range else None} deg, "
        f"slewing period {met.slewing_period and round(met.slewing_period, 2)}, "
        f"heading damping {met.damping.zeta and round(met.damping.zeta, 4)} ({met.damping.method})"
        + (f"; ENDED EARLY at t'={met.t_end:.1f}" if met.ended_early else "")
    )


def time_domain_options(p, t1_default=400.0):
    p.add_argument(
        "--psi0", type=finite_float, default=0.0, help="initial heading [deg] (default 0)"
    )
    p.add_argument(
        "--y0",
        type=finite_float,
        default=0.3,
        help="initial sway offset of the CoG [L] (default 0.3)",
    )
    p.add_argument(
        "--t1",
        type=positive_float,
        default=t1_default,
        help="run length, non-dimensional (by L/U_tug)",
    )
    p.add_argument("--n-save", type=int, default=4001, help="saved samples")
    p.add_argument("--solver", default="auto", choices=("auto", "tsit5", "kvaerno5"))


def positive_int(text: str) -> int:
    """argparse type: a whole number >= 1 (the message names the value)."""
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a whole number >= 1, got {text!r}") from None
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number >= 1, got {n}")
    return n


def finite_float(text: str) -> float:
    """argparse type: a finite number."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(x):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text}")
    return x


def positive_float(text: str) -> float:
    """argparse type: a finite number > 0."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number > 0, got {text!r}") from None
    if not (math.isfinite(x) and x > 0):
        raise argparse.ArgumentTypeError(f"expected a finite number > 0, got {text}")
    return x
