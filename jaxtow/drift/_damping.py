"""Wave-drift damping (Aranha 1994; thesis eqs 2.39-2.42).

B relates the change of the mean drift force to the vessel's slow velocity,
F(ω, β, U) = F(ω, β, 0) + B(ω, β)·(u, v, r) (thesis eq. 2.38), per ζa².
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
from jaxtyping import Array, ArrayLike, Float

from .._units import G
from ._qtf import QTF


def wave_drift_damping(
    q: QTF, omega: ArrayLike, beta: ArrayLike, *, yaw_column: ArrayLike | None = None, g: float = G
) -> Float[Array, "3 3"]:
    """3×3 wave-drift damping matrix B per ζa², columns for (u, v, r), thesis eq. 2.39.

    Surge and sway columns from Aranha's formula (eqs 2.40, 2.41), with ∂F/∂ω and ∂F/∂β
    taken by forward-mode autodiff of the QTF interpolant:

        B_i1 = (ω/g) [ ω cos β ∂F_i/∂ω − 2 sin β ∂F_i/∂β + 4 cos β F_i ]
        B_i2 = (ω/g) [ ω sin β ∂F_i/∂ω + 2 cos β ∂F_i/∂β + 4 sin β F_i ]

    The yaw-rate column (Aranha & Martins 1997, eq. 2.42) needs the sectional first and
    second moments of the drift force, which a QTF table does not hold, and its published
    form was not available to us: pass it as ``yaw_column`` (shape (3,), per ζa²: the change
    of (Fx, Fy, Nz) per unit yaw rate) from a panel computation. The documented fallback is
    zero (no yaw-rate wave-drift damping), returned when ``yaw_column`` is None.
    """
    omega = jnp.asarray(omega, dtype=float)
    beta = jnp.asarray(beta, dtype=float)
    F, dF_dw = jax.jvp(lambda w: q(w, beta), (omega,), (jnp.ones_like(omega),))
    _, dF_db = jax.jvp(lambda b: q(omega, b), (beta,), (jnp.ones_like(beta),))
    c, s = jnp.cos(beta), jnp.sin(beta)
    col_u = omega / g * (omega * c * dF_dw - 2 * s * dF_db + 4 * c * F)
    col_v = omega / g * (omega * s * dF_dw + 2 * c * dF_db + 4 * s * F)
    col_r = jnp.zeros_like(F) if yaw_column is None else jnp.asarray(yaw_column, dtype=F.dtype)
    return jnp.stack([col_u, col_v, col_r], axis=-1)
