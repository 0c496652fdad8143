"""Added resistance in waves from strip-theory motions, and a strip-theory drift table.

**Gerritsma & Beukelman (1972)**, "Analysis of the resistance increase in waves of a fast
cargo ship", International Shipbuilding Progress 19(217): the energy the ship radiates
as damped waves is supplied by the incident wave, whose momentum flux k/ω_e per unit of
energy in the ship's frame then gives the mean force. Per unit wave amplitude squared,

    R_AW = (k cos β / (2|ω_e|)) ∫ b′₃₃(x) |V_z(x)|² dx,   b′₃₃ = b₃₃ − U da₃₃/dx,

with the relative vertical velocity of each strip against the water around it,
V_z = −iω_e(η₃ − xη₅) + Uη₅ + iω ζ*(x) e^{ikx cos χ}, where ζ* is the strip's
effective wave amplitude: its Froude-Krylov heave force over its waterplane stiffness ρgB
(for a wall-sided section in long waves ζ* = 1; it carries the decay e^{kz} over the draft,
Smith's correction, and the lateral variation of oblique waves). R_AW > 0 is a resistance
(a force astern); in following seas (cos β < 0) the formula gives a thrust. It holds only
the radiated part: the reflection of short waves at the bow is missing from it, which is
what the short-wave correction below adds.

**The strips' far field** (``method=FarField()``, any speed): Maruo's (1960) far-field
momentum balance with the strips as the radiating line, the slender-body idea of Joosen
(1966). Each strip radiates 2-D waves of amplitude q = ω_e X₃ V_z/(ρg²) to each side (X₃ its
beam-sea heave force at the encounter frequency: Haskind and the energy identity); seen from
afar the strips are a line of sources with these strengths, whose Kochin function
H(κ, θ) ∝ ∫ q e^{−iκx cos θ} dx is summed over the wave systems that meet the encounter
frequency in the ship's frame (at forward speed two, κ₁ and κ₂, the Doppler-shifted waves
of Maruo's theory; `_far_field`, `_branches`). The force is what the scattered waves take
from the incident wave's momentum less what they carry. Unlike Gerritsma-Beukelman it keeps
the interference of the strips' waves along the hull (a hull short against the waves
radiates less than its strips would alone) and the direction the energy goes. The
radiation is the symmetric (heave-pitch) part only, and the diffraction is the strips'
relative-motion part, as in Gerritsma-Beukelman; waves that overtake the ship (ω_e < 0) are
not built and are marked invalid.

**The reflection at the bow** (``method=WithReflection(waterline)``): either method plus a
waterline method's short-wave reflection at the same speed, by default Liu & Papanikolaou's
correction of Faltinsen's asymptote (`jaxtow.drift.liu`, which vanishes in long waves
through its own R-function factor); with Gerritsma-Beukelman it brings the peaks of all four
of Journée's Wigley models at Fn 0.2 within 25 % (docs/strip.md).

**Drift table at zero speed** (`drift_qtf`): the R-function method of jaxtow's drift
package (`jaxtow.drift.r_function_method`: F = F_M + R(k_e T) F_R) with the Gerritsma-
Beukelman (or far-field) resistance as the motion part F_M (surge only; strip theory gives no lateral
motion-induced drift) and Faltinsen's short-wave asymptote on the hull's waterline as the
reflection part F_R, weighted by the R-function of k T so that it vanishes in long waves.
The result is a `jaxtow.drift.QTF`, so every consumer of a drift source (the tow model,
the resistance budget, the studies) can use strip theory.
"""

from __future__ import annotations

import abc
from typing import ClassVar

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Bool, Float

from .._body import Loading
from .._rules import ParameterError, check_type, is_concrete
from .._units import SEA_WATER, Water
from ..drift import QTF, WATERLINE_METHODS, Waterline, r_function_method
from ._hull import Hull
from ._motions import Motions, MotionSolve, solve_motions
from ._strips import SectionTable

__all__ = [
    "AbstractAddedResistanceMethod",
    "GerritsmaBeukelman",
    "FarField",
    "WithReflection",
    "AddedResistance",
    "added_resistance",
    "drift_qtf",
]


#: directions of the zero-speed far-field integral of `maruo` (midpoint rule over the
#: circle: exact for the trigonometric polynomial |Q(θ)|² of a hull up to kL ≈ 180)
N_DIRECTIONS = 360

#: Gauss nodes per interval of the forward-speed far-field integral (each interval mapped by
#: θ = a + (b − a)(1 − cos πt)/2, which makes the 1/√(1 − 4τ cos θ) ends bounded)
N_NODES = 64


class AbstractAddedResistanceMethod(eqx.Module):
    """A way to get the added resistance in regular waves from the strip-theory motions:
    ``resistance(hull, solve, water)`` → (m,) [N per ζa², > 0 astern] over the flattened
    (ω, β) table of a `MotionSolve`; ``valid(motions)`` the method's own validity (w, b)."""

    name: ClassVar[str]

    @abc.abstractmethod
    def resistance(self, hull: Hull, solve: MotionSolve, water: Water) -> Array: ...

    def valid(self, motions: Motions):
        return motions.valid


class GerritsmaBeukelman(AbstractAddedResistanceMethod):
    """Gerritsma & Beukelman (1972): the energy radiated by the strips' relative vertical
    motion (module docstring). Any speed and heading; the radiated part only."""

    name: ClassVar[str] = "gerritsma_beukelman"

    def resistance(self, hull, solve, water):
        v, k, _, beta = _relative_velocity(hull, solve, water)
        da_dx = jnp.asarray(jnp.gradient(solve.added_mass, hull.x, axis=0))
        b_eff = solve.damping - solve.motions.u * da_dx
        power = jnp.sum(hull.dx[:, None] * b_eff * jnp.abs(v) ** 2, axis=0)  # 2 × mean power
        return k * jnp.cos(beta) * power / (2.0 * jnp.abs(solve.omega_e))


class FarField(AbstractAddedResistanceMethod):
    """The strips' far field in Maruo's (1960) momentum balance (module docstring), with
    ``n_directions`` midpoint directions over the circle at zero speed and ``n_nodes`` Gauss
    nodes per interval of the wave systems at speed. Waves that overtake the ship
    (ω_e < 0) are not built and are marked invalid."""

    n_directions: int = eqx.field(static=True, default=N_DIRECTIONS)
    n_nodes: int = eqx.field(static=True, default=N_NODES)
    name: ClassVar[str] = "far_field"

    def resistance(self, hull, solve, water):
        rho, g = water.rho, water.g
        v, k, _, beta = _relative_velocity(hull, solve, water)
        we = jnp.abs(solve.omega_e)
        u = solve.motions.u
        # each strip's outgoing 2-D wave per unit relative velocity, by Haskind from its
        # beam-sea heave force: |A₃| = ω_e|X₃|/(ρg²) (the energy identity b₃₃ = ω_e|X₃|²/(ρg²));
        # the common phase factor of the relation drops out of |H|². Seen from afar the
        # strips are a line of sources on the centreline with these strengths (slender-body
        # matching)
        q = we[None] / (rho * g**2) * solve.heave_exciting * v  # (n, m)
        # a numerical limit, not physics: held out of the derivatives (its interval ends pass
        # through arccos, whose slope is infinite where they saturate at cos θ = ±1)
        kappa_max = jax.lax.stop_gradient(jnp.pi / jnp.max(hull.dx))
        zero = is_concrete(u) and float(u) == 0.0

        def entry(args):
            q_j, k_j, we_j, cos_chi = args
            amp = lambda kappa: jnp.broadcast_to(q_j[:, None], q_j.shape + kappa.shape)  # noqa: E731
            return _far_field(
                hull.x,
                hull.dx,
                amp,
                k_j,
                we_j**2 / g,
                we_j,
                cos_chi,
                u,
                rho,
                g,
                kappa_max,
                n_directions=self.n_directions if zero else None,
                n_nodes=self.n_nodes,
            )

        return jax.lax.map(entry, (q.T, k, we, -jnp.cos(beta)), batch_size=8)

    def valid(self, motions):
        return motions.valid & (motions.omega_e > 0)


class WithReflection(AbstractAddedResistanceMethod):
    """A strip method's resistance plus the reflection of short waves at the bow:

        R_AW = R_motion + R_reflection,

    ``motion`` the strip method (default `GerritsmaBeukelman`, which holds the radiated part
    only) and ``reflection`` the name of a waterline method of
    `jaxtow.drift.WATERLINE_METHODS` on the hull's ``waterline`` (a `jaxtow.drift.Waterline`
    whose ``block_coefficient`` is the hull's C_B; `wigley_waterline`), at the same speed
    and headings. The default, ``"liu"``, is Liu & Papanikolaou's empirical correction of
    Faltinsen's short-wave asymptote with speed: the factor (0.87/C_B)^((1 + 4√Fn) cos β)
    and, per segment, the R-function of the encounter wave number and the local draft, which
    makes the reflection vanish in long waves. A method without such a factor (``"faltinsen"``,
    the bare asymptote) adds the short-wave limit at every wavelength; the drift table
    (`drift_qtf`) weights that one by R(k_e T) instead. The far field already carries the
    strips' relative-motion diffraction, so ``motion=FarField()`` may count part of the
    reflection twice. Validity: the motion part's (the waterline methods' Froude flag,
    `jaxtow.drift` FROUDE_MAX = 0.15, is set for barges and is not applied here)."""

    waterline: Waterline
    motion: AbstractAddedResistanceMethod = eqx.field(default_factory=GerritsmaBeukelman)
    reflection: str = eqx.field(static=True, default="liu")
    name: ClassVar[str] = "with_reflection"

    def __check_init__(self):
        check_type("waterline", self.waterline, Waterline)
        check_type("motion", self.motion, AbstractAddedResistanceMethod)
        if self.reflection not in WATERLINE_METHODS:
            raise ParameterError(
                "reflection",
                f"parameter 'reflection' must be one of {sorted(WATERLINE_METHODS)}, got "
                f"{self.reflection!r}",
            )

    def resistance(self, hull, solve, water):
        m = solve.motions
        nb = m.beta.shape[0]
        w, beta = jnp.repeat(m.omega, nb), jnp.tile(m.beta, m.omega.shape[0])
        short_wave = WATERLINE_METHODS[self.reflection]
        est = short_wave(self.waterline, w, beta, m.u, rho=water.rho, g=water.g)
        return self.motion.resistance(hull, solve, water) - est.fx

    def valid(self, motions):
        return self.motion.valid(motions)


class AddedResistance(eqx.Module):
    """Added resistance ``resistance`` (w, b) [N per ζa² of the incident wave, i.e. N/m²]
    (> 0 astern) at wave frequencies ``omega`` (w,) [rad/s], headings ``beta`` (b,) [rad]
    (waves from; 0 head seas) and speed ``u`` [m/s], by ``method``; with the `Motions` it
    came from and the ``valid`` mask (the motions' and the method's own)."""

    omega: Float[Array, " w"]
    beta: Float[Array, " b"]
    u: Float[Array, ""]
    resistance: Float[Array, "w b"]
    motions: Motions
    valid: Bool[Array, "w b"]
    method: AbstractAddedResistanceMethod


def _relative_velocity(hull: Hull, solve: MotionSolve, water: Water):
    """(V_z (n, m), k (m,), ω (m,), β (m,)): the strips' relative vertical velocity per unit
    wave amplitude (module docstring) over the flattened (ω, β) table."""
    m = solve.motions
    g = water.g
    nb = m.beta.shape[0]
    w = jnp.repeat(m.omega, nb)
    beta = jnp.tile(m.beta, m.omega.shape[0])
    we = solve.omega_e
    k = w**2 / g
    k_cos = -k * jnp.cos(beta)  # k cos χ
    rao = m.rao.reshape(-1, 5)
    eta3, eta5 = rao[:, 1], rao[:, 3]
    x = hull.x[:, None]
    breadth = 2.0 * hull.y[:, 0][:, None]
    zeta = solve.heave_froude_krylov / (water.rho * g * breadth) * jnp.exp(1j * k_cos[None] * x)
    v = -1j * we * (eta3 - x * eta5) + m.u * eta5 + 1j * w * zeta
    return v, k, w, beta


def _branches(k_e, we, u, g, kappa_max=None, n_nodes=None):
    """The far field's wave systems at forward speed for one table entry: a list of (κ(θ),
    θ, quadrature weight) over Maruo's intervals, κ the wave numbers that meet the
    encounter frequency ω_e in the frame of the ship, (ω_e + κU cos θ)² = gκ:

        κ₂ = 2ω_e²/(g (1 − 2τc + r)),  κ₁ = ω_e²/(U²c² κ₂),  r = √(1 − 4τc),  c = cos θ,

    τ = Uω_e/g. Waves exist for c ≤ c_top = min(1, 1/4τ) (above τ = 1/4 none runs straight
    ahead); κ₂ (increasing in c) all round, κ₁ ahead (c > 0, decreasing in c) and behind
    (c < 0, decreasing in |c|). With ``kappa_max`` (None: no limit) each system keeps only
    its waves up to it; where a system reaches it, ω_e + κU c = ±√(gκ) gives the direction,
    c = (±√(gκ_max) − ω_e)/(κ_max U) (+ for κ₂ and κ₁ ahead, − behind), so that every
    interval's integrand is smooth."""
    tau = u * we / g
    c_top = jnp.minimum(1.0, 0.25 / jnp.maximum(tau, 1e-300))

    def k2(c):
        r = jnp.sqrt(jnp.maximum(1.0 - 4.0 * tau * c, 0.0))
        return 2.0 * we**2 / (g * (1.0 - 2.0 * tau * c + r))

    def k1(c):
        return we**2 / (u**2 * c**2 * k2(c))

    if kappa_max is None:
        c_ahead, c_two, c_behind = 0.0, c_top, 0.0
    else:
        root_g = jnp.sqrt(g * kappa_max)
        cut = (root_g - we) / (kappa_max * u)
        c_ahead = jnp.where(k1(c_top) <= kappa_max, jnp.clip(cut, 0.0, c_top), c_top)
        inside = jnp.where(k2(-1.0) <= kappa_max, jnp.clip(cut, -1.0, c_top), -1.0)
        c_two = jnp.where(k2(c_top) <= kappa_max, c_top, inside)
        c_behind = jnp.clip((-root_g - we) / (kappa_max * u), -1.0, 0.0)
    alpha0 = jnp.arccos(c_top)
    t, w = np.polynomial.legendre.leggauss(N_NODES if n_nodes is None else n_nodes)
    t, w = 0.5 * (t + 1.0), 0.5 * w

    def nodes(a, b):
        theta = a + (b - a) * 0.5 * (1.0 - np.cos(np.pi * t))
        return theta, w * (b - a) * 0.5 * np.pi * np.sin(np.pi * t)

    ahead, two, behind = jnp.arccos(c_ahead), jnp.arccos(c_two), jnp.arccos(c_behind)
    out = [
        (k1, *nodes(alpha0, ahead)),
        (k1, *nodes(-ahead, -alpha0)),
        (k1, *nodes(behind, 2.0 * jnp.pi - behind)),
        (k2, *nodes(two, 2.0 * jnp.pi - two)),
    ]
    return [(kf(jnp.cos(th)), th, wt) for kf, th, wt in out]


def _far_field(
    x, dx, amp, k, k_e, we, cos_chi, u, rho, g, kappa_max=None, n_directions=None, n_nodes=None
):
    """Mean added resistance [N per ζa², > 0 astern] by Maruo's (1960) far-field momentum
    balance, for one table entry: the waves radiated by a line of sources at ``x`` (n,) with
    lengths ``dx``, whose outgoing waves of wave number κ have amplitudes ``amp(κ)`` (n, T)
    per unit length and incident amplitude (normalised so that a strip's own 2-D waves,
    κ = k_e = ω_e²/g, are its 2-D amplitude; the strips give the same for every κ), meet an
    incident wave of wave number ``k`` travelling at cos χ. With the Kochin function
    H(κ, θ) = √(g/k_e) Σ amp e^{−iκx cos θ} dx,

        R = ρ/(8π) Σ_systems ∫ sgn(ω_e + κU cos θ) |H|² κ(κ cos θ − k cos χ)/√(1 − 4τ cos θ) dθ

    over the wave systems of `_branches` (τ = Uω_e/g); the sign is that of the waves'
    frequency in the earth's frame, so that the short waves of the κ₁ system behind the
    ship, which run forward in the earth's frame, count with their true direction (as ω_e
    → 0 the waves ahead and behind then add up to the steady Kelvin waves' resistance, where
    the plain sign would cancel them; tested). The 1/√ factor is the Jacobian from Maruo's
    integral over m = κ cos θ. At zero speed one system remains, κ = k = k_e, and R is the
    momentum the scattered waves take from the incident wave less what they carry away,
    ρk²/(8π) ∫ |H|² (cos θ − cos χ) dθ. At speed, waves beyond ``kappa_max`` (None: none), a
    station spacing's Nyquist limit (the stations cannot resolve them, and they only alias),
    are left out."""
    if n_directions is not None:  # zero speed (a number): the midpoint rule over the circle
        theta = 2.0 * jnp.pi * (jnp.arange(n_directions) + 0.5) / n_directions
        d_theta = jnp.full_like(theta, 2 * jnp.pi / n_directions)
        systems = [(jnp.full_like(theta, k_e), theta, d_theta)]
    else:
        systems = _branches(k_e, we, u, g, kappa_max, n_nodes)
    total = 0.0
    for kappa, theta, wt in systems:
        c = jnp.cos(theta)
        kappa = jnp.where(jnp.isfinite(kappa), kappa, k_e)
        a = amp(kappa)  # (n, T)
        big_h = jnp.sqrt(g / k_e) * jnp.sum(
            dx[:, None] * a * jnp.exp(-1j * kappa[None] * x[:, None] * c[None]), axis=0
        )
        root = jnp.sqrt(jnp.maximum(1.0 - 4.0 * u * we / g * c, 1e-12))
        sign = jnp.sign(we + kappa * u * c)
        dens = sign * jnp.abs(big_h) ** 2 * kappa * (kappa * c - k * cos_chi) / root
        total = total + jnp.sum(dens * wt)
    return rho / (8.0 * jnp.pi) * total


def added_resistance(
    hull: Hull,
    omega,
    beta,
    u=0.0,
    *,
    method: AbstractAddedResistanceMethod | None = None,
    loading: Loading | None = None,
    sections: SectionTable | None = None,
    water: Water = SEA_WATER,
    n_frequencies: int | None = 40,
) -> AddedResistance:
    """Added resistance in regular waves per ζa² [N/m²] by ``method`` (an
    `AbstractAddedResistanceMethod`: `GerritsmaBeukelman` (default) or `FarField`; module
    docstring), from `jaxtow.strip.motions` with the same arguments. Differentiable in the
    hull's offsets, the loading, the speed and the frequencies; jit and vmap over hulls."""
    method = GerritsmaBeukelman() if method is None else method
    check_type("method", method, AbstractAddedResistanceMethod)
    solve = solve_motions(
        hull,
        omega,
        beta,
        u,
        loading=loading,
        sections=sections,
        water=water,
        n_frequencies=n_frequencies,
    )
    zero_speed = is_concrete(u) and float(u) == 0.0
    return _resistance_program(method, hull, solve, water, zero_speed)


@eqx.filter_jit
def _resistance_program(method, hull, solve, water, zero_speed):
    """The resistance from the solve, one compiled program (not hundreds of eager ones).
    ``zero_speed`` (static): the speed was the number zero, which the methods may treat
    exactly (handed to them as a concrete zero)."""
    m = solve.motions
    if zero_speed:
        solve = eqx.tree_at(lambda s: s.motions.u, solve, np.zeros(()))
    return AddedResistance(
        omega=m.omega,
        beta=m.beta,
        u=m.u,
        resistance=method.resistance(hull, solve, water).reshape(m.valid.shape),
        motions=m,
        valid=method.valid(m),
        method=method,
    )


def drift_qtf(
    hull: Hull,
    waterline: Waterline,
    omega,
    beta,
    *,
    method: AbstractAddedResistanceMethod | None = None,
    loading: Loading | None = None,
    water: Water = SEA_WATER,
) -> QTF:
    """A zero-speed mean-drift `jaxtow.drift.QTF` from strip theory (module docstring) on
    ``omega`` [rad/s] × ``beta`` [rad, from 0 to π ascending], completed to ±β by the hull's
    port-starboard symmetry; ``waterline``: the hull's waterline for the short-wave
    reflection part; ``method``, ``loading``: those of `added_resistance`."""
    beta = np.asarray(beta, float)
    if beta.ndim != 1 or beta[0] != 0.0 or not np.isclose(beta[-1], np.pi):
        raise ValueError("parameter 'beta' must run from 0 to pi (the other half by symmetry)")
    ar = added_resistance(hull, omega, beta, 0.0, method=method, loading=loading, water=water)
    r = ar.resistance
    fm = jnp.stack([-r, jnp.zeros_like(r), jnp.zeros_like(r)], axis=-1)
    est = r_function_method(
        waterline,
        ar.omega[:, None],
        jnp.asarray(beta)[None, :],
        motion=lambda *_: fm,
        rho=water.rho,
        g=water.g,
    )
    fy = np.array(est.fy)
    nz = np.array(est.nz)
    ends = np.isclose(beta, 0.0) | np.isclose(beta, np.pi)
    fy[:, ends] = 0.0  # exact symmetry in head and following seas
    nz[:, ends] = 0.0
    return QTF.symmetric(omega=np.asarray(ar.omega), beta=beta, fx=np.asarray(est.fx), fy=fy, nz=nz)
