"""Forward speed: encounter frequency and sailing drift (thesis eqs 2.35, 2.36, 2.38, 5.1)."""

from __future__ import annotations

import jax
import jax.numpy as jnp
from jaxtyping import Array, ArrayLike, Float

from .._units import G
from ..waves._irregular import mean_drift
from ._damping import wave_drift_damping
from ._qtf import QTF


def encounter_frequency(
    omega0: ArrayLike, beta: ArrayLike, u: ArrayLike, v: ArrayLike = 0.0, *, g: float = G
) -> Float[Array, "..."]:
    """Encounter frequency ω_e = ω0 − k0 k̂·U = ω0 + (ω0²/g)(u cos β + v sin β) (eqs 2.35, 2.36).

    jaxtow's β is the direction the waves come *from*, counter-clockwise from the bow, so
    they travel along k̂ = (−cos β, −sin β) in body axes (the same convention as the QTF,
    Aranha's damping in `wave_drift_damping`, the waterline methods and the WAMIT reader).
    Head seas (β = 0) with u > 0 raise ω_e; so does swaying towards waves from port
    (β = π/2, v > 0). The thesis prints eq. 2.35 with ``− v sin β``, i.e. with β measured the
    other way round; with jaxtow's convention and the tow model's β = −ψ this form makes ω_e
    independent of the barge heading, as it must be for waves from ahead of the tug.
    """
    omega0 = jnp.asarray(omega0)
    return omega0 + omega0**2 / g * (u * jnp.cos(beta) + v * jnp.sin(beta))


def sailing_drift(
    q: QTF,
    omega0: ArrayLike,
    beta: ArrayLike,
    u: ArrayLike,
    v: ArrayLike = 0.0,
    r: ArrayLike = 0.0,
    *,
    yaw_column: ArrayLike | None = None,
    g: float = G,
) -> Float[Array, "3"]:
    """Mean drift per ζa² of a vessel moving with (u, v, r) in waves of frequency ω0:
    F(ω_e, β, 0) + B(ω_e, β)·(u, v, r) (eqs 2.38, 5.1); plotted against ω0 the curve
    shifts to lower frequency because the vessel meets the waves at ω_e."""
    we = encounter_frequency(omega0, beta, u, v, g=g)
    B = wave_drift_damping(q, we, beta, yaw_column=yaw_column, g=g)
    return q(we, beta) + B @ jnp.stack(
        [jnp.asarray(u, float), jnp.asarray(v, float), jnp.asarray(r, float)]
    )


def irregular_sailing_drift(
    q: QTF,
    omega: Float[ArrayLike, " nw"],
    S: Float[ArrayLike, " nw"],
    beta: ArrayLike,
    u: ArrayLike,
    v: ArrayLike = 0.0,
    r: ArrayLike = 0.0,
    *,
    yaw_column: ArrayLike | None = None,
    g: float = G,
) -> Float[Array, "3"]:
    """Mean drift in an irregular sea with forward speed: 2 ∫ S(ω0) F_sail(ω0) dω0
    (eq. 2.29 with the sailing drift of eqs 2.38, 5.1), per unit of the spectrum's scale.
    ``omega`` is the wave-frequency grid of the spectrum ``S`` (see `jaxtow.waves`)."""
    F = jax.vmap(lambda w: sailing_drift(q, w, beta, u, v, r, yaw_column=yaw_column, g=g))(
        jnp.asarray(omega)
    )
    return mean_drift(omega, S, F)
