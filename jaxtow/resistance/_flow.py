"""Relative flow and OCIMF-form wind/current loads (thesis eqs 2.23-2.27)."""

from __future__ import annotations

import math

import equinox as eqx
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, ArrayLike, Float

from .._interp import HermiteAxis
from .._rules import POSITIVE, Checked, rule_field
from .._vessel import Vessel

RHO_AIR = 1.225  # kg/m³, ISO standard atmosphere at sea level


def _float(x):
    return jnp.asarray(x, dtype=float)


def _wrap(a):
    return jnp.arctan2(jnp.sin(a), jnp.cos(a))


def relative_flow(
    u: ArrayLike, v: ArrayLike, speed: ArrayLike, angle: ArrayLike
) -> tuple[Float[Array, ""], Float[Array, ""]]:
    """Apparent flow on a vessel with body velocity (u, v) [m/s] in a flow of ``speed`` [m/s]
    coming from ``angle`` [rad, from the bow, counter-clockwise]: returns (U_r², α_r), the
    squared relative speed and the relative angle it comes from (eqs 2.23, 2.24).

    U_r² rather than U_r keeps the loads smooth through zero relative flow; there α_r is set
    to 0 (the load is zero anyway) so that no NaN enters a gradient.
    """
    ax = jnp.asarray(speed * jnp.cos(angle) + u)
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
    axis: HermiteAxis  # the interpolation tables of the angle grid, built with the table
    label: str = eqx.field(static=True, default="")
    illustrative: bool = eqx.field(static=True, default=False)

    def __init__(self, angle, cx, cy, cn, *, label: str = "", illustrative: bool = False):
        a = np.asarray(angle, float)
        vals = np.stack([np.asarray(c, float) for c in (cx, cy, cn)])
        if a.ndim != 1 or a.size < 4 or np.any(np.diff(a) <= 0):
            raise ValueError("parameter 'angle' must be a 1-D ascending grid of >= 4 angles [rad]")
        if abs(a[0] + math.pi) > 1e-9 or abs(a[-1] - math.pi) > 1e-9:
            raise ValueError(
                "parameter 'angle' must cover the full circle from -pi to pi "
                "(use CoefficientTable.symmetric for a 0-180 deg table)"
            )
        if vals.shape != (3, a.size):
            raise ValueError(f"cx, cy, cn must each have the length of 'angle' ({a.size})")
        for name, c in zip(("cx", "cy", "cn"), vals):
            if not np.all(np.isfinite(c)):
                raise ValueError(f"parameter {name!r} must be finite")
            if abs(c[0] - c[-1]) > 1e-12 * max(1.0, np.max(np.abs(c))):
                raise ValueError(f"parameter {name!r} must have equal values at -pi and pi")
        self.angle, self.values = jnp.asarray(a), jnp.asarray(vals)
        # the grid's interval tables once, here: built inside every evaluation they were a
        # seventh of the operations of a sea-state force model's trace (and of its compile)
        self.axis = HermiteAxis(a, "periodic")
        self.label, self.illustrative = label, illustrative

    @classmethod
    def symmetric(cls, angle_deg, cx, cy, cn, *, label: str = "", illustrative: bool = False):
        """Table of a port-starboard symmetric vessel given from 0 to 180° (degrees):
        C_x(−α) = C_x(α), C_y and C_n odd (so they must vanish at 0 and 180°)."""
        a = np.radians(np.asarray(angle_deg, float))
        cx, cy, cn = (np.asarray(c, float) for c in (cx, cy, cn))
        if (
            a.ndim != 1
            or abs(a[0]) > 1e-12
            or abs(a[-1] - math.pi) > 1e-9
            or np.any(np.diff(a) <= 0)
        ):
            raise ValueError("parameter 'angle_deg' must ascend from 0 to 180 degrees")
        for name, c in (("cy", cy), ("cn", cn)):
            if abs(c[0]) > 1e-12 or abs(c[-1]) > 1e-12:
                raise ValueError(
                    f"parameter {name!r} must be 0 at 0 and 180 deg for a symmetric vessel"
                )
        full = np.concatenate([-a[:0:-1], a])
        return cls(
            full,
            np.concatenate([cx[:0:-1], cx]),
            np.concatenate([-cy[:0:-1], cy]),
            np.concatenate([-cn[:0:-1], cn]),
            label=label,
            illustrative=illustrative,
        )

    def __call__(self, alpha):
        return self.axis(self.values, _wrap(alpha))


class ManoeuvringCoefficients(Checked):
    """Current / calm-water coefficients from the vessel's slow-motion manoeuvring derivatives
    (the thesis's fig. 7.1b): a flow from α relative to the bow is the vessel moving through
    still water with (u', v', r') = (cos α, sin α, 0) on the scale U_r, so on the OCIMF areas
    B T, L T, L² T: C_x = (L/B) X'(α), C_y = Y'(α), C_n = N'(α), with X', Y', N' the MMG
    forces of `jaxtow.Vessel.manoeuvring_forces` (X' = −R0 cos α|cos α| + X_vv sin²α, ...).
    Head current: C_x = −R0 L/B (−0.218 for Barge 2a)."""

    vessel: Vessel
    length: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    breadth: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    label: str = eqx.field(static=True, default="manoeuvring derivatives")
    illustrative: bool = eqx.field(static=True, default=False)

    def __call__(self, alpha):
        X, Y, N = self.vessel.manoeuvring_forces(jnp.cos(alpha), jnp.sin(alpha), 0.0)
        return jnp.stack([X * self.length / self.breadth, Y, N])


class OCIMFLoad(Checked):
    """A flow load of OCIMF form (eqs 2.25-2.27): ``coefficients`` (a `CoefficientTable` or
    `ManoeuvringCoefficients`), fluid density ``rho`` [kg/m³], vessel ``length`` L and
    ``breadth`` B [m] and the ``height`` H [m] of the exposed area (above-water height for
    wind, draft for current). ``load(u, v, speed, angle)`` → (F_x, F_y, N) [N, N, N·m] in body
    axes for a flow of ``speed`` from ``angle`` (relative to the bow) on a vessel moving with
    body velocity (u, v)."""

    coefficients: CoefficientTable | ManoeuvringCoefficients
    rho: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    length: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    breadth: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    height: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)

    def __call__(
        self, u: ArrayLike, v: ArrayLike, speed: ArrayLike, angle: ArrayLike
    ) -> Float[Array, "3"]:
        U2, alpha = relative_flow(u, v, speed, angle)
        cx, cy, cn = self.coefficients(alpha)
        q = 0.5 * self.rho * U2 * self.height
        return jnp.stack([q * cx * self.breadth, q * cy * self.length, q * cn * self.length**2])
