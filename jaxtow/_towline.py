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
import numpy as np
from jaxtyping import Array, Float

from ._roots import bisect_fixed
from ._rules import NONNEGATIVE, POSITIVE, Checked, in_range, is_concrete, rule_field

#: Documented range of the bow-hawser attachment point x_p' (distance of the attachment
#: point ahead of the CoG in ship lengths): from the CoG (0) to a bridle apex half a ship
#: length ahead of the bow of a vessel with its CoG amidships (1.0).
XP_RANGE = (0.0, 1.0)
#: Documented range of the transverse attachment offset y_p' (to port, in ship lengths):
#: a point on the hull of a barge with B/L up to 1 (|y_p'| <= 0.5), or a bridle apex offset
#: to one side by as much.
YP_RANGE = (-0.5, 0.5)


class AbstractTowline(Checked):
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
XP_RULE = in_range(*XP_RANGE)
YP_RULE = in_range(*YP_RANGE)


class Towline(AbstractTowline):
    """Linear elastic towline, thesis eq. 2.11: T' = EA' (l'/l0' − 1) when taut, else 0.

    ``l0``: unstretched length / L; ``xp``: attachment point ahead of the CoG / L;
    ``EA``: axial stiffness / (½ρTLU_tug²); ``yp``: transverse attachment offset to port / L
    (default 0; see `jaxtow.vector_field` (docs/model.md section 2) for the extra moment arm).
    """

    l0: Float[Array, ""] = rule_field(rule=POSITIVE)
    xp: Float[Array, ""] = rule_field(rule=XP_RULE)
    EA: Float[Array, ""] = rule_field(rule=POSITIVE)
    yp: Float[Array, ""] = rule_field(rule=YP_RULE, default=0.0)

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

    l0: Float[Array, ""] = rule_field(rule=POSITIVE)
    xp: Float[Array, ""] = rule_field(rule=XP_RULE)
    Sb: Float[Array, ""] = rule_field(rule=POSITIVE)
    q: Float[Array, ""] = rule_field(rule=POSITIVE)
    yp: Float[Array, ""] = rule_field(rule=YP_RULE, default=0.0)

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
        if is_concrete(self.legs) and is_concrete(self.apex):
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

    a, b = bisect_fixed(
        lambda m: catenary_span(jnp.exp(m), l0, EA, w) > l, lo, hi, _CATENARY_BISECTIONS
    )
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

    l0: Float[Array, ""] = rule_field(rule=POSITIVE)
    xp: Float[Array, ""] = rule_field(rule=XP_RULE)
    EA: Float[Array, ""] = rule_field(rule=POSITIVE)
    w: Float[Array, ""] = rule_field(rule=NONNEGATIVE)
    yp: Float[Array, ""] = rule_field(rule=YP_RULE, default=0.0)

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


# ------------------------------------------------------------------ composite lines in series


def _dasinh(a, d):
    """(asinh(a) − asinh(a − d)) / d for d ≥ 0, exact as d → 0 (the midpoint rule there,
    error O(d²), below 1e-12 where it is used)."""
    small = d < 1e-5
    safe = jnp.where(small, 1.0, d)
    mid = a - 0.5 * d
    return jnp.where(
        small, 1.0 / jnp.sqrt(1.0 + mid**2), (jnp.arcsinh(a) - jnp.arcsinh(a - safe)) / safe
    )


def composite_geometry(H, V0, lengths, EA, w):
    """Span and height of each segment of an elastic catenary in series (Irvine 1981, eq.
    2.15 per segment), walking from the hawser to the tug: horizontal tension ``H`` > 0,
    vertical tension ``V0`` at the hawser (the weight it carries), segments of unstretched
    ``lengths``, axial stiffness ``EA`` and submerged weight per unit length ``w`` ≥ 0.

    Returns (dx, dz, V_start, V_end) per segment; dz is the rise (negative: the line goes
    down while V > 0). A weightless segment is a straight elastic line."""
    W = w * lengths
    V_end = V0 - jnp.cumsum(W)
    V_start = V_end + W
    T_s = jnp.sqrt(H**2 + V_start**2)
    T_e = jnp.sqrt(H**2 + V_end**2)
    dx = H * lengths / EA + lengths * _dasinh(V_start / H, W / H)
    # (T_s − T_e)/w written as (V_s + V_e) L / (T_s + T_e): finite as w → 0
    dz = -((V_start + V_end) * lengths / (2.0 * EA) + (V_start + V_end) * lengths / (T_s + T_e))
    return dx, dz, V_start, V_end


def _bracketed_newton(fg, a, b, x0, maxiter=200):
    """The root of an increasing ``fg(x) = (f, f')`` in [a, b] (f(a) ≤ 0 ≤ f(b)): Newton's
    steps, a bisection wherever a step would leave the shrinking bracket (so it converges
    like bisection at worst and quadratically near the root); stops at a step below 1e-14
    relative."""

    def cond(c):
        x, a, b, dx, k = c
        return (jnp.abs(dx) > 1e-14 * (1.0 + jnp.abs(x))) & (k < maxiter)

    def body(c):
        x, a, b, _, k = c
        f, d = fg(x)
        a = jnp.where(f < 0, x, a)
        b = jnp.where(f > 0, x, b)
        xn = x - f / jnp.where(d > 0, d, 1.0)
        xn = jnp.where((d > 0) & (xn > a) & (xn < b), xn, 0.5 * (a + b))
        xn = jnp.where(f == 0, x, xn)
        return xn, a, b, xn - x, k + 1

    return jax.lax.while_loop(cond, body, (x0, a, b, b - a, 0))[0]


def _hawser_share(H, lengths, EA, w):
    """V0 ∈ [0, total weight] with both ends at the same height at horizontal tension H."""
    Wt = jnp.sum(w * lengths)

    def fg(V0):
        z, dz = jax.jvp(
            lambda v: jnp.sum(composite_geometry(H, v, lengths, EA, w)[1]), (V0,), (1.0,)
        )
        return -z, -dz

    return _bracketed_newton(fg, jnp.zeros_like(Wt), Wt, 0.5 * Wt)


def _composite_solve(l, lengths, EA, w):
    """(H, V0) of the composite line with span ``l`` and both ends at the same height:
    bracketed Newton on log H (the span grows with H) around a bracketed Newton on V0 ∈
    [0, total weight] (the height difference falls as the hawser carries more); the span's
    derivative in log H eliminates V0 by the implicit function theorem. (0, 0) where slack."""
    Wt = jnp.sum(w * lengths)
    l0 = jnp.sum(lengths)

    def residual(H, V0):
        dx, dz, _, _ = composite_geometry(H, V0, lengths, EA, w)
        return jnp.stack([jnp.sum(dx), jnp.sum(dz)])

    def span_and_slope(x):
        H = jnp.exp(x)
        V0 = _hawser_share(H, lengths, EA, w)
        r = residual(H, V0)
        JH, JV = jax.jacfwd(residual, argnums=(0, 1))(H, V0)
        # dX/dH along Z = 0: X_H − X_V Z_H / Z_V (Z_V > 0 unless the line is weightless)
        ZV = jnp.where(JV[1] != 0, JV[1], 1.0)
        dX = JH[0] - jnp.where(JV[1] != 0, JV[0] * JH[1] / ZV, 0.0)
        return r[0] - l, H * dX

    hi = jnp.log(jnp.maximum(l, l0) / jnp.sum(lengths / EA) + Wt)
    lo = hi - _CATENARY_LOG_SPAN
    taut = (l > 0) & (span_and_slope(lo)[0] < 0)
    x = _bracketed_newton(span_and_slope, lo, hi, hi - 0.5 * _CATENARY_LOG_SPAN)
    H = jnp.where(taut, jnp.exp(x), 0.0)
    V0 = jnp.where(taut, _hawser_share(jnp.where(taut, H, 1.0), lengths, EA, w), 0.0)
    return H, V0


@jax.custom_jvp
def _composite_tension(l, lengths, EA, w):
    return _composite_solve(l, lengths, EA, w)


@_composite_tension.defjvp
def _composite_tension_jvp(primals, tangents):
    l, lengths, EA, w = primals
    H, V0 = _composite_tension(l, lengths, EA, w)
    taut = H > 0
    Hs = jnp.where(taut, H, 1.0)

    def residual(H, V0, lengths, EA, w):
        dx, dz, _, _ = composite_geometry(H, V0, lengths, EA, w)
        return jnp.stack([jnp.sum(dx), jnp.sum(dz)])

    # F(H, V0; θ) = (X − l, Z) = 0  =>  J d(H, V0) = (dl, 0) − F_θ dθ
    J = jax.jacfwd(residual, argnums=(0, 1))(Hs, V0, lengths, EA, w)
    J = jnp.stack(J, axis=-1)
    dl, dlen, dEA, dw = tangents
    _, F_p = jax.jvp(lambda a, b, c: residual(Hs, V0, a, b, c), (lengths, EA, w), (dlen, dEA, dw))
    rhs = jnp.stack([dl, jnp.zeros_like(dl)]) - F_p
    d = jnp.linalg.solve(jnp.where(taut, J, jnp.eye(2)), rhs)
    return (H, V0), (jnp.where(taut, d[0], 0.0), jnp.where(taut, d[1], 0.0))


class CompositeTowline(AbstractTowline):
    """Segments of different lines in series (e.g. a steel wire with a chain pennant at the
    hawser, or with a nylon stretcher): each an elastic catenary (Irvine 1981) with its own
    stiffness and weight, both ends at the same height, solved for the horizontal tension
    H' and the weight the hawser carries (`composite_geometry`). With no weight it is the
    elastic line of the series stiffness l0'/Σ(l0_i'/EA_i'); with one segment it is
    `CatenaryTowline` (which keeps its one-dimensional solve, many times cheaper).

    ``l0``: total unstretched length (by L); ``share``: each segment's fraction of it, from
    the hawser to the tug (a sweep of l0 scales every segment); ``EA``, ``w``: per segment,
    on the scales of `CatenaryTowline`. Build from SI with `from_si` or from the catalogue
    (`jaxtow.lines`).
    """

    l0: Float[Array, ""] = rule_field(rule=POSITIVE)
    xp: Float[Array, ""] = rule_field(rule=XP_RULE)
    share: Float[Array, " n"] = rule_field(rule=POSITIVE)
    EA: Float[Array, " n"] = rule_field(rule=POSITIVE)
    w: Float[Array, " n"] = rule_field(rule=NONNEGATIVE)
    yp: Float[Array, ""] = rule_field(rule=YP_RULE, default=0.0)

    def __check_init__(self):
        shapes = {jnp.shape(self.share)[-1:], jnp.shape(self.EA)[-1:], jnp.shape(self.w)[-1:]}
        if len(shapes) != 1 or jnp.ndim(self.share) == 0:
            raise ValueError(
                "share, EA and w must be arrays of one length (one entry per segment), "
                f"got shapes {jnp.shape(self.share)}, {jnp.shape(self.EA)}, {jnp.shape(self.w)}"
            )
        total = jnp.sum(self.share, axis=-1)
        try:
            ok = bool(jnp.all(jnp.abs(total - 1.0) < 1e-9))
        except (jax.errors.ConcretizationTypeError, jax.errors.TracerBoolConversionError):
            ok = True  # traced (under jit or vmap): checked where it was built
        if not ok:
            raise ValueError(f"share must sum to 1 (the segments' fractions of l0), got {total}")

    @classmethod
    def from_si(cls, lengths, weights, EAs, *, scales, xp, yp=0.0):
        """From segment ``lengths`` [m], submerged ``weights`` [N/m] and ``EAs`` [N], from
        the hawser to the tug, on the tow of ``scales``; ``xp``, ``yp`` by L."""
        F, L = scales.force, scales.length
        lengths = jnp.asarray(lengths, float)
        total = jnp.sum(lengths)
        return cls(
            l0=total / L,
            xp=xp,
            share=lengths / total,
            EA=jnp.asarray(EAs, float) / F,
            w=jnp.asarray(weights, float) * L / F,
            yp=yp,
        )

    @property
    def series_EA(self):
        """The series stiffness l0'/Σ(l0_i'/EA_i') (the elastic line's EA' of the same
        stretch)."""
        return self.l0 / jnp.sum(self.lengths / self.EA, axis=-1)

    @property
    def lengths(self):
        """Unstretched segment lengths l0_i' (by L)."""
        return self.l0 * self.share

    def _solve(self, l):
        return _composite_tension(jnp.asarray(l, float), self.lengths, self.EA, self.w)

    def tension(self, l):
        return self._solve(l)[0]

    def length_at_tension(self, T):
        T = jnp.asarray(T, float)
        V0 = _hawser_share(T, self.lengths, self.EA, self.w)
        return jnp.sum(composite_geometry(T, V0, self.lengths, self.EA, self.w)[0])

    def rescaled(self, factor):
        return eqx.tree_at(lambda t: (t.EA, t.w), self, (self.EA * factor, self.w * factor))

    def stiffness(self, l):
        """Effective stiffness dH'/dl' at span l' (autodiff of the implicit solve)."""
        return jax.grad(self.tension)(jnp.asarray(l, float))

    def end_tensions(self, l):
        """(hawser, tug) tensions √(H'² + V'²) at the two ends."""
        H, V0 = self._solve(l)
        Wt = jnp.sum(self.w * self.lengths)
        return jnp.sqrt(H**2 + V0**2), jnp.sqrt(H**2 + (V0 - Wt) ** 2)

    def end_tension(self, l):
        """The larger of the two end tensions."""
        return jnp.maximum(*self.end_tensions(l))

    def sag(self, l):
        """Depth of the lowest point below the ends, by L (where the vertical tension
        changes sign, inside the segment that carries it)."""
        H, V0 = self._solve(l)
        Hs = jnp.where(H > 0, H, 1.0)
        dx, dz, Vs, Ve = composite_geometry(Hs, V0, self.lengths, self.EA, self.w)
        z_start = jnp.cumsum(dz) - dz
        # within a segment with Vs ≥ 0 ≥ Ve: the part of length Vs/w down to V = 0
        inside = (Vs >= 0) & (Ve <= 0) & (self.w > 0)
        part = jnp.where(inside, Vs / jnp.where(self.w > 0, self.w, 1.0), 0.0)
        _, dz_part, _, _ = composite_geometry(Hs, Vs, part, self.EA, self.w)
        z_low = jnp.min(jnp.concatenate([z_start, (z_start + dz_part)[None, ...].ravel()]))
        return jnp.where(H > 0, -z_low, 0.0)

    def seabed_clearance(self, l, water_depth, end_depth=0.0):
        """(clearance, ok) as `CatenaryTowline.seabed_clearance`."""
        c = water_depth - end_depth - self.sag(l)
        return c, c > 0
