"""Two-dimensional radiation and diffraction of a ship section in deep water: Frank's
close-fit source method, with an interior lid against the irregular frequencies.

Coordinates of the section plane: x across (the ship's y, to port), y up (the ship's
z), the free surface at y = 0, the fluid below. Time dependence e^{−iωt}; ν = ω²/g.

**Green function** (a unit pulsating source at ζ = ξ + iη below the surface, Wehausen &
Laitone 1960, in this normalisation):

    G(z; ζ) = ln|z − ζ| − ln|z − ζ̄| + 2 Re f(w) − 2πi Re e^{−w},   w = iν(z − ζ̄),

with f(w) = e^{−w} Ei(w) (`jaxtow.strip._expint.exp_ei`). It satisfies ∂G/∂y = νG on
y = 0 and radiates outgoing waves. Every term is integrated over a straight panel in closed
form: ln|z − ζ| through ∫ Ln = (z − ζ)(Ln(z − ζ) − 1) in the panel's own frame, the wave term
through d/dw (Ln w − f) = f, and e^{−w} directly; the velocities need the integrands at the
panel ends only. Nothing is integrated by quadrature, so the influence of a panel is exact for
a constant source strength.

**Method** (Frank 1967, "Oscillation of cylinders in or below the free surface of deep
fluids", NSRDC report 2375): constant-strength sources on N straight panels of the wetted
half contour (the other half by symmetry: heave is symmetric, sway and roll antisymmetric),
the body condition ∂φ/∂n = V·n at the panel midpoints.

**Irregular frequencies.** A source distribution on the hull fails where the interior of the
section (closed by the waterline) has a sloshing eigenfrequency; for a rectangle of beam B
and draft T the first is at ν B/2 = (π/2) coth(πT/B), i.e. ω²B/2g = 1.71 for B/T = 2.
They are removed by an extended boundary condition: sources on the interior waterline (the
"lid") as well, with a rigid lid there, no vertical velocity just below it (the idea of
Ohmatsu 1975 and Zhu 1994). The interior field then meets a Dirichlet condition on the hull
and a Neumann condition on the lid, a problem with no eigenfrequencies. A zero potential on
the lid (Ohmatsu's condition for the potential formulation) does not suit a source
distribution: the potential of a source layer is continuous, so at the waterline corner it
cannot be both the hull's and zero, and the solution then depends on the lid (tested).

**Coefficients** per unit length, modes (sway, heave, roll about the origin on the waterline
centre, positive starboard down): with φ_k the potential of unit velocity in mode k and n
the normal into the fluid, a_jk = −ρ Re ∫ φ_k n_j ds, b_jk = −ωρ Im ∫ φ_k n_j ds. The
exciting forces in beam waves of unit amplitude travelling towards +x (incident potential
φ_0 = −i(g/ω) e^{νy + iνx}, wave elevation e^{i(νx − ωt)}) come from the diffraction
solution: X_j = −iωρ ∫ (φ_0 + φ_d) n_j ds.
"""

from __future__ import annotations

import functools

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Complex, Float

from .._units import SEA_WATER, Water
from ._expint import exp_ei

#: The lid's panels per body panel (at least 2), for the extended boundary condition: no
#: vertical velocity just below the interior waterline.
LID_FRACTION = 0.5


class SectionCoefficients(eqx.Module):
    """Hydrodynamic coefficients of a section per unit length, in SI, over the modes (sway,
    heave, roll about the waterline centre, + starboard down): ``added_mass`` and
    ``damping`` (..., 3, 3) [kg/m, kg/(m s), ... with m and rad], ``exciting`` (..., 3)
    complex per unit wave amplitude in beam waves travelling to +x, i.e. from starboard
    (N/m per m, N m/m per m), at ``omega`` (...) [rad/s]; ``potentials`` (..., panels, 3):
    the radiation potentials of unit velocity in each mode at the half contour's panel
    midpoints (the other half: heave even, sway and roll odd in x) [m²/s]."""

    omega: Float[Array, "..."]
    added_mass: Float[Array, "... 3 3"]
    damping: Float[Array, "... 3 3"]
    exciting: Complex[Array, "... 3"]
    potentials: Complex[Array, "... panels 3"]
    area: Float[Array, ""]
    beam: Float[Array, ""]
    draft: Float[Array, ""]


def panels(y, z):
    """The half contour's panels from the waterline to the keel: ends, midpoints, lengths,
    unit tangents (complex) and normals into the fluid."""
    p = y + 1j * z
    a, b = p[:-1], p[1:]
    mid = 0.5 * (a + b)
    length = jnp.abs(b - a)
    e = (b - a) / length
    # the contour runs from the waterline (x = B/2) down to the keel (x = 0), so the fluid
    # lies to the left of the direction of travel: the normal is the tangent turned by +90°
    normal = 1j * e
    return a, b, mid, length, e, normal


def _rankine(z, a, b):
    """∫ ln|z − ζ| ds over the panel a → b, and the complex velocity d/dz of the analytic
    function it is the real part of (= ∫ ds/(z − ζ)); z must not lie on the panel."""
    length = jnp.abs(b - a)
    e = (b - a) / length
    w = (z - a) / e
    w1 = w - length

    def wlog(v):
        safe = jnp.where(jnp.abs(v) > 0, v, 1.0)
        return jnp.where(jnp.abs(v) > 0, v * (jnp.log(safe) - 1.0), 0.0)

    pot = jnp.real(wlog(w) - wlog(w1))
    vel = jnp.log(w / w1) / e
    return pot, vel


def _segments(lines):
    """The panels of the polylines ``lines`` (between neighbours of one line, never across
    two lines) as the indices of their first vertex in the lines' concatenation, in order
    (a host constant: the lines' sizes are static)."""
    sizes = [v.shape[0] for v in lines]
    starts = np.cumsum([0] + sizes[:-1])
    return np.concatenate([np.arange(s, s + n - 1) for s, n in zip(starts, sizes)])


def _wave(z, lines, nu):
    """The wave part of the sources on the panels of the polylines ``lines`` (panels between
    neighbours), over the image panels: ∫ [2 f(w) − 2πi e^{−w}] ds, real in space for the
    potential's two time components, and the z-derivatives. The exponential integral is
    evaluated once per point and vertex, for all the lines in one call, and shared by the
    two panels that meet at a vertex.

    Returns (∫f ds, ∫e^{−w} ds, d/dz ∫f ds, d/dz ∫e^{−w} ds), each (points, panels), the
    panels of all the lines in order (`_segments`)."""
    img = jnp.conj(jnp.concatenate(lines))
    first = _segments(lines)
    w = 1j * nu * (z[..., None] - img)
    f = exp_ei(w)
    q = jnp.log(w) - f  # an antiderivative of f: d/dw (Ln w − f) = f
    ex = jnp.exp(-w)
    step = img[first + 1] - img[first]
    e = step / jnp.abs(step)

    def jump(v):  # v at each panel's end minus v at its start
        return v[..., first + 1] - v[..., first]

    # w = iν(z − ζ'), dw = −iν e ds: ∫ f ds = −(1/(iνe)) [Ln w − f], ∫ e^{−w} ds likewise
    int_f = -jump(q) / (1j * nu * e)
    int_e = jump(ex) / (1j * nu * e)
    # d/dz ∫ f ds = ∫ iν f'(w) ds = −(1/e) [f];  d/dz ∫ e^{−w} ds = −(1/e) [e^{−w}]
    return int_f, int_e, -jump(f) / e, -jump(ex) / e


def _influence(z, normal, a, b, wave, self_mask):
    """Potential and normal velocity at points z (unit normals ``normal``) of unit sources
    on the panels a → b, with their images and the wave terms ``wave`` (`_wave` of these
    panels); complex in time; ``self_mask`` marks each point's own panel (its jump is taken
    on the fluid side).

    Returns (pot, dn), each (points, panels)."""
    zz = z[:, None]
    a, b = a[None, :], b[None, :]
    pot_r, vel_r = _rankine(zz, a, b)
    pot_i, vel_i = _rankine(zz, jnp.conj(a), jnp.conj(b))
    int_f, int_e, d_f, d_e = wave
    pot = (pot_r - pot_i + 2.0 * jnp.real(int_f)) - 2j * jnp.pi * jnp.real(int_e)
    n = normal[:, None]
    dn_r = jnp.where(self_mask, jnp.pi, jnp.real(vel_r * n))
    dn = (dn_r - jnp.real(vel_i * n) + 2.0 * jnp.real(d_f * n)) - 2j * jnp.pi * jnp.real(d_e * n)
    return pot, dn


def _systems(y, z, nu, n_lid):
    """The symmetric and antisymmetric influence systems (body rows: normal velocity; lid
    rows: vertical velocity just below the lid) and the potential on the body panels."""
    _, _, mid, _, _, normal = panels(y, z)
    n_body = mid.shape[0]
    hull = y + 1j * z
    lid = jnp.linspace(y[0], 0.0, n_lid + 1) + 0j
    lmid = 0.5 * (lid[:-1] + lid[1:])
    # the sources: hull and lid panels, and their mirror images across x = 0 (the other half),
    # all in one set of panels (one copy of the influence code in the compiled program)
    lines = (hull, lid, -jnp.conj(hull), -jnp.conj(lid))
    verts, first = jnp.concatenate(lines), _segments(lines)
    # the field points: the body's panel midpoints, then just below the lid's
    points = jnp.concatenate([mid, lmid])
    normals = jnp.concatenate([normal, jnp.full((n_lid,), -1j)])
    half = n_body + n_lid  # the panels of one half
    own = np.eye(half, 2 * half, dtype=bool)
    own[n_body:] = False  # a point's own panel: the body's only (the lid's points lie below)
    pot_all, dn_all = _influence(
        points, normals, verts[first], verts[first + 1], _wave(points, lines, nu), own
    )
    pot, pot_m = pot_all[:n_body, :half], pot_all[:n_body, half:]
    dn, dn_m = dn_all[:, :half], dn_all[:, half:]
    return [(dn + sign * dn_m, pot + sign * pot_m) for sign in (1.0, -1.0)]


def _incident(mid, normal, omega, g):
    """The unit incident beam wave to +x on the body: its potential and normal velocity,
    split into the parts even and odd in x."""
    nu = omega**2 / g
    x, yy = mid.real, mid.imag
    nx, ny = normal.real, normal.imag
    amp = -1j * g / omega * jnp.exp(nu * yy)
    c, s = jnp.cos(nu * x), jnp.sin(nu * x)
    even = (amp * c, amp * nu * (-s * nx + c * ny))
    odd = (amp * 1j * s, amp * 1j * nu * (c * nx + s * ny))
    return even, odd


def _solve_one(y, z, omega, rho, g, n_lid):
    nu = omega**2 / g
    _, _, mid, length, _, normal = panels(y, z)
    (m_sym, p_sym), (m_anti, p_anti) = _systems(y, z, nu, n_lid)
    nx, ny = normal.real, normal.imag
    n_modes = jnp.stack([nx, ny, mid.real * ny - mid.imag * nx], axis=-1)  # sway, heave, roll
    (phi0_even, dphi_even), (phi0_odd, dphi_odd) = _incident(mid, normal, omega, g)
    pad = lambda v: jnp.concatenate([v.astype(complex), jnp.zeros((n_lid,), complex)])  # noqa: E731
    zero = jnp.zeros_like(pad(nx))
    # columns: heave, even diffraction (and a zero column); sway, roll, odd diffraction
    rhs_sym = jnp.stack([pad(ny), pad(-dphi_even), zero], axis=-1)
    rhs_anti = jnp.stack([pad(nx), pad(n_modes[:, 2]), pad(-dphi_odd)], axis=-1)
    # one batched LAPACK call per kernel: concurrent calls from XLA's threads into scipy's
    # OpenBLAS deadlock (docs/guide.md, "Precision and devices")
    sol = jnp.linalg.solve(jnp.stack([m_sym, m_anti]), jnp.stack([rhs_sym, rhs_anti]))
    phi_sym = p_sym @ sol[0]
    phi_anti = p_anti @ sol[1]

    def integral(phi, j):  # ∫ φ n_j ds over both halves
        return 2.0 * jnp.sum(phi * n_modes[:, j] * length)

    radiated = (phi_anti[:, 0], phi_sym[:, 0], phi_anti[:, 1])  # unit sway, heave, roll
    symmetric = (False, True, False)
    m_int = jnp.stack(
        [
            jnp.stack(
                [
                    integral(radiated[k], j) if symmetric[j] == symmetric[k] else 0.0j
                    for k in range(3)
                ]
            )
            for j in range(3)
        ]
    )
    total = (phi0_odd + phi_anti[:, 2], phi0_even + phi_sym[:, 1], phi0_odd + phi_anti[:, 2])
    exciting = -1j * omega * rho * jnp.stack([integral(total[j], j) for j in range(3)])
    return -rho * m_int.real, -omega * rho * m_int.imag, exciting, jnp.stack(radiated, axis=-1)


@functools.partial(jax.jit, static_argnames=("n_lid",))
def _solve(y, z, omega, rho, g, n_lid):
    return jax.vmap(lambda w: _solve_one(y, z, w, rho, g, n_lid))(omega)


def section_coefficients(y, z, omega, *, water: Water = SEA_WATER, n_lid=None):
    """Added mass, damping and beam-sea exciting forces of a symmetric section per unit
    length (module docstring), by Frank's close-fit method with an interior lid.

    ``y``, ``z``: the half offsets [m], ordered from the waterline (y = B/2, z = 0) to the
    keel on the centreline (y = 0, z = −T); straight panels join them. ``omega``: a scalar
    or 1-D array [rad/s], > 0. ``n_lid``: panels on the half lid (default: half the body's,
    at least 2; 0 leaves the lid out, and the irregular frequencies in); ``water``: ρ and g
    (`jaxtow.Water`). Differentiable in the offsets and ω (vmapped over ω)."""
    y = jnp.asarray(y, dtype=float)
    z = jnp.asarray(z, dtype=float)
    if y.ndim != 1 or y.shape != z.shape or y.shape[0] < 3:
        raise ValueError(
            "y and z must be 1-D arrays of the same length (at least 3 offsets), got shapes "
            f"{y.shape} and {z.shape}"
        )
    n_lid = max(2, int(round(LID_FRACTION * (y.shape[0] - 1)))) if n_lid is None else int(n_lid)
    if n_lid < 0:
        raise ValueError(f"n_lid must be >= 0, got {n_lid}")
    omega = jnp.asarray(omega, dtype=float)
    if omega.ndim > 1:
        raise ValueError(f"omega must be a scalar or a 1-D array, got shape {omega.shape}")
    added, damping, exciting, potentials = _solve(
        y, z, omega.reshape(-1), water.rho, water.g, n_lid
    )
    shape = omega.shape
    # the half section's area by the shoelace formula over the closed contour
    area = 2.0 * 0.5 * jnp.abs(jnp.sum(y[:-1] * z[1:] - y[1:] * z[:-1]))
    return SectionCoefficients(
        omega=omega,
        added_mass=added.reshape(shape + (3, 3)),
        damping=damping.reshape(shape + (3, 3)),
        exciting=exciting.reshape(shape + (3,)),
        potentials=potentials.reshape(shape + potentials.shape[1:]),
        area=area,
        beam=2.0 * y[0],
        draft=-jnp.min(z),
    )
