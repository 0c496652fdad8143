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
import math

import numpy as np

from .._units import RHO_SEA, G
from .body import RigidBody, fixed_body, roll_damping_matrix
from .capytaine_mesh import (
    require_capytaine,
    symmetric_capytaine_mesh,
    to_capytaine_mesh,
)
from .meshes import HullMesh
from .nearfield import apply_gradient, near_field_drift, surface_gradient_operator

#: The rigid-body modes, in Capytaine's names and order.
DOFS = ("Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw")
#: fewer panels per wavelength than this flags a frequency as unresolved (``resolved`` in the dataset)
MIN_PANELS_PER_WAVELENGTH = 6.0


def _theta_grid(step_deg: float = 0.5):
    """Kochin angles: 0…2π in ``step_deg`` steps, padded by 2 steps on each side (the far-field
    routine needs every heading strictly inside; docs/bem.md)."""
    n = int(round(360 / step_deg))
    return np.radians(np.arange(-2, n + 3) * step_deg)


@dataclasses.dataclass(frozen=True)
class _Prepared:
    """What every frequency of one hull and body shares: the Capytaine body, the panels in
    its order, and the frequency-independent geometry of the far and near field."""

    cbody: object
    mesh: HullMesh  # panels in Capytaine's order
    hull_mask: np.ndarray  # the hull panels among hull and lid
    all_centres: np.ndarray  # hull and lid panels (the sources' order)
    all_areas: np.ndarray
    full: object  # Capytaine mesh of hull and lid (sources' order): symmetric, or plain
    centres: np.ndarray  # hull panels
    normals: np.ndarray
    areas: np.ndarray
    wl_points: np.ndarray
    wl_normals: np.ndarray
    wl_lengths: np.ndarray
    gradient: tuple  # (index, weights) of `surface_gradient_operator`
    solver: object  # one Capytaine BEMSolver for every frequency (it loads its tabulation)
    mass_matrix: np.ndarray  # (6, 6) of the body
    reflections: tuple | None  # `_reflection_plan` of the near field's points (None: no symmetry)


_REFLECTIONS = {"xOz": np.array([1.0, -1.0, 1.0]), "yOz": np.array([-1.0, 1.0, 1.0])}


def _matching(points, targets, tol: float = 1e-6):
    """For each of ``points`` (n, 3) the index of the same point among ``targets`` (to
    ``tol``), or None where one has no match."""
    key = {tuple(k): i for i, k in enumerate(np.round(targets / tol).astype(np.int64))}
    idx = [key.get(tuple(k)) for k in np.round(points / tol).astype(np.int64)]
    return None if any(i is None for i in idx) else np.asarray(idx, int)


def _reflection_plan(symmetric_mesh, panel_centres, points):
    """How to get the potential at ``points`` from sources on the panels of a Capytaine
    reflection-symmetric mesh (``panel_centres`` in its merged order) with only the influence
    coefficients of its smallest part, as Capytaine's own symmetric solve does. The free-
    surface Green function is unchanged by a reflection R in a vertical plane, so
    Σ_j G(p, R q_j) σ(R q_j) = Σ_j G(R p, q_j) σ(R q_j) over the part's panels q_j: the
    potential at p is Σ_R S(R p, part) σ[R part] over the reflections R of the mesh's group.
    Returns (the part's mesh, [(R p's index among ``points``, R part's panel indices)] for
    each R), or None where ``points`` are not symmetric too."""
    planes, part = [], symmetric_mesh
    while hasattr(part, "half"):
        planes.append(part.plane)
        part = part.half
    part_centres = np.asarray(part.faces_centers)
    images = []
    for n in range(2 ** len(planes)):  # every product of the plane reflections
        sign = np.ones(3)
        for i, plane in enumerate(planes):
            if n >> i & 1:
                sign = sign * _REFLECTIONS[plane]
        to_point = _matching(points * sign, points)
        to_panel = _matching(part_centres * sign, panel_centres)
        if to_point is None or to_panel is None:
            return None
        images.append((to_point, to_panel))
    return part, images


def prepare(mesh: HullMesh, body: RigidBody, symmetry: bool = True) -> _Prepared:
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
    full = cbody.mesh_including_lid  # the sources are in its panel order (merged or not)
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
    reflections = (
        _reflection_plan(full, all_centres, np.concatenate([centres, wpts]))
        if hasattr(full, "half")
        else None
    )
    if reflections is None and hasattr(full, "merged"):
        full = full.merged()  # for the influence coefficients of every panel
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
        solver=cpt.BEMSolver(method="indirect"),
        mass_matrix=body.mass_matrix(),
        reflections=reflections,
    )


def _point_potential(pr: _Prepared, points, sources, **gf) -> np.ndarray:
    """The potential S·σ at ``points`` (hull centres, then waterline points) of the sources
    ``sources`` (n_panels, n_problems), from Capytaine's influence coefficients of points;
    on a symmetric hull from those of the mesh's smallest part only (`_reflection_plan`)."""
    build = pr.solver.engine.build_S_matrix
    if pr.reflections is None:
        return np.asarray(build(points, pr.full, **gf)) @ sources
    part, images = pr.reflections
    S = np.asarray(build(points, part, **gf))
    pot = np.zeros((points.shape[0], sources.shape[1]), complex)
    for to_point, to_panel in images:
        pot += S[to_point] @ sources[to_panel]
    return pot


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


@dataclasses.dataclass(frozen=True)
class FrequencySolution:
    """One frequency of a panel solve (`solve_frequency`): ``omega`` [rad/s], the headings
    ``beta``, the ``added_mass``, radiation ``damping`` and ``viscous_damping`` (6, 6), the
    ``excitation`` and ``rao`` (β, 6), the ``far_field`` and ``near_field`` mean drift (β, 3),
    the near field's ``near_field_parts`` (β, 4, 3) and ``sectional`` moments, and the
    ``wavenumber``."""

    omega: float
    beta: np.ndarray
    added_mass: np.ndarray
    damping: np.ndarray
    viscous_damping: np.ndarray
    excitation: np.ndarray
    rao: np.ndarray
    far_field: np.ndarray
    near_field: np.ndarray
    near_field_parts: np.ndarray
    sectional: np.ndarray
    wavenumber: float


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
) -> FrequencySolution:
    """Everything at one frequency (see the module docstring); plain NumPy arrays.
    ``fixed=True`` holds the body still (RAOs zero: diffraction only). ``symmetry`` lets the
    solver use the hull's reflection planes (`symmetric_capytaine_mesh`; the same results).
    ``prepared``: the shared geometry from `prepare` (`bem_drift` builds it once)."""
    cpt = require_capytaine()
    from capytaine.bem.airy_waves import airy_waves_potential, froude_krylov_force

    beta = np.asarray(beta, float)
    if body is None:
        if not fixed:
            raise ValueError("parameter 'body' is needed unless fixed=True")
        body = fixed_body()
    pr = prepared if prepared is not None else prepare(mesh, body, symmetry)
    cbody, mesh = pr.cbody, pr.mesh
    solver = solver or pr.solver
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
    Bv = np.zeros((6, 6)) if fixed else roll_damping_matrix(body, A[3, 3])
    H = -(omega**2) * (pr.mass_matrix + A) - 1j * omega * (Bd + Bv) + body.stiffness
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
    pot = _point_potential(pr, pts, src, **gf)  # (n_hull + m, nprob)
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
    return FrequencySolution(
        omega=float(omega),
        beta=beta,
        added_mass=A,
        damping=Bd,
        viscous_damping=Bv,
        excitation=exc,
        rao=rao,
        far_field=ff,
        near_field=nf.force,
        near_field_parts=nf.parts,
        sectional=nf.sectional,
        wavenumber=k,
    )


NEAR_FIELD_PARTS = ("I", "II", "III", "IV")
FORCE_COMPONENTS = ("fx", "fy", "nz")


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
