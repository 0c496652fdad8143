"""A hull mesh as a tow's drift source: the panel solve of the mesh, run on first use and cached
per frequency (`jaxtow.presets.AbstractDriftSource`, the one interface of every drift
source)."""

from __future__ import annotations

import dataclasses

import numpy as np

from .._body import Loading
from ..drift import QTF
from ..presets import AbstractDriftSource
from .capytaine_mesh import read_mesh, require_capytaine
from .database import bem_drift, qtf_from_bem

__all__ = ["MeshDriftSource"]


@dataclasses.dataclass(frozen=True, eq=False)
class MeshDriftSource(AbstractDriftSource):
    """The panel solve (Capytaine, the ``bem`` extra) of the hull mesh ``mesh`` (a file) over
    ``omega`` = (lo, hi, n) [rad/s] × ``beta_deg`` = (lo, hi, n) [deg]; the ``method``'s
    drift (near_field | far_field); the CoG ``cog_z`` above the keel [m] (None: the
    documented estimate, `jaxtow.Loading.estimate`); ``symmetric`` completes the headings
    by port-starboard symmetry; each frequency cached in the folder ``cache``."""

    mesh: str
    method: str = "near_field"
    omega: tuple = (0.05, 2.5, 61)
    beta_deg: tuple = (0.0, 180.0, 25)
    cog_z: float | None = None
    symmetric: bool = True
    cache: str | None = None

    def __post_init__(self):
        if self.method not in ("near_field", "far_field"):
            raise ValueError(
                f"parameter 'method' must be near_field or far_field, got {self.method!r}"
            )

    def _compute(self) -> QTF:
        require_capytaine()
        mesh = read_mesh(self.mesh)
        draft = -float(mesh.vertices[:, 2].min())
        loading = (
            Loading.estimate(draft)
            if self.cog_z is None
            else Loading.above_keel(float(self.cog_z), draft)
        )
        (w0, w1, nw), (b0, b1, nb) = self.omega, self.beta_deg
        omega = np.linspace(float(w0), float(w1), int(nw))
        beta = np.radians(np.linspace(float(b0), float(b1), int(nb)))
        ds = bem_drift(mesh, omega, beta, loading=loading, cache_dir=self.cache, progress=True)
        object.__setattr__(self, "_panels", len(mesh.faces))
        return qtf_from_bem(ds, self.method, symmetric=self.symmetric)

    def describe(self) -> str:
        panels = getattr(self, "_panels", None)
        count = f", {panels} hull panels" if panels else ""
        return f"panel QTF of mesh {self.mesh} ({self.method.replace('_', ' ')}, jaxtow bem{count})"

    def caveat(self) -> str:
        return (
            f"panel solve of mesh {self.mesh} ({self.method}; CoG height, radii of gyration "
            "and roll damping: the documented estimates of jaxtow.ASSUMPTIONS"
            + (
                ")"
                if self.cog_z is None
                else f", the CoG {self.cog_z:g} m above the keel as given)"
            )
        )

    @property
    def spec(self) -> dict:
        out = dict(
            file=self.mesh,
            method=self.method,
            omega=list(self.omega),
            beta_deg=list(self.beta_deg),
            symmetric=self.symmetric,
        )
        if self.cog_z is not None:
            out["cog_z"] = self.cog_z
        return out
