"""The rigid body of a panel solve: the mass and hydrostatics of the hull in a loading
condition (`jaxtow.Loading`: the CoG, the radii of gyration and the roll damping, with the
documented estimates for what is not given)."""

from __future__ import annotations

import dataclasses

import jax
import numpy as np

from .._body import Loading, hydrostatic_restoring, mass_matrix, roll_damping_coefficient
from .._rules import check_type
from .._units import RHO_SEA, G, Water
from .meshes import HullMesh

#: `jaxtow.mass_matrix` as one compiled program (eagerly, each of its operations is compiled
#: on its own: 0.7 s on a panel solve's first frequency)
_mass_matrix_program = jax.jit(mass_matrix)


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
        """(6, 6) about the CoG (`jaxtow.mass_matrix`)."""
        radii = np.sqrt(np.diag(self.inertia) / self.mass) if self.mass > 0 else np.zeros(3)
        return np.asarray(_mass_matrix_program(self.mass, np.zeros(3), radii))


def rigid_body(
    mesh: HullMesh, loading: Loading | None = None, *, rho: float = RHO_SEA, g: float = G
) -> RigidBody:
    """Free-floating rigid body for ``mesh`` in the `jaxtow.Loading` ``loading``: mass ρ∇,
    the CoG ``loading.z_g`` above the waterline (over the centre of buoyancy unless
    ``loading.x_g`` is given), the radii of gyration ``loading.radii`` (default the
    estimate for the mesh's L and B), exact hydrostatic stiffness from the waterline polygon,
    and the linear roll damping ``loading.roll_damping`` times critical (finalised per
    frequency with the roll added mass, `roll_damping_matrix`). Without a loading: the documented
    estimate, `jaxtow.Loading.estimate` at the mesh's draft (the CoG
    `ASSUMPTIONS['cog_z']` above the keel, thesis Table B.3)."""
    keel = float(mesh.vertices[:, 2].min())
    if loading is None:
        loading = Loading.estimate(-keel)
    check_type("loading", loading, Loading)
    V = mesh.volume
    if not V > 0:
        raise ValueError(
            f"mesh {mesh.name!r} has a non-positive displaced volume ({V}); check its normals"
        )
    z_g = float(loading.z_g)
    if z_g < keel:
        raise ValueError(
            f"parameter 'loading': the CoG ({z_g:g} m above the waterline) lies below the keel "
            f"({keel:g} m)"
        )
    xb = mesh.centre_of_buoyancy()
    x_g = xb[0] if loading.x_g is None else float(loading.x_g)
    cog = np.array([x_g, xb[1], z_g])
    m = rho * V
    notes = {"mass": "rho * displaced volume (free floating)", **loading.notes}
    notes["cog_z"] += f" ({z_g - keel:g} m above the keel)"
    L = float(np.ptp(mesh.vertices[:, 0]))
    B = float(np.ptp(mesh.vertices[:, 1]))
    kxx, kyy, kzz = (float(r) for r in loading.radii_for(L, B))
    inertia = m * np.diag([kxx**2, kyy**2, kzz**2])
    wp = mesh.waterplane()
    xg, yg = cog[0], cog[1]
    A = wp.area
    Sx, Sy = wp.sx - xg * A, wp.sy - yg * A  # ∬ (x − x_G), ∬ (y − y_G)
    Ixx = wp.ixx - 2 * xg * wp.sx + xg**2 * A  # ∬ (x − x_G)²
    Iyy = wp.iyy - 2 * yg * wp.sy + yg**2 * A
    Ixy = wp.ixy - xg * wp.sy - yg * wp.sx + xg * yg * A
    water = Water(rho=rho, g=g)
    C = np.asarray(hydrostatic_restoring((A, Sx, Sy, Ixx, Iyy, Ixy), V, xb[2], cog[2], water=water))
    if C[3, 3] <= 0:
        raise ValueError(
            f"parameter 'loading': the hull is unstable in roll: GM_T = "
            f"{C[3, 3] / (rho * g * V):.3f} m <= 0 with the CoG {z_g - keel:g} m above the keel"
        )
    D = np.zeros((6, 6))
    D[3, 3] = float(loading.roll_damping)  # fraction of critical; converted per frequency
    return RigidBody(m, cog, inertia, C, D, notes)


def fixed_body() -> RigidBody:
    """Placeholder body for a fixed (diffraction-only) computation: no mass, no stiffness."""
    return RigidBody(
        0.0, np.zeros(3), np.zeros((3, 3)), np.zeros((6, 6)), np.zeros((6, 6)), {"fixed": True}
    )


def roll_damping_matrix(body: RigidBody, a44: float) -> np.ndarray:
    """Dimensional viscous damping B44 (`jaxtow.roll_damping_coefficient`) at the roll added
    mass A44(ω)."""
    D = np.zeros((6, 6))
    D[3, 3] = float(
        roll_damping_coefficient(
            body.damping[3, 3], body.stiffness[3, 3], body.inertia[0, 0] + max(a44, 0.0)
        )
    )
    return D
