"""Ship motions by strip theory with forward speed (Salvesen, Tuck & Faltinsen 1970, "Ship
motions and sea loads", Trans. SNAME 78), and the added resistance by radiated energy
(Gerritsma & Beukelman 1972).

Axes as in `jaxtow.strip._hull`: x forward from midships, y to port, z up from the
waterline; the modes are sway, heave, roll (starboard down), pitch (bow down) and yaw (bow
to port) about the origin on the waterline at midships. Time dependence e^{−iω_e t} in the
frame that moves with the ship at speed U; β is the direction the waves come from (0 head
seas), so that they travel at χ = β + π and meet the ship at the encounter frequency
ω_e = ω − kU cos χ = ω + kU cos β (`jaxtow.drift.encounter_frequency`, the one
implementation).

**Hydrodynamic forces** (STF, written for this time convention): with the section's complex
coefficient t(x) = ω_e² a(x) + iω_e b(x) (the force per unit length is t times the
section's motion) and c = iU/ω_e, the force in mode j from motion in mode k is

    T_jk = ∫ v_j(x) w_k(x) t dx + c u_j(x_A) w_k(x_A) t(x_A),

with the plain levers u (1 for sway, heave and roll, −x for pitch, x for yaw), the motion
levers w = u plus the speed term (pitch: −x + c; yaw: x − c) and the force levers v = u
minus it (pitch: −x − c; yaw: x + c); the last term acts at a transom x_A only. This is
STF's table (A35 = −∫xa33 − (U/ω²)B33⁰ + …, B35 = −∫xb33 + UA33⁰ − …, A55 = ∫x²a33 +
(U²/ω²)A33⁰ − …) in one formula: the speed terms come from the convective derivative
through Tuck's theorem, and the transom terms from the end of that integration by parts.

**Exciting forces**: Froude-Krylov at the wave frequency plus the diffraction force of each
section through its radiation potentials at the encounter frequency
(`jaxtow.strip._strips.section_wave_forces`), summed with the force levers v_j and the
transom term c u_j(x_A) D_j(x_A).

**Equations**: [−ω_e²(M + A) − iω_e(B + B_v) + C] η = F for the five modes, with M the rigid
body about the origin (`jaxtow.mass_matrix` of the `jaxtow.Loading`), C the hydrostatics
(`jaxtow.hydrostatic_restoring` of the strips' waterplane), and B_v a linear viscous roll
damping, a fraction of the critical at each encounter frequency
(`jaxtow.roll_damping_coefficient`: potential flow alone leaves the roll resonance
unbounded).

**The section solve** is a value: a `SectionTable` over a grid of encounter frequencies,
which `motions` and `added_resistance` accept (``sections=``) and reuse at any speed and
heading it spans. Without one, the grid is planned from the encounter frequencies: at zero
speed (``u`` the number 0) the frequencies themselves; at speed, where the values are
numbers, the distinct encounter frequencies when there are at most ``n_frequencies`` of
them, else ``n_frequencies`` geometrically spaced over their range; under tracing the
geometric grid (its ends held out of the derivatives: a numerical plan, not physics).
Frequencies below 0.3√(g/L) are held there and marked invalid.

Everything is a JAX function: `jax.jit` / `equinox.filter_jit`, `jax.grad` with respect to
the offsets, the principal dimensions, the loading, the speed and the frequencies, and
`jax.vmap` over hull variants.
"""

from __future__ import annotations

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Bool, Complex, Float

from .._body import Loading, hydrostatic_restoring, mass_matrix, roll_damping_coefficient
from .._rules import FINITE, NONNEGATIVE, POSITIVE, check_type, guard, holds_tracers, is_concrete
from .._units import SEA_WATER, Water
from ..drift import encounter_frequency
from ._hull import MODES, Hull
from ._strips import SectionTable, exciting, hydrostatics, radiation, section_table

__all__ = [
    "MODES",
    "FROUDE_LIMIT",
    "LOW_FREQUENCY",
    "Motions",
    "MotionSolve",
    "motions",
    "solve_motions",
    "rigid_body_matrices",
    "plan_sections",
]

#: The highest Froude number U/√(gL) at which the motions are marked valid: strip theory
#: assumes a moderate speed, and its usual validations reach Fn 0.4 (Journée's 1992 Wigley
#: experiments ran at Fn 0.2, 0.3 and 0.4). An estimate of the theory's range, not a sharp
#: limit. The parameter τ = Uω_e/g is no limit of it: τ > 1/4, where no radiated wave runs
#: ahead of the ship, is the usual case in head seas (a Wigley hull at Fn 0.2 has τ ≈ 0.75
#: at its motion peak), and the far-field resistance takes it into account.
FROUDE_LIMIT = 0.4
#: The lowest encounter frequency solved, by √(g/L): below it the sections are held there
#: and the motions marked invalid (strip theory assumes waves shorter than the hull).
LOW_FREQUENCY = 0.3


class Motions(eqx.Module):
    """Strip-theory motions: ``rao`` (w, b, 5) complex over `MODES` (sway, heave [m/m], roll,
    pitch, yaw [rad/m]) about the origin on the waterline at midships, per unit wave
    amplitude at the origin, for wave frequencies ``omega`` (w,) [rad/s], headings ``beta``
    (b,) [rad] (waves from; 0 head seas) and speed ``u`` [m/s]; the encounter frequencies
    ``omega_e`` (w, b) [rad/s]; the hull's added mass and damping (w, b, 5, 5) at them, with
    the speed and transom terms, and the exciting forces (w, b, 5); ``valid`` (w, b): where
    the encounter frequency lies inside the solved range (below it the section
    coefficients are held at the lowest solved frequency) and the Froude number is at
    most `FROUDE_LIMIT`; the ``loading`` used (its roll damping a fraction of critical; a
    hull without roll stability, GM ≤ 0, gets none, and its roll is meaningless)."""

    omega: Float[Array, " w"]
    beta: Float[Array, " b"]
    u: Float[Array, ""]
    omega_e: Float[Array, "w b"]
    rao: Complex[Array, "w b 5"]
    added_mass: Float[Array, "w b 5 5"]
    damping: Float[Array, "w b 5 5"]
    exciting: Complex[Array, "w b 5"]
    valid: Bool[Array, "w b"]
    loading: Loading


class MotionSolve(eqx.Module):
    """The solve behind `Motions`, over the flattened (ω, β) table (m = w·b entries), for
    the added resistance: the encounter frequencies as solved ``omega_e`` (m,) (moved off
    zero), each station's heave ``added_mass``, ``damping`` (n, m) and beam-sea heave
    exciting force ``heave_exciting`` (n, m), and its Froude-Krylov heave force
    ``heave_froude_krylov`` (n, m) in the incident wave (with its phase along the hull)."""

    motions: Motions
    omega_e: Float[Array, " m"]
    added_mass: Float[Array, "n m"]
    damping: Float[Array, "n m"]
    heave_exciting: Complex[Array, "n m"]
    heave_froude_krylov: Complex[Array, "n m"]


def rigid_body_matrices(hull: Hull, loading: Loading | None = None, *, water: Water = SEA_WATER):
    """The mass and restoring matrices (5, 5) over `MODES` about the origin on the waterline
    at midships: mass ρ∇ at the ``loading``'s CoG (x_G default x_B) with its radii of
    gyration (default the estimate for the hull's L and B; `jaxtow.mass_matrix`), and the
    hydrostatics of the strips (`jaxtow.hydrostatic_restoring`). ``loading`` None:
    ``Loading()``, G in the waterline plane over the centre of buoyancy."""
    loading = _loading(hull, loading)
    hs = hydrostatics(hull)
    mass = water.rho * hs.volume
    x_g = hs.x_b if loading.x_g is None else loading.x_g
    cog = jnp.stack([jnp.asarray(x_g, float), jnp.zeros(()), jnp.asarray(loading.z_g, float)])
    radii = loading.radii_for(hull.length, hull.breadth)
    m6 = mass_matrix(mass, cog, radii)
    c6 = hydrostatic_restoring(hs.waterplane, hs.volume, hs.z_b, loading.z_g, water=water)
    return m6[1:, 1:], c6[1:, 1:]


def _loading(hull: Hull, loading: Loading | None) -> Loading:
    if loading is None:
        # G in the waterline plane: a hull of any size stays upright (the panel side's default,
        # `Loading.estimate`, is the thesis's KG of Barge 1 and 2 and would be absurd for a
        # model-scale Wigley hull)
        return Loading()
    check_type("loading", loading, Loading)
    return loading


def _floor(hull: Hull, water: Water):
    return LOW_FREQUENCY * jnp.sqrt(water.g / hull.length)


def plan_sections(hull: Hull, omega, beta, speeds, *, n_frequencies: int = 40, water=SEA_WATER):
    """The encounter-frequency grid [rad/s] of a `SectionTable` that spans the encounter
    frequencies of ``omega`` × ``beta`` at every speed of ``speeds`` [m/s] (numbers, on the
    host): ``n_frequencies`` geometrically spaced over their range (at least the low limit
    0.3√(g/L)), or the distinct values themselves when there are no more. Build the table
    with `jaxtow.strip.section_table` and pass it to `motions` and `added_resistance` at
    each speed and heading."""
    w = np.atleast_1d(np.asarray(omega, float))
    b = np.atleast_1d(np.asarray(beta, float))
    u = np.atleast_1d(np.asarray(speeds, float))
    we = np.abs(
        np.asarray(encounter_frequency(w[:, None, None], b[None, :, None], u[None, None, :]))
    )
    return _grid(we.ravel(), float(_floor(hull, water)), n_frequencies)


def _grid(mag, floor, n):
    """The host plan of `plan_sections` over the magnitudes ``mag`` of the encounter
    frequencies."""
    unique = np.unique(np.maximum(mag, floor))
    if n is None or unique.size <= n:
        grid = unique
    else:
        lo, hi = max(mag.min(), floor), max(mag.max(), floor * 1.01)
        grid = np.maximum(np.geomspace(lo, hi, n), floor)
    if grid.size == 1:
        grid = np.array([grid[0], grid[0] * 1.01])
    return grid


def _traced_grid(mag, floor, n):
    """The geometric grid of `plan_sections` over traced magnitudes (held out of the
    derivatives)."""
    mag = jax.lax.stop_gradient(mag)
    floor = jax.lax.stop_gradient(floor)
    lo = jnp.maximum(jnp.min(mag), floor)
    hi = jnp.maximum(jnp.maximum(jnp.max(mag), floor * 1.01), lo * 1.01)
    return lo * (hi / lo) ** jnp.linspace(0.0, 1.0, n)


def _vector(v):
    """A 1-D float array (converted on the host where the value is concrete: no program)."""
    if is_concrete(v):
        return jnp.asarray(np.atleast_1d(np.asarray(v, dtype=float)))
    return jnp.atleast_1d(jnp.asarray(v, dtype=float))


def _check_inputs(omega, beta, u, n_frequencies):
    for rule, name, v in ((POSITIVE, "omega", omega), (FINITE, "beta", beta)):
        rule.check(name, v)
        if jnp.ndim(v) > 1:
            raise ValueError(f"parameter {name!r} must be a scalar or a 1-D array")
    NONNEGATIVE.check("u", u)
    if n_frequencies is not None and int(n_frequencies) < 2:
        raise ValueError(f"parameter 'n_frequencies' must be >= 2, got {n_frequencies!r}")


def solve_motions(
    hull: Hull,
    omega,
    beta,
    u=0.0,
    *,
    loading: Loading | None = None,
    sections: SectionTable | None = None,
    water: Water = SEA_WATER,
    n_frequencies: int | None = 40,
) -> MotionSolve:
    """`motions` with the solve's internals for the added resistance (`MotionSolve`)."""
    check_type("hull", hull, Hull)
    omega, beta, u = _vector(omega), _vector(beta), jnp.asarray(u, dtype=float)
    _check_inputs(omega, beta, u, n_frequencies)
    loading = _loading(hull, loading)
    if sections is not None:
        check_type("sections", sections, SectionTable)
        if sections.potentials.shape[0] != hull.x.shape[0]:
            raise ValueError(
                f"parameter 'sections': a table of {sections.potentials.shape[0]} stations for "
                f"a hull of {hull.x.shape[0]}"
            )
        plan, grid = "table", None
    elif is_concrete(u) and float(u) == 0.0:
        plan, grid = "zero", None  # the frequencies themselves, each table entry exactly
    elif holds_tracers((hull, omega, beta, u)) or n_frequencies is None:
        plan, grid = "traced", None
    else:  # a host plan: the grid's size depends on the values
        floor = float(LOW_FREQUENCY * np.sqrt(water.g / float(np.sum(np.asarray(hull.dx)))))
        we = _encounter(omega, beta, u, water.g)
        plan, grid = "host", jnp.asarray(_grid(np.abs(np.asarray(we)), floor, n_frequencies))
    n = 40 if n_frequencies is None else int(n_frequencies)
    out, checks = _solve_program(hull, omega, beta, u, loading, sections, grid, water, plan, n)
    return guard(out, checks)


@jax.jit
def _encounter(omega, beta, u, g):
    nw, nb = omega.shape[0], beta.shape[0]
    return encounter_frequency(jnp.repeat(omega, nb), jnp.tile(beta, nw), u, g=g)


@eqx.filter_jit
def _solve_program(hull, omega, beta, u, loading, sections, grid, water, plan, n):
    """The whole solve after the host's plan, one compiled program (an eager call would
    dispatch and compile hundreds of single operations): the section table where none is
    given, the motions, and the traced checks, returned for `guard` to raise on the host or
    attach under an outer trace."""
    checks = [
        POSITIVE.traced("omega", omega),
        FINITE.traced("beta", beta),
        NONNEGATIVE.traced("u (forward speed)", u),
    ]
    nw, nb = omega.shape[0], beta.shape[0]
    we_true = encounter_frequency(jnp.repeat(omega, nb), jnp.tile(beta, nw), u, g=water.g)
    floor = _floor(hull, water)
    index = None
    if plan == "zero":
        sections = section_table(hull, jnp.maximum(omega, floor), water=water)
        index = jnp.repeat(jnp.arange(nw), nb)
    elif plan == "traced":
        sections = section_table(hull, _traced_grid(jnp.abs(we_true), floor, n), water=water)
    elif plan == "host":
        sections = section_table(hull, grid, water=water)
    out = _solve(hull, omega, beta, u, we_true, floor, sections, index, loading, water)
    return out, checks + hull.checks() + loading.checks()


def _solve(hull, omega, beta, u, we_true, floor, sections, index, loading, water):
    nw, nb = omega.shape[0], beta.shape[0]
    w_flat, b_flat = jnp.repeat(omega, nb), jnp.tile(beta, nw)
    g = water.g
    # an encounter frequency of zero (following seas) is moved off zero for the solve, so
    # that the results stay finite (and marked invalid), not NaN
    tiny = 1e-3 * floor
    we = jnp.where(jnp.abs(we_true) < tiny, jnp.where(we_true < 0, -tiny, tiny), we_true)
    a, b, pots, x3, inside = sections.lookup(we, index)
    c = 1j * u / we
    t = we[None, :, None, None] ** 2 * a + 1j * we[None, :, None, None] * b
    tm = radiation(t, hull.x, hull.dx, c, hull.transom)  # (m, 5, 5)
    added = jnp.real(tm) / we[:, None, None] ** 2
    damping = jnp.imag(tm) / we[:, None, None]
    k_cos = -(w_flat**2) / g * jnp.cos(b_flat)  # k cos χ
    f, fk3 = exciting(hull, pots, w_flat, b_flat, c, k_cos, water)
    mm, cc = rigid_body_matrices(hull, loading, water=water)
    bv = roll_damping_coefficient(loading.roll_damping, cc[2, 2], mm[2, 2] + added[:, 2, 2])
    damping_v = damping.at[:, 2, 2].add(bv)
    h = -(we[:, None, None] ** 2) * (mm + added) - 1j * we[:, None, None] * damping_v + cc
    rao = jnp.linalg.solve(h, f[..., None])[..., 0]
    resolved = inside & (jnp.abs(we_true) >= floor * (1 - 1e-12))
    valid = resolved & (u / jnp.sqrt(g * hull.length) <= FROUDE_LIMIT * (1 + 1e-9))
    shape = (nw, nb)
    m = Motions(
        omega=omega,
        beta=beta,
        u=jnp.asarray(u, float),
        omega_e=we_true.reshape(shape),
        rao=rao.reshape(shape + (5,)),
        added_mass=added.reshape(shape + (5, 5)),
        damping=damping.reshape(shape + (5, 5)),
        exciting=f.reshape(shape + (5,)),
        valid=valid.reshape(shape),
        loading=loading,
    )
    return MotionSolve(
        motions=m,
        omega_e=we,
        added_mass=a[..., 1, 1],
        damping=b[..., 1, 1],
        heave_exciting=x3,
        heave_froude_krylov=fk3,
    )


def motions(
    hull: Hull,
    omega,
    beta,
    u=0.0,
    *,
    loading: Loading | None = None,
    sections: SectionTable | None = None,
    water: Water = SEA_WATER,
    n_frequencies: int | None = 40,
) -> Motions:
    """Strip-theory RAOs with forward speed (module docstring) at wave frequencies ``omega``
    [rad/s] and headings ``beta`` [rad] (waves from; 0 head seas), speed ``u`` [m/s] ≥ 0.

    ``loading``: the `jaxtow.Loading` (the CoG above the waterline, its x, the radii of
    gyration and the roll damping; None: ``Loading()``, G in the waterline plane over the
    centre of buoyancy); ``sections``: a `SectionTable` to reuse (`plan_sections`,
    `jaxtow.strip.section_table`; None: solved here on the planned grid of
    ``n_frequencies``, module docstring); ``water``: ρ and g (`jaxtow.Water`). Bad values
    raise a ValueError naming the parameter (eagerly, or `equinox.error_if` under jit)."""
    return solve_motions(
        hull,
        omega,
        beta,
        u,
        loading=loading,
        sections=sections,
        water=water,
        n_frequencies=n_frequencies,
    ).motions
