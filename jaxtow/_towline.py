"""Towline laws and the bow-hawser attachment point.

A towline carries no compression: the tension is exactly zero while the line is shorter
than its unstretched length (slack). The switch is exact (not smoothed), so a slack line is
never hidden inside a stability result; equilibria report whether the line is taut.
"""

from __future__ import annotations

import abc
from typing import TYPE_CHECKING

import equinox as eqx
import jax.numpy as jnp
from jaxtyping import Array, Float

from . import _rules as V

#: Documented range of the bow-hawser attachment point x_p' (distance of the attachment
#: point ahead of the CoG in ship lengths): from the CoG (0) to a bridle apex half a ship
#: length ahead of the bow of a vessel with its CoG amidships (1.0).
XP_RANGE = (0.0, 1.0)
#: Documented range of the transverse attachment offset y_p' (to port, in ship lengths):
#: a point on the hull of a barge with B/L up to 1 (|y_p'| <= 0.5), or a bridle apex offset
#: to one side by as much.
YP_RANGE = (-0.5, 0.5)


class AbstractTowline(V.Checked):
    """A towline of unstretched length ``l0`` attached at ``xp`` ahead of the CoG and ``yp``
    to port of the centreline (default 0: the centred bow hawser of the thesis).

    Subclasses define `tension` (T' as a function of the current length l') and its inverse
    `length_at_tension`, used to place equilibria (thesis eq. 6.13 generalised).
    """

    l0: eqx.AbstractVar[Float[Array, ""]]
    xp: eqx.AbstractVar[Float[Array, ""]]
    if TYPE_CHECKING:  # every towline has a transverse offset (a field of each subclass)
        yp: Float[Array, ""]

    @abc.abstractmethod
    def tension(self, l) -> Float[Array, ""]:
        """Towline tension T'(l') >= 0."""

    @abc.abstractmethod
    def length_at_tension(self, T) -> Float[Array, ""]:
        """Stretched length l' carrying tension T' > 0."""

    def rescaled(self, factor) -> AbstractTowline:
        """The same line with every non-dimensional force parameter multiplied by ``factor``
        (a change of the force scale ½ρTLU²: `jaxtow.at_tug_speed` passes (U_old/U_new)²).
        A towline law must implement it to be used at another tug speed."""
        raise NotImplementedError(
            f"{type(self).__name__} does not define 'rescaled', so the tug speed cannot be "
            "changed for it; implement rescaled(factor) (stiffness' times factor)"
        )


#: The rules of the attachment point (shared by every towline).
XP_RULE = V.in_range(*XP_RANGE)
YP_RULE = V.in_range(*YP_RANGE)


class Towline(AbstractTowline):
    """Linear elastic towline, thesis eq. 2.11: T' = EA' (l'/l0' − 1) when taut, else 0.

    ``l0``: unstretched length / L; ``xp``: attachment point ahead of the CoG / L;
    ``EA``: axial stiffness / (½ρTLU_tug²); ``yp``: transverse attachment offset to port / L
    (default 0; see `jaxtow.vector_field` (docs/model.md section 2) for the extra moment arm).
    """

    l0: Float[Array, ""] = V.rule_field(rule=V.POSITIVE)
    xp: Float[Array, ""] = V.rule_field(rule=XP_RULE)
    EA: Float[Array, ""] = V.rule_field(rule=V.POSITIVE)
    yp: Float[Array, ""] = V.rule_field(rule=YP_RULE, default=0.0)

    def tension(self, l):
        return self.EA * jnp.maximum(l / self.l0 - 1.0, 0.0)

    def length_at_tension(self, T):
        return self.l0 * (1.0 + T / self.EA)

    def rescaled(self, factor):
        return eqx.tree_at(lambda t: t.EA, self, self.EA * factor)


class PowerLawTowline(AbstractTowline):
    """Bernitsas & Kekridis synthetic-line law, thesis eq. 2.22: T' = Sb' (l'/l0' − 1)^q.

    Used for nylon and polyester lines (q > 1 stiffens with stretch). ``Sb``: stiffness
    scale / (½ρTLU_tug²); ``q``: exponent (> 0).
    """

    l0: Float[Array, ""] = V.rule_field(rule=V.POSITIVE)
    xp: Float[Array, ""] = V.rule_field(rule=XP_RULE)
    Sb: Float[Array, ""] = V.rule_field(rule=V.POSITIVE)
    q: Float[Array, ""] = V.rule_field(rule=V.POSITIVE)
    yp: Float[Array, ""] = V.rule_field(rule=YP_RULE, default=0.0)

    def tension(self, l):
        strain = l / self.l0 - 1.0
        taut = strain > 0.0
        safe = jnp.where(taut, strain, 1.0)  # keeps the gradient finite where slack
        return jnp.where(taut, self.Sb * safe**self.q, 0.0)

    def length_at_tension(self, T):
        Tpos = T > 0.0
        safe = jnp.where(Tpos, T, 1.0)
        return self.l0 * (1.0 + jnp.where(Tpos, (safe / self.Sb) ** (1.0 / self.q), 0.0))

    def rescaled(self, factor):
        return eqx.tree_at(lambda t: t.Sb, self, self.Sb * factor)


class Bridle(eqx.Module):
    """A two-leg bridle: legs from hull points ``legs`` = ((x1, y1), (x2, y2)) to the apex
    ``apex`` = (x_a, y_a) (body axes, by L, from the CoG; y to port), the towline from the apex.

    While both legs are taut the towline force acts at the apex, so the bridle is the
    equivalent attachment point (x_p', y_p') = apex of the equations of motion
    (`jaxtow.vector_field` (docs/model.md section 2)); `towline` builds that line. A leg goes slack when the towline
    direction leaves the cone of the legs: `leg_tensions` solves the apex balance
    t1 e1 + t2 e2 = −T' d (e_i unit vectors from the apex to the leg points, d the towline
    pull direction (cos a, −sin a), a = γ + ψ) and `taut` says whether both t_i > 0.
    """

    legs: Float[Array, "2 2"] = eqx.field(converter=lambda x: jnp.asarray(x, float))
    apex: Float[Array, "2"] = eqx.field(converter=lambda x: jnp.asarray(x, float))

    def __check_init__(self):
        if V.is_concrete(self.legs) and V.is_concrete(self.apex):
            import numpy as np

            legs, apex = np.asarray(self.legs), np.asarray(self.apex)
            if legs.shape != (2, 2) or apex.shape != (2,):
                raise ValueError(
                    "parameter 'legs' must be 2 points (2, 2) and 'apex' one point (2,)"
                )
            e = legs - apex
            if (
                np.min(np.hypot(e[:, 0], e[:, 1])) <= 0
                or abs(e[0, 0] * e[1, 1] - e[0, 1] * e[1, 0]) < 1e-12
            ):
                raise ValueError(
                    "parameter 'legs': the two legs must have length and not be parallel"
                )
            XP_RULE.check("apex x (xp)", apex[0])
            YP_RULE.check("apex y (yp)", apex[1])

    @classmethod
    def symmetric(cls, x_legs: float, half_spread: float, apex_x: float, apex_y: float = 0.0):
        """Legs from (x_legs, ±half_spread) to the apex (apex_x, apex_y)."""
        return cls(legs=[[x_legs, half_spread], [x_legs, -half_spread]], apex=[apex_x, apex_y])

    @property
    def leg_lengths(self):
        e = self.legs - self.apex
        return jnp.sqrt(jnp.sum(e**2, axis=-1))

    def towline(self, l0, EA) -> Towline:
        """The elastic towline from the apex (the equivalent attachment point)."""
        return Towline(l0=l0, xp=self.apex[0], yp=self.apex[1], EA=EA)

    def leg_tensions(self, tension, a):
        """Leg tensions (t1, t2) for towline tension T' pulling along a = γ + ψ (Cramer's rule)."""
        e = (self.legs - self.apex) / self.leg_lengths[:, None]
        b = -tension * jnp.stack([jnp.cos(a), -jnp.sin(a)])
        det = e[0, 0] * e[1, 1] - e[1, 0] * e[0, 1]
        t1 = (b[0] * e[1, 1] - e[1, 0] * b[1]) / det
        t2 = (e[0, 0] * b[1] - b[0] * e[0, 1]) / det
        return jnp.stack([t1, t2])

    def taut(self, tension, a):
        """True where both legs carry tension (the equivalent-point model holds)."""
        return jnp.all(self.leg_tensions(tension, a) > 0, axis=0)
