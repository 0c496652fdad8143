"""Parametric hull meshes for the panel method (thesis section 3.5, appendix B), NumPy only.

A `HullMesh` is the wetted hull below the mean waterline z = 0 as flat panels (quads;
a triangle repeats its last vertex), with the normals pointing *out of the hull, into the
water* (Capytaine's convention), plus a lid: the waterplane at z = 0, panelled, used by
Capytaine to remove the irregular frequencies (docs/bem.md: the first one of
a 76.2 × 24.4 × 5 m box lies near 1.5 rad/s, inside the thesis's range).

Axes: x forward from midships, y to port, z up from the mean waterline (metres), the body
axes of jaxtow. Builders:

* `box_barge_mesh`: Barge 1, the wall-sided 76.2 × 24.4 m box;
* `raked_barge_mesh` / `barge2_mesh`: Barge 2, the same waterline with bow and stern faces
  raked from the waterline to the keel over a horizontal distance ``rake`` (the geometry of
  `jaxtow.presets.barge2_rake` and `jaxtow.presets.barge2_waterline`);
* `vertical_cylinder_mesh`: the reference case (bottom-mounted or truncated cylinder);
* `jaxtow.bem.read_mesh` (needs Capytaine) reads user hulls in the formats Capytaine reads.

Panel size control: every patch is cut into ceil(extent / panel_size) panels along each of
its two directions (rounded up to an even number along the length and the breadth, so that
no panel straddles a symmetry plane), so patches share their edge vertices (a conforming mesh).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .. import presets


@dataclasses.dataclass(frozen=True)
class Waterplane:
    """A waterplane's area [m²] and its moments about the mesh's axes: ``sx`` = ∬x dA,
    ``sy`` = ∬y dA [m³], ``ixx`` = ∬x² dA, ``iyy`` = ∬y² dA, ``ixy`` = ∬xy dA [m⁴]."""

    area: float
    sx: float
    sy: float
    ixx: float
    iyy: float
    ixy: float


@dataclasses.dataclass(frozen=True)
class HullMesh:
    """Wetted hull panels and lid: ``vertices`` (nv, 3), ``faces`` (nf, 4) int, ``lid_vertices``,
    ``lid_faces`` (the waterplane, may be empty), ``name``, ``panel_size`` [m] (nominal) and
    ``params`` (the builder's arguments, recorded in every output)."""

    vertices: np.ndarray
    faces: np.ndarray
    lid_vertices: np.ndarray
    lid_faces: np.ndarray
    name: str
    panel_size: float
    params: dict = dataclasses.field(default_factory=dict)

    @property
    def n_panels(self) -> int:
        return int(self.faces.shape[0])

    def _quads(self):
        return self.vertices[self.faces]  # (nf, 4, 3)

    @property
    def centres(self) -> np.ndarray:
        """Area-weighted centroids of the panels (two triangles per quad)."""
        q = self._quads()
        t1, t2 = q[:, [0, 1, 2]], q[:, [0, 2, 3]]
        a1, a2 = _tri_area(t1), _tri_area(t2)
        c = (a1[:, None] * t1.mean(1) + a2[:, None] * t2.mean(1)) / np.maximum(a1 + a2, 1e-300)[
            :, None
        ]
        return c

    @property
    def areas(self) -> np.ndarray:
        q = self._quads()
        return _tri_area(q[:, [0, 1, 2]]) + _tri_area(q[:, [0, 2, 3]])

    @property
    def normals(self) -> np.ndarray:
        """Unit normals, out of the hull into the water (from the diagonals' cross product)."""
        q = self._quads()
        n = np.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 1])
        return n / np.linalg.norm(n, axis=1, keepdims=True)

    @property
    def volume(self) -> float:
        """Displaced volume ∇ = ∬ z n_z dS over the hull (divergence theorem with the outward
        normal; the waterplane z = 0 adds nothing). Exact for flat panels (linear integrand)."""
        return float(np.sum(self.centres[:, 2] * self.normals[:, 2] * self.areas))

    def waterline(self, tol: float = 1e-9):
        """Waterline segments: the panel edges on z = 0. Returns (p0, p1, panel index) with
        p0, p1 (ns, 3) ordered so that the horizontal normal of the owning panel is on the
        right-hand side when walking p0 → p1 seen from above (counter-clockwise round the hull)."""
        p0s, p1s, owner = [], [], []
        for i, f in enumerate(self.faces):
            ring = list(dict.fromkeys(int(v) for v in f))  # drop a repeated triangle vertex
            for a, b in zip(ring, ring[1:] + ring[:1]):
                va, vb = self.vertices[a], self.vertices[b]
                if abs(va[2]) < tol and abs(vb[2]) < tol and np.linalg.norm(vb - va) > tol:
                    p0s.append(va)
                    p1s.append(vb)
                    owner.append(i)
        if not owner:
            raise ValueError(f"mesh {self.name!r} has no panel edges on the waterline z = 0")
        p0, p1, owner = np.array(p0s), np.array(p1s), np.array(owner)
        n = self.normals[owner][:, :2]
        t = (p1 - p0)[:, :2]
        flip = (t[:, 0] * n[:, 1] - t[:, 1] * n[:, 0]) > 0  # normal must be on the right
        p0[flip], p1[flip] = p1[flip].copy(), p0[flip].copy()
        return p0, p1, owner

    def waterplane(self) -> Waterplane:
        """Exact waterplane properties from the waterline polygon (Green's theorem on the
        segments): area, first moments ∬x, ∬y and second moments ∬x², ∬y², ∬xy [m^k]."""
        p0, p1, _ = self.waterline()
        # segments run counter-clockwise with the water on the right: the enclosed region
        # (the waterplane) is on the left, so Green's theorem applies with a + sign.
        x0, y0, x1, y1 = p0[:, 0], p0[:, 1], p1[:, 0], p1[:, 1]
        cr = x0 * y1 - x1 * y0
        area = 0.5 * np.sum(cr)
        sx = np.sum((x0 + x1) * cr) / 6.0  # ∬ x dA
        sy = np.sum((y0 + y1) * cr) / 6.0
        ixx = np.sum((x0 * x0 + x0 * x1 + x1 * x1) * cr) / 12.0  # ∬ x² dA
        iyy = np.sum((y0 * y0 + y0 * y1 + y1 * y1) * cr) / 12.0
        ixy = np.sum((x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * cr) / 24.0
        return Waterplane(
            area=float(area),
            sx=float(sx),
            sy=float(sy),
            ixx=float(ixx),
            iyy=float(iyy),
            ixy=float(ixy),
        )

    def centre_of_buoyancy(self) -> np.ndarray:
        """(x_B, y_B, z_B) [m], exact for flat panels: ∇ x_B,i = ∬ ½ x_i² n_i dS (no sum)."""
        q = self._quads()
        tris = np.concatenate([q[:, [0, 1, 2]], q[:, [0, 2, 3]]])
        nrm = np.concatenate([self.normals, self.normals])
        area = _tri_area(tris)
        mids = 0.5 * (tris + np.roll(tris, -1, axis=1))  # edge midpoints: exact for quadratics
        sq = np.mean(mids**2, axis=1)  # (nt, 3): mean of x_i² over the triangle
        return 0.5 * np.sum(sq * nrm * area[:, None], axis=0) / self.volume


def _tri_area(t):
    return 0.5 * np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1)


def _spacing(n, grading):
    """n + 1 nodes on [0, 1]: uniform blended with cosine clustering towards both ends
    (``grading`` 0 = uniform, 1 = full cosine), which resolves the flow round the hull's
    edges and corners (where the velocity is singular) and at the waterline."""
    u = np.linspace(0.0, 1.0, n + 1)
    return (1.0 - grading) * u + grading * 0.5 * (1.0 - np.cos(math.pi * u))


def _patch(corner, n_s, n_t, outward, grading=(0.0, 0.0)):
    """Structured quads of the bilinear patch ``corner(s, t)`` (s, t in [0, 1]), ordered so
    that the normal points along ``outward``; returns (vertices, faces)."""
    s = _spacing(n_s, grading[0])
    t = _spacing(n_t, grading[1])
    S, T = np.meshgrid(s, t, indexing="ij")
    verts = corner(S, T).reshape(-1, 3)
    idx = np.arange((n_s + 1) * (n_t + 1)).reshape(n_s + 1, n_t + 1)
    faces = np.stack([idx[:-1, :-1], idx[1:, :-1], idx[1:, 1:], idx[:-1, 1:]], axis=-1).reshape(
        -1, 4
    )
    q = verts[faces]
    n = np.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 1])
    flip = n @ np.asarray(outward, float) < 0
    faces[flip] = faces[flip][:, ::-1]
    return verts, faces


def _join(patches, tol=1e-9):
    """Concatenate patches and merge coincident vertices."""
    verts, faces, off = [], [], 0
    for v, f in patches:
        verts.append(v)
        faces.append(f + off)
        off += v.shape[0]
    v = np.concatenate(verts)
    f = np.concatenate(faces)
    key = np.round(v / tol).astype(np.int64)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    return v[first], inverse.reshape(-1)[f]


def _n(extent, panel_size):
    return max(1, int(math.ceil(extent / panel_size - 1e-9)))


def _n_even(extent, panel_size):
    """An even panel count across a symmetry plane, so that no panel straddles it and the
    panel solver can use the hull's reflection symmetry."""
    n = _n(extent, panel_size)
    return n + (n % 2)


def _check(**kw):
    for name, v in kw.items():
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ValueError(f"parameter {name!r} must be a positive finite number, got {v!r}")


def _lid(xmin, xmax, ymin, ymax, panel_size):
    def corner(S, T):
        return np.stack([xmin + (xmax - xmin) * S, ymin + (ymax - ymin) * T, np.zeros_like(S)], -1)

    return _patch(
        corner, _n_even(xmax - xmin, panel_size), _n_even(ymax - ymin, panel_size), (0, 0, -1)
    )


def raked_barge_mesh(
    length: float,
    breadth: float,
    draft: float,
    rake: float = 0.0,
    *,
    panel_size: float = 2.0,
    grading: float = 0.0,
    lid: bool = True,
    name: str = "raked_barge",
) -> HullMesh:
    """Barge with a rectangular L × B waterline whose bow and stern faces run straight from
    the waterline (x = ±L/2) down to the keel (x = ±(L/2 − rake)); ``rake = 0`` is a box.
    ``grading`` in [0, 1] clusters the panels towards every edge (cosine spacing, the same
    number of panels as the uniform mesh of ``panel_size``)."""
    if not (0.0 <= grading <= 1.0):
        raise ValueError(f"parameter 'grading' must lie in [0, 1], got {grading!r}")
    _check(length=length, breadth=breadth, draft=draft, panel_size=panel_size)
    if not (math.isfinite(rake) and 0.0 <= rake < 0.5 * length):
        raise ValueError(f"parameter 'rake' must lie in [0, length/2), got {rake!r}")
    L2, B2, T, a = 0.5 * length, 0.5 * breadth, float(draft), float(rake)
    nx, ny = _n_even(length, panel_size), _n_even(breadth, panel_size)
    nz = _n(math.hypot(a, T), panel_size)

    def side(sign):
        def corner(S, Tt):  # Tt = 0 at the waterline, 1 at the keel
            x0, x1 = -L2 + a * Tt, L2 - a * Tt
            return np.stack([x0 + (x1 - x0) * S, sign * B2 * np.ones_like(S), -T * Tt], -1)

        return _patch(corner, nx, nz, (0, sign, 0), (grading, grading))

    def end(sign):
        def corner(S, Tt):
            return np.stack([sign * (L2 - a * Tt), -B2 + 2 * B2 * S, -T * Tt], -1)

        return _patch(corner, ny, nz, (sign * T, 0, -a), (grading, grading))

    def bottom(S, Tt):
        return np.stack([-(L2 - a) + 2 * (L2 - a) * S, -B2 + 2 * B2 * Tt, -T * np.ones_like(S)], -1)

    v, f = _join(
        [side(1), side(-1), end(1), end(-1), _patch(bottom, nx, ny, (0, 0, -1), (grading, grading))]
    )
    lv, lf = (
        _lid(-L2, L2, -B2, B2, panel_size) if lid else (np.zeros((0, 3)), np.zeros((0, 4), int))
    )
    params = dict(
        length=float(length),
        breadth=float(breadth),
        draft=T,
        rake=a,
        panel_size=float(panel_size),
        grading=float(grading),
    )
    return HullMesh(v, f, lv, lf, name, float(panel_size), params)


def box_barge_mesh(
    length: float = 76.2,
    breadth: float = 24.4,
    draft: float | None = None,
    *,
    panel_size: float = 2.0,
    grading: float = 0.0,
    lid: bool = True,
) -> HullMesh:
    """Barge 1: the wall-sided box (thesis section 3.5). The draft defaults to the documented
    estimate `jaxtow.presets.ASSUMPTIONS['draft']` (5.0 m; not in the thesis text)."""
    T = presets.ASSUMPTIONS["draft"]["value"] if draft is None else draft
    return raked_barge_mesh(
        length, breadth, T, 0.0, panel_size=panel_size, grading=grading, lid=lid, name="barge1_box"
    )


def barge2_mesh(
    draft: float | None = None, *, panel_size: float = 2.0, grading: float = 0.0, lid: bool = True
) -> HullMesh:
    """Barge 2: 76.2 × 24.4 m with raked bow and stern (`jaxtow.presets.barge2_rake`: the rake
    that matches C_B = 0.928 of the published m', a documented estimate)."""
    r = presets.barge2_rake(draft)
    return raked_barge_mesh(
        presets.BARGE2_LENGTH,
        presets.BARGE2_BREADTH,
        r.draft,
        r.extent,
        panel_size=panel_size,
        grading=grading,
        lid=lid,
        name="barge2_raked",
    )


def vertical_cylinder_mesh(
    radius: float, draft: float, *, panel_size: float = 1.0, bottom: bool = True, lid: bool = True
) -> HullMesh:
    """Vertical circular cylinder from z = 0 to z = −draft (an inscribed polygon of
    ceil(2πR / panel_size) sides). ``bottom=False`` leaves the base open, for a cylinder that
    stands on the sea floor (draft = water depth)."""
    _check(radius=radius, draft=draft, panel_size=panel_size)
    nth = max(8, _n(2 * math.pi * radius, panel_size))
    nz = _n(draft, panel_size)

    def wall(S, Tt):
        th = 2 * math.pi * S
        return np.stack([radius * np.cos(th), radius * np.sin(th), -draft * Tt], -1)

    v, f = _patch(wall, nth, nz, (0, 0, 0))
    # outward: fix the orientation with the radial direction of each panel
    q = v[f]
    n = np.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 1])
    c = q.mean(1)
    flip = np.sum(n[:, :2] * c[:, :2], axis=1) < 0
    f[flip] = f[flip][:, ::-1]
    patches = [(v, f)]
    nr = max(1, int(round(radius / panel_size)))
    if bottom:
        patches.append(_disc(radius, nth, nr, -draft, down=True))
    v, f = _join(patches)
    lv, lf = (
        _disc(radius, nth, nr, 0.0, down=True) if lid else (np.zeros((0, 3)), np.zeros((0, 4), int))
    )
    params = dict(
        radius=float(radius), draft=float(draft), bottom=bool(bottom), panel_size=float(panel_size)
    )
    return HullMesh(v, f, lv, lf, "vertical_cylinder", float(panel_size), params)


def _disc(radius, nth, nr, z, *, down):
    """Polar-panelled disc at height z (quads, triangles at the centre)."""
    r = np.linspace(0.0, radius, nr + 1)
    th = np.linspace(0.0, 2 * math.pi, nth + 1)[:-1]
    verts = [np.array([[0.0, 0.0, z]])]
    for ri in r[1:]:
        verts.append(np.stack([ri * np.cos(th), ri * np.sin(th), np.full(nth, z)], -1))
    v = np.concatenate(verts)

    def ring(i, j):  # vertex index of ring i (>= 1), angle j
        return 1 + (i - 1) * nth + (j % nth)

    faces = []
    for j in range(nth):
        faces.append([0, ring(1, j), ring(1, j + 1), ring(1, j + 1)])
        for i in range(1, nr):
            faces.append([ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)])
    f = np.array(faces)
    q = v[f]
    n = np.cross(q[:, 2] - q[:, 0], q[:, 3] - q[:, 1])
    want = -1.0 if down else 1.0
    flip = n[:, 2] * want < 0
    f[flip] = f[flip][:, ::-1]
    return v, f
