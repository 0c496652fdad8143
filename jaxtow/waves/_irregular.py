"""Irregular-sea statistics of regular-wave quantities (thesis eqs 2.29, 2.30, 2.49).

P(ω) below is a mean-drift QTF per unit ζa² (force per m² of amplitude squared), B(ω) a
wave-drift damping per ζa². All integrals use the trapezoidal rule on the given ω grid and
are differentiable in the spectrum's parameters (Hs, Tp, γ), so gradients and vmaps over
Tp grids work.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, ArrayLike, Float

from .._program_cache import host_program
from ._spectra import check_ascending, integrate_density

#: The default wave-frequency grid of every irregular-sea integral in jaxtow [rad/s]: 0.05-4
#: rad/s in 800 points (Δω ≈ 0.005 rad/s). It covers JONSWAP spectra with Tp from about 4 s
#: (ωp = 1.6 rad/s; the tail beyond 4 rad/s then holds < 0.5 % of m0) to beyond 20 s.
DEFAULT_OMEGA = np.linspace(0.05, 4.0, 800)


def spectral_integral(
    omega: Float[ArrayLike, " nw"],
    S: Float[ArrayLike, " nw"],
    X: Float[ArrayLike, "nw ..."],
    *,
    name: str = "X",
) -> Float[Array, "..."]:
    """2 ∫ S(ω) X(ω) dω by the trapezoidal rule on the grid ``omega``: the one irregular-sea
    integral of jaxtow. ``X`` has ω on axis 0 and any trailing axes (a QTF component (n_ω,),
    the three drift components (n_ω, 3), a damping matrix (n_ω, 3, 3)). Shapes are checked
    (also under jit and vmap, where they are known) with an error naming the argument
    (``name``: the integrand's name in the caller's signature)."""
    X = jnp.asarray(X)
    nw = jnp.shape(omega)
    if len(nw) != 1:
        raise ValueError(f"parameter 'omega' must be a 1-D frequency grid, got shape {nw}")
    if jnp.shape(S)[-1:] != nw:
        raise ValueError(
            f"parameter 'S' must hold the spectrum on the grid omega (last axis {nw[0]}), got "
            f"shape {jnp.shape(S)}"
        )
    if X.shape[:1] != nw:
        raise ValueError(
            f"parameter {name!r} must have the frequency grid omega ({nw[0]}) on its first "
            f"axis, got shape {X.shape}"
        )
    check_ascending(omega)  # eagerly, before the program (which sees no values)
    return _spectral_integral(omega, S, X)


@host_program()
def _spectral_integral(omega, S, X):
    return 2.0 * integrate_density(omega, jnp.moveaxis(X, 0, -1) * jnp.asarray(S))


def mean_drift(
    omega: Float[ArrayLike, " nw"], S: Float[ArrayLike, " nw"], P: Float[ArrayLike, "nw ..."]
) -> Float[Array, "..."]:
    """Mean drift force in irregular waves, F̄ = 2 ∫ S(ω) P(ω) dω (thesis eq. 2.29), with
    `spectral_integral`; ``P`` (n_ω, ...) per ζa².

    For a constant P this is P·2m0 = P·Hs²/8 (with 4√m0 = Hs): the short-wave conversion of
    regular-wave ζa² to Hs²/8 (thesis eq. 2.32).
    """
    return spectral_integral(omega, S, P, name="P")


def mean_drift_damping(
    omega: Float[ArrayLike, " nw"], S: Float[ArrayLike, " nw"], B: Float[ArrayLike, "nw ..."]
) -> Float[Array, "..."]:
    """Mean wave-drift damping in irregular waves, b = 2 ∫ B(ω) S(ω) dω (thesis eq. 2.49),
    with `spectral_integral`; ``B`` has ω on axis 0 (e.g. (n_ω, 3, 3) for the full matrix)."""
    return spectral_integral(omega, S, B, name="B")


def slow_drift_force_spectrum(
    omega: Float[ArrayLike, " nw"],
    S: Float[ArrayLike, " nw"],
    P: Float[ArrayLike, " nw"],
    mu: ArrayLike,
) -> Float[Array, " nmu"]:
    """Slow-drift force spectrum S_F(μ) = 8 ∫ S(ω) S(ω+μ) |T(ω, ω+μ)|² dω (thesis eq. 2.30).

    Newman's approximation: T(ω, ω+μ) is the mean-drift QTF at the mean frequency ω + μ/2,
    linearly interpolated from P on the grid. ``mu`` may be an array (vmapped).
    """
    omega = jnp.asarray(omega)
    S = jnp.asarray(S)
    P = jnp.asarray(P)

    def one(m):
        S2 = jnp.interp(omega + m, omega, S, right=0.0)
        T = jnp.interp(omega + 0.5 * m, omega, P)
        return 8.0 * integrate_density(omega, S * S2 * T**2)

    return jax.vmap(one)(jnp.atleast_1d(jnp.asarray(mu)))


def _components(key, omega, S, random_amplitudes: bool):
    """Amplitudes a_i = √(2 S_i Δω_i) and uniform phases; with ``random_amplitudes`` the
    amplitudes are Rayleigh distributed with the same mean square (a Gaussian sea)."""
    check_ascending(omega)  # a descending grid gave negative Δω and NaN amplitudes
    omega = jnp.asarray(omega)
    dw = jnp.gradient(omega)
    a = jnp.sqrt(2.0 * jnp.asarray(S) * dw)
    k1, k2 = jax.random.split(key)
    phase = jax.random.uniform(k1, omega.shape, minval=0.0, maxval=2 * jnp.pi)
    if random_amplitudes:
        a = a * jnp.sqrt(-jnp.log(jax.random.uniform(k2, omega.shape, minval=1e-300, maxval=1.0)))
    return a, phase


def synthesise_elevation(key, omega, S, t, *, random_amplitudes: bool = False):
    """Random-phase wave elevation ζ(t) = Σ a_i cos(ω_i t + φ_i), reproducible from a
    `jax.random` key. The ω grid should be uniform (then the record repeats after 2π/Δω)."""
    a, phase = _components(key, omega, S, random_amplitudes)
    t = jnp.asarray(t)
    return jnp.sum(a * jnp.cos(jnp.asarray(omega) * t[..., None] + phase), axis=-1)


def synthesise_drift_force(key, omega, S, P, t, *, random_amplitudes: bool = False):
    """Slowly varying drift force by Newman's approximation, with the same components as
    `synthesise_elevation` for the same key:

        F(t) = 2 sign(P̄) [Σ a_i √|P_i| cos(ω_i t + φ_i)]²  (low-frequency part),

    keeping only the difference-frequency terms, so that its mean is 2 ∫ S P dω (eq. 2.29)
    when P keeps one sign.
    """
    a, phase = _components(key, omega, S, random_amplitudes)
    c = a * jnp.sqrt(jnp.abs(jnp.asarray(P)))
    t = jnp.asarray(t)
    z = jnp.sum(c * jnp.exp(1j * (jnp.asarray(omega) * t[..., None] + phase)), axis=-1)
    sign = jnp.sign(jnp.sum(jnp.asarray(P) * a**2))
    # |Σ c e^{iθ}|² = Σ_ij c_i c_j cos(θ_i − θ_j): the difference-frequency part of 2(Σ c cos θ)²
    return sign * jnp.abs(z) ** 2
