"""Labelled sweep results: xarray Datasets with units and provenance, saved as NetCDF."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import xarray as xr

from .._config import __version__
from .._parameters import describe
from .._vessel import VESSEL_PARAMETERS
from ._atomic import atomic_path
from ._netcdf import read_netcdf

#: name → (units, long_name) of the sweep outputs.
VARIABLES = {
    "psi": ("rad", "equilibrium heading psi"),
    "gamma": ("rad", "equilibrium towline angle gamma"),
    "tension": ("1", "equilibrium towline tension T' (by 0.5 rho T L U_tug^2)"),
    "length": ("1", "equilibrium stretched towline length l' (by L)"),
    "found": ("1", "slot holds an equilibrium (other slots are padding, values NaN)"),
    "converged": ("1", "root finder converged"),
    "taut": ("1", "towline taut (T' > 1e-12, the force balance's round-off)"),
    "behind_tug": ("1", "vessel behind the tug (|gamma| < pi/2)"),
    "in_range": ("1", "|psi| within the manoeuvring model's range psi_max"),
    "valid": ("1", "found, converged, taut, behind the tug and in range"),
    "branch": ("1", "branch: -1 (psi<0), 0 (straight behind), +1 (psi>0)"),
    "residual": ("1", "max |f| of the vector field at the equilibrium"),
    "eig_real": ("1", "real part of Jacobian eigenvalues (by U_tug/L)"),
    "eig_imag": ("1", "imaginary part of Jacobian eigenvalues (by U_tug/L)"),
    "max_real": ("1", "max real part of the eigenvalues (by U_tug/L); > 0 unstable"),
    "stability": ("1", "-1 stable, 0 marginal, +1 unstable, 2 invalid (NaN)"),
    "routh_hurwitz": ("1", "Routh-Hurwitz criterion: all eigenvalues in the left half-plane"),
    "n_equilibria": ("1", "number of equilibria found"),
    "truncated": ("1", "more equilibria exist than slots (raise max_roots)"),
    "physics_valid": ("1", "every validity flag of the physics holds (validity_* variables)"),
}
#: name → (units, long_name) of the physics' validity variables (``validity_<name>``).
VALIDITY_VARIABLES = {
    "line_taut": ("1", "towline carries tension (not slack)"),
    "moving_ahead": ("1", "the hull moves bow first through the water (u' > 0)"),
    "froude": ("1", "Froude number U/sqrt(gL) of the vessel"),
    "froude_ok": ("1", "Froude number below 0.15 (drift methods' range)"),
    "separation_ratio": ("1", "U/(omega zeta_a) (regular) or U/(omega_p Hs/2) (irregular)"),
    "no_separation": ("1", "separation ratio below 1 (no flow separation)"),
    "encounter_frequency": ("rad s-1", "encounter frequency omega_e"),
    "encounter_positive": ("1", "omega_e > 0 (the vessel does not overtake the waves)"),
    "overtaken_energy": ("1", "fraction of the spectrum's m0 at omega_e <= 0"),
    "tau": ("1", "tau = omega U / g (Aranha's expansion parameter)"),
    "tau_ok": ("1", "tau below 1/4 (Aranha's formula)"),
    "heading_in_table": ("1", "wave heading inside the QTF table"),
    "yaw_rate_damping": ("1", "yaw-rate wave-drift damping included (sectional moments)"),
    "relative_wind_speed": ("m s-1", "relative wind speed"),
    "relative_wind_angle": ("rad", "relative wind angle from the bow"),
}
_FLOAT_MASKED = (
    "psi",
    "gamma",
    "tension",
    "length",
    "residual",
    "eig_real",
    "eig_imag",
    "max_real",
)


def model_attributes(model) -> dict:
    """Provenance attributes: every fixed parameter value and the documented estimates."""

    attrs = {
        "jaxtow_version": __version__,
        "vessel": model.vessel.name,
        "towline_law": type(model.towline).__name__,
        "external_force": type(model.external).__name__,
    }
    for n in VESSEL_PARAMETERS:
        attrs[f"vessel_{n}"] = float(np.asarray(getattr(model.vessel, n)))
    for f in dataclasses.fields(model.towline):
        v = np.asarray(getattr(model.towline, f.name), float)
        attrs[f"towline_{f.name}"] = float(v) if v.ndim == 0 else v  # per segment
    attrs["psi_max"] = float(np.asarray(model.psi_max))
    attrs["assumed_values"] = json.dumps(dict(model.assumed)) if model.assumed else "none"
    if model.assumed:
        attrs["note"] = (
            "Results depend on documented estimates for values the source lacks: "
            + ", ".join(k for k, _ in model.assumed)
            + " (see jaxtow.presets)."
        )
    return attrs


def sweep_dataset(model, arrays: dict, *, method: str) -> xr.Dataset:
    coords = arrays["_coords"]
    names = list(coords)
    ds = xr.Dataset(
        coords={
            n: (n, v, dict(zip(("units", "long_name"), describe(n)))) for n, v in coords.items()
        }
    )
    nslot = arrays["psi"].shape[len(names)]
    ds = ds.assign_coords(equilibrium=np.arange(nslot), mode=np.arange(6))
    found = arrays["found"]
    for k, v in arrays.items():
        if k.startswith("_"):
            continue
        dims = list(names)
        if v.ndim > len(names):
            dims.append("equilibrium")
        if v.ndim > len(names) + 1:
            dims.append("mode")
        masked = k in _FLOAT_MASKED or (k.startswith("validity_") and v.dtype.kind == "f")
        if masked:
            mask = found if v.ndim == found.ndim else found[..., None]
            v = np.where(mask, v, np.nan)
        if k.startswith("validity_"):
            units, long_name = VALIDITY_VARIABLES.get(k[len("validity_") :], ("1", k))
        else:
            units, long_name = VARIABLES.get(k, ("1", k))
        ds[k] = (dims, v, {"units": units, "long_name": long_name})
    ds.attrs.update(model_attributes(model))
    ds.attrs["equilibrium_method"] = method
    ds.attrs["eigenvalue_method"] = arrays.get("_eig_method", "lapack")
    ds.attrs["swept_parameters"] = ",".join(names)
    return ds


def nan_audit(ds: xr.Dataset) -> dict:
    """Where a sweep Dataset's NaN come from. Per-slot floating-point outputs: ``entries``,
    ``nan``, of which ``masked`` (a slot without an equilibrium: NaN by design),
    ``flagged`` (a found equilibrium outside ``valid`` or ``physics_valid``, or of stability
    code 2) and ``unexplained`` (NaN at a found, valid equilibrium with every physics flag
    holding; per-point outputs count here too) with their ``unexplained_variables``.
    """
    found = ds["found"].values
    explained = ~ds["valid"].values | ~ds["physics_valid"].values | (ds["stability"].values == 2)
    counts = dict(entries=0, nan=0, masked=0, flagged=0, unexplained=0)
    variables: list[str] = []
    for k, v in ds.data_vars.items():
        a = v.values
        if a.dtype.kind != "f" or "equilibrium" not in v.dims:
            if a.dtype.kind == "f" and np.isnan(a).any():  # per-point outputs: never NaN
                counts["unexplained"] += int(np.isnan(a).sum())
                variables.append(k)
            continue
        nan = np.isnan(a)
        f, e = found, explained
        if a.ndim > found.ndim:  # (…, slot, mode)
            f, e = found[..., None], explained[..., None]
        counts["entries"] += a.size
        counts["nan"] += int(nan.sum())
        counts["masked"] += int((nan & ~f).sum())
        counts["flagged"] += int((nan & f & e).sum())
        bad = int((nan & f & ~e).sum())
        counts["unexplained"] += bad
        if bad:
            variables.append(k)
    points = int(np.prod([ds.sizes[n] for n in ds.attrs["swept_parameters"].split(",")]))
    return dict(points=points, **counts, unexplained_variables=variables)


def save_dataset(ds: xr.Dataset, path) -> None:
    """Write a dataset to NetCDF (booleans stored as int8, restored by `load_dataset`).

    Atomic: the file is written beside ``path`` under a temporary name and renamed into
    place, so an interrupted write never leaves a partial file under the final name."""

    ds = ds.copy()
    for k, v in ds.data_vars.items():
        if v.dtype == bool:
            ds[k] = v.astype("int8")
            ds[k].attrs["jaxtow_bool"] = 1
    with atomic_path(path) as tmp:
        ds.to_netcdf(tmp)


def load_dataset(path) -> xr.Dataset:
    """A dataset written by `save_dataset` (a clear error for a file that is not NetCDF)."""
    ds = read_netcdf(path, "a jaxtow result dataset (save_dataset)")
    for k, v in ds.data_vars.items():
        if v.attrs.get("jaxtow_bool"):
            ds[k] = v.astype(bool)
            del ds[k].attrs["jaxtow_bool"]
    return ds
