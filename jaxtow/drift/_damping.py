"""Forward speed in the mean drift: Aranha's formula and the wave-drift damping it implies
(Aranha 1994 surge/sway, 1996 yaw moment; thesis eqs 2.35-2.42, 5.1; docs/model.md section 8).

Convention: β is the direction the waves come *from*, counter-clockwise from the bow, so they
travel along k̂ = (−cos β, −sin β) in body axes; ê = (cos β, sin β), ê⊥ = (−sin β, cos β).
For a vessel velocity U = (u, v) in waves of absolute frequency ω, Aranha's formula in its
finite form is

    F(ω, β; U) ≈ [1 + (4ω/g) U·ê] · F(ω_e, β_e; 0),
    ω_e = ω + (ω²/g) U·ê,   β_e = β + (2ω/g) U·ê⊥,

valid for small τ = ω|U|/g. Its derivative at U = 0 is the wave-drift damping B(ω, β) of
eqs 2.40-2.41 (B_i1 = (ω/g)[ω cos β ∂_ω − 2 sin β ∂_β + 4 cos β] F_i and likewise B_i2),
which `wave_drift_damping` takes by forward-mode autodiff of this one formula. The ω ∂_ω
part of B *is* the encounter-frequency shift: the finite form evaluates the QTF at ω_e and
adds nothing; the linear form F(ω) + B(ω)·U does not shift ω. Doing both (F(ω_e) + B(ω_e)·U,
the thesis's reading of eq. 2.38 with the shift of section 5.1) counts the shift twice; it
stays available as ``form="thesis"`` (`jaxtow.drift.sailing_drift`).

Yaw rate (eq. 2.42, Aranha & Martins 1997). Their slender-body expressions were not
available to us; jaxtow implements the slender-body construction the thesis describes: the
section at x (from the CoG) moves sideways with v + r x, so the sectional drift density f(x)
changes by r x ∂_v f, and integrating over the length gives B_16 = ∂_v M_x,1,
B_26 = ∂_v M_y,1 and B_66 = ∂_v M_y,2, with ∂_v the sway operator of eq. 2.41 applied to the
sectional moments of the table (`QTF.sectional`, eqs 2.43-2.48). The yaw moment of a
section is taken as x f_y (the −y f_x part is neglected, slender body), so B_26 ≈ B_62 when
Nz ≈ M_y,1. Without sectional moments the column is zero, and results say so
(``yaw_rate_damping`` validity flag).
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, ArrayLike, Float

from .._program_cache import host_program
from .._rules import is_concrete
from .._units import G
from ._qtf import QTF

#: Upper limit of τ = ω|U|/g for Aranha's formula (a validity flag, not a switch). Aranha's
#: derivation is a first-order expansion in τ; τ = 1/4 is where forward-speed wave theory
#: changes character (for τ > 1/4 the radiated waves can no longer travel ahead of the
#: vessel), the usual bound quoted for small-τ approximations.
TAU_MAX = 0.25


def encounter_frequency(
    omega0: ArrayLike, beta: ArrayLike, u: ArrayLike, v: ArrayLike = 0.0, *, g: float = G
) -> Float[Array, "..."]:
    """Encounter frequency ω_e = ω0 − k0 k̂·U = ω0 + (ω0²/g)(u cos β + v sin β) (eqs 2.35, 2.36).

    Head seas (β = 0) with u > 0 raise ω_e; so does swaying towards waves from port
    (β = π/2, v > 0). The thesis prints eq. 2.35 with ``− v sin β``, i.e. with β measured the
    other way round; with jaxtow's convention and the tow model's β = −ψ this form makes ω_e
    independent of the barge heading, as it must be for waves from ahead of the tug. ω_e ≤ 0
    means the vessel overtakes the waves (following seas faster than their phase speed):
    outside the drift model, flagged by `sailing_validity`.
    """
    return _encounter_frequency(omega0, beta, u, v, g=g)


@host_program()
def _encounter_frequency(omega0, beta, u, v, *, g: float):
    omega0 = jnp.asarray(omega0)
    return omega0 + omega0**2 / g * (u * jnp.cos(beta) + v * jnp.sin(beta))


def aranha(table, omega: ArrayLike, beta: ArrayLike, u: ArrayLike, v: ArrayLike, *, g: float = G):
    """Aranha's finite form [1 + (4ω/g) U·ê] · table(ω_e, β_e) for any zero-speed table
    ``table(omega, beta) -> (3,)`` (a `QTF`, or its sectional moments `QTF.moments`)."""
    omega = jnp.asarray(omega, dtype=float)
    beta = jnp.asarray(beta, dtype=float)
    u, v = jnp.asarray(u, dtype=float), jnp.asarray(v, dtype=float)
    c, s = jnp.cos(beta), jnp.sin(beta)
    along = u * c + v * s  # U·ê
    across = -u * s + v * c  # U·ê⊥
    we = omega + omega**2 / g * along
    be = beta + 2.0 * omega / g * across
    return (1.0 + 4.0 * omega / g * along) * table(we, be)


def _velocity_column(table, omega, beta, g, which: str):
    """d/du (``which="u"``) or d/dv (``"v"``) of Aranha's finite form at U = 0: a (3,)
    column."""
    zero = jnp.zeros((), dtype=float)
    if which == "u":
        f = lambda x: aranha(table, omega, beta, x, zero, g=g)  # noqa: E731
    else:
        f = lambda x: aranha(table, omega, beta, zero, x, g=g)  # noqa: E731
    return jax.jvp(f, (zero,), (1.0 + zero,))[1]


def yaw_rate_damping(q: QTF, omega: ArrayLike, beta: ArrayLike, *, g: float = G):
    """Yaw-rate column (B_16, B_26, B_66) per ζa² [N·s/m², N·s/m², N·m·s/m²] of the wave-drift
    damping: the sway operator of eq. 2.41 applied to the sectional moments (M_x,1, M_y,1,
    M_y,2) (slender-body construction, module docstring). Zero when ``q`` has no sectional
    moments (`QTF.has_sectional`)."""
    if not getattr(q, "has_sectional", False):
        return jnp.zeros(3, dtype=float)
    return _velocity_column(q.moments, omega, beta, g, "v")


def _check_heading(q, beta) -> None:
    """Eager: a concrete β outside a partial table's headings is an error naming it (the
    interpolant would extrapolate silently; under jit the tow model's ``heading_in_table``
    flag reports it instead)."""
    if not isinstance(q, QTF) or not is_concrete(beta):
        return
    inside = np.asarray(q.in_table(beta))
    if not inside.all():
        lo, hi = (float(np.degrees(b)) for b in (q.beta[0], q.beta[-1]))
        raise ValueError(
            f"parameter 'beta' must lie inside the table's headings [{lo:g}, {hi:g}] deg, got "
            f"{np.degrees(np.asarray(beta))} deg (complete the table by symmetry: "
            "QTF.symmetric, or give every heading)"
        )


def wave_drift_damping(
    q: QTF, omega: ArrayLike, beta: ArrayLike, *, g: float = G
) -> Float[Array, "3 3"]:
    """3×3 wave-drift damping matrix B per ζa², columns for (u, v, r), thesis eq. 2.39:
    F(ω, β; u, v, r) ≈ F(ω, β; 0) + B(ω, β)·(u, v, r). ``q``: a `QTF`, or any
    differentiable zero-speed table ``q(omega, beta) -> (3,)``.

    The surge and sway columns are the derivative of Aranha's finite form at U = 0 by
    forward-mode autodiff (equal to the printed eqs 2.40-2.41); the yaw-rate column is
    `yaw_rate_damping` (zero without sectional moments). One (ω, β) a call: vmap over many
    (`jaxtow.waves.mean_drift_damping` integrates a spectrum's)."""
    for name, value in (("omega", omega), ("beta", beta)):
        if jnp.ndim(value) != 0:
            raise ValueError(
                f"parameter {name!r} must be a single value (jax.vmap over many), got shape "
                f"{jnp.shape(value)}"
            )
    _check_heading(q, beta)
    return _wave_drift_damping(q, omega, beta, g=g)


@host_program()
def _wave_drift_damping(q, omega, beta, *, g: float):
    return drift_and_damping(q, omega, beta, g=g)[1]


def damping_matrix(q, omega, beta, *, g: float = G):
    """`wave_drift_damping` without the eager heading check: for the tow model's forces,
    which flag a heading outside the table (``heading_in_table``) instead of refusing it."""
    return drift_and_damping(q, omega, beta, g=g)[1]


def drift_and_damping(q, omega, beta, *, g: float = G):
    """(F(ω, β), B(ω, β)): the zero-speed drift and `damping_matrix` from one table look-up.
    Aranha's finite form is differentiated at U = 0 along u and v in one forward pass (the
    two tangents share the primal, which is F itself), for the forces and, where the table
    has them, the sectional moments (`QTF.forces_and_moments`), whose sway derivative is the
    yaw-rate column (`yaw_rate_damping`)."""
    sectional = bool(getattr(q, "has_sectional", False))
    table = q.forces_and_moments if sectional else q

    def f(x):
        return aranha(table, omega, beta, x[0], x[1], g=g)

    zero = jnp.zeros(2, dtype=float)
    value, jac = jax.vmap(lambda t: jax.jvp(f, (zero,), (t,)), out_axes=(None, -1))(
        jnp.eye(2, dtype=float)
    )
    col_r = jac[3:, 1] if sectional else jnp.zeros(3, dtype=jac.dtype)
    return value[:3], jnp.concatenate([jac[:3], col_r[:, None]], axis=-1)


def sailing_validity(
    omega: ArrayLike, beta: ArrayLike, u: ArrayLike, v: ArrayLike = 0.0, *, g: float = G
) -> dict:
    """Validity of the forward-speed drift model at (ω, β; u, v): the encounter frequency and
    whether it is positive (not overtaking the waves), and τ = ω|U|/g against `TAU_MAX`."""
    we = encounter_frequency(omega, beta, u, v, g=g)
    tau = jnp.asarray(omega) * jnp.sqrt(jnp.asarray(u) ** 2 + jnp.asarray(v) ** 2) / g
    return dict(
        encounter_frequency=we,
        encounter_positive=we > 0,
        tau=tau,
        tau_ok=tau < TAU_MAX,
    )
