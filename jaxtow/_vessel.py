"""The towed vessel: mass, added mass and MMG slow-motion manoeuvring derivatives.

All quantities are non-dimensional in the Hong et al. convention (thesis Table 3.7, eqs
6.14-6.16; docs/model.md section 1): masses by ½ρTL², yaw inertia by ½ρTL⁴, forces by
½ρTLU², moments by ½ρTL²U², velocities by U_tug, yaw rate by U_tug/L.
"""

from __future__ import annotations

import equinox as eqx
import jax.numpy as jnp
from jaxtyping import Array, Float

from ._rules import FINITE, NONNEGATIVE, POSITIVE, Checked, rule_field

#: Field names of a `Vessel` that are physical parameters (in declaration order).
VESSEL_PARAMETERS = (
    "m",
    "Izz",
    "a11",
    "a22",
    "a66",
    "R0",
    "Xvv",
    "Xrr",
    "Yv",
    "Yr",
    "Yvvv",
    "Yrrr",
    "Nv",
    "Nr",
    "Nvvv",
)


class Vessel(Checked):
    """Manoeuvring model of the towed vessel (thesis eqs 6.1-6.3, MMG form of chapter 6).

    Fields (all non-dimensional, primes dropped):

    - ``m``, ``Izz``: mass and yaw moment of inertia about the CoG;
    - ``a11``, ``a22``, ``a66``: surge, sway and yaw added mass/inertia;
    - ``R0``: calm-water resistance coefficient, X = −R0·u|u|;
    - ``Xvv``, ``Xrr``: surge coupling derivatives;
    - ``Yv``, ``Yr``, ``Yvvv``, ``Yrrr``: sway derivatives;
    - ``Nv``, ``Nr``, ``Nvvv``: yaw derivatives.

    Static metadata: ``name``, and ``assumed``, a tuple of ``(field, note)`` pairs listing
    the values that are documented estimates rather than published data (carried into
    every dataset produced from the model).
    """

    m: Float[Array, ""] = rule_field(rule=POSITIVE)
    Izz: Float[Array, ""] = rule_field(rule=POSITIVE)
    a11: Float[Array, ""] = rule_field(rule=NONNEGATIVE)
    a22: Float[Array, ""] = rule_field(rule=NONNEGATIVE)
    a66: Float[Array, ""] = rule_field(rule=NONNEGATIVE)
    R0: Float[Array, ""] = rule_field(rule=POSITIVE)
    Xvv: Float[Array, ""] = rule_field(rule=FINITE)
    Xrr: Float[Array, ""] = rule_field(rule=FINITE)
    Yv: Float[Array, ""] = rule_field(rule=FINITE)
    Yr: Float[Array, ""] = rule_field(rule=FINITE)
    Yvvv: Float[Array, ""] = rule_field(rule=FINITE)
    Yrrr: Float[Array, ""] = rule_field(rule=FINITE)
    Nv: Float[Array, ""] = rule_field(rule=FINITE)
    Nr: Float[Array, ""] = rule_field(rule=FINITE)
    Nvvv: Float[Array, ""] = rule_field(rule=FINITE)
    name: str = eqx.field(static=True, default="vessel")
    assumed: tuple = eqx.field(static=True, default=())

    def inertia(self) -> Float[Array, "3"]:
        """Diagonal generalised inertia (m + a11, m + a22, Izz + a66) of eqs 6.1-6.3."""
        return jnp.stack([self.m + self.a11, self.m + self.a22, self.Izz + self.a66])

    def manoeuvring_forces(self, u, v, r) -> Float[Array, "3"]:
        """Hull forces (X_man, Y_man, N_man), docs/model.md section 2 (thesis eqs 6.1-6.3).

        Resistance is written −R0·u|u| so that it always opposes the surge velocity; with
        R0·u² an unphysical stern-first equilibrium branch would exist.
        """
        X = -self.R0 * u * jnp.abs(u) + self.Xvv * v**2 + self.Xrr * r**2
        Y = self.Yv * v + self.Yr * r + self.Yvvv * v**3 + self.Yrrr * r**3
        N = self.Nv * v + self.Nr * r + self.Nvvv * v**3
        return jnp.stack([X, Y, N])

    def stability_coefficient(self, xG: float = 0.0):
        """Straight-line (course) stability coefficient c (thesis Table 3.7).

        c = Y_v (N_r − m x_G) − N_v (Y_r − m); c > 0 means course stable. The CoG is the
        origin of the body axes in this model, so x_G = 0 by default.
        """
        return self.Yv * (self.Nr - self.m * xG) - self.Nv * (self.Yr - self.m)
