"""From a panel mesh to the stations of strip theory: `mesh_hull` cuts a `HullMesh` (or any
mesh Capytaine reads, through `jaxtow.bem.read_mesh`) at the strip stations and reads each
section's half-breadths at its waterlines, so that strip theory and the panel method can be
run on the same hull (`jaxtow.strip`; docs/strip.md). NumPy geometry; the result is a
`jaxtow.strip.Hull`."""

from __future__ import annotations

import numpy as np

from ..strip import Hull, resample_contour
from .meshes import HullMesh


def _triangles(mesh: HullMesh) -> np.ndarray:
    q = mesh.vertices[mesh.faces]  # (nf, 4, 3); a triangle repeats its last vertex
    return np.concatenate([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])


def _cut(tri: np.ndarray, x: float) -> np.ndarray:
    """The segments (k, 2, 2) in (y, z) where the plane at ``x`` cuts the triangles."""
    d = tri[..., 0] - x  # (nt, 3)
    ends = []
    for i, j in ((0, 1), (1, 2), (2, 0)):
        crosses = (d[:, i] * d[:, j] < 0) | ((d[:, i] == 0) & (d[:, j] != 0))
        t = np.where(crosses, d[:, i] / np.where(crosses, d[:, i] - d[:, j], 1.0), 0.0)
        p = tri[:, i, 1:] + t[:, None] * (tri[:, j, 1:] - tri[:, i, 1:])
        ends.append(np.where(crosses[:, None], p, np.nan))
    pts = np.stack(ends, axis=1)  # (nt, 3, 2): up to two valid crossings per triangle
    ok = np.isfinite(pts[..., 0])
    two = ok.sum(axis=1) == 2
    seg = [pts[k][ok[k]] for k in np.flatnonzero(two)]
    return np.array(seg).reshape(-1, 2, 2)


def _half_breadths(seg: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Largest |y| of the section's segments at each height z."""
    z0, z1 = seg[:, 0, 1][:, None], seg[:, 1, 1][:, None]
    y0, y1 = np.abs(seg[:, 0, 0])[:, None], np.abs(seg[:, 1, 0])[:, None]
    lo, hi = np.minimum(z0, z1), np.maximum(z0, z1)
    inside = (z[None] >= lo) & (z[None] <= hi)
    flat = hi - lo < 1e-12
    t = np.where(flat, 0.0, (z[None] - z0) / np.where(flat, 1.0, z1 - z0))
    y = np.where(flat, np.maximum(y0, y1), y0 + t * (y1 - y0))
    return np.max(np.where(inside, y, 0.0), axis=0)


def mesh_hull(mesh: HullMesh, *, n_stations: int = 21, n_points: int = 12) -> Hull:
    """The strip-theory hull of a panel mesh: ``n_stations`` stations at the midpoints of
    equal strips over the mesh's length; each section's half-breadths are read at 201
    heights from the waterline to its deepest point and its contour, closed to the
    centreline at the keel, resampled to ``n_points`` offsets along its arc length
    (`jaxtow.strip.resample_contour`, as `jaxtow.io.read_offsets`). The hull ends in a transom when the mesh's aft end has a section
    at least half as deep as the deepest. Only the hull panels are cut (not the lid)."""
    if n_stations < 2 or n_points < 3:
        raise ValueError(
            f"parameters 'n_stations' >= 2 and 'n_points' >= 3, got {n_stations}, {n_points}"
        )
    tri = _triangles(mesh)
    x0, x1 = float(tri[..., 0].min()), float(tri[..., 0].max())
    length = x1 - x0
    if not length > 0:
        raise ValueError(f"parameter 'mesh' ({mesh.name}): the mesh has no length")
    dx = length / n_stations
    xs = x0 + dx * (np.arange(n_stations) + 0.5)
    s = 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, 201)))  # heights where the mesh is read
    keep, ys, zs = [], [], []
    nudge = 1e-9 * length  # off the mesh's own vertex planes (a cut through vertices is degenerate)
    for i, x in enumerate(xs):
        seg = _cut(tri, x + nudge)
        if seg.size == 0:
            continue
        depth = -float(seg[..., 1].min())
        if not depth > 0:
            continue
        z = -depth * s
        inset = np.clip(z, -depth * (1 - 1e-9), -depth * 1e-9)  # inside the hull's extent
        y, zc = resample_contour(_half_breadths(seg, inset), z, n_points)
        ys.append(y)
        zs.append(zc)
        keep.append(i)
    if len(keep) < 2:
        raise ValueError(f"parameter 'mesh' ({mesh.name}): fewer than two stations have a section")
    aft = _cut(tri, x0 + 1e-6 * length)
    depths = [-min(z[-1] for z in zs)]
    transom = aft.size > 0 and -float(aft[..., 1].min()) >= 0.5 * max(depths)
    return Hull(
        np.asarray(xs[keep]),
        np.full(len(keep), dx),
        np.asarray(ys),
        np.asarray(zs),
        mesh.name,
        bool(transom),
    )


__all__ = ["mesh_hull"]
