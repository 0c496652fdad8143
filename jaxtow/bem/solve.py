# pyright: reportAttributeAccessIssue=false, reportOptionalMemberAccess=false, reportCallIssue=false
# (Capytaine is untyped and builds its meshes and results dynamically)
"""First-order panel solution with Capytaine, RAOs, and far- and near-field mean drift.

The pipeline for one hull (`bem_drift`), one frequency at a time so that memory stays at one
frequency's matrices (docs/bem.md: about 10 GB per frequency at 0.5 m panels):

1. radiation (6 DOF, unit displacement) and diffraction problems (every heading), solved
   with the indirect (source) method, sources kept;
2. RAOs from (−ω²(M + A) − iω(B + B_v) + C) ξ = F_FK + F_D (Capytaine's e^{−iωt}), with the
   exact hydrostatic stiffness of `rigid_body` and the documented viscous roll damping B_v;
3. far-field drift (surge, sway, yaw) from the Kochin functions with
   `far_field_drift`, the heading-diagonal of Capytaine's far-field formula (Maruo / Newman momentum conservation);
4. near-field drift (Pinkster pressure integration, `jaxtow.bem.nearfield`) from the total
   velocity at the panel centres (Capytaine's surface gradient, with the jump term) and the
   total potential at the waterline-segment midpoints, with the parts I-IV and the
   sectional moments;
5. the frequency's results written to a NetCDF cache file whose name hashes everything that
   determines them (mesh, mass, ω, headings, ρ, g, depth, damping, Capytaine version), so
   a rerun costs nothing.

Headings are jaxtow's: β = 0 head seas, counter-clockwise from the bow, the direction the
waves come *from*; Capytaine's wave direction (travelling *to*) is β + π.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import math
from pathlib import Path

import jax.numpy as jnp
import numpy as np
import xarray as xr

from .. import presets
from .._config import __version__
from .._progress import progress_meter
from .._units import RHO_SEA, G
from ..drift._compare import relative_mse
from ..drift._methods import ZONE_NAMES, zone
from ..drift._qtf import QTF
from ..io._atomic import save_netcdf
from .meshes import HullMesh, raked_barge_mesh
from .nearfield import apply_gradient, near_field_drift, surface_gradient_operator

INSTALL_HINT = (
    "jaxtow.bem needs the optional panel-method extra (Capytaine): "
    "pip install 'jaxtow[bem]'  (or: pip install capytaine)"
)
DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")
#: fewer panels per wavelength than this flags a frequency as unresolved (``resolved`` in the dataset)
MIN_PANELS_PER_WAVELENGTH = 6.0
#: bump when what a cached frequency holds, or how it is computed, changes
_CACHE_VERSION = "nf-lsq-1"


def require_capytaine():
    """Import Capytaine or raise an ImportError that says how to install it."""
    try:
        import capytaine
    except ImportError as err:  # pragma: no cover - exercised with the extra missing
        raise ImportError(INSTALL_HINT) from err
    return capytaine


@dataclasses.dataclass(frozen=True)
class RigidBody:
    """Mass properties and hydrostatics of a freely floating hull, about its CoG.

    ``mass`` [kg], ``cog`` (3,) [m] in mesh axes (z up from the waterline), ``inertia`` (3, 3)
    [kg m²] about the CoG, ``stiffness`` (6, 6) hydrostatic restoring about the CoG,
    ``damping`` (6, 6) additional linear (viscous) damping, ``notes`` (where each value came
    from)."""

    mass: float
    cog: np.ndarray
    inertia: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    notes: dict

    def mass_matrix(self) -> np.ndarray:
        M = np.zeros((6, 6))
        M[:3, :3] = self.mass * np.eye(3)
        M[3:, 3:] = self.inertia
        return M


def rigid_body(
    mesh: HullMesh,
    cog_z: float | None = None,
    *,
    radii=None,
    roll_damping: float | None = None,
    rho: float = RHO_SEA,
    g: float = G,
) -> RigidBody:
    """Free-floating rigid body for ``mesh``: mass ρ∇, CoG above the centre of buoyancy at
    height ``cog_z`` above the keel (thesis Table B.3: 10 m; default
    `presets.ASSUMPTIONS['cog_z']`), radii of gyration ``radii`` = (k_xx, k_yy, k_zz) [m]
    (default: Journée's approximations, `presets.radii_of_gyration`), exact hydrostatic
    stiffness from the waterline polygon, and a linear roll damping of ``roll_damping`` times
    critical (default `presets.ASSUMPTIONS['roll_damping']`; it is finalised per frequency
    with the roll added mass, see `_roll_damping`)."""
    if cog_z is None:
        cog_z = float(presets.ASSUMPTIONS["cog_z"]["value"])
    if roll_damping is None:
        roll_damping = float(presets.ASSUMPTIONS["roll_damping"]["value"])
    if not (math.isfinite(cog_z) and cog_z >= 0):
        raise ValueError(
            f"parameter 'cog_z' (height of the CoG above the keel) must be >= 0, got {cog_z!r}"
        )
    if not (math.isfinite(roll_damping) and 0 <= roll_damping < 1):
        raise ValueError(
            f"parameter 'roll_damping' (fraction of critical) must lie in [0, 1), got {roll_damping!r}"
        )
    V = mesh.volume
    if not V > 0:
        raise ValueError(
            f"mesh {mesh.name!r} has a non-positive displaced volume ({V}); check its normals"
        )
    keel = float(mesh.vertices[:, 2].min())
    xb = mesh.centre_of_buoyancy()
    cog = np.array([xb[0], xb[1], keel + float(cog_z)])
    m = rho * V
    notes = {"mass": "rho * displaced volume (free floating)", "cog_z": f"{cog_z} m above the keel"}
    if radii is None:
        L = float(np.ptp(mesh.vertices[:, 0]))
        B = float(np.ptp(mesh.vertices[:, 1]))
        radii = presets.radii_of_gyration(L, B)
        notes["radii"] = presets.ASSUMPTIONS["radii_of_gyration"]["note"]
    else:
        notes["radii"] = "user"
    kxx, kyy, kzz = (float(r) for r in radii)
    inertia = m * np.diag([kxx**2, kyy**2, kzz**2])
    wp = mesh.waterplane()
    xg, yg = cog[0], cog[1]
    A = wp["area"]
    Sx, Sy = wp["sx"] - xg * A, wp["sy"] - yg * A  # ∬ (x − x_G), ∬ (y − y_G)
    Ixx = wp["ixx"] - 2 * xg * wp["sx"] + xg**2 * A  # ∬ (x − x_G)²
    Iyy = wp["iyy"] - 2 * yg * wp["sy"] + yg**2 * A
    Ixy = wp["ixy"] - xg * wp["sy"] - yg * wp["sx"] + xg * yg * A
    rg = rho * g
    C = np.zeros((6, 6))
    C[2, 2] = rg * A
    C[2, 3] = C[3, 2] = rg * Sy
    C[2, 4] = C[4, 2] = -rg * Sx
    C[3, 3] = rg * (Iyy + V * (xb[2] - cog[2]))
    C[4, 4] = rg * (Ixx + V * (xb[2] - cog[2]))
    C[3, 4] = C[4, 3] = -rg * Ixy
    if C[3, 3] <= 0:
        raise ValueError(
            f"the hull is unstable in roll: GM_T = {C[3, 3] / (rg * V):.3f} m <= 0 with cog_z = {cog_z} m"
        )
    D = np.zeros((6, 6))
    D[3, 3] = roll_damping  # fraction of critical; converted per frequency
    notes["roll_damping"] = f"{roll_damping} of critical (linearised viscous roll damping)"
    return RigidBody(m, cog, inertia, C, D, notes)


def _fixed_body() -> RigidBody:
    """Placeholder body for a fixed (diffraction-only) computation: no mass, no stiffness."""
    return RigidBody(
        0.0, np.zeros(3), np.zeros((3, 3)), np.zeros((6, 6)), np.zeros((6, 6)), {"fixed": True}
    )


def _roll_damping(body: RigidBody, a44: float) -> np.ndarray:
    """Dimensional viscous damping: B44 = 2 ζ sqrt(C44 (I44 + A44(ω)))."""
    D = np.zeros((6, 6))
    D[3, 3] = (
        2
        * body.damping[3, 3]
        * math.sqrt(body.stiffness[3, 3] * (body.inertia[0, 0] + max(a44, 0.0)))
    )
    return D


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


def _merged_hull(cmesh, like: HullMesh) -> HullMesh:
    """A jaxtow HullMesh with the panels in the order of the Capytaine mesh ``cmesh`` (shared
    vertices merged, so that the near-field gradient sees every neighbour)."""
    plain = cmesh.merged() if hasattr(cmesh, "merged") else cmesh
    v = np.asarray(plain.vertices, float)
    f = np.asarray(plain.faces, int)
    _, first, inv = np.unique(np.round(v / 1e-7), axis=0, return_index=True, return_inverse=True)
    return dataclasses.replace(like, vertices=v[first], faces=inv.reshape(-1)[f])


def symmetric_capytaine_mesh(mesh: HullMesh):
    """(hull, lid, ordered mesh): ``mesh`` as Capytaine reflection-symmetric meshes about the
    centre plane y = 0 (Capytaine's "xOz") when the hull and the lid are port-starboard
    symmetric, and the same panels as a jaxtow `HullMesh` in Capytaine's panel order. The
    solver then works on two half-size blocks: about 4× less LU work and half the influence
    matrices, with the same solution (to round-off on the box, to 1e-5 of the added mass on
    the raked barge, where Capytaine's reflected-panel integrals differ slightly). Only the
    centre plane is used: nesting the fore-aft plane too moves the raked barge's added mass
    by 1e-4. A hull with no such symmetry comes back as plain meshes, unchanged."""
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


def _theta_grid(step_deg: float = 0.5):
    """Kochin angles: 0…2π in ``step_deg`` steps, padded by 2 steps on each side (the far-field
    routine needs every heading strictly inside; docs/bem.md)."""
    n = int(round(360 / step_deg))
    return np.radians(np.arange(-2, n + 3) * step_deg)


def _cache_key(mesh, body, omega, beta, rho, g, depth, theta_step, fixed):
    cpt = require_capytaine()
    h = hashlib.sha256()
    for arr in (
        mesh.vertices,
        mesh.faces,
        mesh.lid_vertices,
        mesh.lid_faces,
        body.cog,
        body.inertia,
        body.stiffness,
        body.damping,
        np.asarray(beta, float),
    ):
        h.update(np.ascontiguousarray(arr).tobytes())
    h.update(
        json.dumps(
            [
                float(body.mass),
                float(omega),
                rho,
                g,
                str(depth),
                theta_step,
                bool(fixed),
                cpt.__version__,
                _CACHE_VERSION,
            ]
        ).encode()
    )
    return h.hexdigest()[:20]


@dataclasses.dataclass(frozen=True)
class _Prepared:
    """What every frequency of one hull and body shares: the Capytaine body, the panels in
    its order, and the frequency-independent geometry of the far and near field."""

    cbody: object
    mesh: HullMesh  # panels in Capytaine's order
    hull_mask: np.ndarray  # the hull panels among hull and lid
    all_centres: np.ndarray  # hull and lid panels (the sources' order)
    all_areas: np.ndarray
    full: object  # Capytaine mesh of hull and lid, plain (sources' order)
    centres: np.ndarray  # hull panels
    normals: np.ndarray
    areas: np.ndarray
    wl_points: np.ndarray
    wl_normals: np.ndarray
    wl_lengths: np.ndarray
    gradient: tuple  # (index, weights) of `surface_gradient_operator`


def _prepare(mesh: HullMesh, body: RigidBody, symmetry: bool = True) -> _Prepared:
    """Build the Capytaine body and the geometry once for all frequencies (building the
    symmetric meshes, their panel properties and the gradient operator cost as much as a
    coarse solve when redone per frequency)."""
    cpt = require_capytaine()
    if symmetry:
        hull, lid, mesh = symmetric_capytaine_mesh(mesh)  # mesh: panels in Capytaine's order
    else:
        hull, lid = to_capytaine_mesh(mesh)
    mass_kw = dict(center_of_mass=body.cog, mass=body.mass) if body.mass > 0 else {}
    cbody = cpt.FloatingBody(
        mesh=hull,
        lid_mesh=lid,
        dofs=cpt.rigid_body_dofs(rotation_center=body.cog),
        name=mesh.name,
        **mass_kw,
    )
    hull_mesh = cbody.mesh
    full = cbody.mesh_including_lid  # the sources are in its panel order
    full = full.merged() if hasattr(full, "merged") else full
    centres = np.asarray(hull_mesh.faces_centers)
    all_centres = np.asarray(full.faces_centers)
    hull_mask = np.asarray(cbody.hull_mask, bool)
    if not (
        np.allclose(centres, mesh.centres, atol=1e-6)
        and np.allclose(all_centres[hull_mask], centres, atol=1e-6)
    ):
        raise RuntimeError("the hull panels are not in Capytaine's order")
    nrm = np.asarray(hull_mesh.faces_normals)
    p0, p1, owner = mesh.waterline()
    wpts = 0.5 * (p0 + p1)
    return _Prepared(
        cbody=cbody,
        mesh=mesh,
        hull_mask=hull_mask,
        all_centres=all_centres,
        all_areas=np.asarray(full.faces_areas),
        full=full,
        centres=centres,
        normals=nrm,
        areas=np.asarray(hull_mesh.faces_areas),
        wl_points=wpts,
        wl_normals=mesh.normals[owner],
        wl_lengths=np.linalg.norm(p1 - p0, axis=1),
        gradient=surface_gradient_operator(mesh.vertices, mesh.faces, centres, nrm, wpts, owner),
    )


def kochin(centres, areas, sources, theta, wavenumber: float, water_depth: float = math.inf):
    """Kochin functions H(θ) (n_problems, n_θ) of source distributions ``sources``
    (n_panels, n_problems) on panels with ``centres`` and ``areas``: Capytaine's
    `compute_kochin` (reference point at the origin) for every problem of a frequency at
    once. The (n_θ, n_panels) kernel is the same for all of them, so it is built once."""
    k, h = float(wavenumber), float(water_depth)
    phase = centres[:, :2] @ np.stack([np.cos(theta), np.sin(theta)])  # (n_panels, n_θ)
    if 0 <= k * h < 20:
        depth = np.cosh(k * (centres[:, 2] + h)) / np.cosh(k * h)
    else:
        depth = np.exp(k * centres[:, 2])
    zs = (depth * areas)[None, :] * np.exp(-1j * k * phase.T)
    return (zs @ sources).T / (4 * np.pi)


def solve_frequency(
    mesh: HullMesh,
    body: RigidBody | None,
    omega: float,
    beta,
    *,
    rho: float = RHO_SEA,
    g: float = G,
    water_depth: float = math.inf,
    theta_step: float = 0.5,
    fixed: bool = False,
    solver=None,
    symmetry: bool = True,
    prepared: _Prepared | None = None,
) -> dict:
    """Everything at one frequency (see the module docstring); plain NumPy arrays.
    ``fixed=True`` holds the body still (RAOs zero: diffraction only). ``symmetry`` lets the
    solver use the hull's reflection planes (`symmetric_capytaine_mesh`; the same results).
    ``prepared``: the shared geometry from `_prepare` (`bem_drift` builds it once)."""
    cpt = require_capytaine()
    from capytaine.bem.airy_waves import airy_waves_potential, froude_krylov_force

    beta = np.asarray(beta, float)
    if body is None:
        if not fixed:
            raise ValueError("parameter 'body' is needed unless fixed=True")
        body = _fixed_body()
    pr = prepared if prepared is not None else _prepare(mesh, body, symmetry)
    cbody, mesh = pr.cbody, pr.mesh
    solver = solver or cpt.BEMSolver(method="indirect")
    env = dict(omega=float(omega), rho=rho, g=g, water_depth=water_depth)
    rad = [cpt.RadiationProblem(body=cbody, radiating_dof=d, **env) for d in DOFS]
    dif = [
        cpt.DiffractionProblem(body=cbody, wave_direction=float(b + math.pi), **env) for b in beta
    ]
    results = solver.solve_all(
        rad + dif, keep_details=True, progress_bar=False, _check_wavelength=False
    )
    rres, dres = results[:6], results[6:]

    A = np.array(
        [[r.added_mass[d] for d in DOFS] for r in rres]
    ).T  # A[i, j]: force i from motion j
    Bd = np.array([[r.radiation_damping[d] for d in DOFS] for r in rres]).T
    fk = np.array([[froude_krylov_force(r.problem)[d] for d in DOFS] for r in dres])
    fd = np.array([[r.forces[d] for d in DOFS] for r in dres])
    exc = fk + fd  # (nb, 6)
    Bv = np.zeros((6, 6)) if fixed else _roll_damping(body, A[3, 3])
    H = -(omega**2) * (body.mass_matrix() + A) - 1j * omega * (Bd + Bv) + body.stiffness
    rao = np.zeros_like(exc) if fixed else np.linalg.solve(H, exc.T).T  # (nb, 6)

    # far field (Kochin functions of every problem at once)
    k = float(rres[0].problem.wavenumber)
    theta = _theta_grid(theta_step)
    src = np.stack([r.sources for r in results], axis=-1)  # (n_all, 6 + nb)
    H_all = kochin(pr.all_centres, pr.all_areas, src, theta, k, water_depth)
    ff = far_field_drift(
        H_all[6:],
        H_all[:6],  # DOFS order
        rao,
        beta + math.pi,
        theta,
        omega=float(omega),
        wavenumber=k,
        rho=rho,
        g=g,
        water_depth=water_depth,
    )
    ff[:, 2] -= body.cog[0] * ff[:, 1] - body.cog[1] * ff[:, 0]  # yaw about the CoG's vertical axis

    # near field: total velocity on the hull panels, total potential on the waterline
    gf = dict(free_surface=0.0, water_depth=water_depth, wavenumber=k)
    centres, nrm, wpts = pr.centres, pr.normals, pr.wl_points
    n_hull = centres.shape[0]
    pts = np.concatenate([centres, wpts])
    # the potential S·σ at the collocation points from the influence coefficients of points
    # (not the solver's own ``potential``: its mesh-to-mesh coefficients differ near the
    # free surface, and the near field was validated with these)
    pot = np.asarray(solver.engine.build_S_matrix(pts, pr.full, **gf)) @ src  # (n_hull + m, nprob)
    index, weights = pr.gradient
    phi = np.empty((beta.size, pts.shape[0]), complex)
    for ib, r in enumerate(dres):
        phi[ib] = pot[:, 6 + ib] + airy_waves_potential(pts, r.problem) + pot[:, :6] @ rao[ib]
    # tangential velocity from the surface potential; normal velocity = the hull's (the body condition)
    u_n = (
        -1j
        * omega
        * np.sum((rao[:, None, :3] + np.cross(rao[:, None, 3:], centres - body.cog)) * nrm, axis=-1)
    )
    u_tot = np.moveaxis(apply_gradient(index, weights, phi.T), 1, 0) + u_n[..., None] * nrm
    phi_tot = phi[:, n_hull:]
    nf = near_field_drift(
        omega=omega,
        rho=rho,
        g=g,
        panels=dict(centres=centres, normals=nrm, areas=pr.areas, velocity=u_tot),
        waterline=dict(
            points=wpts, normals=pr.wl_normals, lengths=pr.wl_lengths, potential=phi_tot
        ),
        mass=body.mass,
        inertia=body.inertia,
        cog=body.cog,
        motion=rao,
    )
    return dict(
        omega=float(omega),
        beta=beta,
        added_mass=A,
        damping=Bd,
        viscous_damping=Bv,
        excitation=exc,
        rao=rao,
        far_field=ff,
        near_field=nf["force"],
        near_field_parts=nf["parts"],
        sectional=nf["sectional"],
        wavenumber=k,
    )


_PARTS = ("I", "II", "III", "IV")
_COMPONENTS = ("fx", "fy", "nz")


def far_field_drift(
    kochin_diffraction,
    kochin_radiation,
    rao,
    wave_direction,
    theta,
    *,
    omega: float,
    wavenumber: float,
    rho: float,
    g: float,
    water_depth: float,
) -> np.ndarray:
    """Far-field (Maruo / Newman) mean drift (F_x, F_y, M_z) per ζa² at one frequency, per heading:
    the diagonal of `capytaine.post_pro.mean_drift_force.far_field_mean_drift_force` (same
    formula, Kochin-angle derivative and trapezoid rule), vectorised over headings instead of
    its loop over heading pairs. ``kochin_diffraction`` (n_β, n_θ), ``kochin_radiation``
    (6, n_θ), ``rao`` (n_β, 6), ``wave_direction`` Capytaine's (β + π) and ``theta`` the Kochin
    angles, which must span [0, 2π] with margin. The yaw moment is about the origin."""
    theta = np.asarray(theta, float)
    wd = np.asarray(wave_direction, float)
    if theta.min() >= 0 or theta.max() <= 2 * np.pi:
        raise ValueError("parameter 'theta' must extend beyond [0, 2π] on both sides")
    if np.any(wd <= theta.min()) or np.any(wd >= theta.max()):
        raise ValueError("parameter 'wave_direction' must lie strictly inside the theta grid")
    H = 1j * (np.asarray(kochin_diffraction) + np.asarray(rao) @ np.asarray(kochin_radiation))
    dH = np.gradient(H, theta, axis=-1)

    def at(f):  # linear interpolation of each heading's function at its own direction
        return np.array(
            [
                np.interp(b, theta, f[i].real) + 1j * np.interp(b, theta, f[i].imag)
                for i, b in enumerate(wd)
            ]
        )

    Hb, dHb = at(H), at(dH)
    inside = (theta >= 0) & (theta <= 2 * np.pi)
    th, Hi, dHi = theta[inside], H[:, inside], dH[:, inside]
    m = wavenumber
    coef1 = 2 * np.pi * rho * omega
    if math.isinf(water_depth):
        coef2 = 2 * np.pi * rho * m**2
    else:
        h, k0 = water_depth, omega**2 / g
        coef2 = 2 * np.pi * rho * m * (k0 * h) ** 2 / (h * ((m * h) ** 2 - (k0 * h) ** 2 + k0 * h))
    H2 = np.abs(Hi) ** 2
    fx = -coef1 * np.cos(wd) * Hb.imag - coef2 * np.trapezoid(H2 * np.cos(th), th, axis=-1)
    fy = -coef1 * np.sin(wd) * Hb.imag - coef2 * np.trapezoid(H2 * np.sin(th), th, axis=-1)
    nz = coef1 / m * dHb.real - coef2 / m * np.trapezoid(np.imag(np.conj(Hi) * dHi), th, axis=-1)
    return np.stack([fx, fy, nz], axis=-1)


def _frequency_dataset(r: dict):

    w = [r["omega"]]
    dims_b = ("omega", "beta")
    rao, exc = r["rao"][None], r["excitation"][None]
    ds = xr.Dataset(
        {
            "rao_real": (dims_b + ("dof",), rao.real),
            "rao_imag": (dims_b + ("dof",), rao.imag),
            "excitation_real": (dims_b + ("dof",), exc.real),
            "excitation_imag": (dims_b + ("dof",), exc.imag),
            "added_mass": (("omega", "dof", "dof_j"), r["added_mass"][None]),
            "radiation_damping": (("omega", "dof", "dof_j"), r["damping"][None]),
            "viscous_damping": (("omega", "dof", "dof_j"), r["viscous_damping"][None]),
            "far_field": (dims_b + ("component",), r["far_field"][None]),
            "near_field": (dims_b + ("component",), r["near_field"][None]),
            "near_field_parts": (dims_b + ("part", "component"), r["near_field_parts"][None]),
            "sectional_moments": (dims_b + ("axis", "order"), r["sectional"][None]),
            "wavenumber": (("omega",), [r["wavenumber"]]),
        },
        coords={
            "omega": w,
            "beta": r["beta"],
            "dof": list(DOFS),
            "dof_j": list(DOFS),
            "component": list(_COMPONENTS),
            "part": list(_PARTS),
            "axis": ["x", "y"],
            "order": [0, 1, 2],
        },
    )
    return ds


def _attrs(mesh, body, rho, g, water_depth, fixed, theta_step):
    cpt = require_capytaine()

    return {
        "mesh_name": mesh.name,
        "mesh_params": json.dumps(mesh.params),
        "n_panels": mesh.n_panels,
        "n_lid_panels": int(len(mesh.lid_faces)),
        "panel_size_m": mesh.panel_size,
        "solver": "capytaine.BEMSolver(method='indirect'), Delhommeau Green function, lid for irregular frequencies",
        "capytaine_version": cpt.__version__,
        "jaxtow_version": __version__,
        "rho": rho,
        "g": g,
        "water_depth": str(water_depth),
        "fixed_body": int(fixed),
        "mass_kg": float(body.mass),
        "cog_m": json.dumps([float(c) for c in body.cog]),
        "inertia_kgm2": json.dumps([float(v) for v in np.diag(body.inertia)]),
        "body_notes": json.dumps(body.notes),
        "kochin_step_deg": theta_step,
        "far_field_method": "jaxtow.bem.solve.far_field_drift: diagonal of capytaine.post_pro.far_field_mean_drift_force (Kochin functions)",
        "near_field_method": "Pinkster pressure integration, parts I-IV (jaxtow.bem.nearfield); surface velocity "
        "from a least-squares gradient of the surface potential",
        "conventions": "per unit wave amplitude squared, SI; body axes x forward, y port, z up from the waterline; "
        "beta = 0 head seas, CCW, direction waves come from; yaw about the CoG's vertical axis; "
        "complex amplitudes with exp(-i omega t)",
        "assumptions": json.dumps(
            {
                k: presets.ASSUMPTIONS[k]["note"]
                for k in ("cog_z", "radii_of_gyration", "roll_damping")
            }
        ),
    }


def bem_drift(
    mesh: HullMesh,
    omega,
    beta,
    *,
    body: RigidBody | None = None,
    cog_z: float | None = None,
    radii=None,
    roll_damping: float | None = None,
    rho: float = RHO_SEA,
    g: float = G,
    water_depth: float = math.inf,
    fixed: bool = False,
    cache_dir=None,
    progress: bool = False,
    theta_step: float = 0.5,
):
    """First-order solution, RAOs and far-/near-field mean drift over (ω, β) for ``mesh``,
    one frequency at a time, as an xarray Dataset (variables in `_frequency_dataset`, the
    mesh, solver, versions and assumptions in its attributes).

    ``omega`` rad/s (> 0), ``beta`` rad in jaxtow's convention. ``body`` defaults to
    `rigid_body(mesh, cog_z, radii=..., roll_damping=...)`. With ``cache_dir`` each frequency
    is stored in its own NetCDF file named by a hash of every input, so a rerun (or an
    interrupted run) only solves what is missing. ``progress`` prints a bar on stderr.
    """

    omega = np.atleast_1d(np.asarray(omega, float))
    beta = np.atleast_1d(np.asarray(beta, float))
    if omega.ndim != 1 or not np.all(omega > 0) or not np.all(np.isfinite(omega)):
        raise ValueError("parameter 'omega' must be a 1-D array of positive frequencies [rad/s]")
    if not np.all(np.diff(beta) > 0):
        raise ValueError("parameter 'beta' must be strictly ascending [rad]")
    require_capytaine()
    if body is None and not fixed:
        body = rigid_body(mesh, cog_z, radii=radii, roll_damping=roll_damping, rho=rho, g=g)
    if body is None:
        body = _fixed_body()
    cache = None if cache_dir is None else Path(cache_dir)
    if cache is not None:
        cache.mkdir(parents=True, exist_ok=True)
    bar = progress_meter(progress).start(omega.size, f"bem {mesh.name} ({mesh.n_panels} panels)")
    parts = []
    prepared = None  # built on the first frequency that is not in the cache
    for w in np.sort(omega):
        key = _cache_key(mesh, body, w, beta, rho, g, water_depth, theta_step, fixed)
        path = None if cache is None else cache / f"{mesh.name}_{key}.nc"
        if path is not None and path.exists():
            ds = xr.load_dataset(path)
        else:
            prepared = prepared or _prepare(mesh, body)
            r = solve_frequency(
                mesh,
                body,
                w,
                beta,
                rho=rho,
                g=g,
                water_depth=water_depth,
                fixed=fixed,
                theta_step=theta_step,
                prepared=prepared,
            )
            ds = _frequency_dataset(r)
            if path is not None:
                save_netcdf(ds, path)  # atomic: a killed solve leaves no partial cache file
        parts.append(ds)
        bar.update()
    bar.close()
    out = xr.concat(
        parts,
        dim="omega",
        data_vars="minimal",
        coords="minimal",
        compat="override",
        join="override",
    )
    out.attrs.update(_attrs(mesh, body, rho, g, water_depth, fixed, theta_step))
    # validity: waves must be resolved by the panels (about 6 or more panels per wavelength)
    out["panels_per_wavelength"] = 2 * math.pi / out["wavenumber"] / mesh.panel_size
    out["resolved"] = out["panels_per_wavelength"] >= MIN_PANELS_PER_WAVELENGTH
    out["resolved"].attrs["note"] = (
        f"wavelength / nominal panel size >= {MIN_PANELS_PER_WAVELENGTH}; "
        "results at unresolved frequencies are unreliable"
    )
    return out


def rao(ds):
    """Complex RAOs (omega, beta, dof) from a `bem_drift` dataset [m/m, rad/m]."""
    return ds["rao_real"] + 1j * ds["rao_imag"]


def qtf_from_bem(ds, method: str = "far_field", *, symmetric: bool = False):
    """A jaxtow `QTF` (SI, per ζa²) from a `bem_drift` dataset; ``method`` 'far_field' or
    'near_field'. ``symmetric=True`` (a port-starboard symmetric hull with β from 0) completes
    the table to negative headings with `QTF.symmetric`, setting the head-sea (and
    following-sea) sway and yaw, which vanish by symmetry, to exactly zero. The sectional
    moments (M_x,1, M_y,1, M_y,2) of the pressure integration (``sectional_moments``) come
    with the table, for the yaw-rate wave-drift damping (`jaxtow.drift.yaw_rate_damping`)."""

    if method not in ("far_field", "near_field"):
        raise ValueError(f"parameter 'method' must be 'far_field' or 'near_field', got {method!r}")
    v = np.asarray(ds[method].transpose("omega", "beta", "component"))
    w, b = np.asarray(ds.omega, float), np.asarray(ds.beta, float)
    fx, fy, nz = v[..., 0], v[..., 1].copy(), v[..., 2].copy()
    sec = None
    if "sectional_moments" in ds:
        sm = ds["sectional_moments"].transpose("omega", "beta", "axis", "order")
        sec = [
            np.asarray(sm.sel(axis=a, order=k), float).copy()
            for a, k in (("x", 1), ("y", 1), ("y", 2))
        ]
    if symmetric:
        for j in np.flatnonzero(np.isclose(b, 0.0) | np.isclose(np.abs(b), math.pi)):
            for arr in [fy, nz] + (sec[1:] if sec else []):
                arr[:, j] = 0.0
        return QTF.symmetric(omega=w, beta=b, fx=fx, fy=fy, nz=nz, sectional=sec)
    return QTF(omega=w, beta=b, fx=fx, fy=fy, nz=nz, sectional=sec)


def qtf_attrs(ds, method: str) -> dict:
    """The provenance attributes to store with a QTF made by `qtf_from_bem`."""
    keep = {k: v for k, v in ds.attrs.items()}
    keep["qtf_method"] = method
    keep["qtf_source"] = f"jaxtow.bem {method.replace('_', '-')} mean drift"
    return keep


def mesh_convergence(
    build_mesh, panel_sizes, omega, beta, *, length: float | None = None, **kwargs
):
    """Mesh-convergence study (thesis appendix B.1): `bem_drift` for each panel size
    (``build_mesh(panel_size) -> HullMesh``), and the relative MSE (eq. 3.8 as in
    `jaxtow.drift.relative_mse_by_zone`) of each mesh's far- and near-field surge and sway against the finest
    mesh's far field, per zone and overall, and of each mesh's near field against its own far
    field. Returns (datasets by panel size, summary Dataset over panel_size with
    ``panels_per_length``, ``panels_per_breadth``, ``mse`` (panel_size, drift_method, component,
    zone) and ``near_vs_far`` (panel_size, component, zone))."""

    sizes = sorted((float(p) for p in panel_sizes), reverse=True)
    runs = {p: bem_drift(build_mesh(p), omega, beta, **kwargs) for p in sizes}
    finest = runs[sizes[-1]]
    first = build_mesh(sizes[-1])
    L = float(np.ptp(first.vertices[:, 0])) if length is None else float(length)
    B = float(np.ptp(first.vertices[:, 1]))
    zones = np.asarray(zone(jnp.asarray(np.asarray(finest.omega, float)), L))
    names = list(ZONE_NAMES) + ["all"]

    def by_zone(est, base):
        out = np.full(len(names), np.nan)
        for z, name in enumerate(names):
            mask = (
                np.ones_like(base, bool)
                if name == "all"
                else (zones == z)[:, None] & np.ones_like(base, bool)
            )
            if mask.any() and np.any(base[mask] != 0):
                out[z] = relative_mse(est, base, mask)
        return out

    def comp(ds, method, c):
        return np.asarray(ds[method].isel(component=c).transpose("omega", "beta"))

    mse = np.array(
        [
            [
                [by_zone(comp(runs[p], m, c), comp(finest, "far_field", c)) for c in range(2)]
                for m in ("far_field", "near_field")
            ]
            for p in sizes
        ]
    )
    agree = np.array(
        [
            [
                by_zone(comp(runs[p], "near_field", c), comp(runs[p], "far_field", c))
                for c in range(2)
            ]
            for p in sizes
        ]
    )
    summary = xr.Dataset(
        {
            "mse": (("panel_size", "drift_method", "component", "zone"), mse),
            "near_vs_far": (("panel_size", "component", "zone"), agree),
            "panels_per_length": (("panel_size",), [L / p for p in sizes]),
            "panels_per_breadth": (("panel_size",), [B / p for p in sizes]),
            "n_panels": (("panel_size",), [int(runs[p].attrs["n_panels"]) for p in sizes]),
        },
        coords={
            "panel_size": sizes,
            "drift_method": ["far_field", "near_field"],
            "component": ["fx", "fy"],
            "zone": names,
        },
        attrs={
            "base": f"far field of the finest mesh ({sizes[-1]} m)",
            "length_m": L,
            "breadth_m": B,
        },
    )
    return runs, summary


def box_barge_drift(
    length: float,
    breadth: float,
    draft: float,
    cog_z: float,
    omega,
    beta,
    *,
    panel_size: float = 2.0,
    rake: float = 0.0,
    **kwargs,
):
    """Panel-method mean drift of a (raked) box barge: `BEMDrift` with ``far_field`` and
    ``near_field`` jaxtow `QTF` (SI per ζa², β = 0 head seas; completed by symmetry when β
    starts at 0) and the full ``dataset``. ``cog_z`` is the CoG height above the keel [m];
    other keywords go to `bem_drift` (cache_dir, progress, radii, roll_damping, ...)."""

    mesh = raked_barge_mesh(
        length,
        breadth,
        draft,
        rake,
        panel_size=panel_size,
        name="box_barge" if rake == 0 else "raked_barge",
    )
    ds = bem_drift(mesh, omega, beta, cog_z=cog_z, **kwargs)
    sym = bool(np.isclose(float(np.min(ds.beta)), 0.0))
    return BEMDrift(
        qtf_from_bem(ds, "far_field", symmetric=sym),
        qtf_from_bem(ds, "near_field", symmetric=sym),
        ds,
    )


@dataclasses.dataclass(frozen=True)
class BEMDrift:
    """Far-field and near-field `QTF` of one hull and the `bem_drift` dataset behind them."""

    far_field: object
    near_field: object
    dataset: object
