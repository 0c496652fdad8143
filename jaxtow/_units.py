"""Non-dimensionalisation of the tow model (thesis eqs 2.1, 6.14-6.16, Table 3.7).

Hong et al. convention (docs/model.md section 1): velocities by U_tug, yaw rate by U_tug/L,
lengths by L, time by L/U_tug, masses by ½ρTL², yaw inertia by ½ρTL⁴, forces by ½ρTLU²,
moments by ½ρTL²U². SI units and radians everywhere inside jaxtow; degrees, knots and
periods only at the user boundary (CLI, plots).
"""

from __future__ import annotations

import math

import equinox as eqx
import jax.numpy as jnp
from jaxtyping import Array, Float

from ._rules import POSITIVE, Checked, rule_field

G = 9.80665  # m/s², standard gravity
RHO_SEA = 1025.0  # kg/m³, sea-water density used throughout the thesis
#: One tonne-force [N] (1000 kg under standard gravity): bollard pulls and breaking loads
#: are quoted in t.
TONNE_FORCE = 1000.0 * G
#: One nautical mile [m].
NAUTICAL_MILE = 1852.0
#: One knot [m/s] (a nautical mile an hour).
KNOT = NAUTICAL_MILE / 3600.0


def _float(x):
    return jnp.asarray(x, dtype=float)


class Water(eqx.Module):
    """The water a hull floats in: density ``rho`` [kg/m³] and gravity ``g`` [m/s²] (static:
    the constants of a computation, one value passed whole instead of two numbers)."""

    rho: float = eqx.field(static=True, default=RHO_SEA)
    g: float = eqx.field(static=True, default=G)

    def __check_init__(self):
        for name in ("rho", "g"):
            val = getattr(self, name)
            if not (isinstance(val, (int, float)) and math.isfinite(val) and val > 0):
                raise ValueError(f"parameter {name!r} must be finite and > 0, got {val!r}")


#: Sea water (ρ = 1025 kg/m³) under standard gravity.
SEA_WATER = Water()


class Scales(Checked):
    """Reference scales of the tow model.

    length: L [m]; draft: T [m]; rho: water density [kg/m³] (static: they fix the model's
    structure); u_tug: U_tug [m/s], a traced value, so that the tug speed can be swept and
    differentiated (`jaxtow.at_tug_speed`).
    """

    length: float = eqx.field(static=True)
    draft: float = eqx.field(static=True)
    u_tug: Float[Array, ""] = rule_field(rule=POSITIVE, converter=_float)
    rho: float = eqx.field(static=True, default=RHO_SEA)

    def __check_init__(self):
        for name in ("length", "draft", "rho"):
            val = getattr(self, name)
            if not (isinstance(val, (int, float)) and math.isfinite(val) and val > 0):
                raise ValueError(f"parameter {name!r} must be finite and > 0, got {val!r}")

    @property
    def mass(self) -> float:
        """½ρTL² [kg]."""
        return 0.5 * self.rho * self.draft * self.length**2

    @property
    def inertia(self) -> float:
        """½ρTL⁴ [kg m²]."""
        return 0.5 * self.rho * self.draft * self.length**4

    @property
    def force(self) -> Float[Array, ""]:
        """½ρTLU² [N] (thesis eqs 6.14, 6.15)."""
        return 0.5 * self.rho * self.draft * self.length * self.u_tug**2

    @property
    def moment(self) -> Float[Array, ""]:
        """½ρTL²U² [N m] (thesis eq. 6.16)."""
        return self.force * self.length

    def nondimensional(self, load):
        """(X', Y', N') of a body-axis load (F_x [N], F_y [N], N_z [N m]): forces by ½ρTLU²,
        the moment by ½ρTL²U² (thesis eqs 6.14-6.16). Every dimensional force model of the
        tow goes through this one conversion."""
        return jnp.stack([load[0] / self.force, load[1] / self.force, load[2] / self.moment])

    @property
    def time(self) -> Float[Array, ""]:
        """L/U_tug [s]."""
        return self.length / self.u_tug

    @property
    def froude(self) -> Float[Array, ""]:
        """Froude number U_tug/sqrt(gL) (the wave-drift methods are valid for Fn < 0.15)."""
        return froude_number(self.u_tug, self.length)


def froude_number(u, length):
    """Fn = U / sqrt(g L)."""
    return u / (G * length) ** 0.5
