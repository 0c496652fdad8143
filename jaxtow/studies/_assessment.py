"""The whole assessment of one tow (``jaxtow study``): resistance budget, required bollard
pull, operating speed and transit time per sea state; equilibria and stability in calm water
and in each sea state, at the design speed and at the sea state's operating speed, with a
verdict; a stability map around the design point; the time-domain check from a disturbed
start; the wave drift of the hull; the guideline decision and the way forward. Numbers only,
as typed records (`jaxtow.studies._records`): `jaxtow.reports.tow_report_html` and the
command line turn them into files."""

from __future__ import annotations

import dataclasses
import math
import sys
import time

import equinox as eqx
import jax
import jax.numpy as jnp
import msgspec
import numpy as np
import xarray as xr

from .. import resistance
from .._equilibrium import equilibria
from .._interrupt import requested as interrupt_requested
from .._metrics import FishtailMetrics, Trajectory, fishtail_metrics, trajectory
from .._program_cache import persistent
from .._results import sweep
from .._rules import ParameterError
from .._simulate import initial_state, simulate
from .._units import RHO_SEA, G
from ..drift import irregular_sailing_drift
from ..drift._sailing import overtaken_check
from ..waves import DEFAULT_OMEGA, Jonswap
from ._advice import advice
from ._conditions import condition, sea_conditions
from ._criteria import assessment
from ._records import (
    CatenaryRecord,
    Condition,
    DriftRecord,
    FindingRow,
    Incomplete,
    LineSegmentRow,
    MapRecord,
    MeanDriftRow,
    ResistanceRow,
    StrengthRecord,
    StudySummary,
    TimeDomainRecord,
    TowlineRecord,
    TugRecord,
)
from ._resistance import evaluate_resistance
from ._risk import risk_advice, risk_seas, risk_step, with_risk

__all__ = ["Steps", "TowStudy", "tow_study", "map_grids", "OperatingCurve"]


class Steps:
    """The study's steps: progress on stderr (``[k/n] label ... done in t s``), and, with a
    ``store`` (`jaxtow.io.StepStore`), each step's result stored as it finishes and a stored
    step read back instead of run (``[k/n] label: resumed``). ``current`` is the label of the
    step running (the one named when a study stops early). The total is known before the
    first step runs."""

    def __init__(self, total: int, enabled: bool = True, stream=None, store=None):
        self.total, self.enabled, self.k = total, enabled, 0
        self.stream = stream or sys.stderr
        self.store = store
        self.times: dict[str, float] = {}
        self.current = ""

    def _say(self, text: str) -> None:
        if self.enabled:
            self.stream.write(f"[{self.k}/{self.total}] {text}\n")
            self.stream.flush()

    def run(self, key: str, label: str, fn, *args, **kw):
        """Step ``key`` (its name in the store), shown as ``label``: ``fn(*args, **kw)``.
        A Ctrl-C that arrived, even one swallowed on its way (`jaxtow._interrupt`), stops
        the study here, before the step or after it is stored."""
        if interrupt_requested():
            raise KeyboardInterrupt
        self.k += 1
        self.current = label
        if self.store is not None and (out := self.store.get(key)) is not None:
            self._say(f"{label}: resumed")
            return out
        t0 = time.perf_counter()
        self._say(f"{label} ...")
        out = fn(*args, **kw)
        self.times[label] = time.perf_counter() - t0
        if self.store is not None:
            self.store.put(key, out)
        self._say(f"{label}: done in {self.times[label]:.1f} s")
        if interrupt_requested():
            raise KeyboardInterrupt
        return out


@dataclasses.dataclass(frozen=True)
class OperatingCurve:
    """The resistance of the tow against the tug's pull over the speeds of a sea state's
    figure: ``speeds`` [m/s], the ``components`` (n, 4) and ``total`` [N], the tug's
    ``pull`` [N]."""

    speeds: np.ndarray
    components: np.ndarray
    total: np.ndarray
    pull: np.ndarray


@dataclasses.dataclass(frozen=True)
class TowStudy:
    """What `tow_study` computed: the typed ``summary`` (`StudySummary`: what the report, the
    console and the JSON say), and what the figures draw: ``datasets`` (name → xarray
    Dataset: the stability map), ``runs`` (name → (`jaxtow.Trajectory`,
    `jaxtow.FishtailMetrics`)), ``budgets`` (sea state → `OperatingCurve`), the head-sea
    ``drift_curve`` (ω [rad/s], F_x per ζa² [N/m²]) and the irregular-sea ``risk`` (sea
    state → (`jaxtow.risk.RiskResult`, the results at lower Hs))."""

    tow: object
    summary: StudySummary
    datasets: dict[str, xr.Dataset] = dataclasses.field(default_factory=dict)
    runs: dict[str, tuple[Trajectory, FishtailMetrics]] = dataclasses.field(default_factory=dict)
    budgets: dict[str, OperatingCurve] = dataclasses.field(default_factory=dict)
    drift_curve: tuple[np.ndarray, np.ndarray] | None = None
    risk: dict = dataclasses.field(default_factory=dict)


def _catenary_record(model, water_depth) -> CatenaryRecord:
    """Sag, end tension, effective stiffness and seabed clearance of a catenary towline at
    the calm-water equilibrium nearest straight behind (SI)."""
    eqs = equilibria(model)
    k = int(np.argmin(np.where(np.asarray(eqs.valid), np.abs(np.asarray(eqs.psi)), np.inf)))
    l = eqs.state[k, 3]
    line, sc = model.towline, model.reference_scales
    sag = float(line.sag(l)) * sc.length
    return CatenaryRecord(
        span_m=float(l) * sc.length,
        horizontal_tension=float(line.tension(l) * sc.force),
        end_tension=float(line.end_tension(l) * sc.force),
        sag_m=sag,
        effective_stiffness_nd=float(line.stiffness(l)),
        elastic_stiffness_nd=float(getattr(line, "series_EA", line.EA) / line.l0),
        water_depth=water_depth,
        seabed_clearance_m=None if water_depth is None else water_depth - sag,
    )


def _strength_record(tow, model, conditions: list[Condition]) -> StrengthRecord | None:
    """The towline's catalogue pieces and the largest mean end tension of the equilibria found
    (calm water, every sea state at the design speed and at its operating speed) against the
    weakest piece's MBL."""
    make = tow.make
    if make is None:
        return None
    weakest = make.weakest
    rows = [LineSegmentRow(**dataclasses.asdict(s)) for s in make.segments]
    if make.bridle_leg is not None:
        rows.append(LineSegmentRow(**dataclasses.asdict(make.bridle_leg)))
    best, where = None, None
    for c in conditions:
        # every equilibrium the solver found, also outside the drift theory's validity: the
        # tension is the mean force balance (at an operating speed, the tug's pull)
        for e in c.equilibria:
            if e.found and math.isfinite(e.tension) and (best is None or e.tension > best):
                best, where = e.tension, c.name
    out = dict(segments=rows, weakest=weakest.name, mbl=weakest.mbl)
    if best is not None:
        line, sc = model.towline, model.reference_scales
        end = best
        if hasattr(line, "end_tension"):
            t_nd = best / float(sc.force)
            end = float(line.end_tension(line.length_at_tension(t_nd))) * float(sc.force)
        out.update(max_end_tension=end, max_tension_condition=where, utilisation=end / weakest.mbl)
    if tow.tug is not None:
        out["mbl_over_bollard_pull"] = weakest.mbl / float(tow.tug.bollard_pull)
    return StrengthRecord(**out)


def _towline_record(model, tow) -> TowlineRecord:
    line, sc = model.towline, model.reference_scales
    EA_nd = float(getattr(line, "series_EA", getattr(line, "EA", 0.0)))
    cat = _catenary_record(model, tow.water_depth) if hasattr(line, "sag") else None
    return TowlineRecord(
        l0=float(line.l0),
        length_m=float(line.l0) * sc.length,
        xp=float(line.xp),
        yp=float(getattr(line, "yp", 0.0)),
        EA=EA_nd * float(sc.force),
        EA_nd=EA_nd,
        catenary=cat,
    )


def map_grids(tow, map_xp=None, map_l0=None) -> tuple[np.ndarray, np.ndarray]:
    """The stability map's grids [by L]: given, the tow file's [study], or centred on the
    design point (x_p' ± 0.3 within 0 to 1; l0'/3 to 3 l0'), 25 points each."""
    line = tow.towline
    xp0, l00 = float(line.xp), float(line.l0)
    xp = map_xp if map_xp is not None else tow.study.map_xp
    l0 = map_l0 if map_l0 is not None else tow.study.map_l0
    if xp is None:
        xp = (max(0.0, xp0 - 0.3), min(1.0, xp0 + 0.3), 25)
        if not xp[0] <= xp0 <= xp[1]:
            xp = (xp0 - 0.3, xp0 + 0.3, 25)
    if l0 is None:
        l0 = (l00 / 3.0, 3.0 * l00, 25)
    return _linspace(xp), _linspace(l0)


def _linspace(spec):
    lo, hi, n = spec
    return np.linspace(float(lo), float(hi), int(n))


def tow_study(
    tow,
    *,
    progress: bool = True,
    map_xp=None,
    map_l0=None,
    time_domain: bool | None = None,
    t1: float | None = None,
    n_save: int = 2001,
    speeds=None,
    risk: str | None = None,
    store=None,
) -> TowStudy:
    """Run the whole assessment of ``tow`` (a `jaxtow.tow.Tow`). The grids, the run length
    and the speeds default to the tow file's ``[study]`` (the map: centred on the design
    point); the keywords override them (the tests use small grids). Steps the tow cannot
    take (no manoeuvring model, no tug, no sea state) are listed in ``summary.skipped``
    with the reason, and the criteria that need them are "not checked".

    Nothing finished is lost: a step that fails, or a Ctrl-C, ends the study there and what
    finished is returned, with ``summary.incomplete`` (`Incomplete`). With ``store`` (a
    `jaxtow.io.StepStore`) each step's result is stored as it finishes and a stored step is
    read back instead of run, so a killed study resumes with the same results. ``risk``
    ("auto", "always" or "never") overrides ``[study] risk``, the irregular-sea Monte Carlo."""
    if risk is not None:
        if risk not in ("auto", "always", "never"):
            raise ParameterError(
                "risk", f"parameter 'risk' must be 'auto', 'always' or 'never', got {risk!r}"
            )
        tow = dataclasses.replace(tow, study=dataclasses.replace(tow.study, risk=risk))
    opts = tow.study
    do_td = opts.time_domain if time_domain is None else time_domain
    t1 = opts.t1 if t1 is None else t1
    speeds = _linspace(opts.speeds if speeds is None else speeds)
    has_model = tow.has_model
    seas = list(tow.sea_states) if opts.sea_states else []
    has_tug = tow.tug is not None
    do_risk = has_model and opts.risk != "never"
    n_steps = 2 + has_model * (2 + has_tug + len(seas) + bool(do_td) + 1) + do_risk
    steps = Steps(n_steps, enabled=progress, store=store)
    parts: dict = dict(_particulars(tow), skipped={})
    extra: dict = dict(datasets={}, runs={}, budgets={}, drift_curve=None, risk={})
    try:
        _drift_step(tow, steps, parts, extra)
        if not has_model:
            parts["skipped"]["stability, resistance and time domain"] = (
                "the tow file has no manoeuvring model ([vessel] derivatives or preset, and "
                "[towline])"
            )
        else:
            _model_steps(tow, seas, speeds, steps, parts, extra)
            mx, ml = map_grids(tow, map_xp, map_l0)
            _map(tow, mx, ml, progress, steps, parts, extra)
            if do_td:
                _time_domain(tow.model(), opts, t1, n_save, steps, parts, extra)
            else:
                parts["skipped"]["time domain"] = "switched off in [study]"
        summary = StudySummary(**parts)
        parts["assessment"] = steps.run(
            "criteria", "guideline criteria and the decision", assessment, tow, summary
        )
        if do_risk:
            _risk(tow, steps, parts, extra)
        if has_model:
            summary = StudySummary(**parts)
            parts["advice"] = steps.run(
                "advice", "advice: a way forward for what fails", advice, tow, summary
            ) + risk_advice(parts.get("risk", []))
    except Exception as e:  # noqa: BLE001 - the study keeps what finished and names the failure
        parts["incomplete"] = Incomplete(
            step=steps.current, error=f"{type(e).__name__}: {e}", interrupted=False
        )
    except KeyboardInterrupt:
        parts["incomplete"] = Incomplete(
            step=steps.current, error="interrupted (Ctrl-C)", interrupted=True
        )
    parts["step_times_s"] = dict(steps.times)
    return TowStudy(tow=tow, summary=StudySummary(**parts), **extra)


def _risk(tow, steps: Steps, parts: dict, extra: dict) -> None:
    """The irregular-sea Monte Carlo where the linear verdict cannot decide (`_risk`)."""
    seas = risk_seas(tow, StudySummary(**parts))
    label = "irregular-sea risk (Monte Carlo)" + (
        f" of sea state {', '.join(repr(s.name) for s in seas)}" if seas else ": not needed"
    )
    records, figures = steps.run("risk", label, risk_step, tow, StudySummary(**parts))
    extra["risk"].update(figures)
    parts["risk"] = records
    if records and parts.get("assessment") is not None:
        a = parts["assessment"]
        parts["assessment"] = msgspec.structs.replace(a, checks=with_risk(a.checks, records))


def _particulars(tow) -> dict:
    """The tow as the summary names it: its particulars, sailing form, estimates, warnings,
    plausibility findings and the drift source's description."""
    sc = tow.scales
    return dict(
        tow=tow.name,
        description=tow.description,
        source=tow.source,
        design_speed=float(sc.u_tug),
        length=sc.length,
        breadth=tow.breadth,
        draft=sc.draft,
        force_scale=float(sc.force),
        time_scale=sc.length / float(sc.u_tug),
        sailing_form=tow.form,
        drift_source=tow.drift.describe(),
        assumed=[list(a) for a in tow.assumed],
        warnings=list(tow.warnings),
        plausibility=[
            FindingRow(key=f.key, text=f.text, parameter=f.parameter) for f in tow.findings
        ],
        components=list(resistance.COMPONENTS),
        route_length_m=tow.route_length,
    )


def _drift_step(tow, steps: Steps, parts: dict, extra: dict) -> None:
    """The hull's drift source and its mean drift (`_hull_drift`)."""
    record, curve = steps.run("drift", "wave drift of the hull", _hull_drift, tow)
    parts["drift"] = record
    parts["drift_source"] = record.source
    extra["drift_curve"] = curve


def _hull_drift(tow) -> tuple[DriftRecord, tuple]:
    """The head-sea surge drift of the hull against the short-wave wall limit, and the
    mean drift in each sea state at rest and at the design speed (no model needed)."""
    q = tow.drift.qtf()
    seas = [s for s in tow.sea_states if float(s.hs) > 0]
    # the seas' spectra, stacked on the host (float64, as the spectra's own fields) and
    # evaluated in the program
    spectra = [Jonswap(hs=s.hs, tp=s.tp, gamma=s.gamma) for s in seas]
    stacked = (
        jax.tree.map(lambda *a: np.stack([np.asarray(x, float) for x in a]), *spectra)
        if seas
        else None
    )
    angles = np.array([float(s.wave_angle) for s in seas])
    speeds = np.array([0.0, float(tow.scales.u_tug)])
    fx, drift, over = jax.device_get(_drift_program(q, stacked, angles, speeds, form=tow.form))
    for k, s in enumerate(seas):  # the check irregular_sailing_drift makes eagerly
        for j, u in enumerate(speeds):
            if over[k, j]:
                S = spectra[k](DEFAULT_OMEGA)
                _, msg = overtaken_check(DEFAULT_OMEGA, S, angles[k], u)
                raise ValueError(f"sea state {s.name!r}: {msg}")
    rows = [
        MeanDriftRow(
            sea_state=s.name,
            hs=float(s.hs),
            tp=float(s.tp),
            fx_stationary=float(drift[k, 0]),
            fx_design_speed=float(drift[k, 1]),
        )
        for k, s in enumerate(seas)
    ]
    wall = 0.5 * RHO_SEA * G * tow.breadth  # Faltinsen's wall-sided short-wave limit ½ρgB
    record = DriftRecord(
        source=tow.drift.describe(), wall_limit_ratio=float(-fx[-1] / wall), mean_drift=rows
    )
    return record, (np.asarray(q.omega), fx)


@persistent
@eqx.filter_jit
def _drift_program(q, spectra, angles, speeds, *, form):
    """`_hull_drift`'s numbers as one compiled program: the head-sea surge drift on the
    table's frequencies, and the mean surge drift (and whether the sea is partly overtaken)
    of each sea state (rows) at each speed (columns). ``spectra``: the seas' spectra
    stacked along their fields (None for no sea)."""
    fx = jax.vmap(lambda x: q(x, 0.0))(q.omega)[:, 0]
    if spectra is None:
        return fx, jnp.zeros((0, speeds.shape[0])), jnp.zeros((0, speeds.shape[0]), bool)
    spectra = jax.vmap(lambda sp: sp.density(DEFAULT_OMEGA))(spectra)

    def one(S, angle, u):
        F = irregular_sailing_drift(q, DEFAULT_OMEGA, S, angle, u, 0.0, form=form, throw=False)
        return F[0], overtaken_check(DEFAULT_OMEGA, S, angle, u)[0]

    per_speed = jax.vmap(one, in_axes=(None, None, 0))
    drift, over = jax.vmap(per_speed, in_axes=(0, 0, None))(spectra, angles, speeds)
    return fx, drift, over


def _model_steps(tow, seas, speeds, steps: Steps, parts: dict, extra: dict) -> None:
    """Resistance, and the equilibria in calm water and in each sea state."""
    model = tow.model()
    parts["stability_coefficient_c"] = float(model.vessel.stability_coefficient())
    parts["towline"] = _towline_record(model, tow)
    rows: list[ResistanceRow] = []
    if tow.tug is not None:
        rows = _resistance(tow, tow.sea_states, speeds, steps, parts, extra)
        t = tow.tug
        parts["tug"] = TugRecord(
            bollard_pull=float(t.bollard_pull),
            free_speed=float(t.max_speed),
            efficiency=float(t.efficiency),
            efficiencies=dict(tow.efficiencies),
            efficiency_estimate=any(k == "tug_efficiency" for k, _ in tow.assumed),
        )
    else:
        parts["skipped"]["resistance"] = "the tow file has no [tug]"
    ops = {r.sea_state: r.operating_speed for r in rows if r.status == "successful"}
    conditions = [
        steps.run(
            "calm", "equilibria and stability in calm water", condition, model, "calm water", "calm"
        )
    ]
    for s in seas:
        op = ops.get(s.name)
        label = f"equilibria and stability in sea state {s.name!r}" + (
            f" (design speed and operating speed {op:.2f} m/s)" if op is not None else ""
        )
        conditions += steps.run(f"sea state {s.name}", label, sea_conditions, tow, s, op)
    if not tow.study.sea_states:
        parts["skipped"]["sea states"] = "switched off in [study]"
    parts["conditions"] = conditions
    strength = _strength_record(tow, model, conditions)
    if strength is not None:
        parts["towline"] = msgspec.structs.replace(parts["towline"], strength=strength)


def _resistance(tow, seas, speeds, steps: Steps, parts: dict, extra: dict) -> list[ResistanceRow]:
    """Per sea state: the required pull, operating speed and transit time, and the budget
    over the speeds (for the figures)."""
    tr = tow.resistance()

    def budget():
        rows = [evaluate_resistance(tr, tow.tug_in(s), s, 0.0, tow.route_length) for s in seas]
        # the figures reach past every operating point (the [study] speeds may stop short)
        tops = [float(speeds[-1])] + [1.1 * r.operating_speed for r in rows if r.operating_speed]
        top = max(tops)
        u = speeds if top <= float(speeds[-1]) else np.linspace(float(speeds[0]), top, speeds.size)
        curves = {}
        for s in seas:
            tug = tow.tug_in(s)
            b = resistance.resistance_grid(tr, s, jnp.asarray(u), jnp.array([float(s.tp)]), tug=tug)
            curves[s.name] = OperatingCurve(
                speeds=u,
                components=np.asarray(b.resistance[:, 0]),
                total=np.asarray(b.total[:, 0]),
                pull=np.asarray(tug.pull(jnp.asarray(u))),
            )
        return rows, curves

    rows, curves = steps.run("resistance", "resistance, bollard pull and operating speed", budget)
    extra["budgets"].update(curves)
    parts["resistance"] = rows
    return rows


def _map(tow, map_xp, map_l0, progress: bool, steps: Steps, parts: dict, extra: dict) -> None:
    """The calm-water stability map around the design point, and the share of it where the
    straight-behind equilibrium is stable."""
    model = tow.model()

    def stability_map():
        return sweep(model, {"xp": map_xp, "l0": map_l0}, progress=progress)

    ds = steps.run("map", "stability map around the design point", stability_map)
    extra["datasets"]["map_xp_l0"] = ds
    straight = ds["max_real"].where(ds["valid"] & (ds["branch"] == 0)).max("equilibrium")
    stable = (straight < 0).values
    parts["map"] = MapRecord(
        xp=[float(map_xp[0]), float(map_xp[-1]), int(map_xp.size)],
        l0=[float(map_l0[0]), float(map_l0[-1]), int(map_l0.size)],
        design_xp=float(model.towline.xp),
        design_l0=float(model.towline.l0),
        length=tow.scales.length,
        straight_stable_share=float(np.mean(stable)),
    )


def _time_domain(
    model, opts, t1: float, n_save: int, steps: Steps, parts: dict, extra: dict
) -> None:
    """The calm-water run from the [study]'s disturbed start, and its fishtailing metrics."""

    def run():
        y0 = initial_state(model, psi0=math.radians(opts.psi0_deg), y0=opts.y0)
        sim = simulate(model, y0, t1=t1, n_save=n_save)
        met = fishtail_metrics(model, sim)
        flags = {k: bool(np.all(np.asarray(v))) for k, v in sim.validity.items()}
        return trajectory(model, sim), met, flags

    traj, met, flags = steps.run("time domain", "time-domain check from a disturbed start", run)
    extra["runs"]["calm"] = (traj, met)
    parts["time_domain"] = TimeDomainRecord(
        psi0_deg=opts.psi0_deg,
        y0=opts.y0,
        t1=t1,
        outcome=met.outcome,
        path_width=met.path_width,
        yaw_range=None if met.yaw_range is None else list(met.yaw_range),
        slewing_period=met.slewing_period,
        ended_early=bool(met.ended_early),
        validity=flags,
    )
