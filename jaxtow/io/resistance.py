"""Labelled tow-resistance budgets (xarray / NetCDF), thesis figs 7.2-7.4."""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..resistance._budget import COMPONENTS, OVERTAKEN_TOL, Budget
from ..resistance._flow import CoefficientTable


def resistance_dataset(
    budget: Budget, speeds, tps, *, tow=None, sea=None, attrs: dict | None = None
) -> xr.Dataset:
    """Dataset over (speed, tp, component) from a `jaxtow.resistance.resistance_grid` budget:
    ``resistance`` [N] per component along the course, ``total`` [N], ``share`` [%],
    ``froude``, ``overtaken_energy`` and its flag ``waves_complete`` (following seas the tow
    outruns: the drift theory gives no wave resistance there) and the body-axis loads
    ``fx``, ``fy`` [N], ``nz`` [N m]. The tow's
    assumptions (illustrative tables, estimates) go into the attributes."""
    speeds, tps = np.asarray(speeds, float), np.asarray(tps, float)
    r = np.asarray(budget.resistance)
    body = np.asarray(budget.body)
    total = r.sum(-1)
    dims = ("speed", "tp", "component")
    data = {
        "resistance": (dims, r, {"units": "N", "long_name": "resistance along the course"}),
        "total": (dims[:2], total, {"units": "N", "long_name": "total tow resistance"}),
        "share": (
            dims,
            np.asarray(budget.shares),
            {"units": "%", "long_name": "share of the total"},
        ),
        "froude": (("speed",), np.asarray(budget.froude)[:, 0], {"long_name": "Fn = U/sqrt(gL)"}),
        "froude_ok": (
            ("speed",),
            np.asarray(budget.froude)[:, 0] < 0.15,
            {"long_name": "Fn < 0.15"},
        ),
        "overtaken_energy": (
            dims[:2],
            np.asarray(budget.overtaken_energy),
            {
                "long_name": "share of the sea's m0 the tow overtakes (encounter frequency <= 0: "
                "outside the drift theory, no wave resistance counted there)",
            },
        ),
        "waves_complete": (
            dims[:2],
            np.asarray(budget.overtaken_energy) <= OVERTAKEN_TOL,
            {"long_name": f"overtaken_energy <= {OVERTAKEN_TOL}: the wave resistance is complete"},
        ),
    }
    for i, (c, u) in enumerate((("fx", "N"), ("fy", "N"), ("nz", "N m"))):
        data[c] = (dims, body[..., i], {"units": u, "long_name": f"body-axis load {c}"})
    a = {}
    if tow is not None:
        a["tow"] = tow.name
        a["length"] = float(tow.length)
        for k, note in tow.assumed:
            a[f"assumed_{k}"] = note
        if tow.waves is not None:
            a["wave_drift_method"] = tow.waves.method
        if tow.wind is not None:
            a["wind_coefficients"] = tow.wind.coefficients.label
    if sea is not None:
        for k in (
            "hs",
            "gamma",
            "wind_speed",
            "current_speed",
            "wave_angle",
            "wind_angle",
            "current_angle",
        ):
            a[k] = float(getattr(sea, k))
        a["sea_state"] = sea.name
    a["convention"] = (
        "angles: direction the wind/current/waves come from, counter-clockwise from the course, "
        "0 = from ahead; resistance = minus the along-course force"
    )
    a.update(attrs or {})
    return xr.Dataset(
        data,
        coords={
            "speed": ("speed", speeds, {"units": "m/s"}),
            "tp": ("tp", tps, {"units": "s"}),
            "component": list(COMPONENTS),
        },
        attrs=a,
    )


def read_coefficient_table(path) -> CoefficientTable:
    """A port-starboard symmetric OCIMF-form coefficient table (wind or current) from a CSV
    file of four columns angle_deg, cx, cy, cn over 0…180° (``#`` comments);
    `jaxtow.resistance.CoefficientTable.symmetric`. ValueError names the file."""
    try:
        t = np.loadtxt(path, delimiter=",", comments="#", ndmin=2)
    except (ValueError, OSError) as e:
        raise ValueError(f"{path}: {e}") from None
    if t.shape[1] != 4:
        raise ValueError(f"{path}: expected 4 columns angle_deg, cx, cy, cn, got {t.shape[1]}")
    return CoefficientTable.symmetric(
        t[:, 0], t[:, 1], t[:, 2], t[:, 3], label=f"wind table {path}"
    )
