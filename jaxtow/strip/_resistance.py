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

**The strips' far field** (``method="maruo"``, zero speed): Maruo's (1960) far-field
momentum balance with the strips as the radiating line, the slender-body idea of Joosen
(1966). Each strip radiates 2-D waves of amplitude q = ω X₃ V_z/(ρg²) to each side (X₃ its
beam-sea heave force: Haskind and the energy identity), their 3-D sum has the Kochin
function Q(θ) = ∫ q e^{−ikx cos θ} dx, and the force is what the scattered waves take from
the incident wave's momentum less what they carry (`_far_field`). Unlike Gerritsma-
Beukelman it keeps the interference of the strips' waves along the hull (a hull short
against the waves radiates less than its strips would alone) and the direction the
energy goes. The radiation is the symmetric (heave-pitch) part only.

**Drift table at zero speed** (`drift_qtf`): the R-function method of jaxtow's drift
package (`jaxtow.drift.r_function_method`: F = F_M + R(k_e T) F_R) with the Gerritsma-
Beukelman (or far-field) resistance as the motion part F_M (surge only; strip theory gives no lateral
motion-induced drift) and Faltinsen's short-wave asymptote on the hull's waterline as the
reflection part F_R, weighted by the R-function of k T so that it vanishes in long waves.
The result is a `jaxtow.drift.QTF`, so every consumer of a drift source (the tow model,
the resistance budget, the studies) can use strip theory.
"""

from __future__ import annotations

import equinox as eqx
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Bool, Float

from ..drift import QTF, Waterline, r_function_method
from ._hull import Hull
from ._motions import Motions, _motions

#: the added-resistance methods by name
METHODS = ("gerritsma_beukelman", "maruo")


class AddedResistance(eqx.Module):
    """Added resistance per unit wave amplitude squared ``r`` (w, b) [N/m²] (> 0 astern) at
    wave frequencies ``omega`` (w,) [rad/s], headings ``beta`` (b,) [rad] (waves from; 0
    head seas) and speed ``u`` [m/s], by ``method``; with the `Motions` it came from and
    their ``valid`` mask."""

    omega: Float[Array, " w"]
    beta: Float[Array, " b"]
    u: float = eqx.field(static=True)
    r: Float[Array, "w b"]
    motions: Motions
    valid: Bool[Array, "w b"]
    method: str = eqx.field(static=True)


def _relative_velocity(hull: Hull, m: Motions, internals, rho, g):
    """(V_z (n, m), k (m,), ω (m,), β (m,)): the strips' relative vertical velocity per unit
    wave amplitude (module docstring) over the flattened (ω, β) table."""
    nb = m.beta.shape[0]
    w = jnp.repeat(m.omega, nb)
    beta = jnp.tile(m.beta, m.omega.shape[0])
    we = internals["we_solved"]
    k = w**2 / g
    k_cos = -k * jnp.cos(beta)  # k cos χ
    eta3 = internals["rao"][:, 1]
    eta5 = internals["rao"][:, 3]
    x = hull.x[:, None]
    breadth = 2.0 * hull.y[:, 0][:, None]
    zeta = internals["fk3"] / (rho * g * breadth) * jnp.exp(1j * k_cos[None] * x)
    v = -1j * we * (eta3 - x * eta5) + m.u * eta5 + 1j * w * zeta
    return v, k, w, beta


def _gerritsma_beukelman(hull: Hull, m: Motions, internals, rho, g):
    v, k, _, beta = _relative_velocity(hull, m, internals, rho, g)
    a33 = internals["a"][..., 1, 1]
    b33 = internals["b"][..., 1, 1]
    da_dx = jnp.asarray(jnp.gradient(a33, hull.x, axis=0))
    b_eff = b33 - m.u * da_dx
    power = jnp.sum(hull.dx[:, None] * b_eff * jnp.abs(v) ** 2, axis=0)  # 2 × mean power
    return k * jnp.cos(beta) * power / (2.0 * jnp.abs(internals["we_solved"]))


#: directions of the far-field integral of `maruo` (midpoint rule over the circle)
N_DIRECTIONS = 360


def _far_field(x, dx, q, k, omega, cos_chi, rho, g):
    """Mean power [W per ζa²] and surge drift force [N per ζa²] of the waves radiated by a
    line of strips at ``x`` (n,) with lengths ``dx`` whose 2-D outgoing wave amplitudes
    (each side, per unit incident amplitude) are ``q`` (n, m), at wave number ``k`` and
    frequency ``omega`` (m,), for an incident wave travelling at cos χ (m,):

        dP/dθ = ρ g c_g k/(4π) |Q(θ)|²,  Q(θ) = Σ q e^{−ikx cos θ} dx,
        F_x = (k/ω) ∫ dP/dθ (cos χ − cos θ) dθ,

    the momentum the scattered waves take from the incident wave (energy over phase speed
    along its direction) less the momentum they carry away. The constant makes the power of
    a long uniform line equal to the 2-D strips' ρ g c_g |q|² per unit length."""
    theta = 2.0 * jnp.pi * (jnp.arange(N_DIRECTIONS) + 0.5) / N_DIRECTIONS
    phase = jnp.exp(-1j * k[None, :, None] * x[:, None, None] * jnp.cos(theta)[None, None])
    big_q = jnp.einsum("n,nm,nmt->mt", dx, q, phase)  # (m, θ)
    const = rho * g * (g / (2.0 * omega)) * k / (4.0 * jnp.pi)
    dens = const[:, None] * jnp.abs(big_q) ** 2
    d_theta = 2.0 * jnp.pi / N_DIRECTIONS
    power = jnp.sum(dens, axis=1) * d_theta
    lost = jnp.sum(dens * (cos_chi[:, None] - jnp.cos(theta)[None]), axis=1)
    force = k / omega * lost * d_theta
    return power, force


def _maruo(hull: Hull, m: Motions, internals, rho, g):
    v, k, w, beta = _relative_velocity(hull, m, internals, rho, g)
    # each strip's outgoing wave per unit relative velocity, by Haskind from its beam-sea
    # heave force: |A₃| = ω|X₃|/(ρg²) (the energy identity b₃₃ = ω|X₃|²/(ρg²)); the common
    # phase factor of the relation drops out of |Q|²
    q = w[None] / (rho * g**2) * internals["x3"] * v
    _, fx = _far_field(hull.x, hull.dx, q, k, w, -jnp.cos(beta), rho, g)
    return -fx


def added_resistance(
    hull: Hull,
    omega,
    beta,
    u: float = 0.0,
    *,
    method: str = "gerritsma_beukelman",
    z_g: float = 0.0,
    x_g=None,
    radii=None,
    roll_damping: float | None = None,
    n_encounter: int = 40,
    rho: float = 1025.0,
    g: float = 9.80665,
) -> AddedResistance:
    """Added resistance in regular waves per ζa² [N/m²] by ``method`` (`METHODS`; module
    docstring), from `jaxtow.strip.motions` with the same arguments. Differentiable in the
    hull's offsets."""
    if method not in METHODS:
        raise ValueError(f"parameter 'method' must be one of {METHODS}, got {method!r}")
    if method == "maruo" and u != 0:
        raise ValueError(
            f"parameter 'u' = {u!r}: method 'maruo' is the zero-speed far field (its "
            "forward-speed form, with the Doppler-shifted wave systems, is not built)"
        )
    m, internals = _motions(
        hull, omega, beta, u, z_g, x_g, radii, roll_damping, n_encounter, rho, g
    )
    solve = _maruo if method == "maruo" else _gerritsma_beukelman
    r = solve(hull, m, internals, rho, g)
    return AddedResistance(
        omega=m.omega,
        beta=m.beta,
        u=m.u,
        r=r.reshape(m.valid.shape),
        motions=m,
        valid=m.valid,
        method=method,
    )


def drift_qtf(
    hull: Hull,
    waterline: Waterline,
    omega,
    beta,
    *,
    rho: float = 1025.0,
    g: float = 9.80665,
    **motion_options,
) -> QTF:
    """A zero-speed mean-drift `jaxtow.drift.QTF` from strip theory (module docstring) on
    ``omega`` [rad/s] × ``beta`` [rad, from 0 to π ascending], completed to ±β by the hull's
    port-starboard symmetry; ``waterline``: the hull's waterline for the short-wave
    reflection part; ``motion_options``: those of `added_resistance` (method, z_g, radii,
    roll_damping, ...)."""
    beta = np.asarray(beta, float)
    if beta.ndim != 1 or beta[0] != 0.0 or not np.isclose(beta[-1], np.pi):
        raise ValueError("parameter 'beta' must run from 0 to pi (the other half by symmetry)")
    ar = added_resistance(hull, omega, beta, 0.0, rho=rho, g=g, **motion_options)
    fm = jnp.stack([-ar.r, jnp.zeros_like(ar.r), jnp.zeros_like(ar.r)], axis=-1)
    est = r_function_method(
        waterline,
        ar.omega[:, None],
        jnp.asarray(beta)[None, :],
        motion=lambda *_: fm,
        rho=rho,
        g=g,
    )
    fy = np.array(est.fy)
    nz = np.array(est.nz)
    ends = np.isclose(beta, 0.0) | np.isclose(beta, np.pi)
    fy[:, ends] = 0.0  # exact symmetry in head and following seas
    nz[:, ends] = 0.0
    return QTF.symmetric(omega=np.asarray(ar.omega), beta=beta, fx=np.asarray(est.fx), fy=fy, nz=nz)


__all__ = ["METHODS", "AddedResistance", "added_resistance", "drift_qtf"]
