"""The frequency-domain response of the linearised tow to the slowly varying drift: the check
of the Monte Carlo that does not depend on its time stepping.

About the static equilibrium y* of the mean model, the tow is ẏ = J (y − y*) + G f(t), with
J the Jacobian of the mean model (its wave-drift damping included) and G = ∂ẏ/∂F the
response of the vector field to a body-axis load (autodiff, through the mass matrix). The
slow drift of `jaxtow.forces.SlowDriftForce` in Newman's approximation is a sum over the pairs
of components i < j of 2 a_i a_j T_ij cos((ω_e,i − ω_e,j) t + ε_i − ε_j), T_ij = (T_i + T_j)/2
with T_i the sailing drift at y*. With independent uniform phases the pairs are
uncorrelated, so the variance of any state is exactly

    σ² = Σ_{i<j} ½ |H(μ_ij) c_ij|²,   H(μ) = (iμ I − J)⁻¹ G,   c_ij = a_i a_j (T_i + T_j),

(μ_ij the pair's frequency by U/L, c_ij non-dimensional) for the very components the runs
use. The sway offset's variance is that of its linearisation about y*.
"""

from __future__ import annotations

import dataclasses
import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from .._dynamics import TowModel, sway_offset, unchecked_vector_field
from .._equilibrium import equilibria, straight_behind
from .._stability import jacobian
from ..forces import CombinedForce, ConstantBodyForce, SlowDriftForce, combine, force_terms

__all__ = ["LinearResponse", "linear_response"]


@dataclasses.dataclass(frozen=True)
class LinearResponse:
    """The standard deviations of the linearised tow's yaw [deg] and sway offset [L] in the
    slow drift, the equilibrium ``state`` they are about, and the largest real part of the
    Jacobian's eigenvalues (< 0: the linearisation has a stationary response)."""

    yaw_std: float
    sway_std: float
    state: np.ndarray
    max_real: float


def linear_response(model: TowModel) -> LinearResponse:
    """The linear response of ``model`` (a tow model holding one `SlowDriftForce`, e.g. a
    run's model from `jaxtow.risk.risk_model`) to its slow drift (module docstring)."""
    forces = force_terms(model.external)
    slow = [f for f in forces if isinstance(f, SlowDriftForce)]
    if len(slow) != 1:
        raise ValueError("parameter 'model': needs exactly one SlowDriftForce")
    force = slow[0]
    mean_forces = [f.mean_force() if isinstance(f, SlowDriftForce) else f for f in forces]
    mean = eqx.tree_at(lambda m: m.external, model, combine(mean_forces))
    eqs = equilibria(mean)
    mask = np.asarray(straight_behind(np.asarray(eqs.psi), np.asarray(eqs.valid)))
    if not mask.any():
        raise ValueError("parameter 'model': its mean model has no straight-behind equilibrium")
    y = jnp.asarray(np.asarray(eqs.state)[int(np.argmax(mask))])
    J = jacobian(mean, y)

    def with_load(F):
        m = eqx.tree_at(
            lambda m: m.external, mean, CombinedForce((*mean_forces, ConstantBodyForce(F)))
        )
        return unchecked_vector_field(0.0, y, m)

    G = jax.jacfwd(with_load)(jnp.zeros(3))  # (6, 3)
    sc = force.scales
    U, L = sc.u_tug, sc.length
    T = jax.vmap(sc.nondimensional)(force.transfer(y))  # (n, 3)
    a = force.amplitudes()
    we = force.encounter()
    i, j = np.triu_indices(int(a.shape[0]), k=1)
    mu = (we[i] - we[j]) * L / U
    c = (a[i] * a[j])[:, None] * (T[i] + T[j])  # (pairs, 3)
    eye = jnp.eye(6)

    def response(m, cij):
        return jnp.linalg.solve(1j * m * eye - J, G @ cij)

    X = jax.vmap(response)(mu, c)  # (pairs, 6)
    ds = jax.grad(lambda yy: sway_offset(yy, model.towline.xp, model.towline.yp))(y)
    yaw_var = 0.5 * jnp.sum(jnp.abs(X[:, 5]) ** 2)
    sway_var = 0.5 * jnp.sum(jnp.abs(X @ ds) ** 2)
    lam = np.linalg.eigvals(np.asarray(J))
    return LinearResponse(
        yaw_std=float(jnp.sqrt(yaw_var)) * 180.0 / math.pi,
        sway_std=float(jnp.sqrt(sway_var)),
        state=np.asarray(y),
        max_real=float(np.max(lam.real)),
    )
