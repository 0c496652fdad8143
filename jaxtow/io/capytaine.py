"""Capytaine's drift output (its NetCDF datasets of mean drift forces) as a `QTF`:
Capytaine's headings (the direction the waves travel to) turned into jaxtow's, half tables
completed by symmetry, the yaw moment moved to the CoG."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from ..drift._qtf import QTF
from ._netcdf import read_netcdf
from ._tables import complete_table, heading_deg, reference_point_of, shift_yaw

_CAPY_VARIABLES = ("drift_force_surge", "drift_force_sway", "drift_force_yaw")


def _capytaine_values(name, da):
    """(omega, wave_direction) real values of one Capytaine drift DataArray."""

    if "complex" in da.dims:  # stored as Capytaine saves complex values: a re/im axis
        labels = [str(v) for v in da["complex"].values] if "complex" in da.coords else []
        if labels != ["re", "im"]:
            raise ValueError(
                f"{name}: a 'complex' dimension must have the labels ['re', 'im'], got {labels}"
            )
        da = da.sel(complex="re") + 1j * da.sel(complex="im")
    dims = set(da.dims)
    if {"wave_direction_k", "wave_direction_l"} <= dims:  # Capytaine 3 drift output
        da = xr.DataArray(
            np.diagonal(
                np.asarray(da.transpose("omega", "wave_direction_k", "wave_direction_l")),
                axis1=1,
                axis2=2,
            ),
            dims=("omega", "wave_direction"),
            coords={"omega": da["omega"].values, "wave_direction": da["wave_direction_k"].values},
        )
    extra = [d for d in da.dims if d not in ("omega", "wave_direction")]
    if len(extra) == 1 and str(extra[0]).startswith("wave_direction"):
        vals = np.diagonal(
            np.asarray(da.transpose("omega", "wave_direction", extra[0])), axis1=1, axis2=2
        )
    elif not extra:
        vals = np.asarray(da.transpose("omega", "wave_direction"))
    else:
        raise ValueError(
            f"{name}: expected dims (omega, wave_direction[, a second heading]) or Capytaine 3's "
            f"(omega, wave_direction_k, wave_direction_l), with an optional 'complex' (re, im) "
            f"dimension; got {da.dims}"
        )
    return (
        np.real(vals),
        np.asarray(da["omega"].values, float),
        np.asarray(da["wave_direction"].values, float),
    )


def qtf_from_capytaine(
    fx,
    fy=None,
    nz=None,
    *,
    symmetry: str = "auto",
    symmetry_tol: float | None = None,
    reference_point=(0.0, 0.0),
    length: float = 1.0,
) -> QTF:
    """QTF from Capytaine mean-drift results, per unit wave amplitude, SI: either a Dataset
    with ``drift_force_surge``, ``drift_force_sway``, ``drift_force_yaw`` (what Capytaine 3's
    ``far_field_mean_drift_force`` returns, dims (omega, wave_direction_k, wave_direction_l),
    of which the diagonal is the mean drift) or three DataArrays (fx, fy, nz) with dims
    ``omega`` and ``wave_direction`` (optionally a second heading dim, of which the diagonal
    is taken). Complex values, or a ``complex`` (re, im) dimension as Capytaine stores them
    in NetCDF, give their real part. Capytaine's ``wave_direction`` is the direction the
    waves travel *to*, counter-clockwise from +x (π = head seas on a bow at +x), so
    β_jaxtow = wave_direction − π. ``reference_point`` (x, y) [m] moves the yaw moment from
    the origin of the result to that point; ``symmetry`` as in `complete_table`, the yaw
    scale ``length`` [m]."""

    if isinstance(fx, xr.Dataset):
        ds = fx
        missing = [v for v in _CAPY_VARIABLES if v not in ds]
        if missing:
            raise ValueError(
                f"the dataset has no Capytaine drift variables {missing} (it has "
                f"{sorted(ds.data_vars)}): compute the drift with jaxtow bem or Capytaine's "
                "far_field_mean_drift_force"
            )
        fx, fy, nz = (ds[v] for v in _CAPY_VARIABLES)
    if fy is None or nz is None:
        raise ValueError("parameters 'fy' and 'nz' are needed unless 'fx' is a Dataset")
    (vx, w, wd), (vy, _, _), (vn, _, _) = (
        _capytaine_values(n, d) for n, d in (("fx", fx), ("fy", fy), ("nz", nz))
    )
    bdeg = heading_deg(np.degrees(wd))
    order_w, order_b = np.argsort(w), np.argsort(bdeg)
    vx, vy, vn = (v[order_w][:, order_b] for v in (vx, vy, vn))
    ref, _ = reference_point_of(reference_point, {})
    vn = shift_yaw(vx, vy, vn, ref)
    return complete_table(
        w[order_w],
        bdeg[order_b],
        vx,
        vy,
        vn,
        symmetry=symmetry,
        tol=symmetry_tol,
        length=length,
        origin="Capytaine drift result",
    )[0]


def read_capytaine_drift(path, **options) -> QTF:
    """A Capytaine drift result saved as NetCDF (complex values on a ``complex`` (re, im)
    axis, as Capytaine writes them); the options of `qtf_from_capytaine`."""

    path = Path(path)
    ds = read_netcdf(path, "a Capytaine drift result")
    try:
        return qtf_from_capytaine(ds, **options)
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None
