"""Equilibrium branches and limit cycles in one parameter (``jaxtow bifurcation``): the
continuation of the equilibria, their special points (pitchfork, fold, Hopf with its first
Lyapunov coefficient) and the fishtailing limit cycles across the oscillatory-unstable
stretch of the straight-behind branch next to a Hopf point."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._parameters import get_parameter, with_parameters
from ..continuation import equilibrium_branch, limit_cycle_branch, limit_cycle_from_simulation


@dataclass(frozen=True)
class BifurcationStudy:
    """``branch`` (with its side branches), ``orbits`` (limit cycles, by parameter),
    ``special`` and ``cycles`` (JSON-ready records of both) and ``note`` (why no limit cycle
    was computed, where that is so)."""

    parameter: str
    p_range: tuple
    branch: object
    orbits: list
    special: list
    cycles: list
    note: str = ""


def _unstable_runs(branch, ds: float) -> list:
    """Parameter runs of the straight-behind branch where it is unstable, next to a Hopf point."""
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
    span = max(ds * 3, 1e-3)
    return [r for r in runs if any(min(abs(r[0] - h), abs(r[-1] - h)) < span for h in hopf)]


def _limit_cycles(model, parameter: str, run, n: int) -> list:
    """``n`` limit cycles across ``run``: one from a time-domain run in its middle, then
    continued both ways."""
    values = np.linspace(run[0], run[-1], n + 2)[1:-1]
    mid = len(values) // 2
    first = limit_cycle_from_simulation(with_parameters(model, **{parameter: float(values[mid])}))
    first.parameter = float(values[mid])
    up = limit_cycle_branch(model, parameter, values[mid + 1 :], start=first)
    down = limit_cycle_branch(model, parameter, values[:mid][::-1], start=first)
    return sorted([first, *up, *down], key=lambda o: o.parameter)


def bifurcation_study(model, parameter: str, p_range, *, ds: float, cycles: int = 4):
    """Continue the equilibria of ``model`` in ``parameter`` over ``p_range`` (starting at
    the model's value, clipped to the range) with step ``ds``; compute ``cycles`` limit
    cycles across the longest unstable run of the straight-behind branch next to a Hopf
    point."""
    lo, hi = p_range
    p0 = min(max(float(get_parameter(model, parameter)), lo), hi)
    model = with_parameters(model, **{parameter: p0})
    branch = equilibrium_branch(model, parameter, p_range=(lo, hi), ds=ds)
    orbits, note = [], ""
    runs = _unstable_runs(branch, ds)
    if cycles > 0 and runs:
        try:
            orbits = _limit_cycles(model, parameter, max(runs, key=len), cycles)
        except RuntimeError as e:
            note = f"limit cycles not computed: {e}"
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
    records = [
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
    return BifurcationStudy(parameter, (lo, hi), branch, orbits, special, records, note)
