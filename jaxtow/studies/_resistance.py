"""One sea state's resistance summary: what ``jaxtow resistance`` tabulates and ``jaxtow
study`` reports (required bollard pull at zero speed, the worst Tp, the operating speed, the
pull the tug gives there and the transit time; SI), as typed `ResistanceRow` records."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import jax.numpy as jnp
import numpy as np

from .. import resistance
from .._units import KNOT, TONNE_FORCE
from ..io import resistance_dataset
from ..resistance import OVERTAKEN_TOL
from ..waves import physical_tp_range
from ._records import ResistanceRow


def evaluate_resistance(tow, tug, sea, heading, route_length, *, n_tp: int = 41) -> ResistanceRow:
    """Everything the resistance table prints for one sea state (SI): a `ResistanceRow`."""
    req = resistance.required_pull(tow, sea, heading=heading, tug=tug)
    row = dict(
        sea_state=sea.name,
        hs=float(sea.hs),
        tp=float(sea.tp),
        wind_speed=float(sea.wind_speed),
        current_speed=float(sea.current_speed),
        efficiency=float(tug.efficiency),
        hold=dict(zip(resistance.COMPONENTS, map(float, req.budget.resistance))),
        hold_towing_force=float(req.towing_force),
        required_bollard_pull=float(req.bollard_pull),
    )
    if float(sea.hs) > 0:
        bp, tp = worst_over_tp(tow, sea, heading=heading, tug=tug, n_tp=n_tp)
        row.update(
            physical_tp_range=[float(t) for t in physical_tp_range(float(sea.hs))],
            worst_tp=tp,
            worst_required_bollard_pull=bp,
        )
    p = resistance.operating_speed(tow, tug, sea, heading=heading, throw=False)
    msg = resistance.status_message(p, tug, tow) or ""
    names = ("successful", "cannot_hold", "no_crossing", "froude_too_high")
    status = next(n for n in names if bool(p.result == getattr(resistance.RESULTS, n)))
    row.update(status=status, message=msg)
    if status in ("successful", "froude_too_high"):
        speed = float(p.speed)
        row.update(
            operating_speed=speed,
            froude=float(p.froude),
            available_pull=float(p.pull) - float(tug.resistance(speed)),
            operating_resistance=dict(zip(resistance.COMPONENTS, map(float, p.budget.resistance))),
            overtaken_energy=float(p.budget.overtaken_energy),
        )
        if float(p.budget.overtaken_energy) > OVERTAKEN_TOL:
            row["message"] = msg + (
                f" WARNING: the tow overtakes {100 * float(p.budget.overtaken_energy):.1f} % "
                "of the sea's wave energy (encounter frequency <= 0), where no drift is "
                "counted: the wave resistance is incomplete."
            )
        if route_length:
            row["transit_time_h"] = float(p.transit_time(route_length)) / 3600.0
    return ResistanceRow(**row)


def worst_over_tp(tow, sea, *, heading=0.0, tug=None, n_tp: int = 41) -> tuple[float, float]:
    """(required bollard pull [N], the Tp [s] it needs) at zero speed, the worst over the
    physical Tp range of the sea state's Hs (thesis eq. 3.5), in one compiled call
    (`jaxtow.resistance.worst_bollard_pull`); without a ``tug`` the pull is the towing
    force."""
    lo, hi = (float(t) for t in physical_tp_range(float(sea.hs)))
    tps = np.linspace(lo, hi, n_tp)
    bp = np.asarray(resistance.worst_bollard_pull(tow, sea, tps, heading=heading, tug=tug))
    k = int(np.argmax(bp))
    return float(bp[k]), float(tps[k])


#: The columns of `resistance_table`.
TABLE_COLUMNS = (
    "sea state",
    "Hs m",
    "Tp s",
    "wind m/s",
    "current m/s",
    "tug eff.",
    "hold kN",
    "req. BP t",
    "worst BP t @Tp s",
    "U_op m/s (kn)",
    "Fn",
    "transit h",
    "% " + "/".join(resistance.COMPONENTS) + " at U_op",
)


def resistance_table(rows: list[ResistanceRow]) -> tuple:
    """(columns, rows of strings) of `ResistanceRow`s: the one table of `jaxtow resistance`
    and the study report. The hull's share is its resistance through the water, with the
    current where the sea state has one."""
    table = []
    for r in rows:
        worst = (
            f"{r.worst_required_bollard_pull / TONNE_FORCE:.1f} @{r.worst_tp:.1f}"
            if r.worst_required_bollard_pull is not None and r.worst_tp is not None
            else "-"
        )
        if r.operating_speed is not None and r.operating_resistance is not None:
            tot = sum(r.operating_resistance.values()) or 1.0
            shares = "/".join(f"{100 * v / tot:.0f}" for v in r.operating_resistance.values())
            speed = f"{r.operating_speed:.2f} ({r.operating_speed / KNOT:.1f})"
            fn = f"{r.froude:.3f}" if r.froude is not None else "-"
            transit = f"{r.transit_time_h:.0f}" if r.transit_time_h is not None else "-"
        else:
            shares = speed = fn = transit = "-"
        table.append(
            [
                r.sea_state,
                f"{r.hs:g}",
                f"{r.tp:g}",
                f"{r.wind_speed:g}",
                f"{r.current_speed:g}",
                f"{r.efficiency:g}",
                f"{r.hold_towing_force / 1e3:.1f}",
                f"{r.required_bollard_pull / TONNE_FORCE:.1f}",
                worst,
                speed,
                fn,
                transit,
                shares,
            ]
        )
    return TABLE_COLUMNS, table


#: The Tp grid of the resistance budgets [s] (thesis figs 7.2, 7.3).
BUDGET_TP = (5.0, 16.0, 45)


@dataclass(frozen=True)
class ResistanceStudy:
    """What `resistance_study` computed: the table ``rows`` (one `evaluate_resistance` a sea state);
    on first use, per sea state, its budget over (speed, Tp) as a dataset (``budgets``) and
    the total resistance against the tug's pull over the tug's speeds (``curves``: speeds,
    pull, total [N])."""

    tow: resistance.TowResistance
    tug: resistance.Tug
    seas: tuple
    heading: float
    rows: list[ResistanceRow]

    def tp_range(self, sea):
        """The physical Tp range of a sea state's Hs (None in calm water)."""
        if float(sea.hs) <= 0:
            return None
        return tuple(float(t) for t in physical_tp_range(float(sea.hs)))

    @cached_property
    def budgets(self) -> dict:
        tps = jnp.linspace(*BUDGET_TP)
        speeds = jnp.linspace(0.0, min(3.5, float(self.tug.max_speed)), 15)
        grid = jnp.unique(jnp.concatenate([speeds, jnp.array([0.0, 2.0])]))
        return {
            sea.name: resistance_dataset(
                resistance.resistance_grid(
                    self.tow, sea, grid, tps, heading=self.heading, tug=self.tug
                ),
                grid,
                tps,
                tow=self.tow,
                sea=sea,
            )
            for sea in self.seas
        }

    @cached_property
    def curves(self) -> dict:
        out = {}
        u = jnp.linspace(0.0, float(self.tug.max_speed), 80)
        for sea in self.seas:
            tp = jnp.array([float(sea.tp)])
            b = resistance.resistance_grid(self.tow, sea, u, tp, heading=self.heading, tug=self.tug)
            out[sea.name] = (np.asarray(u), np.asarray(self.tug.pull(u)), np.asarray(b.total[:, 0]))
        return out


def resistance_study(tow, tug, seas, heading: float = 0.0, route_length=None) -> ResistanceStudy:
    """The resistance budget, required pull, operating speed and transit time of ``tow`` (a
    `jaxtow.resistance.TowResistance`) behind ``tug`` in each of ``seas`` (``jaxtow
    resistance``; thesis sections 7.1-7.2, fig. 2.1)."""
    rows = [evaluate_resistance(tow, tug, s, heading, route_length) for s in seas]
    return ResistanceStudy(tow, tug, tuple(seas), heading, rows)
