"""The calm-water towing-stability study of one or more tows (``jaxtow calm``, thesis section
6.1): the equilibria against the attachment point, the straight-behind stability against the
towline length, the (x_p', l0') map, the equilibria at the design point and, on request, the
run from the thesis's disturbed start (``jaxtow simulate`` runs that alone). Typed records:
the command line plots and writes them."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import xarray as xr

from .._metrics import (
    FishtailMetrics,
    ForceHistory,
    Trajectory,
    fishtail_metrics,
    force_history,
    trajectory,
)
from .._results import sweep
from .._simulate import Simulation, initial_state, simulate
from ._conditions import condition
from ._records import Condition, Record, TimeDomainRecord

__all__ = ["CalmRecord", "CalmStudy", "TimeDomainRun", "calm_study", "time_domain_run"]


class CalmRecord(Record, frozen=True, kw_only=True):
    """One tow in calm water: the course-stability coefficient c (> 0: course stable), the
    design point (x_p', l0', EA'), the equilibria there (`Condition`), the range of the
    straight-behind max Re λ' over the l0' sweep, the estimates it rests on, and the
    time-domain run where one was asked for."""

    tow: str
    stability_coefficient_c: float
    course_stable: bool
    xp: float
    l0: float
    EA_nd: float
    design: Condition
    straight_max_real_range_over_l0: list[float]
    assumed: dict[str, str]
    time_domain: TimeDomainRecord | None = None
    n_steps: int | None = None
    validity_share: dict[str, float] = {}


@dataclasses.dataclass(frozen=True)
class TimeDomainRun:
    """A run from a disturbed start: the `jaxtow.Simulation`, its `Trajectory`, its
    `FishtailMetrics`, its `ForceHistory`, the share of the run inside each validity flag
    and its typed ``record``."""

    simulation: Simulation
    trajectory: Trajectory
    metrics: FishtailMetrics
    forces: ForceHistory
    validity_share: dict[str, float]
    record: TimeDomainRecord


@dataclasses.dataclass(frozen=True)
class CalmStudy:
    """What `calm_study` computed: per tow its ``records`` (`CalmRecord`), its ``datasets``
    (equilibria against x_p', max Re λ' against l0', the map) and its ``runs``."""

    models: dict
    records: dict[str, CalmRecord]
    datasets: dict[str, dict[str, xr.Dataset]]
    runs: dict[str, TimeDomainRun]


def time_domain_run(model, *, psi0_deg: float, y0: float, t1: float, n_save: int, solver="tsit5"):
    """The run from heading ``psi0_deg`` and sway offset ``y0`` (by L) for ``t1`` (by L/U), and
    everything the command line reports of it (`TimeDomainRun`)."""
    start = initial_state(model, psi0=math.radians(psi0_deg), y0=y0)
    sim = simulate(model, start, t1=t1, n_save=n_save, solver=solver)
    met = fishtail_metrics(model, sim)
    flags = {k: np.asarray(v) for k, v in sim.validity.items()}
    finite = np.all(np.isfinite(np.asarray(sim.ys)), axis=-1)
    share = {
        k: float(np.mean(v[finite])) for k, v in flags.items() if v.dtype == bool and finite.any()
    }
    record = TimeDomainRecord(
        psi0_deg=psi0_deg,
        y0=y0,
        t1=t1,
        outcome=met.outcome,
        path_width=met.path_width,
        yaw_range=None if met.yaw_range is None else list(met.yaw_range),
        slewing_period=met.slewing_period,
        ended_early=bool(met.ended_early),
        validity={k: bool(np.all(v)) for k, v in flags.items() if v.dtype == bool},
    )
    return TimeDomainRun(
        simulation=sim,
        trajectory=trajectory(model, sim),
        metrics=met,
        forces=force_history(model, sim),
        validity_share=share,
        record=record,
    )


def calm_study(
    models: dict,
    *,
    xp_grid,
    l0_grid,
    map_xp,
    map_l0,
    chunk_size: int = 16384,
    progress: bool = True,
    time_domain: dict | None = None,
) -> CalmStudy:
    """The calm-water study of ``models`` (name → `jaxtow.TowModel`): the three sweeps (the
    numerical equilibria), the design point's equilibria and, with ``time_domain`` (the
    keywords of `time_domain_run`), the run from the disturbed start."""
    opts = dict(method="numerical", progress=progress, chunk_size=chunk_size)
    records, datasets, runs = {}, {}, {}
    for name, model in models.items():
        ds_xp = sweep(model, {"xp": xp_grid}, **opts)
        ds_l0 = sweep(model, {"l0": l0_grid}, **opts)
        ds_map = sweep(model, {"xp": map_xp, "l0": map_l0}, **opts)
        datasets[name] = dict(equilibria_vs_xp=ds_xp, max_real_vs_l0=ds_l0, map_xp_l0=ds_map)
        c = float(model.vessel.stability_coefficient())
        straight = (
            ds_l0["max_real"].where(ds_l0["valid"] & (ds_l0["branch"] == 0)).max("equilibrium")
        )
        run = None
        if time_domain is not None:
            run = runs[name] = time_domain_run(model, **time_domain)
        records[name] = CalmRecord(
            tow=name,
            stability_coefficient_c=c,
            course_stable=c > 0,
            xp=float(model.towline.xp),
            l0=float(model.towline.l0),
            EA_nd=float(getattr(model.towline, "EA", np.nan)),
            design=condition(model, "calm water", "calm"),
            straight_max_real_range_over_l0=[float(straight.min()), float(straight.max())],
            assumed=dict(model.assumed),
            time_domain=None if run is None else run.record,
            n_steps=None if run is None else int(run.simulation.n_steps),
            validity_share={} if run is None else run.validity_share,
        )
    return CalmStudy(models=dict(models), records=records, datasets=datasets, runs=runs)
