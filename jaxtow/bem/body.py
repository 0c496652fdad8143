"""The rigid body of a panel solve: mass, CoG (its height above the keel, thesis Table B.3),
radii of gyration (Journée's approximations, `jaxtow.presets.ASSUMPTIONS`) and the exact
hydrostatics of the hull; the roll damping of the documented estimate."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .. import presets
from .._units import RHO_SEA, G
from .meshes import HullMesh


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
