"""Short-wave and empirical mean wave-drift methods from the waterline (thesis sections 2.3-2.5,
eqs 2.31-2.34, 2.50-2.65, C.1; docs/model.md section 7).

Every method is a pure function ``method(wl, omega, beta, u=0.0, v=0.0, ...)`` of a
`Waterline`, the wave frequency ω [rad/s], the wave heading β [rad] (β = 0 head seas, the
direction the waves come from, counter-clockwise from the bow; waves travel along
k̂ = (−cos β, −sin β)) and the vessel's surge/sway speed u, v [m/s]. It returns a
`DriftEstimate`: (Fx, Fy, Nz) per unit ζa² in N/m² and N·m/m² about the waterline origin
(midships), plus the validity flags of the method. Unpack it as ``Fx, Fy, Nz = ...``. The
functions use jax.numpy only: jit, vmap (over ω, β, u, v) and grad (also with respect to the
waterline coordinates) all work.

The wall-reflection kernel shared by the Faltinsen family: a straight segment with inward
normal n, lit by waves with k̂·n = c > 0, carries the mean force per unit length

    ½ ρ g ζa² [ c² − (ω/g) c (f_u u n_x + f_v v n_y) ] n,

which is Faltinsen's sin²(θ+β) n (eq. 2.31; c = −sin(θ+β) with n = (sin θ, cos θ)) plus
the forward-speed term of eq. 2.58: (2ω/g) u (cos β − cos θ cos(θ+β)) = −(2ω/g) u n_x c,
an identity. The sway-speed term is the same expression with the velocity component along
y (eq. 2.59 is garbled in the extracted text; this is the frame-independent form,
−(2ω/g)(U·n) c, i.e. the normal velocity of the wall into the waves). The factor f = 2 is
Faltinsen's; the thesis proposes f_u = 4 for surge (eq. C.1), which is Aranha's short-wave
limit (a constant QTF gives B11 = 4ωF/g): ``speed_factor=(4.0, 2.0)`` reproduces it.
The yaw moment is the moment of the same segment forces about the origin (each straight
segment's uniform load acts at its midpoint).

Formulas the extracted text garbles and that we could not check against the original
papers are implemented as read from the thesis and say so in their docstrings (Liu et al.'s
exponent grouping, Kashiwagi's C_fv, DNV 1996, the R-function combination); DNV's
reflection-coefficient table was not available: pass R yourself.
"""

from __future__ import annotations

import equinox as eqx
import jax.numpy as jnp

from .._rules import check_finite, check_positive
from .._special import r_function
from .._units import RHO_SEA, G
from ._damping import encounter_frequency
from ._waterline import Waterline

#: Zone edges in L/λ (eq. 3.7): motion zone below the first, reflection zone above the
#: second, transition between. The thesis's Table 4.1 values are lost in the extracted text;
#: these edges follow its discussion (peaks at L/λ ≈ 1, reflection dominated beyond ≈ 2).
ZONE_EDGES = (1.0, 2.0)
ZONE_NAMES = ("motion", "transition", "reflection")
#: Fujii & Takahashi / Kuroda / Kashiwagi were fitted on blunt hulls; jaxtow calls a hull
#: blunt when its head-sea bluntness B_f(0) (eq. 2.51) is at least this (box barge: 1.0).
BLUNT_BF_MIN = 0.5
FROUDE_MAX = 0.15


class DriftEstimate(eqx.Module):
    """Mean drift per ζa² from a waterline method, with its validity flags.

    ``fx``, ``fy`` [N/m²], ``nz`` [N·m/m²]; ``flags``: dict of boolean arrays (True = inside
    the method's range); ``zone``: 0 motion, 1 transition, 2 reflection (L/λ, eq. 3.7);
    ``froude``: Fn = |U|/√(gL). Iterating yields (fx, fy, nz)."""

    fx: jnp.ndarray
    fy: jnp.ndarray
    nz: jnp.ndarray
    flags: dict
    zone: jnp.ndarray
    froude: jnp.ndarray
    method: str = eqx.field(static=True, default="")

    def __iter__(self):
        return iter((self.fx, self.fy, self.nz))

    @property
    def force(self):
        """(..., 3) stack of (Fx, Fy, Nz)."""
        return jnp.stack([self.fx, self.fy, self.nz], axis=-1)

    @property
    def valid(self):
        """True where every flag holds."""
        out = jnp.ones(jnp.shape(self.fx), dtype=bool)
        for f in self.flags.values():
            out = out & f
        return out


def wavelength_ratio(omega, length, g: float = G):
    """L/λ = ω² L / (2π g) (thesis eq. 3.7, deep water)."""
    return jnp.asarray(omega) ** 2 * length / (2 * jnp.pi * g)


def zone(omega, length, edges=ZONE_EDGES, g: float = G):
    """0 motion, 1 transition, 2 reflection zone, by L/λ (eq. 3.7) and ``edges``."""
    r = wavelength_ratio(omega, length, g)
    return (r >= edges[0]).astype(jnp.int32) + (r >= edges[1]).astype(jnp.int32)


def froude(wl: Waterline, u, v=0.0, g: float = G):
    """Fn = |U| / √(g L) with U = (u, v) and L the waterline length."""
    U2 = jnp.asarray(u, float) ** 2 + jnp.asarray(v, float) ** 2
    safe = jnp.where(U2 > 0, U2, 1.0)
    return jnp.where(U2 > 0, jnp.sqrt(safe), 0.0) / jnp.sqrt(g * wl.length)


def _sqrt0(x):
    """√x with a finite (zero) derivative at x = 0 (the one-sided one is infinite)."""
    pos = x > 0
    return jnp.where(pos, jnp.sqrt(jnp.where(pos, x, 1.0)), 0.0)


def _lit(wl: Waterline, beta):
    """c_i = k̂·n_i per segment; the segment is lit where c_i > 0."""
    beta = jnp.asarray(beta, float)
    n = wl.normals
    return -jnp.cos(beta)[..., None] * n[:, 0] - jnp.sin(beta)[..., None] * n[:, 1]


def _resultant(wl: Waterline, q):
    """(Fx, Fy, Nz) from a uniform normal load q_i [N/m per ζa²] on each segment."""
    n, dl, xm = wl.normals, wl.lengths, wl.midpoints
    fx = jnp.sum(q * n[:, 0] * dl, axis=-1)
    fy = jnp.sum(q * n[:, 1] * dl, axis=-1)
    nz = jnp.sum(q * dl * (xm[:, 0] * n[:, 1] - xm[:, 1] * n[:, 0]), axis=-1)
    return fx, fy, nz


def _wall_load(wl, omega, beta, u, v, speed_factor, rho, g):
    """Per-segment load of the Faltinsen kernel (module docstring), per ζa²."""
    c = _lit(wl, beta)
    lit = jnp.maximum(c, 0.0)
    fu, fv = speed_factor
    n = wl.normals
    w = (jnp.asarray(omega, float) / g)[..., None]
    un = (
        fu * jnp.asarray(u, float)[..., None] * n[:, 0]
        + fv * jnp.asarray(v, float)[..., None] * n[:, 1]
    )
    return 0.5 * rho * g * (lit**2 - w * lit * un)


def bluntness(wl: Waterline, beta):
    """Fujii & Takahashi's bluntness coefficient B_f(β) (eq. 2.51): the lit part of
    (1/B) ∫ sin²(θ±β) sin θ dl, i.e. minus the stationary Faltinsen surge force divided by
    ½ρgζa²B. 1 for a wall-sided box in head seas."""
    c = jnp.maximum(_lit(wl, beta), 0.0)
    return -jnp.sum(c**2 * wl.normals[:, 0] * wl.lengths, axis=-1) / wl.breadth


def _inputs(omega, beta, u, v):
    omega, beta, u, v = (jnp.asarray(a, dtype=float) for a in (omega, beta, u, v))
    check_positive("omega", omega)
    check_finite("beta", beta)
    check_finite("u", u)
    check_finite("v", v)
    return jnp.broadcast_arrays(omega, beta, u, v)


def _estimate(method, wl, omega, u, v, F, flags, zone_ok, g, edges=ZONE_EDGES):
    fx, fy, nz = (jnp.broadcast_to(a, jnp.shape(omega)) for a in F)
    fn = froude(wl, u, v, g)
    z = zone(omega, wl.length, edges, g)
    flags = dict(flags)
    flags["froude"] = fn < FROUDE_MAX
    if zone_ok is not None:
        flags["zone"] = jnp.isin(z, jnp.asarray(zone_ok))
    flags["convex"] = jnp.full(jnp.shape(omega), wl.convex)
    flags = {k: jnp.broadcast_to(f, jnp.shape(omega)) for k, f in flags.items()}
    return DriftEstimate(fx=fx, fy=fy, nz=nz, flags=flags, zone=z, froude=fn, method=method)


def _wall_sided(wl, shape):
    return jnp.broadcast_to(jnp.all(jnp.abs(wl.flare) < 1e-9), shape)


def faltinsen(
    wl: Waterline,
    omega,
    beta,
    u=0.0,
    v=0.0,
    *,
    speed_factor=(2.0, 2.0),
    rho: float = RHO_SEA,
    g: float = G,
) -> DriftEstimate:
    """Faltinsen's short-wave asymptote, stationary (eq. 2.31) and with speed (eqs 2.57-2.59).

    F = ½ρgζa² ∫_lit [ sin²(θ+β) + (f ω/g)(U·n) sin(θ+β) ] n dl, i.e. the vector form of the
    module docstring. Wall-sided box in head seas: Fx = −½ρgζa²B (1 + f_u ω u / g). ``speed_factor``
    = (f_u, f_v): (2, 2) is Faltinsen (1980); (4, 2) the thesis's modification (eq. C.1).
    Valid in the reflection zone, for wall-sided hulls, Fn < 0.15.
    """
    omega, beta, u, v = _inputs(omega, beta, u, v)
    q = _wall_load(wl, omega, beta, u, v, speed_factor, rho, g)
    flags = dict(wall_sided=_wall_sided(wl, omega.shape))
    return _estimate("faltinsen", wl, omega, u, v, _resultant(wl, q), flags, (2,), g)


def liu(
    wl: Waterline,
    omega,
    beta,
    u=0.0,
    v=0.0,
    *,
    speed_factor=(2.0, 2.0),
    rho: float = RHO_SEA,
    g: float = G,
) -> DriftEstimate:
    """Liu et al. (2015, 2016) empirical correction of Faltinsen's formula (eqs 2.61-2.63).

    Per segment: the Faltinsen-with-speed load × (0.87/C_B)^((1 + 4√Fn) f(β)) × C_d / cos η,
    with f(β) = cos β for |β| < π/2 and 0 beyond, C_d = R(k_e T_l) the R-function of the
    encounter wave number k_e = ω_e²/g and the local effective draft
    T_l = min(T cos η, d(x)) (η the waterline flare, d the local draft). The grouping of the
    factors is read from the garbled eq. 2.61 (the exponent form is Liu & Papanikolaou's
    published one as far as we could establish); not checked against the original paper.
    """
    omega, beta, u, v = _inputs(omega, beta, u, v)
    q = _wall_load(wl, omega, beta, u, v, speed_factor, rho, g)
    fn = froude(wl, u, v, g)
    f_beta = jnp.maximum(jnp.cos(beta), 0.0)
    empirical = (0.87 / wl.block_coefficient) ** ((1.0 + 4.0 * _sqrt0(fn)) * f_beta)
    ke = encounter_frequency(omega, beta, u, v, g=g) ** 2 / g
    Tl = jnp.minimum(wl.draft * jnp.cos(wl.flare), wl.local_draft)
    Cd = r_function(ke[..., None] * Tl)
    q = q * empirical[..., None] * Cd / jnp.cos(wl.flare)
    return _estimate("liu", wl, omega, u, v, _resultant(wl, q), {}, (1, 2), g)


def _stationary_faltinsen(wl, omega, beta, rho, g):
    z = jnp.zeros_like(omega)
    return _resultant(wl, _wall_load(wl, omega, beta, z, z, (2.0, 2.0), rho, g))


def _ft_flags(wl, beta, shape):
    return dict(
        wall_sided=_wall_sided(wl, shape),
        blunt=jnp.broadcast_to(bluntness(wl, 0.0) >= BLUNT_BF_MIN, shape),
    )


def fujii_takahashi(
    wl: Waterline, omega, beta, u=0.0, v=0.0, *, rho: float = RHO_SEA, g: float = G
) -> DriftEstimate:
    """Fujii & Takahashi (1975), eqs 2.50-2.53: F = ½ρgζa² B B_f(β) α_d (1 + α_U),
    α_d = R(k d) (the R-function of the wave number k = ω²/g and the draft d),
    α_U = 5√Fn. ½ρgζa² B B_f is the stationary Faltinsen surge force; jaxtow applies the
    same factor α_d(1 + α_U) to the stationary Faltinsen sway force and yaw moment, as the
    thesis does for its sway comparisons. Blunt hulls only."""
    omega, beta, u, v = _inputs(omega, beta, u, v)
    F0 = _stationary_faltinsen(wl, omega, beta, rho, g)
    factor = r_function(omega**2 / g * wl.draft) * (1.0 + 5.0 * _sqrt0(froude(wl, u, v, g)))
    F = tuple(f * factor for f in F0)
    return _estimate(
        "fujii_takahashi", wl, omega, u, v, F, _ft_flags(wl, beta, omega.shape), (1, 2), g
    )


def kuroda(
    wl: Waterline, omega, beta, u=0.0, v=0.0, *, rho: float = RHO_SEA, g: float = G
) -> DriftEstimate:
    """Kuroda et al. (2008), eqs 2.54-2.55: Fujii & Takahashi with α_d = R(k_e d) at the
    encounter wave number and α_U = C_U Fn, C_U = max(10, 68 − 310 B_f(β))."""
    omega, beta, u, v = _inputs(omega, beta, u, v)
    F0 = _stationary_faltinsen(wl, omega, beta, rho, g)
    ke = encounter_frequency(omega, beta, u, v, g=g) ** 2 / g
    cu = jnp.maximum(10.0, 68.0 - 310.0 * bluntness(wl, beta))
    factor = r_function(ke * wl.draft) * (1.0 + cu * froude(wl, u, v, g))
    F = tuple(f * factor for f in F0)
    return _estimate("kuroda", wl, omega, u, v, F, _ft_flags(wl, beta, omega.shape), (1, 2), g)


def kashiwagi_speed_factor(fn, wavelength_over_length):
    """Kashiwagi et al.'s forward-speed correction as read from the thesis (eq. 2.56):
    C_fv = 1 + 4 tanh(Fn) exp(−0.02 (λ/L)^10 / Fn³) (1 at Fn = 0, smoothly). The extracted
    equation is garbled and could not be checked against the original paper."""
    pos = fn > 0
    f = jnp.where(pos, fn, 1.0)
    return 1.0 + jnp.where(
        pos, 4.0 * jnp.tanh(f) * jnp.exp(-0.02 * wavelength_over_length**10 / f**3), 0.0
    )


def kashiwagi(
    wl: Waterline, omega, beta, u=0.0, v=0.0, *, rho: float = RHO_SEA, g: float = G
) -> DriftEstimate:
    """Kashiwagi et al.: the Fujii & Takahashi result multiplied by C_fv(Fn, λ/L)
    (`kashiwagi_speed_factor`, eq. 2.56)."""
    est = fujii_takahashi(wl, omega, beta, u, v, rho=rho, g=g)
    c = kashiwagi_speed_factor(est.froude, 1.0 / wavelength_ratio(omega, wl.length, g))
    return DriftEstimate(
        fx=est.fx * c,
        fy=est.fy * c,
        nz=est.nz * c,
        flags=est.flags,
        zone=est.zone,
        froude=est.froude,
        method="kashiwagi",
    )


#: DNV 2014 reflection coefficients R (DNV-RP-C205 table, thesis Table 2.2). The table was
#: not available to us; the one entry we can justify is the vertical wall (R = 1, which makes
#: DNV 2014 twice Faltinsen's limit for a wall-sided barge, as the thesis reports). Pass any
#: other R explicitly.
DNV2014_REFLECTION = {"vertical_wall": 1.0}


def dnv2014(
    wl: Waterline,
    omega,
    beta,
    u=0.0,
    v=0.0,
    *,
    reflection: float = 1.0,
    rho: float = RHO_SEA,
    g: float = G,
) -> DriftEstimate:
    """DNV (2014) short-wave surge drift, eq. 2.33: Fx = −ρ g R² ζa² B, frequency
    independent, head seas. jaxtow projects it as −ρgR²B·max(cos β, 0) off head seas
    (an assumption) and flags headings beyond ±15° as outside the method. No sway or yaw."""
    omega, beta, u, v = _inputs(omega, beta, u, v)
    fx = -rho * g * reflection**2 * wl.breadth * jnp.maximum(jnp.cos(beta), 0.0)
    z = jnp.zeros_like(omega)
    flags = dict(heading=jnp.abs(beta) <= jnp.radians(15.0))
    return _estimate("dnv2014", wl, omega, u, v, (fx, z, z), flags, None, g)


def dnv1996(
    wl: Waterline, omega, beta, u=0.0, v=0.0, *, rho: float = RHO_SEA, g: float = G
) -> DriftEstimate:
    """DNV (1996) surge drift for very wide structures, eq. 2.34 as read from the garbled
    text: F = ρ g Hs² (B/L)(0.52 L − 13) [L in m], per ζa² with Hs² = 8 ζa² (the thesis's
    conversion, eq. 2.32). Stated range (as printed): B/L > 3, T/B > 6, U = 0. The thesis
    reports that this formula gives about half the far-field drift of Barge 1; our reading
    does not (it exceeds DNV 2014 for Barge 1), so the printed form is probably not the
    published one. Kept for completeness, flagged outside its range for barges."""
    omega, beta, u, v = _inputs(omega, beta, u, v)
    L, B = wl.length, wl.breadth
    fx = -rho * g * 8.0 * (B / L) * (0.52 * L - 13.0) * jnp.maximum(jnp.cos(beta), 0.0)
    z = jnp.zeros_like(omega)
    shape = omega.shape
    flags = dict(
        dimensions=jnp.broadcast_to((B / L > 3.0) & (wl.draft / B > 6.0), shape),
        stationary=(u == 0) & (v == 0),
        heading=jnp.abs(beta) <= jnp.radians(15.0),
    )
    return _estimate("dnv1996", wl, omega, u, v, (fx, z, z), flags, None, g)


#: Floor on L_b (as a fraction of L) in the IMO formula; blunt bows have L_b → 0.
IMO_MIN_BOW_LENGTH = 0.01


def imo(
    wl: Waterline, omega, beta, u=0.0, v=0.0, *, rho: float = RHO_SEA, g: float = G
) -> DriftEstimate:
    """IMO formula after Söding & Shigunov, eq. 2.65: Fx = −½ρgζa² B √(B/L_b), L_b the
    distance from the bow to 95 % of the maximum breadth (`Waterline.bow_length_to_95_breadth`).
    Valid from head to bow-quartering seas (|β| ≤ 45°; projected with max(cos β, 0) as
    for DNV) and for bows with a finite entrance: L_b is floored at 1 % of L and the
    ``bow_length`` flag is False below that (box barges: L_b = 0, the thesis's
    "unrealistic" case). No speed dependence, no sway or yaw."""
    omega, beta, u, v = _inputs(omega, beta, u, v)
    Lb_raw = wl.bow_length_to_95_breadth()
    Lb = jnp.maximum(Lb_raw, IMO_MIN_BOW_LENGTH * wl.length)
    fx = -0.5 * rho * g * wl.breadth * jnp.sqrt(wl.breadth / Lb) * jnp.maximum(jnp.cos(beta), 0.0)
    z = jnp.zeros_like(omega)
    flags = dict(
        bow_length=jnp.broadcast_to(Lb_raw >= IMO_MIN_BOW_LENGTH * wl.length, omega.shape),
        heading=jnp.abs(beta) <= jnp.radians(45.0),
    )
    return _estimate("imo", wl, omega, u, v, (fx, z, z), flags, None, g)


def r_function_method(
    wl: Waterline,
    omega,
    beta,
    u=0.0,
    v=0.0,
    *,
    motion,
    reflection=None,
    rho: float = RHO_SEA,
    g: float = G,
) -> DriftEstimate:
    """R-function combination of a motion-induced and a reflection-induced part (Guo & Steen
    2011; Seo et al.; thesis eq. 2.64, whose exact form is lost in the extracted text):

        F = F_M(ω, β, u, v) + R(k_e T) · F_R(ω, β, u, v),

    the additive form R_AW = R_AWM + α_d R_AWR of those papers, with the R-function of the
    encounter wave number and the draft weighting the reflection part, which therefore
    vanishes in long waves. ``motion``: callable (ω, β, u, v) → (3,) array per ζa² (e.g. a
    strip-theory or panel QTF without reflection); ``reflection``: a waterline method
    (default `faltinsen` with the thesis's speed factor (4, 2)). A motion part that already
    contains the short-wave reflection (a full panel QTF) would be counted twice.
    """
    omega, beta, u, v = _inputs(omega, beta, u, v)

    def short_wave(wl_, w, b, uu, vv):
        return faltinsen(wl_, w, b, uu, vv, speed_factor=(4.0, 2.0), rho=rho, g=g)

    R = (short_wave if reflection is None else reflection)(wl, omega, beta, u, v)
    FM = jnp.asarray(motion(omega, beta, u, v))
    alpha = r_function(encounter_frequency(omega, beta, u, v, g=g) ** 2 / g * wl.draft)
    F = tuple(FM[..., i] + alpha * f for i, f in enumerate(R))
    return _estimate("r_function", wl, omega, u, v, F, {}, None, g)


#: The waterline methods by name (the R-function method needs a motion part and is not here).
WATERLINE_METHODS = {
    "faltinsen": faltinsen,
    "liu": liu,
    "fujii_takahashi": fujii_takahashi,
    "kuroda": kuroda,
    "kashiwagi": kashiwagi,
    "dnv2014": dnv2014,
    "dnv1996": dnv1996,
    "imo": imo,
}
