"""Fishtailing risk and towline loads in an irregular sea: batched time-domain Monte Carlo.

Each run integrates the tow model (thesis eqs 6.1-6.6) over ``duration`` seconds in one
realisation of the sea state: the mean plus slowly varying wave drift of the tow's drift
source (`jaxtow.forces.SlowDriftForce`: Newman's approximation, or a full
difference-frequency QTF, with the forward-speed form of the drift at the vessel's state),
the wind with NPD gusts (`jaxtow.forces.GustWindForce`) and the current, on the tow's
elastic towline. The runs differ in their random phases (one set of component frequencies
per ``seed``, drawn once), in the start heading, and, optionally, in the documented input
uncertainties (``uncertain``: each run draws every named parameter uniformly in its range).
Runs go through one compiled kernel in chunks (vmapped groups inside a chunk), resumable
from a checkpoint like the sweeps; the results are deterministic for a seed, whatever the
chunking.

Each run's statistics are reduced inside the kernel (after the start-up, `risk_transient`):
its yaw amplitude (half the peak-to-peak heading) and largest |ψ|, the sway offset's
amplitude, their standard deviations, the largest and smallest towline tension and the
number of slack events. A run fishtails when its yaw amplitude exceeds ``yaw_threshold``
(or its sway amplitude ``sway_threshold``, when given).
"""

from __future__ import annotations

import dataclasses
import math
import time
from typing import Protocol, runtime_checkable

import diffrax
import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from .. import guidelines
from .._dynamics import TowModel, sway_offset, validity
from .._equilibrium import equilibria, straight_behind
from .._parameters import check_values, with_parameters
from .._progress import AbstractProgressMeter, NoProgressMeter
from .._rules import ParameterError, check_now
from .._simulate import initial_state, integrate, solver_tolerances
from .._sweep import without_metadata
from .._units import TONNE_FORCE, Scales
from .._values import ASSUMPTIONS
from ..drift import FullQTF
from ..forces import (
    GustWindForce,
    IrregularWaveDriftForce,
    SlowDriftForce,
    WindForce,
    combine,
    force_terms,
)
from ..resistance import SeaState
from ..waves import Jonswap
from ._stats import GumbelFit, exposure_probability, gumbel_fit, wilson_interval

__all__ = ["RiskSettings", "RiskResult", "TowLike", "irregular_sea", "risk_model"]


@runtime_checkable
class TowLike(Protocol):
    """What `irregular_sea` reads of a resolved tow file (`jaxtow.tow.Tow`): its model in a
    sea state, its scales and sea states; the towline's make, the tug and the criteria (for
    the MBL checks) where it has them."""

    scales: Scales
    sea_states: tuple

    def sea_model(self, sea: SeaState) -> TowModel: ...


@dataclasses.dataclass(frozen=True)
class RiskSettings:
    """The settings of a Monte Carlo (each with its documented default):

    ``n_runs`` runs of ``duration`` [s] from ``seed``; ``n_components`` wave components over
    ``omega_range`` [rad/s] (None: where the spectrum holds more than 1e-3 of its peak), the
    drift evaluated at ``nodes`` frequencies and interpolated to them (None: at each
    component; `jaxtow.forces.SlowDriftForce`), and ``n_gusts`` gust components; ``yaw_threshold`` [deg] and ``sway_threshold`` [L, None:
    not used] for a fishtail; ``transient`` [s] left out of each run's statistics;
    ``initial_yaw`` [deg]: the start heading's spread; ``save_step`` [s] between saved
    samples; the solver and its tolerances; ``chunk_size`` runs per kernel call and
    ``batch_size`` runs per vmapped group inside it on the CPU (1: one run after another,
    the fastest on a CPU, where vmapped adaptive runs wait for the slowest; on a GPU every
    chunk is one vmap); ``uncertain``:
    (parameter, low, high) triples drawn uniformly per run (`jaxtow.with_parameters` names);
    ``slack_fraction`` of the static tension below which the line is slack."""

    n_runs: int = 256
    duration: float = 3 * 3600.0
    seed: int = 0
    n_components: int = 256
    omega_range: tuple[float, float] | None = None
    nodes: int | None = 64
    n_gusts: int = 128
    yaw_threshold: float = float(ASSUMPTIONS["fishtail_yaw_amplitude"]["value"])
    sway_threshold: float | None = None
    transient: float = float(ASSUMPTIONS["risk_transient"]["value"])
    initial_yaw: float = float(ASSUMPTIONS["risk_initial_yaw"]["value"])
    save_step: float = 2.0
    solver: str = "tsit5"
    rtol: float = 1e-6
    atol: float = 1e-6
    max_steps: int = 1_000_000
    chunk_size: int = 256
    batch_size: int | None = 1
    uncertain: tuple = ()
    slack_fraction: float = float(ASSUMPTIONS["slack_fraction"]["value"])

    def __post_init__(self):
        checks = (
            ("n_runs", self.n_runs, isinstance(self.n_runs, int) and self.n_runs >= 1),
            ("duration", self.duration, self.duration > self.transient >= 0),
            ("transient", self.transient, self.transient >= 0),
            ("n_components", self.n_components, int(self.n_components) >= 2),
            ("n_gusts", self.n_gusts, int(self.n_gusts) >= 2),
            ("yaw_threshold", self.yaw_threshold, 0 < self.yaw_threshold < 90),
            ("initial_yaw", self.initial_yaw, 0 <= self.initial_yaw < 45),
            ("save_step", self.save_step, self.save_step > 0),
            ("chunk_size", self.chunk_size, int(self.chunk_size) >= 1),
            ("slack_fraction", self.slack_fraction, 0 <= self.slack_fraction < 1),
        )
        for name, value, ok in checks:
            if not ok or (isinstance(value, float) and not math.isfinite(value)):
                raise ParameterError(name, f"parameter {name!r} is out of range: {value!r}")
        if self.sway_threshold is not None and not self.sway_threshold > 0:
            raise ParameterError(
                "sway_threshold",
                f"parameter 'sway_threshold' must be > 0, got {self.sway_threshold}",
            )
        for item in self.uncertain:
            if len(item) != 3 or not float(item[1]) < float(item[2]):
                raise ParameterError(
                    "uncertain",
                    f"parameter 'uncertain': (name, low, high) with low < high, got {item!r}",
                )


@dataclasses.dataclass(frozen=True)
class RiskResult:
    """A Monte Carlo's runs and what a planner reads of them.

    Per run (arrays of ``n_runs``): ``fishtails``, ``yaw_amplitude`` and ``max_yaw`` [deg],
    ``sway_amplitude`` [L], ``yaw_std`` [deg], ``sway_std`` [L], ``max_tension`` and
    ``min_tension`` [N], ``slack_events``, ``completed`` (the solver reached the end).
    ``static`` holds the static equilibrium's state and tension [N]; ``validity`` the
    mean model's validity flags there (the forward-speed drift's among them); ``mbl`` and
    ``design_load`` [N] the towline's MBL and the guideline's MBL / f(BP) where known;
    ``samples`` a few runs' heading and sway series for figures; ``settings`` and
    ``described`` what was run."""

    settings: RiskSettings
    described: dict
    fishtails: np.ndarray
    yaw_amplitude: np.ndarray
    max_yaw: np.ndarray
    sway_amplitude: np.ndarray
    yaw_std: np.ndarray
    sway_std: np.ndarray
    max_tension: np.ndarray
    min_tension: np.ndarray
    slack_events: np.ndarray
    completed: np.ndarray
    static_tension: float
    validity: dict
    mbl: float | None = None
    design_load: float | None = None
    samples: dict = dataclasses.field(default_factory=dict)

    @property
    def n(self) -> int:
        """Runs that reached the end (the others are counted in ``failed_runs``)."""
        return int(np.sum(self.completed))

    @property
    def failed_runs(self) -> int:
        return int(self.completed.size - self.n)

    @property
    def record_hours(self) -> float:
        """The length of each run's record after the start-up [h]."""
        return (self.settings.duration - self.settings.transient) / 3600.0

    def _proportion(self, events) -> tuple[float, tuple[float, float]]:
        k = int(np.sum(np.asarray(events) & self.completed))
        return k / max(self.n, 1), wilson_interval(k, max(self.n, 1))

    @property
    def fishtail_probability(self) -> float:
        """The share of runs that fishtail within their record."""
        return self._proportion(self.fishtails)[0]

    @property
    def confidence_interval(self) -> tuple[float, float]:
        """The 95 % Wilson interval (low, high) of `fishtail_probability`."""
        return self._proportion(self.fishtails)[1]

    def probability_at(self, yaw_threshold: float) -> tuple[float, tuple[float, float]]:
        """The fishtail probability and its interval at another yaw threshold [deg]."""
        return self._proportion(self.yaw_amplitude > yaw_threshold)

    def probability_in(self, hours: float) -> tuple[float, tuple[float, float]]:
        """The fishtail probability and its interval over an exposure of ``hours``."""
        p, (lo, hi) = self._proportion(self.fishtails)
        d = self.record_hours
        return (
            float(exposure_probability(p, d, hours)),
            (float(exposure_probability(lo, d, hours)), float(exposure_probability(hi, d, hours))),
        )

    @property
    def tension_fit(self) -> GumbelFit:
        """The Gumbel fit of the runs' largest tensions [N] (per record)."""
        return gumbel_fit(self.max_tension[self.completed])

    def mpm_tension_in(self, hours: float) -> float:
        """The most probable maximum tension [N] over an exposure of ``hours``."""
        return self.tension_fit.over(hours / self.record_hours).mode

    @property
    def mpm_tension(self) -> float:
        """The most probable maximum towline tension [N] in 3 hours."""
        return self.mpm_tension_in(3.0)

    def exceedance(self, load: float) -> tuple[float, tuple[float, float]]:
        """The share of runs whose largest tension exceeds ``load`` [N], and its interval."""
        return self._proportion(self.max_tension > load)

    @property
    def slack_probability(self) -> tuple[float, tuple[float, float]]:
        """The share of runs with at least one slack event, and its interval."""
        return self._proportion(self.slack_events > 0)


# ---------------------------------------------------------------------- the model of a run


def _band(spectrum, lo=0.05, hi=5.0, floor=1e-3) -> tuple[float, float]:
    """Where the spectrum holds more than ``floor`` of its peak density, on [lo, hi]."""
    w = np.linspace(lo, hi, 2000)
    S = np.asarray(spectrum.density(jnp.asarray(w)))
    keep = w[S > floor * S.max()]
    return float(keep[0]), float(keep[-1])


def risk_model(mean: TowModel, settings: RiskSettings, *, full_qtf=None, wind_height=10.0):
    """The time-domain model of ``mean`` (a tow model with its mean sea forces): its
    `IrregularWaveDriftForce` becomes a seeded `SlowDriftForce` (``full_qtf``: a
    `jaxtow.drift.FullQTF` for the off-diagonal terms) and its `WindForce` a seeded
    `GustWindForce`, from ``settings.seed``; the other forces stay. Returns (model, band)."""
    out, band = [], None
    for f in force_terms(mean.external):
        if isinstance(f, IrregularWaveDriftForce):
            band = settings.omega_range or _band(f.spectrum)
            f = SlowDriftForce.seeded(
                f.qtf,
                f.spectrum,
                f.scales,
                seed=settings.seed,
                n=int(settings.n_components),
                omega_range=band,
                form=f.form,
                yaw_rate=f.yaw_rate,
                full_qtf=full_qtf,
                angle=float(f.angle),
                nodes=settings.nodes,
            )
        elif isinstance(f, WindForce) and float(f.speed) > 0:
            f = GustWindForce.seeded(
                f, seed=settings.seed + 1, n=int(settings.n_gusts), height=wind_height
            )
        out.append(f)
    if full_qtf is not None and not isinstance(full_qtf, FullQTF):
        raise TypeError(f"parameter 'full_qtf' must be a jaxtow.drift.FullQTF, got {full_qtf!r}")
    return eqx.tree_at(lambda m: m.external, mean, combine(out), is_leaf=lambda x: x is None), band


def _with_phases(model: TowModel, wave_phase, gust_phase) -> TowModel:
    forces = force_terms(model.external)
    for i, f in enumerate(forces):
        if isinstance(f, SlowDriftForce):
            forces[i] = eqx.tree_at(lambda g: g.phase, f, wave_phase)
        elif isinstance(f, GustWindForce):
            forces[i] = eqx.tree_at(lambda g: g.phase, f, gust_phase)
    return eqx.tree_at(lambda m: m.external, model, combine(forces))


def _n_phases(model: TowModel, kind) -> int:
    return sum(int(f.phase.shape[0]) for f in force_terms(model.external) if isinstance(f, kind))


# ---------------------------------------------------------------------- the kernel


def _statistics(model, ys, window, force_scale, slack_level):
    """One run's statistics over the samples in ``window`` (in the kernel)."""
    psi = ys[:, 5]
    ok = window & jnp.all(jnp.isfinite(ys), axis=-1)
    nan = jnp.nan

    def masked(x):
        return jnp.where(ok, x, nan)

    xp, yp = model.towline.xp, model.towline.yp
    sway = sway_offset(ys, xp, yp)
    tension = jax.vmap(model.towline.tension)(jnp.where(ok, ys[:, 3], model.towline.l0))
    tension = tension * force_scale
    below = (tension < slack_level) & ok
    n = jnp.maximum(jnp.sum(ok), 1)

    def std(x):
        m = jnp.sum(jnp.where(ok, x, 0.0)) / n
        return jnp.sqrt(jnp.sum(jnp.where(ok, (x - m) ** 2, 0.0)) / n)

    deg = 180.0 / math.pi
    return dict(
        yaw_amplitude=0.5 * (jnp.nanmax(masked(psi)) - jnp.nanmin(masked(psi))) * deg,
        max_yaw=jnp.nanmax(jnp.abs(masked(psi))) * deg,
        sway_amplitude=0.5 * (jnp.nanmax(masked(sway)) - jnp.nanmin(masked(sway))),
        yaw_std=std(psi) * deg,
        sway_std=std(sway),
        max_tension=jnp.nanmax(masked(tension)),
        min_tension=jnp.nanmin(masked(tension)),
        slack_events=jnp.sum(below[1:] & ~below[:-1]),
    )


def _chunk(model, y0s, wave_phase, gust_phase, params, ts, window, force_scale, slack_level,
           keep, *, solver, rtol, atol, max_steps, batch_size):  # fmt: skip
    def one(args):
        y0, wp, gp, p = args
        m = with_parameters(_with_phases(model, wp, gp), **p)
        run = integrate(m, y0, ts, solver=solver, rtol=rtol, atol=atol, max_steps=max_steps)
        out = _statistics(m, run.ys, window, force_scale, slack_level)
        out["completed"] = diffrax.is_successful(run.result)
        if keep:
            out["psi"] = run.ys[:, 5]
            out["sway"] = sway_offset(run.ys, m.towline.xp, m.towline.yp)
        return out

    args = (y0s, wave_phase, gust_phase, params)
    if batch_size is None:
        return jax.vmap(one)(args)
    return jax.lax.map(one, args, batch_size=batch_size)


_chunk_jit = jax.jit(
    _chunk, static_argnames=("keep", "solver", "rtol", "atol", "max_steps", "batch_size")
)


# ---------------------------------------------------------------------- the entry point


def _inputs(tow, sea_state):
    """(mean model, scales, description, mbl, design_load, wind height) of the arguments."""
    if isinstance(tow, TowModel):
        mean = tow
        if sea_state is not None:
            mean = _model_in(tow, sea_state)
        scales = next((f.scales for f in force_terms(mean.external) if hasattr(f, "scales")), None)
        if scales is None:
            raise ValueError(
                "parameter 'tow': a TowModel needs a sea force with its scales (an "
                "IrregularWaveDriftForce, a WindForce); give a resolved tow file otherwise"
            )
        return mean, scales, dict(tow="TowModel"), None, None, 10.0
    if not isinstance(tow, TowLike):
        raise TypeError(
            f"parameter 'tow': a resolved tow file (jaxtow.tow.load) or a jaxtow.TowModel, got {tow!r}"
        )
    if isinstance(sea_state, str):
        names = [s.name for s in tow.sea_states]
        if sea_state not in names:
            raise ParameterError(
                "sea_state", f"parameter 'sea_state': {sea_state!r} is not one of the tow's {names}"
            )
        sea_state = tow.sea_states[names.index(sea_state)]
    if not isinstance(sea_state, SeaState):
        raise TypeError(
            f"parameter 'sea_state': a jaxtow SeaState or the name of one of the tow's sea "
            f"states, got {sea_state!r}"
        )
    mean = tow.sea_model(sea_state)
    mbl = design = None
    make = getattr(tow, "make", None)
    if make is not None:
        mbl = float(make.weakest.mbl)
        tug, crit = getattr(tow, "tug", None), getattr(tow, "criteria", None)
        if tug is not None and crit is not None:
            bp_t = float(tug.bollard_pull) / TONNE_FORCE
            design = mbl / guidelines.mbl_factor(bp_t, crit)
    described = dict(
        tow=getattr(tow, "name", ""),
        sea_state=sea_state.name,
        hs=float(sea_state.hs),
        tp=float(sea_state.tp),
        gamma=float(sea_state.gamma),
        wind_speed=float(sea_state.wind_speed),
        current_speed=float(sea_state.current_speed),
        wave_angle_deg=math.degrees(float(sea_state.wave_angle)),
    )
    return mean, tow.scales, described, mbl, design, float(getattr(tow, "wind_height", 10.0))


def _model_in(model: TowModel, sea: SeaState) -> TowModel:
    """A tow model's mean wave force set to the sea state's waves (Hs, Tp, γ, direction)."""
    forces = force_terms(model.external)
    idx = [i for i, f in enumerate(forces) if isinstance(f, IrregularWaveDriftForce)]
    if not idx and float(sea.hs) > 0:
        raise ValueError(
            "parameter 'sea_state': the TowModel has no IrregularWaveDriftForce to put the "
            "waves in (give a resolved tow file, or a model with its drift)"
        )
    for i in idx:
        f = forces[i]
        if float(sea.hs) > 0:
            forces[i] = dataclasses.replace(
                f, spectrum=Jonswap(hs=sea.hs, tp=sea.tp, gamma=sea.gamma), angle=sea.wave_angle
            )
    forces = [f for j, f in enumerate(forces) if j not in idx or float(sea.hs) > 0]
    return eqx.tree_at(lambda m: m.external, model, combine(forces), is_leaf=lambda x: x is None)


def _start(mean: TowModel):
    """The static straight-behind equilibrium (else the thesis's start state) and whether
    it is the equilibrium."""
    eqs = equilibria(mean)
    mask = np.asarray(straight_behind(np.asarray(eqs.psi), np.asarray(eqs.valid)))
    if mask.any():
        return np.asarray(eqs.state)[int(np.argmax(mask))], True
    return np.asarray(initial_state(mean)), False


def irregular_sea(
    tow,
    sea_state=None,
    *,
    n_runs: int = 256,
    duration: float = 3 * 3600.0,
    seed: int = 0,
    settings: RiskSettings | None = None,
    full_qtf=None,
    keep: int = 8,
    parameters: dict | None = None,
    budget_s: float | None = None,
    progress_meter: AbstractProgressMeter | None = None,
    checkpoint=None,
) -> RiskResult:
    """The fishtailing risk and the towline loads of ``tow`` in ``sea_state`` from
    ``n_runs`` time-domain runs of ``duration`` [s] (module docstring).

    ``tow``: a resolved tow file (`jaxtow.tow.load`; ``sea_state`` a `SeaState` or the name
    of one of its sea states), or a `jaxtow.TowModel` with its mean sea forces
    (``sea_state`` None, or a `SeaState` whose waves replace the model's). ``settings``: a
    `RiskSettings` for everything else (its ``n_runs``, ``duration`` and ``seed`` are
    replaced by the arguments). ``full_qtf``: a `jaxtow.drift.FullQTF` for the off-diagonal
    drift. ``keep``: runs whose heading and sway series are kept for figures.
    ``parameters``: changes to the tow model (`jaxtow.with_parameters` names → values, e.g.
    {"l0": 2.0, "xp": 0.4}) for every run. ``budget_s``: a wall-time budget [s]: the runs
    stop after the chunk that reaches it (at least one chunk runs; the result holds the
    runs that finished, a prefix of the full batch). ``progress_meter``, ``checkpoint``: as `jaxtow.sweep_arrays`. Deterministic for a seed."""
    if not int(n_runs) >= 2:
        raise ParameterError("n_runs", f"parameter 'n_runs' must be at least 2, got {n_runs!r}")
    s = dataclasses.replace(
        settings or RiskSettings(), n_runs=int(n_runs), duration=float(duration), seed=int(seed)
    )
    mean, scales, described, mbl, design, height = _inputs(tow, sea_state)
    if parameters:
        for name, value in parameters.items():
            check_values(mean, name, np.atleast_1d(np.asarray(value, float)))
        mean = with_parameters(mean, **parameters)
        described["parameters"] = {k: float(v) for k, v in parameters.items()}
    check_now(mean)
    model, band = risk_model(mean, s, full_qtf=full_qtf, wind_height=height)
    y_eq, at_eq = _start(mean)
    draws = _draws(s, model, mean, y_eq)
    static_T = float(mean.towline.tension(y_eq[3])) * float(scales.force)
    deadline = None if budget_s is None else time.perf_counter() + float(budget_s)
    arrays, samples = _run(
        without_metadata(model),
        draws,
        s,
        scales,
        static_T,
        keep,
        progress_meter,
        checkpoint,
        deadline,
    )
    done = int(arrays["completed"].size)
    if done < s.n_runs:
        described["stopped_by_budget"] = f"{done} of {s.n_runs} runs within {budget_s:g} s"
        s = dataclasses.replace(s, n_runs=done)
    described.update(
        omega_range=None if band is None else list(band),
        start="static straight-behind equilibrium" if at_eq else "thesis start state",
        speed=float(scales.u_tug),
        full_qtf=full_qtf is not None,
    )
    flags = {k: np.asarray(v).tolist() for k, v in validity(mean, jnp.asarray(y_eq)).items()}
    return _result(s, described, arrays, samples, static_T, flags, mbl, design)


def _result(s, described, arrays, samples, static_T, flags, mbl, design) -> RiskResult:
    fish = arrays["yaw_amplitude"] > s.yaw_threshold
    if s.sway_threshold is not None:
        fish = fish | (arrays["sway_amplitude"] > s.sway_threshold)
    return RiskResult(
        settings=s,
        described=described,
        fishtails=np.asarray(fish, bool),
        yaw_amplitude=arrays["yaw_amplitude"],
        max_yaw=arrays["max_yaw"],
        sway_amplitude=arrays["sway_amplitude"],
        yaw_std=arrays["yaw_std"],
        sway_std=arrays["sway_std"],
        max_tension=arrays["max_tension"],
        min_tension=arrays["min_tension"],
        slack_events=arrays["slack_events"].astype(int),
        completed=np.asarray(arrays["completed"], bool),
        static_tension=static_T,
        validity=flags,
        mbl=mbl,
        design_load=design,
        samples=samples,
    )


def _draws(s: RiskSettings, model: TowModel, mean: TowModel, y_eq) -> dict:
    """Every run's random numbers, from the seed alone: the start states, the wave and gust
    phases and the uncertain parameters, each from its own stream, so that the first k runs
    are the same whatever ``n_runs`` (a shorter batch is a prefix of a longer one: common
    random numbers between variants, and budgets that stop early)."""

    def stream(k: int):
        return np.random.default_rng([s.seed, 7, k])

    nw, ng = _n_phases(model, SlowDriftForce), _n_phases(model, GustWindForce)
    wave_phase = stream(1).uniform(0.0, 2 * np.pi, (s.n_runs, nw))
    gust_phase = stream(2).uniform(0.0, 2 * np.pi, (s.n_runs, ng))
    dpsi = np.radians(stream(3).uniform(-s.initial_yaw, s.initial_yaw, s.n_runs))
    params = {}
    for i, (name, lo, hi) in enumerate(s.uncertain):
        v = stream(10 + i).uniform(float(lo), float(hi), s.n_runs)
        check_values(mean, name, v)
        params[name] = v
    y0s = np.repeat(np.asarray(y_eq)[None], s.n_runs, axis=0)
    y0s[:, 5] += dpsi
    return dict(y0s=y0s, wave_phase=wave_phase, gust_phase=gust_phase, params=params)


def _run(model, draws, s: RiskSettings, scales, static_T, keep, progress_meter, checkpoint,
         deadline=None):  # fmt: skip
    """The runs, chunk by chunk (each chunk padded to one shape: one program), through the
    checkpoint's store where there is one. Returns (per-run arrays, kept samples)."""
    U, L = float(scales.u_tug), float(scales.length)
    n_save = int(math.ceil(s.duration / s.save_step)) + 1
    ts = jnp.linspace(0.0, s.duration * U / L, n_save)
    window = jnp.asarray(np.linspace(0.0, s.duration, n_save) >= s.transient)
    rtol, atol = solver_tolerances(s.rtol, s.atol)
    batch = s.batch_size if jax.default_backend() == "cpu" else None
    nchunks = -(-s.n_runs // s.chunk_size)
    store = None
    if checkpoint is not None:
        opts = dict(dataclasses.asdict(s), uncertain=[list(u) for u in s.uncertain], keep=keep)
        axes = (np.arange(s.n_runs, dtype=float),)
        store = checkpoint.open(model, ("run",), axes, s.chunk_size, opts, nchunks)
    bar = (progress_meter or NoProgressMeter()).start(nchunks, "runs")
    pieces = []
    for c in range(nchunks):
        lo, hi = c * s.chunk_size, min((c + 1) * s.chunk_size, s.n_runs)
        piece = None if store is None else store.get(c)
        if piece is None:
            out = _chunk_jit(
                model,
                *(jnp.asarray(_cut(draws[k], lo, hi, s.chunk_size)) for k in _DRAWN),
                {k: jnp.asarray(_cut(v, lo, hi, s.chunk_size)) for k, v in draws["params"].items()},
                ts,
                window,
                float(scales.force),
                s.slack_fraction * static_T,
                lo < keep,
                solver=s.solver,
                rtol=rtol,
                atol=atol,
                max_steps=s.max_steps,
                batch_size=None if batch is None else min(batch, s.chunk_size),
            )
            piece = {k: np.asarray(v)[: hi - lo] for k, v in jax.device_get(out).items()}
            if store is not None:
                store.put(c, piece)
        pieces.append(piece)
        bar.update()
        if deadline is not None and time.perf_counter() > deadline:
            break
    bar.close()
    keys = [k for k in pieces[0] if k not in ("psi", "sway")]
    arrays = {k: np.concatenate([p[k] for p in pieces]) for k in keys}
    kept = [p for p in pieces if "psi" in p]
    samples = {}
    if kept:
        samples = dict(
            t=np.linspace(0.0, s.duration, n_save),
            psi=np.degrees(np.concatenate([p["psi"] for p in kept])[:keep]),
            sway=np.concatenate([p["sway"] for p in kept])[:keep],
        )
    return arrays, samples


_DRAWN = ("y0s", "wave_phase", "gust_phase")


def _cut(a, lo: int, hi: int, size: int):
    """Rows lo..hi of ``a``, padded to ``size`` rows by repeating the last."""
    a = np.asarray(a)[lo:hi]
    pad = size - (hi - lo)
    return np.concatenate([a, np.repeat(a[-1:], pad, axis=0)]) if pad else a
