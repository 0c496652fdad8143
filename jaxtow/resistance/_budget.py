"""The resistance budget of a tow and the required pull (thesis sections 7.1-7.2, figs 2.1, 7.2-7.4)."""

from __future__ import annotations

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from .._program_cache import persistent
from .._rules import FINITE, NONNEGATIVE, POSITIVE, check_now, guard, holds_tracers, is_concrete
from .._units import RHO_SEA, froude_number
from .._vessel import Vessel
from ..drift import (
    QTF,
    WATERLINE_METHODS,
    Waterline,
    encounter_frequency,
    irregular_sailing_drift,
)
from ..drift._compare import method_mean_drift
from ..drift._sailing import check_form
from ..waves import DEFAULT_OMEGA, spectral_integral
from ..waves._spectra import jonswap_density
from ._flow import RHO_AIR, CoefficientTable, ManoeuvringCoefficients, OCIMFLoad
from ._sea import SeaState
from ._tug import Tug

#: The components of the resistance budget: the hull's resistance through the water (the
#: current included), the wind, the mean wave drift and the tug's own resistance.
COMPONENTS = ("hull", "wind", "waves", "tug")


#: Largest share of the sea's m0 the tow may overtake (encounter frequency <= 0) before the
#: wave resistance is flagged incomplete (``overtaken_energy``; 0.1 %).
OVERTAKEN_TOL = 1e-3


class WaveDrift(eqx.Module):
    """Mean wave drift in a JONSWAP sea with forward speed, (F_x, F_y, N) [N, N, N·m].

    Either a waterline method of `jaxtow.drift.WATERLINE_METHODS` (``method``, ``waterline``, its keyword
    ``options``) or a panel/WAMIT mean-drift ``qtf`` (then the encounter frequency and
    Aranha's formula gives the speed effect, `jaxtow.drift.sailing_drift` with ``form``,
    eqs 2.35-2.41). ``omega`` is the integration grid [rad/s] (default
    `jaxtow.waves.DEFAULT_OMEGA`)."""

    waterline: Waterline | None
    qtf: QTF | None
    omega: jnp.ndarray
    method: str = eqx.field(static=True, default="kashiwagi")
    options: tuple = eqx.field(static=True, default=())
    form: str = eqx.field(static=True, default="aranha")

    def __init__(
        self,
        waterline=None,
        *,
        method: str = "kashiwagi",
        qtf=None,
        omega=None,
        options=None,
        form: str = "aranha",
    ):
        if (waterline is None) == (qtf is None):
            raise ValueError("WaveDrift needs exactly one of 'waterline' (with 'method') or 'qtf'")
        if qtf is None and method not in WATERLINE_METHODS:
            raise ValueError(
                f"parameter 'method': unknown drift method {method!r}; choose from {sorted(WATERLINE_METHODS)}"
            )
        self.waterline, self.qtf = waterline, qtf
        self.method = "qtf" if qtf is not None else method
        self.omega = jnp.asarray(DEFAULT_OMEGA if omega is None else omega, float)
        self.options = tuple(sorted((options or {}).items()))
        self.form = check_form(form)

    def overtaken_energy(self, hs, tp, gamma, beta, u, v):
        """Fraction of the sea's m0 at frequencies the tow overtakes (encounter frequency
        ω_e ≤ 0): there the drift theory does not apply and the drift is taken as zero, so
        the wave resistance is incomplete by what these waves would add."""
        S = self.spectrum(hs, tp, gamma)
        over = (encounter_frequency(self.omega, beta, u, v) <= 0).astype(S.dtype)
        m0 = spectral_integral(self.omega, S, jnp.ones_like(S))
        share = spectral_integral(self.omega, S, over) / jnp.where(m0 > 0, m0, 1.0)
        return jnp.where(m0 > 0, share, 0.0)  # Hs = 0: no waves, none overtaken

    def spectrum(self, hs, tp, gamma):
        """JONSWAP S(ω) on ``omega`` (`jaxtow.waves.jonswap`; Hs = 0 gives a calm sea). The
        values are the sea state's, checked by its rules (`SeaState`; `resistance_grid`
        checks its Tp grid), so no run-time check is compiled in."""
        return jonswap_density(self.omega, hs, tp, gamma)

    def __call__(self, hs, tp, gamma, beta, u, v):
        S = self.spectrum(hs, tp, gamma)
        if self.qtf is not None:
            return irregular_sailing_drift(
                self.qtf, self.omega, S, beta, u, v, 0.0, form=self.form, throw=False
            )
        return method_mean_drift(
            self.method, self.waterline, self.omega, S, beta, u, v, **dict(self.options)
        )


class TowResistance(eqx.Module):
    """What is towed: its current/calm-water load ``hull``, its ``wind`` load and its mean
    ``waves`` drift (either may be None), with ``assumed`` listing the estimates the
    results depend on (carried into datasets). ``length`` [m] of the hull sets the Froude
    number. Build Barge 2's with `jaxtow.presets.barge2_resistance`."""

    hull: OCIMFLoad
    wind: OCIMFLoad | None = None
    waves: WaveDrift | None = None
    name: str = eqx.field(static=True, default="tow")
    assumed: tuple = eqx.field(static=True, default=())

    @property
    def length(self):
        return self.hull.length

    def body_forces(self, sea: SeaState, speed, heading=0.0):
        """(3, 3) body-axis loads (F_x, F_y, N) of (current, wind, waves) at tow speed U."""
        speed, heading = jnp.asarray(speed, float), jnp.asarray(heading, float)
        u, v = speed * jnp.cos(heading), -speed * jnp.sin(heading)
        zero = jnp.zeros(3)
        hull = self.hull(u, v, sea.current_speed, sea.current_angle - heading)
        wind = (
            zero if self.wind is None else self.wind(u, v, sea.wind_speed, sea.wind_angle - heading)
        )
        waves = (
            zero
            if self.waves is None
            else self.waves(sea.hs, sea.tp, sea.gamma, sea.wave_angle - heading, u, v)
        )
        return jnp.stack([hull, wind, waves])


def tow_resistance(
    vessel: Vessel,
    length: float,
    breadth: float,
    draft: float,
    waves,
    *,
    wind_table: CoefficientTable,
    wind_height: float,
    name: str = "tow",
    assumed: tuple = (),
) -> TowResistance:
    """The `jaxtow.resistance.TowResistance` of any vessel: the current/calm-water load from
    its manoeuvring derivatives (fig. 7.1b) on L, B, T [m], the OCIMF wind load of
    ``wind_table`` on the windage height [m], and ``waves`` (a `WaveDrift`)."""
    L, B = float(length), float(breadth)
    hull = OCIMFLoad(ManoeuvringCoefficients(vessel, L, B), RHO_SEA, L, B, float(draft))
    wind = OCIMFLoad(wind_table, RHO_AIR, L, B, float(wind_height))
    return TowResistance(hull=hull, wind=wind, waves=waves, name=name, assumed=tuple(assumed))


class Budget(eqx.Module):
    """Resistance budget at one speed: ``resistance`` (4,) [N] along the course for
    `COMPONENTS` = (hull, wind, waves, tug), ``body`` (4, 3) body-axis loads, ``speed``
    [m/s], ``froude`` Fn = U/√(gL), ``overtaken_energy`` the fraction of the sea's m0 the
    tow overtakes (ω_e ≤ 0: no drift counted there; > 0 flags an incomplete wave
    resistance). ``total`` sums the components; ``shares`` gives each in % of the total."""

    resistance: jnp.ndarray
    body: jnp.ndarray
    speed: jnp.ndarray
    froude: jnp.ndarray
    overtaken_energy: jnp.ndarray = eqx.field(default_factory=lambda: jnp.zeros(()))

    @property
    def total(self):
        return jnp.sum(self.resistance, axis=-1)

    @property
    def shares(self):
        """Each component in % of the total (0 where the total is exactly 0: no load at all)."""
        tot = self.total[..., None]
        return jnp.where(tot != 0, 100.0 * self.resistance / jnp.where(tot != 0, tot, 1.0), 0.0)

    def as_dict(self) -> dict:
        return {c: self.resistance[..., i] for i, c in enumerate(COMPONENTS)}


def resistance(
    tow: TowResistance,
    sea: SeaState,
    speed,
    *,
    heading=0.0,
    tug: Tug | None = None,
    throw: bool = True,
) -> Budget:
    """Resistance budget of the tow at speed U [m/s] along the course and heading ψ [rad]
    (thesis figs 7.2-7.4): along-course resistance of current/calm water, wind, waves and (if
    a ``tug`` is given) the tug's own resistance, R = −(F_x cos ψ − F_y sin ψ).

    ``throw=True``: the sea state, the tug, the speed and the heading are checked (eagerly,
    or with `equinox.error_if` when traced; see `jaxtow.vector_field`); ``throw=False``: no
    check, as in jaxtow's own compiled grids, which check their inputs first."""
    if throw:  # eager: the same rules, before anything is computed
        FINITE.check("speed", speed)
        FINITE.check("heading", heading)
        check_now(sea)
        if tug is not None:
            check_now(tug)
    out = _budget(tow, sea, speed, heading, tug)
    if not throw:
        return out
    checks = [FINITE.traced("speed", speed), FINITE.traced("heading", heading), *sea.checks()]
    return guard(out, checks + (tug.checks() if tug is not None else []))


def _budget(tow: TowResistance, sea: SeaState, speed, heading, tug: Tug | None) -> Budget:
    speed, heading = jnp.asarray(speed, float), jnp.asarray(heading, float)
    body = tow.body_forces(sea, speed, heading)
    along = -(body[:, 0] * jnp.cos(heading) - body[:, 1] * jnp.sin(heading))
    r_tug = jnp.zeros(()) if tug is None else tug.resistance(speed)
    body = jnp.concatenate([body, jnp.stack([-r_tug, 0.0 * r_tug, 0.0 * r_tug])[None]])
    over = (
        jnp.zeros(())
        if tow.waves is None
        else tow.waves.overtaken_energy(
            sea.hs,
            sea.tp,
            sea.gamma,
            sea.wave_angle - heading,
            speed * jnp.cos(heading),
            -speed * jnp.sin(heading),
        )
    )
    return Budget(
        resistance=jnp.concatenate([along, r_tug[None]]),
        body=body,
        speed=speed,
        froude=froude_number(speed, tow.length),
        overtaken_energy=over,
    )


class PullRequirement(eqx.Module):
    """`required_pull` result: ``towing_force`` [N] (the total resistance), ``bollard_pull``
    [N] the tug's rated bollard pull needed (towing force / (η · P(U)/BP) with the tug's curve;
    equal to the towing force without a tug), and the ``budget``."""

    towing_force: jnp.ndarray
    bollard_pull: jnp.ndarray
    budget: Budget


def required_pull(
    tow: TowResistance, sea: SeaState, *, speed=0.0, heading=0.0, tug: Tug | None = None
) -> PullRequirement:
    """Required towing force / bollard pull to hold the tow (``speed = 0``, the thesis's
    survival case, sea state 1) or to make ``speed`` [m/s] in ``sea``.

    With a ``tug`` its efficiency η, pull-curve shape and own resistance are used: the rated
    bollard pull BP with η BP P(U)/BP = R_tow(U) + R_tug(U). Differentiable in every input.
    A negative total (the environment pushes the tow ahead) is reported, not clipped."""
    NONNEGATIVE.check("speed", speed)
    _check_pull_inputs(sea, heading, tug)
    if tug is not None:
        if is_concrete(speed) and is_concrete(tug.free_speed):
            if np.any(np.asarray(speed) >= np.asarray(tug.free_speed)):
                raise ValueError(
                    f"parameter 'speed' must be below the tug's free speed "
                    f"{float(np.max(tug.free_speed)):g} m/s (where its pull vanishes), got "
                    f"{speed!r}"
                )
    if not holds_tracers((tow, sea, speed, heading, tug)):
        # everything checked above: one compiled program, no run-time check (a host
        # callback would keep it out of the persistent compilation cache)
        # (speed and heading as arrays: a Python number would be a static argument, one
        # compile per value)
        speed, heading = jnp.asarray(speed, float), jnp.asarray(heading, float)
        return _pull_program(tow, sea.unnamed(), speed, heading, tug)
    out = _pull(tow, sea, speed, heading, tug)
    checks = [NONNEGATIVE.traced("speed", speed), *_traced_pull_checks(sea, heading, tug)]
    if tug is not None:
        below = jnp.any(jnp.asarray(speed) >= tug.free_speed)
        checks.append((below, "parameter 'speed' must be below the tug's free speed"))
    return guard(out, checks)


def _check_pull_inputs(sea, heading, tug) -> None:
    """Eager: the heading, the sea state and the tug (its bollard pull) of a pull
    requirement, with a clear error naming a bad one (nothing is checked for traced
    values: `_traced_pull_checks`)."""
    FINITE.check("heading", heading)
    check_now(sea)
    if tug is not None:
        check_now(tug)
        POSITIVE.check("bollard_pull", tug.bollard_pull)


def _traced_pull_checks(sea, heading, tug) -> list:
    """The checks of `_check_pull_inputs` for a traced call (`guard`)."""
    return [FINITE.traced("heading", heading), *sea.checks()] + (
        tug.checks() if tug is not None else []
    )


def _pull(tow, sea, speed, heading, tug) -> PullRequirement:
    b = resistance(tow, sea, speed, heading=heading, tug=tug, throw=False)
    total = b.total
    bp = total if tug is None else total / (tug.efficiency * tug.shape(b.speed))
    return PullRequirement(towing_force=total, bollard_pull=bp, budget=b)


_pull_program = persistent(eqx.filter_jit(_pull))


def worst_bollard_pull(
    tow: TowResistance, sea: SeaState, tps, *, heading=0.0, tug: Tug | None = None
):
    """`required_pull`'s bollard pull at zero speed over the peak periods ``tps`` [s] (the
    sea state's own Tp replaced), as one compiled program where everything is concrete."""
    POSITIVE.check("tps", tps)
    _check_pull_inputs(sea, heading, tug)
    if holds_tracers((tow, sea, tps, heading, tug)):  # under a caller's jit or vmap
        checks = [POSITIVE.traced("tps", tps), *_traced_pull_checks(sea, heading, tug)]
        return guard(_pulls_over_tp(tow, sea, tps, heading, tug), checks)
    tps, heading = jnp.asarray(tps, float), jnp.asarray(heading, float)
    return _pulls_over_tp_program(tow, sea.unnamed(), tps, heading, tug)


def _pulls_over_tp(tow, sea, tps, heading, tug):
    tps = jnp.asarray(tps, float)

    def one(t):
        return _pull(tow, eqx.tree_at(lambda s: s.tp, sea, t), 0.0, heading, tug).bollard_pull

    return jax.vmap(one)(tps)


_pulls_over_tp_program = persistent(eqx.filter_jit(_pulls_over_tp))


def resistance_grid(
    tow: TowResistance, sea: SeaState, speeds, tps, *, heading=0.0, tug: Tug | None = None
) -> Budget:
    """`resistance` over a (speed, Tp) grid in one vmapped call: a `Budget` whose arrays
    lead with (n_speed, n_tp) (thesis figs 7.2-7.4). The grids are checked before the
    compiled call (under a caller's tracing, on its result)."""
    NONNEGATIVE.check("speeds", speeds)
    POSITIVE.check("tps", tps)
    out = _resistance_grid(tow, sea.unnamed(), speeds, tps, heading=heading, tug=tug)
    return guard(out, [NONNEGATIVE.traced("speeds", speeds), POSITIVE.traced("tps", tps)])


@persistent
@eqx.filter_jit
def _resistance_grid(tow, sea, speeds, tps, *, heading, tug):
    speeds, tps = jnp.asarray(speeds, float), jnp.asarray(tps, float)

    def one(s, t):
        return resistance(
            tow, eqx.tree_at(lambda x: x.tp, sea, t), s, heading=heading, tug=tug, throw=False
        )

    return jax.vmap(lambda s: jax.vmap(lambda t: one(s, t))(tps))(speeds)
