"""What ``jaxtow bem`` reports of a panel solve: its mesh and provenance, the short-wave
head-sea surge drift against the wall limit ρgB (far and near field), and the relative
mean square error of the near field against the far field per zone (thesis eq. 4.1)."""

from __future__ import annotations

import json

import numpy as np

from .._units import RHO_SEA, G
from ..drift import relative_mse_by_zone


def bem_summary(ds, mesh) -> dict:
    """The summary of a `jaxtow.bem.bem_drift` dataset ``ds`` solved on ``mesh``."""
    beta = ds.beta.values
    L = float(np.ptp(mesh.vertices[:, 0]))
    B = float(np.ptp(mesh.vertices[:, 1]))
    summary = {
        "mesh": mesh.name,
        "n_panels": mesh.n_panels,
        "panel_size_m": mesh.panel_size,
        "capytaine_version": ds.attrs["capytaine_version"],
        "assumptions": json.loads(ds.attrs["assumptions"]),
    }
    head = ds.sel(beta=float(beta[0]))
    summary["short_wave_surge_head_seas"] = {
        m: float(head[m].sel(component="fx").isel(omega=-1)) / (RHO_SEA * G * B)
        for m in ("far_field", "near_field")
    }
    for c in ("fx", "fy"):
        summary[f"near_vs_far_{c}"] = relative_mse_by_zone(
            ds.near_field.sel(component=c).values,
            ds.far_field.sel(component=c).values,
            np.repeat(ds.omega.values[:, None], beta.size, 1),
            L,
        )
    return summary
