"""Waterline geometry for the short-wave and empirical drift methods (thesis section 2.3, C.1).

A `Waterline` is a closed polygon in body axes (x forward from midships, y to port, metres),
ordered counter-clockwise seen from above, i.e. from the bow along the port side to the
stern and back along starboard, as the thesis's input files describe it. Segment i runs
from ``points[i]`` to ``points[i+1]`` (the last back to the first) and carries its own
waterline flare η_i (angle of the hull surface from the vertical at the waterline, 0 for a
wall-sided hull) and local draft d_i, which Liu et al.'s method uses.

Geometry used by the methods, all differentiable in the coordinates:

* inward unit normal n_i (into the hull) and length dl_i of each segment;
* Faltinsen's waterline angle θ_i with n = (sin θ, cos θ) (thesis eqs 2.31, 2.60);
* the illuminated part for a wave heading β: waves travel along k̂ = (−cos β, −sin β)
  (β = 0 head seas, counter-clockwise from the bow; the convention of `jaxtow.drift`), and a
  segment is lit where k̂·n > 0. For a convex waterline this is exact; shadowing of one part
  of a non-convex waterline by another is not modelled, and ``convex`` says so.

Builders of the built-in hulls' waterlines are in `jaxtow.presets` (`box_waterline`,
`barge2_waterline`); `jaxtow.io.read_waterline` reads the thesis's half-waterline text format
and mirrors it about the centreline (`mirror_half`).
"""

from __future__ import annotations

import math

import equinox as eqx
import jax.numpy as jnp
import numpy as np

from .._rules import POSITIVE

GEOMETRY_TOL = 1e-9


class Waterline(eqx.Module):
    """A closed, counter-clockwise waterline polygon (build it with `waterline` or a builder;
    those check it). Arrays are per vertex (``points``, shape (N, 2)) and per segment
    (``flare`` [rad], ``local_draft`` [m], shape (N,))."""

    points: jnp.ndarray
    flare: jnp.ndarray
    local_draft: jnp.ndarray
    draft: jnp.ndarray
    block_coefficient: jnp.ndarray
    convex: bool = eqx.field(static=True, default=True)
    name: str = eqx.field(static=True, default="")

    @property
    def n_segments(self) -> int:
        return self.points.shape[0]

    @property
    def ends(self):
        return jnp.roll(self.points, -1, axis=0)

    @property
    def lengths(self):
        d = self.ends - self.points
        return jnp.sqrt(jnp.sum(d**2, axis=-1))

    @property
    def midpoints(self):
        return 0.5 * (self.points + self.ends)

    @property
    def normals(self):
        """Inward unit normals (left of the counter-clockwise direction of travel)."""
        d = self.ends - self.points
        t = d / self.lengths[:, None]
        return jnp.stack([-t[:, 1], t[:, 0]], axis=-1)

    @property
    def theta(self):
        """Faltinsen's waterline angle θ per segment, n = (sin θ, cos θ) (thesis eq. 2.60)."""
        n = self.normals
        return jnp.arctan2(n[:, 0], n[:, 1])

    @property
    def length(self):
        """Waterline length (x extent) [m]."""
        x = self.points[:, 0]
        return jnp.max(x) - jnp.min(x)

    @property
    def breadth(self):
        """Waterline breadth (y extent) [m]."""
        y = self.points[:, 1]
        return jnp.max(y) - jnp.min(y)

    @property
    def area(self):
        """Waterplane area [m²] (shoelace formula)."""
        p, q = self.points, self.ends
        return 0.5 * jnp.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1])

    def bow_length_to_95_breadth(self):
        """L_b of the IMO / Söding–Shigunov formula (thesis eq. 2.65): the distance from the
        foremost point of the waterline to the foremost station where the half-breadth |y|
        reaches 95 % of its maximum (measured from the centreline y = 0). Zero for a
        transom-like bow such as a box barge's."""
        y0, y1 = jnp.abs(self.points[:, 1]), jnp.abs(self.ends[:, 1])
        x0, x1 = self.points[:, 0], self.ends[:, 0]
        h = 0.95 * jnp.max(y0)
        at_vertex = jnp.where(y0 >= h, x0, -jnp.inf)
        crosses = (y0 - h) * (y1 - h) < 0
        s = (h - y0) / jnp.where(crosses, y1 - y0, 1.0)
        at_cross = jnp.where(crosses, x0 + s * (x1 - x0), -jnp.inf)
        x95 = jnp.maximum(jnp.max(at_vertex), jnp.max(at_cross))
        return jnp.max(x0) - x95


def _segments_intersect(p, q, r, s) -> bool:
    """Proper or touching intersection of closed segments pq and rs (2-D, numpy)."""

    def orient(a, b, c):
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])

    def on_seg(a, b, c, eps):
        return (
            min(a[0], b[0]) - eps <= c[0] <= max(a[0], b[0]) + eps
            and min(a[1], b[1]) - eps <= c[1] <= max(a[1], b[1]) + eps
        )

    scale = max(np.ptp([p[0], q[0], r[0], s[0]]), np.ptp([p[1], q[1], r[1], s[1]]), 1.0)
    eps = GEOMETRY_TOL * scale
    d1, d2, d3, d4 = orient(r, s, p), orient(r, s, q), orient(p, q, r), orient(p, q, s)
    e = eps * scale
    if ((d1 > e and d2 < -e) or (d1 < -e and d2 > e)) and (
        (d3 > e and d4 < -e) or (d3 < -e and d4 > e)
    ):
        return True
    return (
        (abs(d1) <= e and on_seg(r, s, p, eps))
        or (abs(d2) <= e and on_seg(r, s, q, eps))
        or (abs(d3) <= e and on_seg(p, q, r, eps))
        or (abs(d4) <= e and on_seg(p, q, s, eps))
    )


def _per_segment(name, value, n):
    a = np.asarray(value, dtype=float)
    if a.ndim > 1 or (a.ndim == 1 and a.size not in (1, n)):
        raise ValueError(
            f"parameter {name!r} must be one value or one per segment ({n} segments), got "
            f"shape {a.shape}"
        )
    a = np.broadcast_to(a, (n,)).copy()
    if not np.all(np.isfinite(a)):
        raise ValueError(f"parameter {name!r} must be finite, got {a!r}")
    return a


def waterline(
    points, *, draft: float, flare=0.0, local_draft=None, block_coefficient=None, name: str = ""
) -> Waterline:
    """A checked `Waterline` from a closed polyline.

    ``points``: (N+1, 2) vertices [m] with the last equal to the first (a closed polyline),
    in either orientation (clockwise input is reversed). ``flare`` [rad] and ``local_draft``
    [m] are per segment (scalars broadcast; local draft defaults to ``draft``).
    ``block_coefficient`` defaults to the waterplane coefficient A_wp/(L·B), which equals C_B
    for a wall-sided prismatic hull.

    Raises ValueError naming the problem for a polyline that is not closed, has fewer than
    three segments, repeated points, self-intersects, or has zero breadth or length.
    """
    p = np.asarray(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2 or p.shape[0] < 4:
        raise ValueError(
            f"parameter 'points' must have shape (N+1, 2) with N >= 3 segments, got {p.shape}"
        )
    if not np.all(np.isfinite(p)):
        raise ValueError("parameter 'points' must be finite")
    size = max(np.ptp(p[:, 0]), np.ptp(p[:, 1]))
    if np.ptp(p[:, 1]) <= GEOMETRY_TOL * max(size, 1.0):
        raise ValueError("parameter 'points': the waterline has zero breadth")
    if np.ptp(p[:, 0]) <= GEOMETRY_TOL * max(size, 1.0):
        raise ValueError("parameter 'points': the waterline has zero length")
    if np.linalg.norm(p[-1] - p[0]) > GEOMETRY_TOL * size:
        raise ValueError(
            f"parameter 'points': the waterline is not closed (first point {p[0]}, "
            f"last point {p[-1]}; repeat the first point at the end)"
        )
    p = p[:-1]
    n = p.shape[0]
    seg = np.roll(p, -1, axis=0) - p
    if np.any(np.linalg.norm(seg, axis=1) <= GEOMETRY_TOL * size):
        raise ValueError(
            "parameter 'points': the waterline has repeated consecutive points (zero-length segment)"
        )
    for i in range(n):
        for j in range(i + 1, n):
            if j == i + 1 or (i == 0 and j == n - 1):
                continue  # neighbours share a vertex
            if _segments_intersect(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n]):
                raise ValueError(
                    f"parameter 'points': the waterline self-intersects (segments {i} and {j})"
                )
    fl = _per_segment("flare", flare, n)
    if np.any(np.abs(fl) >= 0.5 * math.pi):
        raise ValueError("parameter 'flare' must lie in (-pi/2, pi/2) rad")
    POSITIVE.check("draft", draft)  # before it becomes the default local draft
    ld = _per_segment("local_draft", draft if local_draft is None else local_draft, n)
    POSITIVE.check("local_draft", ld)
    area2 = np.sum(p[:, 0] * np.roll(p[:, 1], -1) - np.roll(p[:, 0], -1) * p[:, 1])
    if area2 < 0:  # clockwise: reverse vertices, and the per-segment values with them
        p = p[::-1].copy()
        fl = np.roll(fl[::-1], -1)
        ld = np.roll(ld[::-1], -1)
        area2 = -area2
    seg = np.roll(p, -1, axis=0) - p
    cross = seg[:, 0] * np.roll(seg, -1, axis=0)[:, 1] - seg[:, 1] * np.roll(seg, -1, axis=0)[:, 0]
    convex = bool(np.all(cross >= -GEOMETRY_TOL * size**2))
    if block_coefficient is None:
        block_coefficient = 0.5 * area2 / (np.ptp(p[:, 0]) * np.ptp(p[:, 1]))
    if not (0 < block_coefficient <= 1.0 + 1e-12):
        raise ValueError(
            f"parameter 'block_coefficient' must lie in (0, 1], got {block_coefficient}"
        )
    return Waterline(
        points=jnp.asarray(p),
        flare=jnp.asarray(fl),
        local_draft=jnp.asarray(ld),
        draft=jnp.asarray(float(draft)),
        block_coefficient=jnp.asarray(float(block_coefficient)),
        convex=convex,
        name=name,
    )


def mirror_half(half, flare=0.0, local_draft=None):
    """Full closed polyline and per-segment values from half a waterline.

    ``half``: (M, 2) vertices from the bow on the centreline (y = 0) along one side to the
    stern on the centreline; per-segment ``flare``/``local_draft`` have M−1 entries (or are
    scalars). Returns (points (2M−1, 2) closed, flare (2M−2,), local_draft (2M−2,) or None).
    """
    h = np.asarray(half, dtype=float)
    if h.ndim != 2 or h.shape[1] != 2 or h.shape[0] < 2:
        raise ValueError(f"half waterline must have shape (M, 2), M >= 2, got {h.shape}")
    size = max(np.ptp(h[:, 0]), np.ptp(h[:, 1]), 1.0)
    if abs(h[0, 1]) > GEOMETRY_TOL * size or abs(h[-1, 1]) > GEOMETRY_TOL * size:
        raise ValueError(
            "half waterline: the first and last points must lie on the centreline y = 0, "
            f"got y = {h[0, 1]} and {h[-1, 1]}; otherwise the mirrored waterline is not closed"
        )
    m = h.shape[0] - 1
    mirrored = h[-2::-1] * np.array([1.0, -1.0])
    pts = np.concatenate([h, mirrored], axis=0)
    fl = np.broadcast_to(np.asarray(flare, float), (m,))
    fl = np.concatenate([fl, fl[::-1]])
    ld = None
    if local_draft is not None:
        ld = np.broadcast_to(np.asarray(local_draft, float), (m,))
        ld = np.concatenate([ld, ld[::-1]])
    return pts, fl, ld
