"""Labelled results of the waterline drift-method comparison (xarray / NetCDF)."""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..drift._methods import ZONE_EDGES, ZONE_NAMES

_UNITS = {"fx": "N/m2", "fy": "N/m2", "nz": "N m/m2"}


def drift_methods_dataset(
    estimates: dict,
    omega,
    *,
    beta,
    u=0.0,
    v=0.0,
    waterline=None,
    base: str | None = None,
    attrs: dict | None = None,
) -> xr.Dataset:
    """Dataset over (method, omega) from {name: DriftEstimate} on one ω grid: fx, fy, nz per
    ζa², each method's combined ``valid`` flag and every individual flag (missing flags are
    True), the zone code and L/λ."""
    names = list(estimates)
    omega = np.asarray(omega, float)
    data = {
        c: (
            ("method", "omega"),
            np.stack([np.asarray(getattr(estimates[n], c)) for n in names]),
            {"units": _UNITS[c], "long_name": f"mean drift {c} per zeta_a^2"},
        )
        for c in ("fx", "fy", "nz")
    }
    data["valid"] = (
        ("method", "omega"),
        np.stack([np.asarray(estimates[n].valid) for n in names]),
        {"long_name": "inside every validity range of the method"},
    )
    flags = sorted({k for n in names for k in estimates[n].flags})
    for k in flags:
        data[f"flag_{k}"] = (
            ("method", "omega"),
            np.stack(
                [np.asarray(estimates[n].flags.get(k, np.ones(omega.shape, bool))) for n in names]
            ),
            {"long_name": f"validity flag {k!r}"},
        )
    first = estimates[names[0]]
    data["zone"] = (
        ("omega",),
        np.asarray(first.zone),
        {
            "long_name": "0 " + ", 1 ".join(ZONE_NAMES[:2]) + ", 2 reflection (by L/lambda)",
            "edges_L_over_lambda": list(ZONE_EDGES),
        },
    )
    a = dict(
        beta=float(beta),
        u=float(u),
        v=float(v),
        convention="beta=0 head seas, waves from beta CCW from bow",
    )
    if waterline is not None:
        a.update(
            waterline=waterline.name,
            length=float(waterline.length),
            breadth=float(waterline.breadth),
            draft=float(waterline.draft),
            block_coefficient=float(waterline.block_coefficient),
        )
    if base:
        a["base"] = base
    a.update(attrs or {})
    ds = xr.Dataset(
        data, coords={"method": names, "omega": ("omega", omega, {"units": "rad/s"})}, attrs=a
    )
    if waterline is not None:
        ds = ds.assign_coords(
            L_over_lambda=("omega", omega**2 * float(waterline.length) / (2 * np.pi * 9.80665))
        )
    return ds
