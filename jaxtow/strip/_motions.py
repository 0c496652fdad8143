"""Ship motions by strip theory with forward speed (Salvesen, Tuck & Faltinsen 1970, "Ship
motions and sea loads", Trans. SNAME 78), and the added resistance by radiated energy
(Gerritsma & Beukelman 1972).

Axes as in `jaxtow.strip._hull`: x forward from midships, y to port, z up from the
waterline; the modes are sway, heave, roll (starboard down), pitch (bow down) and yaw (bow
to port) about the origin on the waterline at midships. Time dependence e^{−iω_e t} in the
frame that moves with the ship at speed U; β is the direction the waves come from (0 head
seas), so that they travel at χ = β + π and meet the ship at the encounter frequency
ω_e = ω − kU cos χ = ω + kU cos β.

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
section through its radiation potentials at the encounter frequency (`_hull._section_wave_
forces`), summed with the force levers v_j and the transom term c u_j(x_A) D_j(x_A).

**Equations**: [−ω_e²(M + A) − iω_e(B + B_v) + C] η = F for the five modes, with M the rigid
body about the origin (mass ρ∇ at (x_G, z_G), radii of gyration about G), C the
hydrostatics (`hydrostatics`, with ρg∇(z_B − z_G) in roll and pitch), and B_v a linear
viscous roll damping, a fraction of the critical 2√((M44 + A44) C44) at each encounter
frequency (`jaxtow.ASSUMPTIONS['roll_damping']`, an estimate: potential flow alone leaves
the roll resonance unbounded).
"""

from __future__ import annotations

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Bool, Complex, Float

from .._values import ASSUMPTIONS
from ._hull import MODES, Hull, _concrete, _exciting, _radiation, hydrostatics
from ._sections import section_coefficients


class Motions(eqx.Module):
    """Strip-theory motions: ``rao`` (w, b, 5) complex over `MODES` (sway, heave [m/m], roll,
    pitch, yaw [rad/m]) about the origin on the waterline at midships, per unit wave
    amplitude at the origin, for wave frequencies ``omega`` (w,) [rad/s], headings ``beta``
    (b,) [rad] (waves from; 0 head seas) and speed ``u`` [m/s]; the encounter frequencies
    ``omega_e`` (w, b) [rad/s]; the hull's added mass and damping (w, b, 5, 5) at them, with
    the speed and transom terms, and the exciting forces (w, b, 5); ``valid`` (w, b): where
    the encounter frequency lies inside the computed range (below it the section
    coefficients are held at the lowest computed frequency) and the Froude number is at
    most `FROUDE_LIMIT`. ``roll_damping``: the fraction of critical used (an estimate; a hull
    without roll stability, GM ≤ 0, gets none, and its roll is meaningless)."""

    omega: Float[Array, " w"]
    beta: Float[Array, " b"]
    u: float = eqx.field(static=True)
    omega_e: Float[Array, "w b"]
    rao: Complex[Array, "w b 5"]
    added_mass: Float[Array, "w b 5 5"]
    damping: Float[Array, "w b 5 5"]
    exciting: Complex[Array, "w b 5"]
    valid: Bool[Array, "w b"]
    roll_damping: float = eqx.field(static=True)


#: The highest Froude number U/√(gL) at which the motions are marked valid: strip theory
#: assumes a moderate speed, and its usual validations reach Fn 0.4 (Journée's 1992 Wigley
#: experiments ran at Fn 0.2, 0.3 and 0.4). An estimate of the theory's range, not a sharp
#: limit. The parameter τ = Uω_e/g is no limit of it: τ > 1/4, where no radiated wave runs
#: ahead of the ship, is the usual case in head seas (a Wigley hull at Fn 0.2 has τ ≈ 0.75
#: at its motion peak), and the far-field resistance (`maruo`) takes it into account.
FROUDE_LIMIT = 0.4


def encounter_frequency(omega, beta, u, g: float = 9.80665):
    """ω_e = ω + (ω²/g) U cos β [rad/s] (β the direction the waves come from, 0 head seas);
    negative where following waves overtake the ship."""
    omega = jnp.asarray(omega, dtype=float)
    return omega + omega**2 / g * u * jnp.cos(beta)


def _frequency_grid(omega_e, n, floor):
    """The section solve's frequencies: ``omega_e`` itself where it holds few values, else
    ``n`` geometrically spaced between its smallest and largest magnitude (at least
    ``floor``); with the linear-interpolation index and weight of every |ω_e|."""
    mag = np.abs(np.asarray(omega_e, float)).ravel()
    lo, hi = max(mag.min(), floor), max(mag.max(), floor * 1.01)
    grid = np.unique(mag) if n is None or np.unique(mag).size <= n else np.geomspace(lo, hi, n)
    grid = np.maximum(grid, floor)
    if grid.size == 1:
        grid = np.array([grid[0], grid[0] * 1.01])
    q = np.clip(mag, grid[0], grid[-1])
    i = np.clip(np.searchsorted(grid, q) - 1, 0, grid.size - 2)
    t = (q - grid[i]) / (grid[i + 1] - grid[i])
    return grid, i, t, mag >= grid[0] * (1 - 1e-12)


def _mass_matrix(mass, x_g, z_g, radii):
    kxx, kyy, kzz = radii
    m = jnp.zeros((5, 5))
    m = m.at[0, 0].set(mass).at[1, 1].set(mass)
    m = m.at[0, 2].set(-mass * z_g).at[2, 0].set(-mass * z_g)
    m = m.at[0, 4].set(mass * x_g).at[4, 0].set(mass * x_g)
    m = m.at[1, 3].set(-mass * x_g).at[3, 1].set(-mass * x_g)
    m = m.at[2, 2].set(mass * (kxx**2 + z_g**2))
    m = m.at[3, 3].set(mass * (kyy**2 + x_g**2 + z_g**2))
    return m.at[4, 4].set(mass * (kzz**2 + x_g**2))


def _restoring(hs, mass, z_g, rho, g):
    lever = rho * g * hs["volume"] * (hs["z_b"] - z_g)
    c = jnp.zeros((5, 5))
    c = c.at[1, 1].set(hs["c33"]).at[1, 3].set(hs["c35"]).at[3, 1].set(hs["c35"])
    c = c.at[2, 2].set(hs["c44"] + lever)
    return c.at[3, 3].set(hs["c55"] + lever)


def _sections_at(hull, omega_e, n_encounter, rho, g):
    """Section coefficients, radiation potentials and beam-sea heave exciting forces of every
    station at |ω_e| (m,), linearly interpolated from a solve on `_frequency_grid`; the
    complex ones conjugated where ω_e < 0 (the radiated waves of the reversed time
    dependence)."""
    length = float(jnp.sum(hull.dx))
    grid, i, t, inside = _frequency_grid(omega_e, n_encounter, 0.3 * np.sqrt(g / length))
    secs = jax.vmap(lambda y, z: section_coefficients(y, z, jnp.asarray(grid), rho=rho, g=g))(
        hull.y, hull.z
    )

    def at(v):  # (n, G, ...) -> (n, m, ...)
        tt = jnp.asarray(t).reshape((1, -1) + (1,) * (v.ndim - 2))
        return v[:, i] * (1 - tt) + v[:, i + 1] * tt

    neg = jnp.asarray(np.asarray(omega_e) < 0)[None, :]
    pots = at(secs.potentials)
    pots = jnp.where(neg[..., None, None], jnp.conj(pots), pots)
    x3 = at(secs.exciting[..., 1])
    x3 = jnp.where(neg, jnp.conj(x3), x3)
    return at(secs.added_mass), at(secs.damping), pots, x3, inside


def _motion_solve(hull, omega, beta, u, z_g, x_g, radii, roll_damping, n_encounter, rho, g):
    w_flat = jnp.repeat(omega, beta.shape[0])
    b_flat = jnp.tile(beta, omega.shape[0])
    we_true = encounter_frequency(w_flat, b_flat, u, g)
    length = float(jnp.sum(hull.dx))
    floor = 0.3 * np.sqrt(g / length)  # below it: invalid (`valid`)
    # an encounter frequency of zero (following seas) is moved off zero for the solve, so
    # that the results stay finite (and marked invalid), not NaN
    tiny = 1e-3 * floor
    we = jnp.where(jnp.abs(we_true) < tiny, jnp.where(we_true < 0, -tiny, tiny), we_true)
    n_grid = None if u == 0 else n_encounter  # at zero speed: the frequencies themselves
    a, b, pots, x3, inside = _sections_at(hull, np.asarray(we), n_grid, rho, g)
    c = 1j * u / we
    t = we[None, :, None, None] ** 2 * a + 1j * we[None, :, None, None] * b
    tm = _radiation(t, hull.x, hull.dx, c, hull.transom)  # (m, 5, 5)
    added = jnp.real(tm) / we[:, None, None] ** 2
    damping = jnp.imag(tm) / we[:, None, None]
    k_cos = -(w_flat**2) / g * jnp.cos(b_flat)  # k cos χ
    f, fk3 = _exciting(hull, pots, w_flat, b_flat, c, k_cos, rho, g)
    mm, cc = rigid_body_matrices(hull, z_g=z_g, x_g=x_g, radii=radii, rho=rho, g=g)
    i44 = mm[2, 2] + added[:, 2, 2]
    crit = i44 * cc[2, 2]  # no critical damping where the hull has no roll stability
    bv = 2.0 * roll_damping * jnp.where(crit > 0, jnp.sqrt(jnp.where(crit > 0, crit, 1.0)), 0.0)
    damping_v = damping.at[:, 2, 2].add(bv)
    h = -(we[:, None, None] ** 2) * (mm + added) - 1j * we[:, None, None] * damping_v + cc
    rao = jnp.linalg.solve(h, f[..., None])[..., 0]
    resolved = jnp.asarray(inside) & (jnp.abs(we_true) >= floor * (1 - 1e-12))
    valid = resolved & (u / np.sqrt(g * length) <= FROUDE_LIMIT * (1 + 1e-9))
    return dict(
        we=we_true,
        we_solved=we,
        rao=rao,
        added=added,
        damping=damping,
        f=f,
        valid=valid,
        fk3=fk3,
        a=a,
        b=b,
        x3=x3,
    )


def _inputs(hull, omega, beta, u, radii, roll_damping):
    omega = np.atleast_1d(np.asarray(omega, dtype=float))
    beta = np.atleast_1d(np.asarray(beta, dtype=float))
    if omega.ndim != 1 or not np.all(np.isfinite(omega)) or np.any(omega <= 0):
        raise ValueError(f"parameter 'omega' must be a 1-D array of frequencies > 0, got {omega}")
    if beta.ndim != 1 or not np.all(np.isfinite(beta)):
        raise ValueError(f"parameter 'beta' must be a 1-D array of finite headings, got {beta}")
    if not (np.isfinite(u) and u >= 0):
        raise ValueError(f"parameter 'u' (forward speed) must be finite and >= 0, got {u!r}")
    if not (np.isfinite(roll_damping) and 0 <= roll_damping < 1):
        raise ValueError(
            f"parameter 'roll_damping' (fraction of critical) must lie in [0, 1), got {roll_damping!r}"
        )
    concrete = [r for r in radii if _concrete(r)]
    if len(radii) != 3 or not all(np.isfinite(r) and r > 0 for r in concrete):
        raise ValueError(f"parameter 'radii' must be three radii of gyration > 0, got {radii!r}")
    return jnp.asarray(omega), jnp.asarray(beta)


def default_radii(hull: Hull) -> tuple[float, float, float]:
    """(k_xx, k_yy, k_zz) [m] from `jaxtow.ASSUMPTIONS['radii_of_gyration']` (fractions of
    the hull's beam and length; an estimate)."""
    fx, fy, fz = ASSUMPTIONS["radii_of_gyration"]["value"]
    length = jnp.sum(hull.dx)
    breadth = 2.0 * jnp.max(hull.y[:, 0])
    return fx * breadth, fy * length, fz * length


def rigid_body_matrices(
    hull: Hull,
    *,
    z_g: float = 0.0,
    x_g=None,
    radii=None,
    rho: float = 1025.0,
    g: float = 9.80665,
):
    """The mass and restoring matrices (5, 5) over `MODES` about the origin on the waterline
    at midships: mass ρ∇ at (x_G, z_G) [m] (x_G default x_B), radii of gyration ``radii``
    about G (default `default_radii`), and the hydrostatics of the strips with
    ρg∇(z_B − z_G) in roll and pitch."""
    radii = default_radii(hull) if radii is None else tuple(radii)
    hs = hydrostatics(hull, rho=rho, g=g)
    mass = rho * hs["volume"]
    x_g = hs["x_b"] if x_g is None else x_g
    return _mass_matrix(mass, x_g, z_g, radii), _restoring(hs, mass, z_g, rho, g)


def motions(
    hull: Hull,
    omega,
    beta,
    u: float = 0.0,
    *,
    z_g: float = 0.0,
    x_g=None,
    radii=None,
    roll_damping: float | None = None,
    n_encounter: int = 40,
    rho: float = 1025.0,
    g: float = 9.80665,
) -> Motions:
    """Strip-theory RAOs with forward speed (module docstring) at wave frequencies ``omega``
    [rad/s] and headings ``beta`` [rad] (waves from; 0 head seas), speed ``u`` [m/s] ≥ 0.

    ``z_g``: the centre of gravity's height above the waterline [m] (default 0, the
    waterline); ``x_g``: its x [m] (default: the centre of buoyancy's); ``radii``: (k_xx,
    k_yy, k_zz) about G [m] (default `default_radii`, an estimate); ``roll_damping``: the
    linear viscous roll damping as a fraction of critical (default
    `jaxtow.ASSUMPTIONS['roll_damping']`, an estimate). The sections are solved at
    ``n_encounter`` encounter frequencies spanning the table and interpolated linearly
    (at zero speed, or where the table has no more distinct encounter frequencies, at the
    frequencies themselves); frequencies below 0.3√(g/L) are held there and marked
    invalid. ``omega``, ``beta`` and ``u`` are data (not traced);
    the result is differentiable in the hull's offsets and the mass properties."""
    return _motions(hull, omega, beta, u, z_g, x_g, radii, roll_damping, n_encounter, rho, g)[0]


def _motions(hull, omega, beta, u, z_g, x_g, radii, roll_damping, n_encounter, rho, g):
    """(`Motions`, the solve's internals for the added resistance)."""
    if not isinstance(hull, Hull):
        raise TypeError(f"parameter 'hull' must be a jaxtow.strip.Hull, got {type(hull).__name__}")
    radii = default_radii(hull) if radii is None else tuple(radii)
    if roll_damping is None:
        roll_damping = float(ASSUMPTIONS["roll_damping"]["value"])
    omega, beta = _inputs(hull, omega, beta, u, radii, roll_damping)
    r = _motion_solve(
        hull, omega, beta, float(u), z_g, x_g, radii, roll_damping, n_encounter, rho, g
    )
    shape = (omega.shape[0], beta.shape[0])
    out = Motions(
        omega=omega,
        beta=beta,
        u=float(u),
        omega_e=r["we"].reshape(shape),
        rao=r["rao"].reshape(shape + (5,)),
        added_mass=r["added"].reshape(shape + (5, 5)),
        damping=r["damping"].reshape(shape + (5, 5)),
        exciting=r["f"].reshape(shape + (5,)),
        valid=r["valid"].reshape(shape),
        roll_damping=float(roll_damping),
    )
    return out, r


__all__ = [
    "MODES",
    "FROUDE_LIMIT",
    "Motions",
    "motions",
    "encounter_frequency",
    "default_radii",
    "rigid_body_matrices",
]
