"""Mesh convergence of the panel drift (thesis appendix B.1, fig. B.1): the drift at several
panel sizes, each against the finest, and the near field against the far field, per zone."""

from __future__ import annotations

import jax.numpy as jnp
import numpy as np
import xarray as xr

from ..drift._compare import relative_mse
from ..drift._methods import ZONE_NAMES, zone
from .database import bem_drift


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
