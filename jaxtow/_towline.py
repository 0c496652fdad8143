"""Towline laws and the bow-hawser attachment point.

A towline carries no compression: the tension is exactly zero while the line is shorter
than its unstretched length (slack). The switch is exact (not smoothed), so a slack line is
never hidden inside a stability result; equilibria report whether the line is taut.
"""

from __future__ import annotations

import abc
from typing import TYPE_CHECKING

import equinox as eqx
import jax
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


#: Bisection steps on log H of the catenary's tension solve (a bracket of 60 in log H,
#: halved 80 times: below the float64 resolution of H).
_CATENARY_BISECTIONS = 80
#: The bracket's width on log H below the elastic-line bound (e⁻⁶⁰ ≈ 1e-26).
_CATENARY_LOG_SPAN = 60.0


def _asinhc(a):
    """asinh(a)/a, exact at a = 0 (the weightless limit) and smooth for a ≥ 0."""
    small = a < 1e-4
    safe = jnp.where(small, 1.0, a)
    return jnp.where(small, 1.0 - a**2 / 6.0 + 3.0 * a**4 / 40.0, jnp.arcsinh(safe) / safe)


def catenary_span(H, l0, EA, w):
    """Horizontal span X of an elastic catenary (Irvine 1981, eq. 2.15 with both ends at the
    same height): X = l0 (H/EA + asinh(a)/a), a = w l0 / (2H), for horizontal tension H > 0,
    unstretched length l0, axial stiffness EA and weight per unit length w (any consistent
    units; jaxtow's non-dimensional ones in `CatenaryTowline`)."""
    a = w * l0 / (2.0 * H)
    return l0 * (H / EA + _asinhc(a))


@jax.custom_jvp
def _catenary_tension(l, l0, EA, w):
    """H with `catenary_span`(H) = l (0 where l ≤ 0): bisection on log H, then Newton; its
    derivatives come from the implicit function theorem (the custom JVP)."""
    hi = jnp.log(EA * jnp.maximum(l, l0) / l0 + w * l0)  # X(hi) ≥ l: X ≥ H l0 / EA
    lo = hi - _CATENARY_LOG_SPAN

    def step(_, bracket):
        a, b = bracket
        m = 0.5 * (a + b)
        long = catenary_span(jnp.exp(m), l0, EA, w) > l
        return jnp.where(long, a, m), jnp.where(long, m, b)

    a, b = jax.lax.fori_loop(0, _CATENARY_BISECTIONS, step, (lo, hi))
    # no root below the bracket: a weightless line shorter than l0 is slack
    taut = (l > 0) & (catenary_span(jnp.exp(lo), l0, EA, w) < l)
    return jnp.where(taut, jnp.exp(0.5 * (a + b)), 0.0)


@_catenary_tension.defjvp
def _catenary_tension_jvp(primals, tangents):
    l, l0, EA, w = primals
    H = _catenary_tension(l, l0, EA, w)
    safe = jnp.where(H > 0, H, 1.0)
    # X(H, l0, EA, w) = l  =>  X_H dH = dl − X_l0 dl0 − X_EA dEA − X_w dw
    dl, dl0, dEA, dw = tangents
    _, X_H = jax.jvp(lambda h: catenary_span(h, l0, EA, w), (safe,), (jnp.ones_like(safe),))
    _, X_p = jax.jvp(lambda a, b, c: catenary_span(safe, a, b, c), (l0, EA, w), (dl0, dEA, dw))
    dH = jnp.where(H > 0, (dl - X_p) / X_H, 0.0)
    return H, dH


class CatenaryTowline(AbstractTowline):
    """A towline with weight: the elastic catenary (Irvine, *Cable Structures*, 1981, ch. 2)
    between the hawser and the tug's towing point, both at the same height.

    The tow model's towline force is the horizontal tension H', a function of the horizontal
    span l' (the model's towline length): l' = l0' (H'/EA' + asinh(a)/a), a = w' l0'/(2H')
    (`catenary_span`). A line with weight always pulls (H' > 0 for every span > 0) and is
    never slack: its sag, not its stretch, carries a short span. As w' → 0 it is the elastic
    line `Towline` (for l' > l0'); as EA' → ∞ the classic catenary.

    ``l0``, ``xp``, ``yp``: as `Towline`; ``EA``: axial stiffness / (½ρTLU_tug²); ``w``:
    submerged weight per unit length × L / (½ρTLU_tug²) (build from SI values with
    `from_si`). The end tension, the sag and the lowest point are `end_tension`, `sag`,
    `seabed_clearance`; `stiffness` the effective dH'/dl'.
    """

    l0: Float[Array, ""] = V.rule_field(rule=V.POSITIVE)
    xp: Float[Array, ""] = V.rule_field(rule=XP_RULE)
    EA: Float[Array, ""] = V.rule_field(rule=V.POSITIVE)
    w: Float[Array, ""] = V.rule_field(rule=V.NONNEGATIVE)
    yp: Float[Array, ""] = V.rule_field(rule=YP_RULE, default=0.0)

    @classmethod
    def from_si(cls, length, weight, EA, *, scales, xp, yp=0.0):
        """From a line of ``length`` [m], submerged weight ``weight`` [N/m] and axial
        stiffness ``EA`` [N], on the tow of ``scales`` (`jaxtow.Scales`); ``xp``, ``yp`` by L."""
        F, L = scales.force, scales.length
        return cls(l0=length / L, xp=xp, EA=EA / F, w=weight * L / F, yp=yp)

    def tension(self, l):
        return _catenary_tension(jnp.asarray(l, float), self.l0, self.EA, self.w)

    def length_at_tension(self, T):
        return catenary_span(T, self.l0, self.EA, self.w)

    def rescaled(self, factor):
        return eqx.tree_at(lambda t: (t.EA, t.w), self, (self.EA * factor, self.w * factor))

    def stiffness(self, l):
        """Effective stiffness dH'/dl' at span l' (autodiff of the implicit solve)."""
        return jax.grad(self.tension)(jnp.asarray(l, float))

    def end_tension(self, l):
        """Tension at either end, √(H'² + (w' l0'/2)²) (the hawser and the tug carry half
        the weight each)."""
        H = self.tension(l)
        return jnp.sqrt(H**2 + (0.5 * self.w * self.l0) ** 2)

    def sag(self, l):
        """Depth of the lowest point (mid-span) below the ends, by L:
        w' l0'²/(8 EA') + (H'/w')(√(1 + a²) − 1), a = w' l0'/(2H')."""
        H = self.tension(l)
        a = self.w * self.l0 / (2.0 * H)
        # (H/w)(√(1+a²) − 1) = (l0/2) a / (√(1+a²) + 1): finite as w → 0
        return self.w * self.l0**2 / (8.0 * self.EA) + 0.5 * self.l0 * a / (
            jnp.sqrt(1.0 + a**2) + 1.0
        )

    def seabed_clearance(self, l, water_depth, end_depth=0.0):
        """(clearance, ok): water depth less the lowest point's depth (the ends
        ``end_depth`` below the surface, plus the sag), by L; ok where it is positive."""
        c = water_depth - end_depth - self.sag(l)
        return c, c > 0
