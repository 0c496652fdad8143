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
from jaxtyping import Array, Float

from ._sections import section_coefficients

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
    return Hull(jnp.asarray(x), jnp.asarray(dx), jnp.tile(ys, (n, 1)), jnp.tile(zs, (n, 1)), "box")


def wigley(
    length: float, breadth: float, draft: float, *, n_stations: int = 21, n_points: int = 12
) -> Hull:
    """The Wigley hull y = (B/2)(1 − (2x/L)²)(1 − (z/T)²), the mathematical hull of many
    seakeeping experiments (Journée 1992 tested it at L/B = 10, B/T = 1.6 and variants).
    Offsets at n_points depths, cosine-spaced towards the waterline and the keel."""
    for name, v in (("breadth", breadth), ("draft", draft)):
        if not v > 0:
            raise ValueError(f"{name} must be > 0, got {v!r}")
    x, dx = _strips(length, n_stations)
    s = 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, n_points)))
    zs = -draft * s
    half = 0.5 * breadth * (1.0 - (2.0 * x / length) ** 2)
    ys = half[:, None] * (1.0 - (zs / draft) ** 2)[None, :]
    return Hull(
        jnp.asarray(x), jnp.asarray(dx), jnp.asarray(ys), jnp.tile(zs, (len(x), 1)), "wigley"
    )


def offsets_file(path, *, n_points: int = 12) -> Hull:
    """A hull from an offsets table (CSV): the first row is ``x`` and the waterline heights z
    [m] (0 at the still waterline, negative below; they must include 0); each further row is
    a station, its x [m] from midships (+ forward) and the half-breadths [m] at those
    waterlines. Each station is resampled to ``n_points`` offsets between the waterline and
    the deepest waterline, and closed to the centreline at the keel. Stations whose breadth
    at the waterline is zero are left out (they carry no section); strips follow the
    stations' spacing (half-way to each neighbour)."""
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
    zq = zs[-1] * 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, n_points - 1)))
    ys = np.array([np.interp(-zq, -zs, h) for h in half[keep]])
    ys = np.c_[ys, np.zeros(len(ys))]
    zz = np.tile(np.r_[zq, zq[-1]], (len(ys), 1))
    return Hull(
        jnp.asarray(x_all[keep]),
        jnp.asarray(dx_all[keep]),
        jnp.asarray(ys),
        jnp.asarray(zz),
        path.stem,
    )


class HullCoefficients(eqx.Module):
    """Zero-speed strip-theory added mass and damping of a hull, (..., 5, 5) over `MODES`
    (sway, heave, roll, pitch, yaw) in SI, at ``omega`` (...)."""

    omega: Float[Array, "..."]
    added_mass: Float[Array, "... 5 5"]
    damping: Float[Array, "... 5 5"]


def _strip_matrix(sec, x, dx):
    """Σ over strips of a (n, w, 3, 3) section matrix into (w, 5, 5): sway-yaw and heave-pitch
    through the lever x (vertical motion η3 − xη5, lateral η2 + xη6)."""
    s = sec * dx[:, None, None, None]
    xs = x[:, None]
    m = jnp.zeros(s.shape[1:2] + (5, 5))
    # sway (0), heave (1), roll (2) of the section; hull modes 0 sway,1 heave,2 roll,3 pitch,4 yaw
    m = m.at[:, :3, :3].set(jnp.sum(s, axis=0))
    m = m.at[:, 1, 3].set(-jnp.sum(xs * s[..., 1, 1], axis=0))
    m = m.at[:, 3, 1].set(-jnp.sum(xs * s[..., 1, 1], axis=0))
    m = m.at[:, 3, 3].set(jnp.sum(xs**2 * s[..., 1, 1], axis=0))
    m = m.at[:, 0, 4].set(jnp.sum(xs * s[..., 0, 0], axis=0))
    m = m.at[:, 4, 0].set(jnp.sum(xs * s[..., 0, 0], axis=0))
    m = m.at[:, 2, 4].set(jnp.sum(xs * s[..., 2, 0], axis=0))
    m = m.at[:, 4, 2].set(jnp.sum(xs * s[..., 0, 2], axis=0))
    m = m.at[:, 4, 4].set(jnp.sum(xs**2 * s[..., 0, 0], axis=0))
    return m


def hull_coefficients(
    hull: Hull, omega, *, rho: float = 1025.0, g: float = 9.80665
) -> HullCoefficients:
    """Zero-speed strip theory: the section coefficients of every station
    (`section_coefficients`, vmapped over the stations) summed over the strips, with the
    lever arms of pitch and yaw. Differentiable in the offsets."""
    omega = jnp.atleast_1d(jnp.asarray(omega, dtype=float))
    secs = jax.vmap(lambda y, z: section_coefficients(y, z, omega, rho=rho, g=g))(hull.y, hull.z)
    return HullCoefficients(
        omega=omega,
        added_mass=_strip_matrix(secs.added_mass, hull.x, hull.dx),
        damping=_strip_matrix(secs.damping, hull.x, hull.dx),
    )
