"""The rigid body of a floating hull for its wave-frequency motions, one home for the panel
method (`jaxtow.bem.rigid_body`) and strip theory (`jaxtow.strip.motions`): its loading
condition (`Loading`: the centre of gravity, the radii of gyration and the linear viscous
roll damping, with the documented estimates for what is not given, `jaxtow.ASSUMPTIONS`),
its mass matrix, its hydrostatic restoring, and the roll damping's one formula.

Heights are above the still waterline, z up (the axes of both the meshes and the strips); a
CoG given above the keel (the thesis's KG, Table B.3) converts with `Loading.above_keel`.
"""

from __future__ import annotations

import math

import jax.numpy as jnp
from jaxtyping import Array, Float

from ._rules import FINITE, POSITIVE, Checked, Rule, rule_field
from ._units import SEA_WATER, Water
from ._values import ASSUMPTIONS

__all__ = [
    "Loading",
    "ROLL_DAMPING_RULE",
    "radii_of_gyration",
    "roll_damping_coefficient",
    "mass_matrix",
    "hydrostatic_restoring",
]

#: A linear roll damping as a fraction of critical: 0 <= zeta < 1.
ROLL_DAMPING_RULE = Rule(
    "must lie in [0, 1) (a fraction of critical)",
    lambda xp, x: xp.isfinite(x) & (x >= 0) & (x < 1),
)
_RADII_RULE = Rule("must be three radii of gyration > 0", lambda xp, x: xp.isfinite(x) & (x > 0))


def radii_of_gyration(length, breadth) -> tuple:
    """(k_xx, k_yy, k_zz) [m] of a hull of ``length`` and ``breadth`` [m] from the documented
    estimate `ASSUMPTIONS['radii_of_gyration']` (Journée's fractions of B and L)."""
    fx, fy, fz = ASSUMPTIONS["radii_of_gyration"]["value"]
    return fx * breadth, fy * length, fz * length


def roll_damping_coefficient(fraction, restoring, inertia):
    """Dimensional linear roll damping B44 = 2 ζ √(C44 I44) [N m s] for ``fraction`` ζ of
    critical, the roll restoring C44 [N m] and the roll inertia I44 (mass and added) [kg m²];
    zero where the hull has no roll stability (C44 I44 ≤ 0: its roll is meaningless)."""
    crit = restoring * inertia
    return 2.0 * fraction * jnp.where(crit > 0, jnp.sqrt(jnp.where(crit > 0, crit, 1.0)), 0.0)


def _skew(r):
    x, y, z = r[0], r[1], r[2]
    zero = jnp.zeros_like(x)
    return jnp.stack([jnp.stack([zero, -z, y]), jnp.stack([z, zero, -x]), jnp.stack([-y, x, zero])])


def mass_matrix(mass, cog, radii):
    """The rigid-body mass matrix (6, 6) about the origin, over surge, sway, heave, roll,
    pitch, yaw: ``mass`` [kg] at ``cog`` (3,) [m], with the radii of gyration ``radii``
    (k_xx, k_yy, k_zz) [m] about axes through G parallel to the body axes:
    [[m I, −m [r]ₓ], [m [r]ₓ, I_G − m [r]ₓ[r]ₓ]]. Differentiable."""
    r = jnp.asarray(cog, float)
    k = jnp.asarray(radii, float)
    s = _skew(r)
    top = jnp.concatenate([mass * jnp.eye(3), -mass * s], axis=1)
    bottom = jnp.concatenate([mass * s, mass * jnp.diag(k**2) - mass * s @ s], axis=1)
    return jnp.concatenate([top, bottom], axis=0)


def hydrostatic_restoring(waterplane, volume, z_b, z_g, *, water: Water = SEA_WATER):
    """The hydrostatic restoring matrix (6, 6) of a free-floating hull about a reference
    point on the waterplane, over surge … yaw: ``waterplane`` = (A, S_x, S_y, I_xx, I_yy,
    I_xy), its area and moments ∬x, ∬y, ∬x², ∬y², ∬xy [m², m³, m⁴] about the reference
    point's vertical axis; ``volume`` ∇ [m³], the centre of buoyancy's and of gravity's
    heights ``z_b``, ``z_g`` above the waterline [m]. C33 = ρgA, C34 = ρgS_y,
    C35 = −ρgS_x, C44 = ρg(I_yy + ∇(z_B − z_G)), C55 = ρg(I_xx + ∇(z_B − z_G)),
    C45 = −ρgI_xy (Journée & Massie, Offshore Hydromechanics, ch. 2), in ``water``.
    Differentiable."""
    area, sx, sy, ixx, iyy, ixy = (jnp.asarray(w, float) for w in waterplane)
    rg = water.rho * water.g
    lever = volume * (z_b - z_g)
    c = jnp.zeros((6, 6))
    c = c.at[2, 2].set(rg * area)
    c = c.at[2, 3].set(rg * sy).at[3, 2].set(rg * sy)
    c = c.at[2, 4].set(-rg * sx).at[4, 2].set(-rg * sx)
    c = c.at[3, 3].set(rg * (iyy + lever))
    c = c.at[4, 4].set(rg * (ixx + lever))
    return c.at[3, 4].set(-rg * ixy).at[4, 3].set(-rg * ixy)


def _float(x):
    return jnp.asarray(x, dtype=float)


def _radii(x):
    return None if x is None else jnp.asarray(x, dtype=float)


class Loading(Checked):
    """The loading condition: ``z_g`` the centre of gravity's height above the waterline
    [m]; ``x_g`` its distance ahead of midships [m] (None: over the centre of buoyancy);
    ``radii`` (k_xx, k_yy, k_zz) about it [m] (None: `radii_of_gyration` of the hull, an
    estimate); ``roll_damping`` the linear viscous roll damping as a fraction of critical
    (default `ASSUMPTIONS['roll_damping']`, an estimate: potential flow alone leaves the
    roll resonance unbounded). Array fields: differentiable and vmappable.

    ``Loading()`` puts G in the waterline plane (strip theory's default, right for a hull of
    any size); ``Loading.estimate(draft)`` is the thesis's KG of Barge 1 and 2 (the panel
    side's default, `ASSUMPTIONS['cog_z']`); ``Loading.above_keel(kg, draft)`` converts a KG."""

    z_g: Float[Array, ""] = rule_field(rule=FINITE, converter=_float, default=0.0)
    x_g: Float[Array, ""] | None = rule_field(rule=FINITE, converter=_radii, default=None)
    radii: Float[Array, "3"] | None = rule_field(rule=_RADII_RULE, converter=_radii, default=None)
    roll_damping: Float[Array, ""] = rule_field(
        rule=ROLL_DAMPING_RULE,
        converter=_float,
        default=float(ASSUMPTIONS["roll_damping"]["value"]),
    )

    def __check_init__(self):
        super().__check_init__()
        if self.radii is not None and jnp.shape(self.radii) != (3,):
            raise ValueError(
                f"parameter 'radii' must be three radii of gyration (k_xx, k_yy, k_zz), got "
                f"shape {jnp.shape(self.radii)}"
            )

    @classmethod
    def above_keel(cls, kg: float, draft: float, **kw) -> Loading:
        """The loading with the CoG ``kg`` [m] above the keel of a hull of ``draft`` [m]."""
        for name, v in (("kg", kg), ("draft", draft)):
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
                raise ValueError(f"parameter {name!r} must be a finite number >= 0, got {v!r}")
        return cls(z_g=float(kg) - float(draft), **kw)

    @classmethod
    def estimate(cls, draft, **kw) -> Loading:
        """The documented estimate of a barge's loading at ``draft`` [m]: the CoG
        `ASSUMPTIONS['cog_z']` above the keel (thesis Table B.3, Barge 1 with deck cargo),
        the radii and roll damping of the other estimates; ``kw`` replaces any of them. A
        barge estimate: give the loading of any other hull (a ship model's KG is far lower)."""
        POSITIVE.check("draft", draft)
        return cls(z_g=float(ASSUMPTIONS["cog_z"]["value"]) - draft, **kw)

    def radii_for(self, length, breadth):
        """The radii of gyration (3,) [m]: the given ones, else the estimate for a hull of
        ``length`` and ``breadth``."""
        if self.radii is not None:
            return self.radii
        return jnp.stack([jnp.asarray(r, float) for r in radii_of_gyration(length, breadth)])

    @property
    def notes(self) -> dict:
        """Where each value came from (for a body's provenance)."""
        est = "estimate"
        return {
            "cog_z": f"{float(self.z_g):g} m above the waterline",
            "radii": ASSUMPTIONS["radii_of_gyration"]["note"] if self.radii is None else "given",
            "roll_damping": f"{float(self.roll_damping):g} of critical (linearised viscous roll "
            f"damping; {est} unless given)",
        }
