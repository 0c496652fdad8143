"""Tow resistance and operating speed: wind, current/calm water, mean wave drift and the tug
(thesis sections 2 intro, 2.2, 7.1-7.2, appendix A; MODEL.md section 9).

The planning questions of an ocean tow (thesis fig. 2.1):

* **required towing force** — in a survival sea state the tug must hold the tow in place, so
  the required pull is the total resistance at zero speed (`required_pull`);
* **operating speed** — in a sailing sea state the tow sails where the tug's available pull
  equals the total resistance, both speed dependent (`operating_speed`), which gives the
  transit time of a route.

Conventions. SI units and radians. The tow sails along the global x axis at speed U ≥ 0 with
the barge at heading ψ (counter-clockwise, ψ = 0 straight ahead); body axes are x forward,
y to port, N counter-clockwise (as the QTF and the waterline methods). Wind, current and
waves are given by the direction they come *from*, counter-clockwise from the course
(0 = head wind / head current / head seas), so relative to the bow their angle is α − ψ.
The resistance of a component is minus the along-course component of its force,
R = −(Fx cos ψ − Fy sin ψ), so a force that holds the tow back is a positive resistance.

Relative flow (eqs 2.23, 2.24, with the barge's sway velocity added): a flow of speed W from
angle α meets a vessel with body velocity (u, v) as the apparent flow
(W cos α + u, W sin α + v); for v = 0 its speed is √(u² + W² + 2uW cos α) and its angle
atan2(W sin α, u + W cos α), exactly eqs 2.23-2.24. OCIMF form (eqs 2.25-2.27):
F_x = ½ C_x ρ U_r² B H, F_y = ½ C_y ρ U_r² L H, N = ½ C_n ρ U_r² L² H, with air density and
the above-water height H for wind (the text prints ρ_w; it is air), water density and the
draft T for current. The coefficients come from a table over the relative angle
(`CoefficientTable`, C¹ periodic cubic Hermite; the thesis fits cubic splines) or, for
current/calm water, from the vessel's manoeuvring derivatives (`ManoeuvringCoefficients`,
the thesis's fig. 7.1b).

Mean wave drift in irregular seas with forward speed (`WaveDrift`): 2∫S(ω)F(ω; u, v)dω
(eq. 2.29) of a waterline method of `jaxtow.drift` (default Kashiwagi: Fujii-Takahashi
diffraction, which vanishes in long waves, with Kashiwagi's speed factor) or of a panel QTF
with encounter frequency and wave-drift damping (`jaxtow.drift.irregular_sailing_drift`).
The waterline methods miss the motion-induced drift peak in the motion zone (issue 5:
relative MSE ≈ 1 there), so results that use them say so in ``assumed``.

Everything is a pure JAX function of pytrees: jit, vmap over grids of speed/Tp/Hs, and
grad with respect to every input. `operating_speed` brackets the first crossing of
pull − resistance on a speed grid and refines it with optimistix's bisection, whose implicit
adjoint gives exact derivatives dU/dθ = −(∂g/∂θ)/(∂g/∂U).
"""

from __future__ import annotations

import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import optimistix as optx

from . import _validate as V
from .dynamics import AbstractExternalForce
from .drift.methods import FROUDE_MAX, METHODS
from .drift.qtf import QTF, _hermite, _three_point_slopes
from .drift.sailing import irregular_sailing_drift
from .drift.waterline import Waterline
from .units import G, RHO_SEA, Scales, froude_number
from .waves.irregular import mean_drift
from .waves.spectra import jonswap

RHO_AIR = 1.225  # kg/m³, ISO standard atmosphere at sea level
COMPONENTS = ("current", "wind", "waves", "tug")

#: `OperatingPoint.status` codes.
STATUS = {0: "ok", 1: "cannot hold the tow at zero speed", 2: "no crossing below the tug's top speed",
          3: "Froude number at the operating speed >= 0.15"}

_f = dict(converter=lambda x: jnp.asarray(x, dtype=float))


def _wrap(a):
    return jnp.arctan2(jnp.sin(a), jnp.cos(a))


def relative_flow(u, v, speed, angle):
    """Apparent flow on a vessel with body velocity (u, v) [m/s] in a flow of ``speed`` [m/s]
    coming from ``angle`` [rad, from the bow, counter-clockwise]: returns (U_r², α_r), the
    squared relative speed and the relative angle it comes from (eqs 2.23, 2.24).

    U_r² rather than U_r keeps the loads smooth through zero relative flow; there α_r is set
    to 0 (the load is zero anyway) so that no NaN enters a gradient.
    """
    ax = speed * jnp.cos(angle) + u
    ay = speed * jnp.sin(angle) + v
    s2 = ax**2 + ay**2
    safe = s2 > 1e-300
    alpha = jnp.arctan2(jnp.where(safe, ay, 0.0), jnp.where(safe, ax, 1.0))
    return s2, alpha


class CoefficientTable(eqx.Module):
    """OCIMF-form load coefficients (C_x, C_y, C_n) against the relative angle α the flow comes
    from (0 = from ahead, counter-clockwise), tabulated over the full circle [−π, π] and
    interpolated by a C¹ periodic cubic Hermite curve (three-point node slopes; the thesis
    fits cubic splines). Build a port-starboard symmetric table with `CoefficientTable.symmetric`
    from 0…180°. ``table(alpha)`` → (3,); differentiable in α and in the table values.

    ``label`` says where the numbers come from; ``illustrative`` marks tables that are not
    measured data (results computed with them carry that label).
    """

    angle: jnp.ndarray
    values: jnp.ndarray  # (3, n)
    label: str = eqx.field(static=True, default="")
    illustrative: bool = eqx.field(static=True, default=False)

    def __init__(self, angle, cx, cy, cn, *, label: str = "", illustrative: bool = False):
        a = np.asarray(angle, float)
        vals = np.stack([np.asarray(c, float) for c in (cx, cy, cn)])
        if a.ndim != 1 or a.size < 4 or np.any(np.diff(a) <= 0):
            raise ValueError("parameter 'angle' must be a 1-D ascending grid of >= 4 angles [rad]")
        if abs(a[0] + math.pi) > 1e-9 or abs(a[-1] - math.pi) > 1e-9:
            raise ValueError("parameter 'angle' must cover the full circle from -pi to pi "
                             "(use CoefficientTable.symmetric for a 0-180 deg table)")
        if vals.shape != (3, a.size):
            raise ValueError(f"cx, cy, cn must each have the length of 'angle' ({a.size})")
        for name, c in zip(("cx", "cy", "cn"), vals):
            if not np.all(np.isfinite(c)):
                raise ValueError(f"parameter {name!r} must be finite")
            if abs(c[0] - c[-1]) > 1e-12 * max(1.0, np.max(np.abs(c))):
                raise ValueError(f"parameter {name!r} must have equal values at -pi and pi")
        self.angle, self.values = jnp.asarray(a), jnp.asarray(vals)
        self.label, self.illustrative = label, illustrative

    @classmethod
    def symmetric(cls, angle_deg, cx, cy, cn, *, label: str = "", illustrative: bool = False):
        """Table of a port-starboard symmetric vessel given from 0 to 180° (degrees):
        C_x(−α) = C_x(α), C_y and C_n odd (so they must vanish at 0 and 180°)."""
        a = np.radians(np.asarray(angle_deg, float))
        cx, cy, cn = (np.asarray(c, float) for c in (cx, cy, cn))
        if a.ndim != 1 or abs(a[0]) > 1e-12 or abs(a[-1] - math.pi) > 1e-9 or np.any(np.diff(a) <= 0):
            raise ValueError("parameter 'angle_deg' must ascend from 0 to 180 degrees")
        for name, c in (("cy", cy), ("cn", cn)):
            if abs(c[0]) > 1e-12 or abs(c[-1]) > 1e-12:
                raise ValueError(f"parameter {name!r} must be 0 at 0 and 180 deg for a symmetric vessel")
        full = np.concatenate([-a[:0:-1], a])
        return cls(full, np.concatenate([cx[:0:-1], cx]), np.concatenate([-cy[:0:-1], cy]),
                   np.concatenate([-cn[:0:-1], cn]), label=label, illustrative=illustrative)

    def __call__(self, alpha):
        m = _three_point_slopes(self.angle, self.values, periodic=True)
        return _hermite(self.angle, self.values, m, _wrap(alpha))


class ManoeuvringCoefficients(eqx.Module):
    """Current / calm-water coefficients from the vessel's slow-motion manoeuvring derivatives
    (the thesis's fig. 7.1b): a flow from α relative to the bow is the vessel moving through
    still water with (u', v', r') = (cos α, sin α, 0) on the scale U_r, so on the OCIMF areas
    B T, L T, L² T: C_x = (L/B) X'(α), C_y = Y'(α), C_n = N'(α), with X', Y', N' the MMG
    forces of `jaxtow.Vessel.manoeuvring_forces` (X' = −R0 cos α|cos α| + X_vv sin²α, ...).
    Head current: C_x = −R0 L/B (−0.218 for Barge 2a)."""

    vessel: eqx.Module
    length: jnp.ndarray = eqx.field(**_f)
    breadth: jnp.ndarray = eqx.field(**_f)
    label: str = eqx.field(static=True, default="manoeuvring derivatives")
    illustrative: bool = eqx.field(static=True, default=False)

    def __call__(self, alpha):
        X, Y, N = self.vessel.manoeuvring_forces(jnp.cos(alpha), jnp.sin(alpha), 0.0)
        return jnp.stack([X * self.length / self.breadth, Y, N])


class OCIMFLoad(eqx.Module):
    """A flow load of OCIMF form (eqs 2.25-2.27): ``coefficients`` (a `CoefficientTable` or
    `ManoeuvringCoefficients`), fluid density ``rho`` [kg/m³], vessel ``length`` L and
    ``breadth`` B [m] and the ``height`` H [m] of the exposed area (above-water height for
    wind, draft for current). ``load(u, v, speed, angle)`` → (F_x, F_y, N) [N, N, N·m] in body
    axes for a flow of ``speed`` from ``angle`` (relative to the bow) on a vessel moving with
    body velocity (u, v)."""

    coefficients: eqx.Module
    rho: jnp.ndarray = eqx.field(**_f)
    length: jnp.ndarray = eqx.field(**_f)
    breadth: jnp.ndarray = eqx.field(**_f)
    height: jnp.ndarray = eqx.field(**_f)

    def __check_init__(self):
        for n in ("rho", "length", "breadth", "height"):
            V.check_positive(n, getattr(self, n))

    def __call__(self, u, v, speed, angle):
        U2, alpha = relative_flow(u, v, speed, angle)
        cx, cy, cn = self.coefficients(alpha)
        q = 0.5 * self.rho * U2 * self.height
        return jnp.stack([q * cx * self.breadth, q * cy * self.length, q * cn * self.length**2])


class WaveDrift(eqx.Module):
    """Mean wave drift in a JONSWAP sea with forward speed, (F_x, F_y, N) [N, N, N·m].

    Either a waterline method of `jaxtow.drift.METHODS` (``method``, ``waterline``, its keyword
    ``options``) or a panel/WAMIT mean-drift ``qtf`` (then the encounter frequency and
    Aranha's wave-drift damping give the speed effect, eqs 2.35-2.41). ``omega`` is the
    integration grid [rad/s] (default 0.05-4 rad/s, 800 points)."""

    waterline: Waterline | None
    qtf: QTF | None
    omega: jnp.ndarray
    method: str = eqx.field(static=True, default="kashiwagi")
    options: tuple = eqx.field(static=True, default=())

    def __init__(self, waterline=None, *, method: str = "kashiwagi", qtf=None, omega=None, options=None):
        if (waterline is None) == (qtf is None):
            raise ValueError("WaveDrift needs exactly one of 'waterline' (with 'method') or 'qtf'")
        if qtf is None and method not in METHODS:
            raise ValueError(f"parameter 'method': unknown drift method {method!r}; choose from {sorted(METHODS)}")
        self.waterline, self.qtf = waterline, qtf
        self.method = "qtf" if qtf is not None else method
        self.omega = jnp.linspace(0.05, 4.0, 800) if omega is None else jnp.asarray(omega, float)
        self.options = tuple(sorted((options or {}).items()))

    def __call__(self, hs, tp, gamma, beta, u, v):
        S = jonswap(self.omega, hs=hs, tp=tp, gamma=gamma)
        if self.qtf is not None:
            return irregular_sailing_drift(self.qtf, self.omega, S, beta, u, v, 0.0)
        F = METHODS[self.method](self.waterline, self.omega, beta, u, v, **dict(self.options)).force
        return jax.vmap(lambda Fi: mean_drift(self.omega, S, Fi), in_axes=1)(F)


class SeaState(eqx.Module):
    """Environment of a tow: JONSWAP waves (``hs`` [m], ``tp`` [s], ``gamma``), wind
    (``wind_speed`` [m/s] at the reference height of the wind table), current
    (``current_speed`` [m/s]) and the directions they come from relative to the course
    (``wave_angle``, ``wind_angle``, ``current_angle`` [rad], 0 = from ahead). ``hs = 0`` is
    calm water. All fields are arrays: vmap and grad over any of them."""

    hs: jnp.ndarray = eqx.field(**_f)
    tp: jnp.ndarray = eqx.field(**_f)
    wind_speed: jnp.ndarray = eqx.field(**_f, default=0.0)
    current_speed: jnp.ndarray = eqx.field(**_f, default=0.0)
    gamma: jnp.ndarray = eqx.field(**_f, default=3.3)
    wave_angle: jnp.ndarray = eqx.field(**_f, default=0.0)
    wind_angle: jnp.ndarray = eqx.field(**_f, default=0.0)
    current_angle: jnp.ndarray = eqx.field(**_f, default=0.0)
    name: str = eqx.field(static=True, default="")

    def __check_init__(self):
        V.check_nonnegative("hs", self.hs)
        V.check_positive("tp", self.tp)
        V.check_nonnegative("wind_speed", self.wind_speed)
        V.check_nonnegative("current_speed", self.current_speed)
        if V.is_concrete(self.gamma) and not np.all(np.asarray(self.gamma) >= 1.0):
            raise ValueError(f"parameter 'gamma' must be >= 1, got {self.gamma!r}")
        for n in ("wave_angle", "wind_angle", "current_angle"):
            V.check_finite(n, getattr(self, n))

    def checks(self) -> list:
        return [V.check("hs", V.bad_negative(self.hs)), V.check("tp", V.bad_not_positive(self.tp)),
                V.check("wind_speed", V.bad_negative(self.wind_speed)),
                V.check("current_speed", V.bad_negative(self.current_speed))]


class Tug(eqx.Module):
    """The tug's available pull against speed.

    Quadratic pull curve (default): P(U) = BP (1 − (U/U_free)²) with the bollard pull
    ``bollard_pull`` [N] and the free-running speed ``free_speed`` [m/s] where the pull
    vanishes; or a table (`Tug.from_table`) of pulls [N] at speeds [m/s] from 0, interpolated
    by a C¹ cubic Hermite curve. The towing ``efficiency`` η (e.g. 0.75 offshore) scales
    the pull; the tug's own calm-water resistance ``resistance_coefficient`` c [N s²/m²]
    adds R_tug = c U² to the budget (0 when the pull curve is already net of it, as the
    thesis's fig. 2.1).
    """

    bollard_pull: jnp.ndarray = eqx.field(**_f)
    free_speed: jnp.ndarray = eqx.field(**_f)
    efficiency: jnp.ndarray = eqx.field(**_f, default=1.0)
    resistance_coefficient: jnp.ndarray = eqx.field(**_f, default=0.0)
    speeds: jnp.ndarray | None = None
    pulls: jnp.ndarray | None = None

    def __check_init__(self):
        V.check_positive("bollard_pull", self.bollard_pull)
        V.check_positive("free_speed", self.free_speed)
        V.check_range("efficiency", self.efficiency, 1e-12, 1.0)
        V.check_nonnegative("resistance_coefficient", self.resistance_coefficient)

    @classmethod
    def from_table(cls, speeds, pulls, *, efficiency=1.0, resistance_coefficient=0.0):
        """Pull curve from a table: ``speeds`` [m/s] ascending from 0, ``pulls`` [N] ≥ 0 with
        pulls[0] the bollard pull."""
        s, p = np.asarray(speeds, float), np.asarray(pulls, float)
        if s.ndim != 1 or s.size < 2 or s[0] != 0.0 or np.any(np.diff(s) <= 0):
            raise ValueError("parameter 'speeds' must ascend from 0 m/s (>= 2 points)")
        if p.shape != s.shape:
            raise ValueError("parameter 'pulls' must have the length of 'speeds'")
        if not np.all(np.isfinite(p)) or np.any(p < 0):
            raise ValueError(f"parameter 'pulls' must be >= 0 N (a tug pulls forward), got {p.tolist()}")
        return cls(bollard_pull=p[0], free_speed=s[-1], efficiency=efficiency,
                   resistance_coefficient=resistance_coefficient, speeds=jnp.asarray(s), pulls=jnp.asarray(p))

    def checks(self) -> list:
        out = [V.check("bollard_pull", V.bad_not_positive(self.bollard_pull)),
               V.check("free_speed", V.bad_not_positive(self.free_speed)),
               V.check("efficiency", V.bad_outside(self.efficiency, 1e-12, 1.0)),
               V.check("resistance_coefficient", V.bad_negative(self.resistance_coefficient))]
        if self.pulls is not None:
            out.append(V.check("pulls", V.bad_negative(self.pulls)))
        return out

    @property
    def max_speed(self):
        """Highest speed of the pull curve [m/s] (the free-running speed)."""
        return self.free_speed

    def shape(self, speed):
        """P(U)/BP."""
        if self.pulls is None:
            return 1.0 - (speed / self.free_speed) ** 2
        m = _three_point_slopes(self.speeds, self.pulls)
        return _hermite(self.speeds, self.pulls, m, speed) / self.bollard_pull

    def pull(self, speed):
        """Available pull η P(U) [N]."""
        return self.efficiency * self.bollard_pull * self.shape(speed)

    def resistance(self, speed):
        """The tug's own resistance c U|U| [N]."""
        return self.resistance_coefficient * speed * jnp.abs(speed)


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
        wind = zero if self.wind is None else self.wind(u, v, sea.wind_speed, sea.wind_angle - heading)
        waves = zero if self.waves is None else self.waves(sea.hs, sea.tp, sea.gamma, sea.wave_angle - heading, u, v)
        return jnp.stack([hull, wind, waves])


class Budget(eqx.Module):
    """Resistance budget at one speed: ``resistance`` (4,) [N] along the course for
    `COMPONENTS` = (current, wind, waves, tug), ``body`` (4, 3) body-axis loads, ``speed``
    [m/s], ``froude`` Fn = U/√(gL). ``total`` sums the components; ``shares`` gives each in
    % of the total."""

    resistance: jnp.ndarray
    body: jnp.ndarray
    speed: jnp.ndarray
    froude: jnp.ndarray

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


def resistance(tow: TowResistance, sea: SeaState, speed, *, heading=0.0, tug: Tug | None = None) -> Budget:
    """Resistance budget of the tow at speed U [m/s] along the course and heading ψ [rad]
    (thesis figs 7.2-7.4): along-course resistance of current/calm water, wind, waves and (if
    a ``tug`` is given) the tug's own resistance, R = −(F_x cos ψ − F_y sin ψ)."""
    speed, heading = jnp.asarray(speed, float), jnp.asarray(heading, float)
    body = tow.body_forces(sea, speed, heading)
    along = -(body[:, 0] * jnp.cos(heading) - body[:, 1] * jnp.sin(heading))
    r_tug = jnp.zeros(()) if tug is None else tug.resistance(speed)
    body = jnp.concatenate([body, jnp.stack([-r_tug, 0.0 * r_tug, 0.0 * r_tug])[None]])
    return Budget(resistance=jnp.concatenate([along, r_tug[None]]), body=body, speed=speed,
                  froude=froude_number(speed, tow.length))


class PullRequirement(eqx.Module):
    """`required_pull` result: ``towing_force`` [N] (the total resistance), ``bollard_pull``
    [N] the tug's rated bollard pull needed (towing force / (η · P(U)/BP) with the tug's curve;
    equal to the towing force without a tug), and the ``budget``."""

    towing_force: jnp.ndarray
    bollard_pull: jnp.ndarray
    budget: Budget


def required_pull(tow: TowResistance, sea: SeaState, *, speed=0.0, heading=0.0,
                  tug: Tug | None = None) -> PullRequirement:
    """Required towing force / bollard pull to hold the tow (``speed = 0``, the thesis's
    survival case, sea state 1) or to make ``speed`` [m/s] in ``sea``.

    With a ``tug`` its efficiency η, pull-curve shape and own resistance are used: the rated
    bollard pull BP with η BP P(U)/BP = R_tow(U) + R_tug(U). Differentiable in every input.
    A negative total (the environment pushes the tow ahead) is reported, not clipped."""
    if tug is not None:
        V.check_positive("bollard_pull", tug.bollard_pull)
    b = resistance(tow, sea, speed, heading=heading, tug=tug)
    total = b.total
    bp = total if tug is None else total / (tug.efficiency * tug.shape(b.speed))
    return PullRequirement(towing_force=total, bollard_pull=bp, budget=b)


class OperatingPoint(eqx.Module):
    """`operating_speed` result: ``speed`` [m/s] where available pull = total resistance,
    ``pull`` [N] there, the ``budget`` there, ``froude``, ``status`` (see `STATUS`; 0 = ok),
    and ``margin`` = pull − resistance at zero speed [N] (the holding margin)."""

    speed: jnp.ndarray
    pull: jnp.ndarray
    budget: Budget
    froude: jnp.ndarray
    status: jnp.ndarray
    margin: jnp.ndarray

    @property
    def valid(self):
        return self.status == 0

    def transit_time(self, route_length):
        """Time [s] to sail ``route_length`` [m] at the operating speed."""
        return jnp.asarray(route_length, float) / self.speed


def _excess(speed, args):
    tow, tug, sea, heading = args
    return tug.pull(speed) - resistance(tow, sea, speed, heading=heading, tug=tug).total


@eqx.filter_jit
def _operating_point(tow, tug, sea, heading, n_scan, rtol):
    args = (tow, tug, sea, heading)
    umax = tug.max_speed
    grid = jnp.linspace(0.0, 1.0, n_scan + 1) * jax.lax.stop_gradient(umax)
    g = jax.vmap(lambda s: _excess(s, args))(grid)
    below = g < 0.0
    i = jnp.clip(jnp.argmax(below), 1, n_scan)  # first grid speed with pull < resistance
    hold = g[0] >= 0.0
    crosses = jnp.any(below)
    lo, hi = jax.lax.stop_gradient(grid[i - 1]), jax.lax.stop_gradient(grid[i])
    ok_bracket = hold & crosses
    # a valid bracket for the solver in every case (the status says when it is not the answer)
    lo = jnp.where(ok_bracket, lo, 0.0)
    hi = jnp.where(ok_bracket, hi, jax.lax.stop_gradient(umax))
    fn = lambda s, a: jnp.where(ok_bracket, _excess(s, a), s - 0.5 * (lo + hi))
    sol = optx.root_find(fn, optx.Bisection(rtol=rtol, atol=rtol * jax.lax.stop_gradient(umax)),
                         0.5 * (lo + hi), args, options=dict(lower=lo, upper=hi), throw=False)
    speed = jnp.where(hold, jnp.where(crosses, sol.value, umax), 0.0)
    fn_op = froude_number(speed, tow.length)
    status = jnp.where(~hold, 1, jnp.where(~crosses, 2, jnp.where(fn_op >= FROUDE_MAX, 3, 0)))
    b = resistance(tow, sea, speed, heading=heading, tug=tug)
    return OperatingPoint(speed=speed, pull=tug.pull(speed), budget=b, froude=fn_op, status=status, margin=g[0])


def _status_message(p: OperatingPoint, tug: Tug, tow: TowResistance) -> str | None:
    s = int(p.status)
    if s == 0:
        return None
    if s == 1:
        need = float(p.pull) - float(p.margin)
        return (f"no intersection of the pull and resistance curves: at zero speed the available pull "
                f"{float(p.pull) / 1e3:.1f} kN is below the resistance {need / 1e3:.1f} kN, so the tug "
                f"cannot hold the tow in this sea state (raise 'bollard_pull' to at least "
                f"{need / float(tug.efficiency) / 1e3:.1f} kN or see required_pull)")
    if s == 2:
        return (f"no intersection of the pull and resistance curves below the tug's top speed "
                f"{float(tug.max_speed):.3g} m/s: the resistance stays below the pull (a following "
                f"environment?); check 'free_speed' and the sea state")
    umax = FROUDE_MAX * math.sqrt(G * float(tow.length))
    return (f"operating speed {float(p.speed):.3f} m/s gives Froude number Fn = {float(p.froude):.3f} >= "
            f"{FROUDE_MAX}: outside the validity of the slow-speed manoeuvring and wave-drift models "
            f"(U < {umax:.2f} m/s for L = {float(tow.length):g} m); pass check=False to get the "
            f"result flagged instead")


def operating_speed(tow: TowResistance, tug: Tug, sea: SeaState, *, heading=0.0, check: bool = True,
                    n_scan: int = 64, rtol: float = 1e-12) -> OperatingPoint:
    """Operating (transit) speed of the tow: the lowest speed U in [0, U_free] where the tug's
    available pull meets the total resistance, η P(U) = R_tow(U) + R_tug(U) (thesis fig. 2.1,
    section 7.2), found by scanning ``n_scan`` speeds for the first crossing and refining it
    by optimistix bisection to ``rtol``. Use ``.transit_time(route_length)`` for the transit
    time.

    Differentiable with respect to every input (implicit function theorem through the root).
    Outside validity — the tug cannot hold the tow at zero speed, no crossing below the tug's
    top speed, or Fn ≥ 0.15 at the operating speed — ``check=True`` raises an error that
    says which and by how much (an `eqx.error_if` under jit/grad); with ``check=False`` the
    result carries ``status`` (`STATUS`) for maps over many sea states.
    """
    if V.is_concrete(tug.bollard_pull):
        V.check_positive("bollard_pull", tug.bollard_pull)
    p = _operating_point(tow, tug, sea, jnp.asarray(heading, float), int(n_scan), float(rtol))
    if not check:
        return p
    if V.is_concrete(p.status):
        msg = _status_message(p, tug, tow)
        if msg is not None:
            raise ValueError(msg)
        return p
    checks = tug.checks() + sea.checks()
    checks += [(p.status == k, f"operating_speed: {STATUS[k]} (call with check=False to get the status)")
               for k in (1, 2, 3)]
    return V.guard(p, checks)


def barge2_wind_table() -> CoefficientTable:
    """The ILLUSTRATIVE Barge 2 wind table (`jaxtow.presets.BARGE2_WIND_TABLE`)."""
    from . import presets

    t = presets.BARGE2_WIND_TABLE
    return CoefficientTable.symmetric(t["angle_deg"], t["cx"], t["cy"], t["cn"],
                                      label="ILLUSTRATIVE Barge 2 wind table (jaxtow.presets.BARGE2_WIND_TABLE)",
                                      illustrative=True)


def barge2_resistance(version: str = "2a", *, method: str = "kashiwagi", wind_table: CoefficientTable | None = None,
                      wind_height: float | None = None, qtf: QTF | None = None, draft: float | None = None,
                      omega=None) -> TowResistance:
    """Barge 2 (thesis section 7.1-7.2): current/calm-water load from the manoeuvring
    derivatives of version ``2a`` or ``2b`` (fig. 7.1b), wind from ``wind_table`` (default
    the ILLUSTRATIVE table) on H = ``wind_height`` (default the ILLUSTRATIVE 10 m), mean
    wave drift from the Barge 2 waterline by ``method`` or from a panel ``qtf``. The
    returned ``assumed`` lists every estimate the numbers depend on."""
    from . import presets
    from .drift.waterline import barge2_waterline

    if version not in ("2a", "2b"):
        raise ValueError(f"parameter 'version' must be '2a' or '2b', got {version!r}")
    vessel = presets.VESSELS[f"barge_{version}"](draft)
    T = presets.ASSUMPTIONS["draft"]["value"] if draft is None else float(draft)
    L, B = presets.BARGE2_LENGTH, presets.BARGE2_BREADTH
    H = presets.ASSUMPTIONS["wind_height"]["value"] if wind_height is None else float(wind_height)
    table = barge2_wind_table() if wind_table is None else wind_table
    hull = OCIMFLoad(ManoeuvringCoefficients(vessel, L, B), RHO_SEA, L, B, T)
    wind = OCIMFLoad(table, RHO_AIR, L, B, H)
    waves = (WaveDrift(qtf=qtf, omega=omega) if qtf is not None
             else WaveDrift(barge2_waterline(draft), method=method, omega=omega))
    assumed = [("draft", f"T = {T} m: {presets.ASSUMPTIONS['draft']['note']}")]
    if table.illustrative:
        assumed.append(("wind_table", presets.ASSUMPTIONS["wind_table"]["note"]))
    if wind_height is None:
        assumed.append(("wind_height", presets.ASSUMPTIONS["wind_height"]["note"]))
    if qtf is None:
        assumed.append(("wave_drift", f"waterline method {method!r} on the estimated Barge 2 rake "
                                      f"({presets.ASSUMPTIONS['rake']['note']}); misses the motion-induced "
                                      "drift in the motion zone (L/lambda < 1)"))
    return TowResistance(hull=hull, wind=wind, waves=waves, name=f"barge_{version}", assumed=tuple(assumed))


def sea_state(name: str, **overrides) -> SeaState:
    """Thesis sea state ``'survival'`` (1: Hs = 5 m, U_wind = 20 m/s) or ``'sailing'`` (2:
    Hs = 2.4 m, U_wind = 10 m/s), `jaxtow.presets.SEA_STATES`, with any field overridden."""
    from . import presets

    if name not in presets.SEA_STATES:
        raise ValueError(f"parameter 'name': unknown sea state {name!r}; choose from {sorted(presets.SEA_STATES)}")
    return SeaState(**{**presets.SEA_STATES[name], **overrides}, name=name)


def illustrative_tug(**overrides) -> Tug:
    """The ILLUSTRATIVE 40 t tug of the examples (`jaxtow.presets.ILLUSTRATIVE_TUG`)."""
    from . import presets

    return Tug(**{**presets.ILLUSTRATIVE_TUG, **overrides})


@eqx.filter_jit
def resistance_grid(tow: TowResistance, sea: SeaState, speeds, tps, *, heading=0.0, tug: Tug | None = None) -> Budget:
    """`resistance` over a (speed, Tp) grid in one vmapped call: a `Budget` whose arrays
    lead with (n_speed, n_tp) (thesis figs 7.2-7.4)."""
    speeds, tps = jnp.asarray(speeds, float), jnp.asarray(tps, float)

    def one(s, t):
        return resistance(tow, eqx.tree_at(lambda x: x.tp, sea, t), s, heading=heading, tug=tug)

    return jax.vmap(lambda s: jax.vmap(lambda t: one(s, t))(tps))(speeds)


class WindForce(AbstractExternalForce):
    """Wind on the towed vessel as a tow-model force (`jaxtow.TowModel.external`; eqs
    2.23-2.27): the OCIMF ``load`` (e.g. ``barge2_resistance().wind``) at the relative wind of
    the barge's body velocity (u'U, v'U) in a wind of ``speed`` [m/s] from ``angle`` [rad]
    relative to the tug's course (0 = head wind), i.e. from ``angle − ψ`` relative to the
    bow; non-dimensional with ½ρTLU² (forces) and ½ρTL²U² (moment) of ``scales``. The yaw
    rate's effect on the apparent wind is neglected (quasi-steady loads)."""

    load: OCIMFLoad
    speed: jnp.ndarray = eqx.field(**_f)
    angle: jnp.ndarray = eqx.field(**_f, default=0.0)
    scales: Scales = eqx.field(static=True, default=None)

    def __check_init__(self):
        V.check_nonnegative("speed", self.speed)
        if self.scales is None:
            raise ValueError("parameter 'scales' is required (e.g. jaxtow.presets.barge2_scales())")

    def dimensional(self, y):
        U = self.scales.u_tug
        return self.load(y[0] * U, y[1] * U, self.speed, self.angle - y[5])

    def __call__(self, t, y, model):
        F = self.dimensional(y)
        return jnp.stack([F[0] / self.scales.force, F[1] / self.scales.force, F[2] / self.scales.moment])
