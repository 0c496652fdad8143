"""The strip integrals: the section solve of every station over a frequency grid as one
reusable value (`SectionTable`), the sums of the section coefficients over the strips with
the lever arms of pitch and yaw and the forward-speed terms of Salvesen, Tuck & Faltinsen
(`radiation`), the exciting forces (`exciting`), the zero-speed coefficients of a hull
(`hull_coefficients`) and its hydrostatics (`hydrostatics`). JAX throughout: jit, grad and
vmap over the hull's offsets and the frequencies.
"""

from __future__ import annotations

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Complex, Float

from .._units import SEA_WATER, Water
from ..drift import Waterline, waterline
from ._hull import Hull, wigley, wigley_form
from ._sections import panels, section_coefficients

__all__ = [
    "SectionTable",
    "section_table",
    "HullCoefficients",
    "hull_coefficients",
    "Hydrostatics",
    "hydrostatics",
    "wigley_waterline",
]


class SectionTable(eqx.Module):
    """The section solve of a hull, once, over a grid of frequencies ``omega`` (G,) [rad/s]
    ascending: every station's ``added_mass``, ``damping`` (n, G, 3, 3), radiation
    ``potentials`` (n, G, panels, 3) and beam-sea ``exciting`` forces (n, G, 3) per unit
    length (`jaxtow.strip.section_coefficients`). The section coefficients depend on the
    hull and the frequency only, so one table serves `jaxtow.strip.motions` and
    `jaxtow.strip.added_resistance` at every speed and heading whose encounter frequencies
    it spans (`lookup` interpolates it linearly in ω_e; outside the grid the values are held
    at its ends and marked)."""

    omega: Float[Array, " G"]
    added_mass: Float[Array, "n G 3 3"]
    damping: Float[Array, "n G 3 3"]
    potentials: Complex[Array, "n G p 3"]
    exciting: Complex[Array, "n G 3"]

    def lookup(self, omega_e, index=None):
        """(a, b, potentials, heave exciting force X₃, inside) of every station at the
        encounter frequencies ``omega_e`` (m,) [rad/s]: linear in |ω_e| between the grid's
        points (``index`` (m,) ints: the grid points themselves, no interpolation); the
        complex values conjugated where ω_e < 0 (the radiated waves of the reversed time
        dependence); ``inside`` (m,) where |ω_e| lies within the grid."""
        if index is not None:
            i0, i1 = index, index
            t = jnp.zeros(index.shape)
            inside = jnp.ones(index.shape, bool)
        else:
            grid = self.omega
            q = jnp.abs(omega_e)
            inside = (q >= grid[0] * (1 - 1e-12)) & (q <= grid[-1] * (1 + 1e-12))
            qc = jnp.clip(q, grid[0], grid[-1])
            i0 = jnp.clip(jnp.searchsorted(grid, qc, side="right") - 1, 0, grid.shape[0] - 2)
            i1 = i0 + 1
            step = grid[i1] - grid[i0]
            t = jnp.where(step > 0, (qc - grid[i0]) / jnp.where(step > 0, step, 1.0), 0.0)

        def at(v):  # (n, G, ...) -> (n, m, ...)
            tt = t.reshape((1, -1) + (1,) * (v.ndim - 2))
            return v[:, i0] * (1 - tt) + v[:, i1] * tt

        neg = (omega_e < 0)[None, :]
        pots = at(self.potentials)
        pots = jnp.where(neg[..., None, None], jnp.conj(pots), pots)
        x3 = at(self.exciting[..., 1])
        x3 = jnp.where(neg, jnp.conj(x3), x3)
        return at(self.added_mass), at(self.damping), pots, x3, inside


def section_table(hull: Hull, omega, *, water: Water = SEA_WATER) -> SectionTable:
    """The `SectionTable` of ``hull`` over the frequencies ``omega`` (G,) [rad/s] (ascending,
    > 0): the close-fit solve of every station, vmapped over the stations. Differentiable in
    the offsets and the frequencies."""
    omega = jnp.atleast_1d(jnp.asarray(omega, dtype=float))
    secs = jax.vmap(lambda y, z: section_coefficients(y, z, omega, water=water))(hull.y, hull.z)
    return SectionTable(
        omega=omega,
        added_mass=secs.added_mass,
        damping=secs.damping,
        potentials=secs.potentials,
        exciting=secs.exciting,
    )


class HullCoefficients(eqx.Module):
    """Zero-speed strip-theory added mass and damping of a hull, (w, 5, 5) over `MODES`
    (sway, heave, roll, pitch, yaw) in SI, at ``omega`` (w); with headings ``beta`` (b)
    [rad] (waves from, counter-clockwise from the bow: 0 head seas), the exciting forces
    per unit wave amplitude at midships ``exciting`` (w, b, 5) (else None)."""

    omega: Float[Array, " w"]
    added_mass: Float[Array, "w 5 5"]
    damping: Float[Array, "w 5 5"]
    beta: Float[Array, " b"] | None = None
    exciting: Complex[Array, "w b 5"] | None = None


def section_wave_forces(y, z, potentials, omega, sin_chi, water: Water):
    """Sway, heave and roll forces per unit length of a wave of unit amplitude and frequency
    ``omega`` travelling at angle χ to the ship's x axis, on one section, as (Froude-Krylov,
    diffraction): X_j = −iωρ ∮ φ₀ n_j ds + iωρ ∮ φ_j ∂φ₀/∂n ds (the diffraction of Salvesen,
    Tuck & Faltinsen 1970 through the radiation potentials ``potentials``, the Haskind form
    of strip theory; at forward speed the potentials are those of the encounter frequency);
    φ₀ = −i(g/ω) e^{kz + iky sinχ} on the section, the factor e^{ikx cosχ} left to the
    caller. ``omega``, ``sin_chi`` (m,), ``potentials`` (m, panels, 3); returns two (m, 3).
    At sinχ = 1 and zero speed the sum is the 2-D beam-sea diffraction force (tested against
    the direct solve)."""
    rho, g = water.rho, water.g
    _, _, mid, length, _, normal = panels(y, z)
    k = (omega**2 / g)[:, None]  # (m, 1)
    s = sin_chi[:, None]
    pts = jnp.concatenate([mid, -jnp.conj(mid)])
    nrm = jnp.concatenate([normal, -jnp.conj(normal)])
    ln = jnp.concatenate([length, length])
    parity = jnp.array([-1.0, 1.0, -1.0])
    phi = jnp.concatenate([potentials, potentials * parity], axis=-2)  # (m, 2n, 3)
    x, yy, nx, ny = pts.real, pts.imag, nrm.real, nrm.imag
    n_modes = jnp.stack([nx, ny, x * ny - yy * nx], axis=-1)  # (2n, 3)
    phi0 = -1j * g / omega[:, None] * jnp.exp(k * yy + 1j * k * x * s)
    dphi0 = phi0 * k * (1j * s * nx + ny)
    pre = -1j * omega[:, None] * rho
    fk = pre * jnp.sum((phi0 * ln)[..., None] * n_modes, axis=-2)
    diffraction = -pre * jnp.sum(phi * (dphi0 * ln)[..., None], axis=-2)
    return fk, diffraction


#: section mode (sway 0, heave 1, roll 2) of each hull mode (`MODES`)
_SECTION_MODE = np.array([0, 1, 2, 1, 0])
#: the speed term of each hull mode's motion lever: pitch −x + c, yaw x − c
_SPEED_SIGN = np.array([0.0, 0.0, 0.0, 1.0, -1.0])


def levers(x, c):
    """(plain u, motion w, force v) levers of the five hull modes at stations x (n,) for the
    speed factors c (m,): each (n, m, 5)."""
    one = jnp.ones(x.shape + c.shape)
    xx = jnp.broadcast_to(x[:, None], one.shape)
    plain = jnp.stack([one, one, one, -xx, xx], axis=-1)
    speed = jnp.asarray(_SPEED_SIGN) * c[None, :, None]
    return plain, plain + speed, plain - speed


def radiation(t, x, dx, c, transom):
    """T (m, 5, 5) from the section coefficients t (n, m, 3, 3): the strip integrals with
    the speed terms c (m,) of Salvesen, Tuck & Faltinsen and the transom term (the formula is
    in the docstring of `jaxtow.strip._motions`; c = 0 gives the zero-speed integrals)."""
    plain, motion, force = levers(x, c)
    ts = t[:, :, _SECTION_MODE][:, :, :, _SECTION_MODE]  # (n, m, 5, 5)
    body = jnp.einsum("n,nmj,nmk,nmjk->mjk", dx, force, motion, ts)
    if not transom:
        return body
    end = c[:, None, None] * plain[0, :, :, None] * motion[0, :, None, :] * ts[0]
    return body + end


def exciting(hull, pots, omega, beta_flat, c, k_cos, water: Water):
    """Exciting forces (m, 5) and the sections' Froude-Krylov heave force (n, m) (for the
    relative motion of the added resistance)."""
    sin_chi = -jnp.sin(beta_flat)
    fk, dif = jax.vmap(lambda y, z, p: section_wave_forces(y, z, p, omega, sin_chi, water))(
        hull.y, hull.z, pots
    )  # (n, m, 3) each
    phase = jnp.exp(1j * k_cos[None] * hull.x[:, None])  # (n, m)
    plain, _, force = levers(hull.x, c)
    fk_m = fk[..., _SECTION_MODE] * phase[..., None]
    dif_m = dif[..., _SECTION_MODE] * phase[..., None]
    f = jnp.einsum("n,nmj->mj", hull.dx, plain * fk_m + force * dif_m)
    if hull.transom:
        f = f + c[:, None] * plain[0] * dif_m[0]
    return f, fk[..., 1]


def hull_coefficients(
    hull: Hull, omega, beta=None, *, water: Water = SEA_WATER
) -> HullCoefficients:
    """Zero-speed strip theory: the section coefficients of every station (`section_table`)
    summed over the strips with the lever arms of pitch and yaw (`radiation` without the
    speed terms); with headings ``beta`` [rad] also the exciting forces (`exciting`: each
    station's, with the wave's phase along the hull). Differentiable in the offsets and
    the frequencies; jit and vmap over hulls."""
    omega = jnp.atleast_1d(jnp.asarray(omega, dtype=float))
    table = section_table(hull, omega, water=water)
    zero = jnp.zeros(omega.shape, complex)  # no speed: the plain levers
    added = jnp.real(radiation(table.added_mass, hull.x, hull.dx, zero, False))
    damping = jnp.real(radiation(table.damping, hull.x, hull.dx, zero, False))
    if beta is None:
        return HullCoefficients(omega=omega, added_mass=added, damping=damping)
    beta = jnp.atleast_1d(jnp.asarray(beta, dtype=float))
    nw, nb = omega.shape[0], beta.shape[0]
    w_flat, b_flat = jnp.repeat(omega, nb), jnp.tile(beta, nw)
    pots = jnp.repeat(table.potentials, nb, axis=1)  # (n, w·b, panels, 3)
    k_cos = -(w_flat**2) / water.g * jnp.cos(b_flat)  # k cos χ
    f, _ = exciting(hull, pots, w_flat, b_flat, jnp.zeros_like(w_flat, complex), k_cos, water)
    return HullCoefficients(
        omega=omega, added_mass=added, damping=damping, beta=beta, exciting=f.reshape(nw, nb, 5)
    )


class Hydrostatics(eqx.Module):
    """The hydrostatics of a hull from its strips: displacement ``volume`` ∇ [m³], centre of
    buoyancy ``x_b``, ``z_b`` [m], and the waterplane's ``area`` [m²] and moments about
    midships ``s_x`` = ∫xB dx [m³], ``i_xx`` = ∫x²B dx, ``i_yy`` = ∫B³/12 dx [m⁴] (the
    strips' waterplane, symmetric: S_y = I_xy = 0)."""

    volume: Float[Array, ""]
    x_b: Float[Array, ""]
    z_b: Float[Array, ""]
    area: Float[Array, ""]
    s_x: Float[Array, ""]
    i_xx: Float[Array, ""]
    i_yy: Float[Array, ""]

    @property
    def waterplane(self) -> tuple:
        """(A, S_x, S_y, I_xx, I_yy, I_xy) for `jaxtow.hydrostatic_restoring`."""
        zero = jnp.zeros_like(self.area)
        return (self.area, self.s_x, zero, self.i_xx, self.i_yy, zero)


def hydrostatics(hull: Hull) -> Hydrostatics:
    """The `Hydrostatics` of ``hull`` (the restoring follows with
    `jaxtow.hydrostatic_restoring`, which needs the centre of gravity too)."""
    y, z = hull.y, hull.z
    cross = y[:, :-1] * z[:, 1:] - y[:, 1:] * z[:, :-1]  # shoelace terms of the half contour
    area = jnp.abs(jnp.sum(cross, axis=1))  # both halves: 2 × ½ |Σ|
    zc = jnp.sum(cross * (z[:, :-1] + z[:, 1:]), axis=1) / (3.0 * jnp.sum(cross, axis=1))
    vol = jnp.sum(area * hull.dx)
    b = 2.0 * y[:, 0]
    return Hydrostatics(
        volume=vol,
        x_b=jnp.sum(hull.x * area * hull.dx) / vol,
        z_b=jnp.sum(zc * area * hull.dx) / vol,
        area=jnp.sum(b * hull.dx),
        s_x=jnp.sum(hull.x * b * hull.dx),
        i_xx=jnp.sum(hull.x**2 * b * hull.dx),
        i_yy=jnp.sum(b**3 / 12.0 * hull.dx),
    )


def wigley_waterline(
    length, breadth, draft, *, alpha=None, n_points: int = 101, n_stations: int = 21
) -> Waterline:
    """The waterline of `jaxtow.strip.wigley` (L, B, T, α) as a `jaxtow.drift.Waterline`
    for the waterline methods (`WithReflection`, `drift_qtf`): its half-breadth at z = 0,
    (B/2)(1 − ξ²) (with α: (B/2)(1 − ξ²)(1 + 0.2ξ²)), at ``n_points`` stations from bow to
    stern, wall-sided (the sections' slope at the waterline is zero), with the block
    coefficient of the strips of ``n_stations`` (∇/(LBT) of `hydrostatics`). NumPy on the
    host (numbers, not traced)."""
    xi = np.linspace(1.0, -1.0, int(n_points))
    eta = wigley_form(xi**2, 0.0, None if alpha is None else float(alpha))
    half = np.stack([0.5 * float(length) * xi, 0.5 * float(breadth) * eta], axis=1)
    half[[0, -1], 1] = 0.0
    points = np.concatenate([half, half[-2::-1] * np.array([1.0, -1.0])])
    hull = wigley(length, breadth, draft, alpha=alpha, n_stations=n_stations)
    cb = float(hydrostatics(hull).volume) / (float(length) * float(breadth) * float(draft))
    return waterline(points, draft=float(draft), block_coefficient=cb, name="wigley")
