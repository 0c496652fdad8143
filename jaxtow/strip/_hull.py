"""Hulls for strip theory: stations of half offsets, the built-in box and Wigley hulls, an
offsets table file, and the zero-speed strip integrals of the section coefficients.

Axes: x forward from midships, y to port, z up from the waterline; pitch is positive bow
down and yaw bow to port. Every station has the same number of offsets (so that the section
solve is vmapped over them), from the waterline (y = B(x)/2, z = 0) to the keel on the
centreline. Strips are the midpoint rule: station i stands for the strip of length
``dx[i]`` around ``x[i]``; stations at the very ends of a fine hull, where the breadth is
zero, carry no section and are left out.
"""

from __future__ import annotations

import csv
from pathlib import Path

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Complex, Float

from ._sections import _panels, section_coefficients

#: The zero-speed radiation modes of a hull: sway, heave, roll, pitch, yaw (ship modes 2-6).
MODES = ("sway", "heave", "roll", "pitch", "yaw")


class Hull(eqx.Module):
    """A hull by its stations: ``x`` (n,) [m], strip lengths ``dx`` (n,) [m], half offsets
    ``y``, ``z`` (n, m) [m] from the waterline to the keel."""

    x: Float[Array, " n"]
    dx: Float[Array, " n"]
    y: Float[Array, "n m"]
    z: Float[Array, "n m"]
    name: str = eqx.field(static=True, default="hull")
    #: whether the hull ends aft in a transom (the aftmost station's section, not a point):
    #: the forward-speed end terms of Salvesen, Tuck & Faltinsen act there
    transom: bool = eqx.field(static=True, default=False)

    def __check_init__(self):
        shape = jnp.shape(self.y)
        if len(shape) != 2 or jnp.shape(self.z) != shape or shape[1] < 3:
            raise ValueError(
                f"y and z must be (stations, offsets) arrays of one shape with at least 3 "
                f"offsets, got {jnp.shape(self.y)} and {jnp.shape(self.z)}"
            )
        if jnp.shape(self.x) != shape[:1] or jnp.shape(self.dx) != shape[:1]:
            raise ValueError(f"x and dx must have one value per station ({shape[0]})")


def _strips(length: float, n_stations: int):
    if not (length > 0 and n_stations >= 2):
        raise ValueError(f"length must be > 0 and n_stations >= 2, got {length!r}, {n_stations!r}")
    dx = length / n_stations
    x = -0.5 * length + dx * (np.arange(n_stations) + 0.5)
    return x, np.full(n_stations, dx)


def box(
    length: float,
    breadth: float,
    draft: float,
    *,
    n_stations: int = 21,
    n_side: int = 6,
    n_bottom: int = 6,
) -> Hull:
    """A wall-sided box (Barge 1 of the thesis): rectangular sections B x T."""
    for name, v in (("breadth", breadth), ("draft", draft)):
        if not v > 0:
            raise ValueError(f"{name} must be > 0, got {v!r}")
    x, dx = _strips(length, n_stations)
    ys = np.r_[np.full(n_side + 1, breadth / 2), np.linspace(breadth / 2, 0.0, n_bottom + 1)[1:]]
    zs = np.r_[np.linspace(0.0, -draft, n_side + 1), np.full(n_bottom, -draft)]
    n = len(x)
    return Hull(
        jnp.asarray(x), jnp.asarray(dx), jnp.tile(ys, (n, 1)), jnp.tile(zs, (n, 1)), "box", True
    )


def raked_box(
    length: float,
    breadth: float,
    draft: float,
    rake,
    *,
    bow_rake=None,
    n_stations: int = 21,
    n_side: int = 6,
    n_bottom: int = 6,
) -> Hull:
    """A barge with a rectangular L × B waterline whose stern and bow faces run straight from
    the waterline (x = ∓L/2) down to the keel at x = ∓(L/2 − rake): rectangular sections
    B × d(x), d = T min(1, (L/2 + x)/rake, (L/2 − x)/bow_rake) (``bow_rake`` defaults to
    ``rake``; the hull of `jaxtow.bem.meshes.raked_barge_mesh`; Barge 2 with
    `jaxtow.presets.barge2_hull`). The raked ends close at the waterline, so the hull has no
    transom (``rake = 0`` at both ends is `box`, which has). Differentiable in the rakes."""
    bow_rake = rake if bow_rake is None else bow_rake
    if _concrete(rake) and _concrete(bow_rake) and float(rake) == 0 and float(bow_rake) == 0:
        return box(length, breadth, draft, n_stations=n_stations, n_side=n_side, n_bottom=n_bottom)
    for name, v in (("rake", rake), ("bow_rake", bow_rake)):
        if _concrete(v) and not (0 < float(v) < length):
            raise ValueError(f"parameter {name!r} must lie in (0, length), got {float(v)!r}")
    hull = box(length, breadth, draft, n_stations=n_stations, n_side=n_side, n_bottom=n_bottom)
    x = hull.x
    depth = draft * jnp.minimum(
        1.0, jnp.minimum((0.5 * length + x) / rake, (0.5 * length - x) / bow_rake)
    )
    z = hull.z * (depth / draft)[:, None]
    return Hull(hull.x, hull.dx, hull.y, z, "raked_box", False)


def _concrete(v) -> bool:
    """Whether ``v`` has a value now (not a tracer inside jit or grad)."""
    try:
        np.asarray(v)
    except (TypeError, jax.errors.TracerArrayConversionError):
        return False
    return True


def lewis_section(breadth, draft, sigma, *, n_points: int = 12):
    """Half offsets (y, z) of a Lewis-form section (Lewis 1929): the conformal map
    y = M((1 + a₁) sin θ − a₃ sin 3θ), z = −M((1 − a₁) cos θ + a₃ cos 3θ), θ from π/2 (the
    waterline, y = B/2) to 0 (the keel), whose three coefficients give the beam ``breadth``,
    the draft ``draft`` and the area coefficient ``sigma`` = A/(BT) exactly (the form of
    Journée & Adegeest, "Theoretical manual of strip theory program SEAWAY", TU Delft report
    1370). The cheap hull description of three numbers per station; the section is then
    solved by the close-fit method like any other. Points are cosine-spaced in θ.
    Differentiable in the three numbers. Raises ValueError naming ``sigma`` where no Lewis
    form has that area coefficient at that B/2T (the map would loop)."""
    h0 = breadth / (2.0 * draft)
    c1 = (3.0 + 4.0 * sigma / jnp.pi) + (1.0 - 4.0 * sigma / jnp.pi) * (
        (h0 - 1.0) / (h0 + 1.0)
    ) ** 2
    disc = 9.0 - 2.0 * c1
    if _concrete(disc) and not (float(disc) >= 0 and float(breadth) > 0 and float(draft) > 0):
        raise ValueError(
            f"parameter 'sigma' = {float(sigma):g}: no Lewis form has that area coefficient "
            f"at B/2T = {float(h0):g} (and breadth, draft must be > 0)"
        )
    a3 = (-c1 + 3.0 + jnp.sqrt(jnp.maximum(disc, 0.0))) / c1
    a1 = (h0 - 1.0) * (a3 + 1.0) / (h0 + 1.0)
    scale = 0.5 * breadth / (1.0 + a1 + a3)
    theta = 0.25 * jnp.pi * (1.0 + jnp.cos(jnp.linspace(0.0, jnp.pi, n_points)))  # π/2 → 0
    y = scale * ((1.0 + a1) * jnp.sin(theta) - a3 * jnp.sin(3.0 * theta))
    z = -scale * ((1.0 - a1) * jnp.cos(theta) + a3 * jnp.cos(3.0 * theta))
    if _concrete(y) and np.any(np.asarray(y) < -1e-9 * float(breadth)):
        raise ValueError(
            f"parameter 'sigma' = {float(sigma):g}: the Lewis form at B/2T = {float(h0):g} "
            "crosses the centreline"
        )
    return y.at[-1].set(0.0), z


def lewis_hull(x, dx, breadth, draft, sigma, *, n_points: int = 12, name: str = "lewis") -> Hull:
    """A hull of Lewis-form sections (`lewis_section`) from its sectional particulars:
    station x and strip length dx [m], breadth and draft [m] and area coefficient of each
    station (arrays of one length, or scalars broadcast); no transom."""
    x, dx, breadth, draft, sigma = jnp.broadcast_arrays(
        *(jnp.asarray(v, dtype=float) for v in (x, dx, breadth, draft, sigma))
    )
    secs = [
        lewis_section(b, t, s, n_points=n_points)
        for b, t, s in zip(breadth, draft, sigma, strict=True)
    ]
    return Hull(x, dx, jnp.stack([y for y, _ in secs]), jnp.stack([z for _, z in secs]), name)


def wigley(
    length: float,
    breadth: float,
    draft: float,
    *,
    alpha: float | None = None,
    n_stations: int = 21,
    n_points: int = 12,
) -> Hull:
    """The Wigley hull y = (B/2)(1 − ξ²)(1 − ζ²), ξ = 2x/L, ζ = z/T, the mathematical hull of
    many seakeeping experiments; with ``alpha``, the fuller form of Journée's (1992, Delft
    report 909) four models, y = (B/2)[(1 − ζ²)(1 − ξ²)(1 + 0.2ξ²) + α ζ²(1 − ζ⁸)(1 − ξ²)⁴]
    (α = 1: models I and II, midship coefficient 0.909; α = 0: III and IV, 0.667; all at
    L = 3 m, T = 0.1875 m, B = 0.3 m (I, III) or 0.6 m (II, IV)). Offsets at n_points depths,
    cosine-spaced towards the waterline and the keel."""
    for name, v in (("breadth", breadth), ("draft", draft)):
        if not v > 0:
            raise ValueError(f"{name} must be > 0, got {v!r}")
    if alpha is not None and not (np.isfinite(alpha) and alpha >= 0):
        raise ValueError(f"parameter 'alpha' must be None or a finite number >= 0, got {alpha!r}")
    x, dx = _strips(length, n_stations)
    s = 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, n_points)))
    zs = -draft * s
    xi2 = (2.0 * x / length)[:, None] ** 2
    zeta2 = (zs / draft)[None, :] ** 2
    if alpha is None:
        eta = (1.0 - xi2) * (1.0 - zeta2)
    else:
        eta = (1.0 - zeta2) * (1.0 - xi2) * (1.0 + 0.2 * xi2)
        eta = eta + alpha * zeta2 * (1.0 - zeta2**4) * (1.0 - xi2) ** 4
    ys = 0.5 * breadth * eta
    return Hull(
        jnp.asarray(x), jnp.asarray(dx), jnp.asarray(ys), jnp.tile(zs, (len(x), 1)), "wigley"
    )


def contour(y, z, n_points: int):
    """``n_points`` half offsets along the section contour through the points (y, z) [m],
    from the waterline down to the keel, then closed to the centreline at the keel: the
    panels follow the contour's arc length, the corners (turns over 20°) are kept as panel
    ends, and each straight piece gets panels in proportion to its length (at least one),
    cosine-spaced towards its ends. Points below where the contour first reaches the
    centreline are dropped. NumPy (for files and meshes; not differentiable)."""
    y, z = np.asarray(y, float), np.asarray(z, float)
    on_axis = np.flatnonzero(y <= 1e-12 * max(np.max(y), 1e-300))
    stop = on_axis[0] + 1 if on_axis.size else y.size
    y, z = y[:stop], z[:stop]
    if y[-1] > 0:  # close to the centreline along the keel
        y, z = np.r_[y, 0.0], np.r_[z, z[-1]]
    p = np.stack([y, z], axis=1)
    keep = np.r_[True, np.linalg.norm(np.diff(p, axis=0), axis=1) > 1e-12 * np.ptp(p)]
    p = p[keep]
    d = np.diff(p, axis=0)
    heading = np.arctan2(d[:, 1], d[:, 0])
    turn = np.abs((np.diff(heading) + np.pi) % (2 * np.pi) - np.pi)
    corners = np.r_[0, np.flatnonzero(turn > np.radians(20.0)) + 1, len(p) - 1]
    arc = np.r_[0.0, np.cumsum(np.linalg.norm(d, axis=1))]
    pieces = np.diff(arc[corners])
    n_panels = n_points - 1
    if n_panels < len(pieces):
        raise ValueError(
            f"parameter 'n_points' = {n_points}: the contour has {len(pieces)} straight pieces, "
            f"so it needs at least {len(pieces) + 1} points"
        )
    share = np.maximum(1, np.floor(pieces / pieces.sum() * n_panels).astype(int))
    while share.sum() < n_panels:
        share[np.argmax(pieces / share)] += 1
    while share.sum() > n_panels:
        share[np.argmax(np.where(share > 1, share / pieces, -1))] -= 1
    s = [arc[corners[0] : corners[0] + 1]]
    for k, m in enumerate(share):
        a0, a1 = arc[corners[k]], arc[corners[k + 1]]
        t = 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, m + 1)[1:]))
        s.append(a0 + t * (a1 - a0))
    s = np.concatenate(s)
    return np.interp(s, arc, p[:, 0]), np.interp(s, arc, p[:, 1])


def offsets_file(path, *, n_points: int = 12) -> Hull:
    """A hull from an offsets table (CSV): the first row is ``x`` and the waterline heights z
    [m] (0 at the still waterline, negative below; they must include 0); each further row is
    a station, its x [m] from midships (+ forward) and the half-breadths [m] at those
    waterlines. Each station's contour through those points, closed to the centreline at
    its keel, is resampled to ``n_points`` offsets along its arc length (`contour`). Stations whose breadth
    at the waterline is zero are left out (they carry no section); strips follow the
    stations' spacing (half-way to each neighbour). The hull ends in a transom when the
    first (aftmost) station of the file has breadth at the waterline and depth below it."""
    path = Path(path)
    with path.open(newline="") as fh:
        rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
    if len(rows) < 3:
        raise ValueError(f"offsets file {path}: needs a header row and at least two stations")
    ragged = [i + 2 for i, r in enumerate(rows[1:]) if len(r) != len(rows[0])]
    if ragged:
        raise ValueError(
            f"offsets file {path}: each station needs x and {len(rows[0]) - 1} half-breadths "
            f"(row {ragged[0]} of the table has {len(rows[ragged[0] - 1])} values)"
        )
    try:
        zs = np.array([float(v) for v in rows[0][1:]])
        table = np.array([[float(v) for v in r] for r in rows[1:]])
    except ValueError as e:
        raise ValueError(f"offsets file {path}: not a table of numbers ({e})") from None
    if table.shape[1] != zs.size + 1:
        raise ValueError(f"offsets file {path}: each station needs x and {zs.size} half-breadths")
    if not np.any(zs == 0.0) or np.any(zs > 0):
        raise ValueError(f"offsets file {path}: waterline heights must include 0 and be <= 0")
    order = np.argsort(-zs)
    zs, half = zs[order], table[:, 1:][:, order]
    x_all = table[:, 0]
    if np.any(np.diff(x_all) <= 0):
        raise ValueError(f"offsets file {path}: station x must increase down the file")
    if np.any(half < 0) or not np.all(np.isfinite(half)):
        raise ValueError(f"offsets file {path}: half-breadths must be finite and >= 0")
    edges = np.r_[x_all[0], 0.5 * (x_all[1:] + x_all[:-1]), x_all[-1]]
    dx_all = np.diff(edges)
    keep = half[:, 0] > 0
    sections = [contour(h, zs, n_points) for h in half[keep]]
    ys = np.array([c[0] for c in sections])
    zz = np.array([c[1] for c in sections])
    return Hull(
        jnp.asarray(x_all[keep]),
        jnp.asarray(dx_all[keep]),
        jnp.asarray(ys),
        jnp.asarray(zz),
        path.stem,
        bool(half[0, 0] > 0 and np.any(half[0, 1:] > 0)),
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


def _section_wave_forces(y, z, potentials, omega, sin_chi, rho, g):
    """Sway, heave and roll forces per unit length of a wave of unit amplitude and frequency
    ``omega`` travelling at angle χ to the ship's x axis, on one section, as (Froude-Krylov,
    diffraction): X_j = −iωρ ∮ φ₀ n_j ds + iωρ ∮ φ_j ∂φ₀/∂n ds (the diffraction of Salvesen,
    Tuck & Faltinsen 1970 through the radiation potentials ``potentials``, the Haskind form
    of strip theory; at forward speed the potentials are those of the encounter frequency);
    φ₀ = −i(g/ω) e^{kz + iky sinχ} on the section, the factor e^{ikx cosχ} left to the
    caller. ``omega``, ``sin_chi`` (m,), ``potentials`` (m, panels, 3); returns two (m, 3).
    At sinχ = 1 and zero speed the sum is the 2-D beam-sea diffraction force (tested against
    the direct solve)."""
    _, _, mid, length, _, normal = _panels(y, z)
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


def _levers(x, c):
    """(plain u, motion w, force v) levers of the five hull modes at stations x (n,) for the
    speed factors c (m,): each (n, m, 5)."""
    one = jnp.ones(x.shape + c.shape)
    xx = jnp.broadcast_to(x[:, None], one.shape)
    plain = jnp.stack([one, one, one, -xx, xx], axis=-1)
    speed = jnp.asarray(_SPEED_SIGN) * c[None, :, None]
    return plain, plain + speed, plain - speed


def _radiation(t, x, dx, c, transom):
    """T (m, 5, 5) from the section coefficients t (n, m, 3, 3): the strip integrals with
    the speed terms c (m,) of Salvesen, Tuck & Faltinsen and the transom term (the formula is
    in the docstring of `jaxtow.strip._motions`; c = 0 gives the zero-speed integrals)."""
    plain, motion, force = _levers(x, c)
    ts = t[:, :, _SECTION_MODE][:, :, :, _SECTION_MODE]  # (n, m, 5, 5)
    body = jnp.einsum("n,nmj,nmk,nmjk->mjk", dx, force, motion, ts)
    if not transom:
        return body
    end = c[:, None, None] * plain[0, :, :, None] * motion[0, :, None, :] * ts[0]
    return body + end


def _exciting(hull, pots, omega, beta_flat, c, k_cos, rho, g):
    """Exciting forces (m, 5) and the sections' Froude-Krylov heave force (n, m) (for the
    relative motion of the added resistance)."""
    sin_chi = -jnp.sin(beta_flat)
    fk, dif = jax.vmap(lambda y, z, p: _section_wave_forces(y, z, p, omega, sin_chi, rho, g))(
        hull.y, hull.z, pots
    )  # (n, m, 3) each
    phase = jnp.exp(1j * k_cos[None] * hull.x[:, None])  # (n, m)
    plain, _, force = _levers(hull.x, c)
    fk_m = fk[..., _SECTION_MODE] * phase[..., None]
    dif_m = dif[..., _SECTION_MODE] * phase[..., None]
    f = jnp.einsum("n,nmj->mj", hull.dx, plain * fk_m + force * dif_m)
    if hull.transom:
        f = f + c[:, None] * plain[0] * dif_m[0]
    return f, fk[..., 1]


def hull_coefficients(
    hull: Hull, omega, beta=None, *, rho: float = 1025.0, g: float = 9.80665
) -> HullCoefficients:
    """Zero-speed strip theory: the section coefficients of every station
    (`section_coefficients`, vmapped over the stations) summed over the strips with the
    lever arms of pitch and yaw (`_radiation` without the speed terms); with headings
    ``beta`` [rad] also the exciting forces (`_exciting`: each station's, with the wave's
    phase along the hull).
    Differentiable in the offsets."""
    omega = jnp.atleast_1d(jnp.asarray(omega, dtype=float))
    secs = jax.vmap(lambda y, z: section_coefficients(y, z, omega, rho=rho, g=g))(hull.y, hull.z)
    zero = jnp.zeros(omega.shape, complex)  # no speed: the plain levers
    out = dict(
        omega=omega,
        added_mass=jnp.real(_radiation(secs.added_mass, hull.x, hull.dx, zero, False)),
        damping=jnp.real(_radiation(secs.damping, hull.x, hull.dx, zero, False)),
    )
    if beta is None:
        return HullCoefficients(**out)
    beta = jnp.atleast_1d(jnp.asarray(beta, dtype=float))
    nw, nb = omega.shape[0], beta.shape[0]
    w_flat, b_flat = jnp.repeat(omega, nb), jnp.tile(beta, nw)
    pots = jnp.repeat(secs.potentials, nb, axis=1)  # (n, w·b, panels, 3)
    k_cos = -(w_flat**2) / g * jnp.cos(b_flat)  # k cos χ
    f, _ = _exciting(hull, pots, w_flat, b_flat, jnp.zeros_like(w_flat, complex), k_cos, rho, g)
    exciting = f.reshape(nw, nb, 5)
    return HullCoefficients(**out, beta=beta, exciting=exciting)


def hydrostatics(hull: Hull, *, rho: float = 1025.0, g: float = 9.80665) -> dict:
    """Displacement ∇ [m³], centre of buoyancy (x_B, z_B) [m], and the waterplane's restoring
    C33 = ρg∫B dx, C35 = −ρg∫xB dx, C55 = ρg∫x²B dx, C44 = ρg∫B³/12 dx [N/m, N, N m, N m]
    from the stations (the waterplane by the strips; C44 and C55 without ρg∇(z_B − z_G),
    which needs the centre of gravity)."""
    y, z = hull.y, hull.z
    cross = y[:, :-1] * z[:, 1:] - y[:, 1:] * z[:, :-1]  # shoelace terms of the half contour
    area = jnp.abs(jnp.sum(cross, axis=1))  # both halves: 2 × ½ |Σ|
    zc = jnp.sum(cross * (z[:, :-1] + z[:, 1:]), axis=1) / (3.0 * jnp.sum(cross, axis=1))
    vol = jnp.sum(area * hull.dx)
    b = 2.0 * y[:, 0]
    return dict(
        volume=vol,
        x_b=jnp.sum(hull.x * area * hull.dx) / vol,
        z_b=jnp.sum(zc * area * hull.dx) / vol,
        c33=rho * g * jnp.sum(b * hull.dx),
        c35=-rho * g * jnp.sum(hull.x * b * hull.dx),
        c55=rho * g * jnp.sum(hull.x**2 * b * hull.dx),
        c44=rho * g * jnp.sum(b**3 / 12.0 * hull.dx),
    )
