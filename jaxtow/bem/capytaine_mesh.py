# pyright: reportAttributeAccessIssue=false, reportOptionalMemberAccess=false, reportCallIssue=false
"""Capytaine's side of a hull: a jaxtow `HullMesh` as a Capytaine mesh (with the symmetry
planes Capytaine exploits found from the vertices) and a user's hull read in any format
Capytaine reads."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from .meshes import HullMesh

INSTALL_HINT = (
    "jaxtow.bem needs the optional panel-method extra (Capytaine): "
    "pip install 'jaxtow[bem]'  (or: pip install capytaine)"
)


def require_capytaine():
    """Import Capytaine or raise an ImportError that says how to install it."""
    try:
        import capytaine
    except ImportError as err:  # pragma: no cover - exercised with the extra missing
        raise ImportError(INSTALL_HINT) from err
    return capytaine


def to_capytaine_mesh(mesh: HullMesh):
    """(hull, lid) as Capytaine meshes (lid None when the mesh has none)."""
    cpt = require_capytaine()
    hull = cpt.Mesh(vertices=mesh.vertices, faces=mesh.faces, name=mesh.name)
    lid = (
        cpt.Mesh(vertices=mesh.lid_vertices, faces=mesh.lid_faces, name=mesh.name + "_lid")
        if len(mesh.lid_faces)
        else None
    )
    return hull, lid


_PLANES = {"xOz": 1, "yOz": 0}  # Capytaine's plane name -> the coordinate it reflects


def _mirror_planes(vertices, faces, tol: float = 1e-7) -> list:
    """The reflection planes (Capytaine's "xOz": y -> -y, "yOz": x -> -x) that map the panel
    set onto itself with no panel on the plane."""
    q = vertices[faces]
    c = q.mean(axis=1)
    out = []
    for plane, ax in _PLANES.items():
        if np.any(np.abs(c[:, ax]) <= tol):
            continue
        pos, neg = c[c[:, ax] > tol], c[c[:, ax] < -tol].copy()
        neg[:, ax] *= -1
        if len(pos) != len(neg):
            continue

        def key(a):
            return a[np.lexsort(np.round(a / tol).T[::-1])]

        if np.allclose(key(pos), key(neg), atol=10 * tol):
            out.append(plane)
    return out


def _symmetric_mesh(vertices, faces, planes, name):
    """The Capytaine ReflectionSymmetricMesh over ``planes`` (outermost last) of the panels on
    the positive side of every plane."""
    cpt = require_capytaine()
    c = vertices[faces].mean(axis=1)
    keep = np.ones(len(faces), bool)
    for p in planes:
        keep &= c[:, _PLANES[p]] > 0
    m = cpt.Mesh(vertices=vertices, faces=faces[keep], name=name)
    for p in planes:
        m = cpt.ReflectionSymmetricMesh(half=m, plane=p, name=name)
    return m


def _corners(cmesh) -> np.ndarray:
    """The corners (n_panels, 4, 3) of every panel of the Capytaine mesh ``cmesh``, in the
    order and orientation of its ``merged()`` form: a reflection-symmetric mesh is its half,
    then the half mirrored about its plane with each panel's corners reversed (the normals
    kept pointing out), as Capytaine joins them. NumPy on whole arrays, where Capytaine's
    ``merged()`` builds the joined mesh face by face in Python and cleans it."""
    if hasattr(cmesh, "half") and hasattr(cmesh, "plane"):
        half = _corners(cmesh.half)
        other = half[:, ::-1].copy()
        other[..., _PLANES[cmesh.plane]] *= -1.0
        return np.concatenate([half, other])
    return np.asarray(cmesh.vertices, float)[np.asarray(cmesh.faces, int)]


def _merged_hull(cmesh, like: HullMesh) -> HullMesh:
    """A jaxtow HullMesh with the panels in the order of the Capytaine mesh ``cmesh`` (shared
    vertices merged, so that the near-field gradient sees every neighbour)."""
    c = _corners(cmesh)
    v = c.reshape(-1, 3)
    _, first, inv = np.unique(np.round(v / 1e-7), axis=0, return_index=True, return_inverse=True)
    return dataclasses.replace(like, vertices=v[first], faces=inv.reshape(c.shape[:2]))


def symmetric_capytaine_mesh(mesh: HullMesh):
    """(hull, lid, ordered mesh): ``mesh`` as Capytaine reflection-symmetric meshes about
    every plane of symmetry the hull and the lid share, the centre plane y = 0 (Capytaine's
    "xOz") innermost, then the midship plane x = 0 ("yOz"), and the same panels as a jaxtow
    `HullMesh` in Capytaine's panel order. The solver then works on half- or quarter-size
    blocks, with the same solution: to round-off on the box; on the raked barge the added
    mass moves by 1e-4 of its largest value and the mean drift by 0.5 % of its largest
    (Capytaine's reflected-panel integrals differ slightly; the plain solve is the one that
    breaks the symmetry). A hull with no such symmetry comes back as plain meshes,
    unchanged."""
    planes = _mirror_planes(mesh.vertices, mesh.faces)
    if len(mesh.lid_faces):
        lid_planes = _mirror_planes(mesh.lid_vertices, mesh.lid_faces)
        planes = [p for p in planes if p in lid_planes]
    if not planes:
        hull, lid = to_capytaine_mesh(mesh)
        return hull, lid, mesh
    planes = sorted(planes, key=lambda p: p != "xOz")  # xOz innermost, as in Capytaine's docs
    hull = _symmetric_mesh(mesh.vertices, mesh.faces, planes, mesh.name)
    lid = (
        _symmetric_mesh(mesh.lid_vertices, mesh.lid_faces, planes, mesh.name + "_lid")
        if len(mesh.lid_faces)
        else None
    )
    return hull, lid, _merged_hull(hull, mesh)


def read_mesh(
    path, *, panel_size: float | None = None, lid: bool = True, name: str | None = None
) -> HullMesh:
    """Read a user hull in any format Capytaine reads (GDF, MAR, NEMOH, STL, PNL, ...), keep
    its immersed part (z <= 0) and add a lid on the waterplane (Capytaine's
    ``generate_lid``). Normals must point into the water."""
    cpt = require_capytaine()
    m = cpt.load_mesh(str(path))
    if hasattr(m, "immersed_part"):
        m = m.immersed_part()
    v = np.asarray(m.vertices, float)
    f = np.asarray(m.faces, int)
    if f.shape[1] == 3:
        f = np.concatenate([f, f[:, 2:3]], axis=1)
    lv, lf = np.zeros((0, 3)), np.zeros((0, 4), int)
    if lid:
        lm = m.generate_lid(z=0.0)
        lv, lf = np.asarray(lm.vertices, float), np.asarray(lm.faces, int)
        if lf.size and lf.shape[1] == 3:
            lf = np.concatenate([lf, lf[:, 2:3]], axis=1)
    ps = (
        float(np.sqrt(np.median(HullMesh(v, f, lv, lf, "x", 0.0).areas)))
        if panel_size is None
        else panel_size
    )
    return HullMesh(v, f, lv, lf, name or Path(path).stem, ps, dict(path=str(path)))


def available() -> bool:
    """True when Capytaine can be imported."""
    try:
        require_capytaine()
    except ImportError:
        return False
    return True
