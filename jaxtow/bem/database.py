"""Drift databases from panel solves: `bem_drift` solves a hull over (ω, β) one frequency
at a time, with an on-disk cache keyed by every input, and assembles the RAOs and the
far- and near-field mean drift into one dataset with its provenance; `qtf_from_bem` turns it
into a `QTF`; `box_barge_drift` is the whole pipeline for a box barge (Barge 1)."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import xarray as xr

from .. import presets
from .._body import Loading
from .._config import __version__
from .._progress import progress_meter
from .._units import RHO_SEA, G
from ..drift._qtf import QTF
from ..io import Fingerprint, save_netcdf
from .body import RigidBody, fixed_body, rigid_body
from .capytaine_mesh import require_capytaine
from .meshes import HullMesh, raked_barge_mesh
from .solve import (
    DOFS,
    FORCE_COMPONENTS,
    MIN_PANELS_PER_WAVELENGTH,
    NEAR_FIELD_PARTS,
    FrequencySolution,
    prepare,
    solve_frequency,
)

#: bump when what a cached frequency holds, or how it is computed, changes
_CACHE_VERSION = "nf-lsq-1"


def _cache_key(mesh, body, omega, beta, rho, g, depth, theta_step, fixed):
    """The name of one frequency's cache file: the `jaxtow.io.Fingerprint` of every input
    (the arrays as raw bytes, then the numbers as JSON: the digests of the files the
    project ships)."""
    cpt = require_capytaine()
    h = Fingerprint()
    for arr in (
        mesh.vertices,
        mesh.faces,
        mesh.lid_vertices,
        mesh.lid_faces,
        body.cog,
        body.inertia,
        body.stiffness,
        body.damping,
        np.asarray(beta, float),
    ):
        h.raw(np.ascontiguousarray(arr).tobytes())
    h.raw(
        json.dumps(
            [
                float(body.mass),
                float(omega),
                rho,
                g,
                str(depth),
                theta_step,
                bool(fixed),
                cpt.__version__,
                _CACHE_VERSION,
            ]
        ).encode()
    )
    return h.hexdigest(20)


def _frequency_dataset(r: FrequencySolution):
    w = [r.omega]
    dims_b = ("omega", "beta")
    rao, exc = r.rao[None], r.excitation[None]
    ds = xr.Dataset(
        {
            "rao_real": (dims_b + ("dof",), np.real(rao)),
            "rao_imag": (dims_b + ("dof",), np.imag(rao)),
            "excitation_real": (dims_b + ("dof",), np.real(exc)),
            "excitation_imag": (dims_b + ("dof",), np.imag(exc)),
            "added_mass": (("omega", "dof", "dof_j"), r.added_mass[None]),
            "radiation_damping": (("omega", "dof", "dof_j"), r.damping[None]),
            "viscous_damping": (("omega", "dof", "dof_j"), r.viscous_damping[None]),
            "far_field": (dims_b + ("component",), r.far_field[None]),
            "near_field": (dims_b + ("component",), r.near_field[None]),
            "near_field_parts": (dims_b + ("part", "component"), r.near_field_parts[None]),
            "sectional_moments": (dims_b + ("axis", "order"), r.sectional[None]),
            "wavenumber": (("omega",), [r.wavenumber]),
        },
        coords={
            "omega": w,
            "beta": r.beta,
            "dof": list(DOFS),
            "dof_j": list(DOFS),
            "component": list(FORCE_COMPONENTS),
            "part": list(NEAR_FIELD_PARTS),
            "axis": ["x", "y"],
            "order": [0, 1, 2],
        },
    )
    return ds


def _attrs(mesh, body, rho, g, water_depth, fixed, theta_step):
    cpt = require_capytaine()

    return {
        "mesh_name": mesh.name,
        "mesh_params": json.dumps(mesh.params),
        "n_panels": mesh.n_panels,
        "n_lid_panels": int(len(mesh.lid_faces)),
        "panel_size_m": mesh.panel_size,
        "solver": "capytaine.BEMSolver(method='indirect'), Delhommeau Green function, lid for irregular frequencies",
        "capytaine_version": cpt.__version__,
        "jaxtow_version": __version__,
        "rho": rho,
        "g": g,
        "water_depth": str(water_depth),
        "fixed_body": int(fixed),
        "mass_kg": float(body.mass),
        "cog_m": json.dumps([float(c) for c in body.cog]),
        "inertia_kgm2": json.dumps([float(v) for v in np.diag(body.inertia)]),
        "body_notes": json.dumps(body.notes),
        "kochin_step_deg": theta_step,
        "far_field_method": "jaxtow.bem.solve.far_field_drift: diagonal of capytaine.post_pro.far_field_mean_drift_force (Kochin functions)",
        "near_field_method": "Pinkster pressure integration, parts I-IV (jaxtow.bem.nearfield); surface velocity "
        "from a least-squares gradient of the surface potential",
        "conventions": "per unit wave amplitude squared, SI; body axes x forward, y port, z up from the waterline; "
        "beta = 0 head seas, CCW, direction waves come from; yaw about the CoG's vertical axis; "
        "complex amplitudes with exp(-i omega t)",
        "assumptions": json.dumps(
            {
                k: presets.ASSUMPTIONS[k]["note"]
                for k in ("cog_z", "radii_of_gyration", "roll_damping")
            }
        ),
    }


def _solve_frequencies(mesh, body, omega, beta, solve: dict, cache_dir, progress: bool) -> list:
    """One dataset a frequency (ascending), read from the cache where it is there, else
    solved (and cached)."""
    cache = None if cache_dir is None else Path(cache_dir)
    if cache is not None:
        cache.mkdir(parents=True, exist_ok=True)
    bar = progress_meter(progress).start(omega.size, f"bem {mesh.name} ({mesh.n_panels} panels)")
    parts = []
    prepared = None  # built on the first frequency that is not in the cache
    for w in np.sort(omega):
        key = _cache_key(
            mesh,
            body,
            w,
            beta,
            solve["rho"],
            solve["g"],
            solve["water_depth"],
            solve["theta_step"],
            solve["fixed"],
        )
        path = None if cache is None else cache / f"{mesh.name}_{key}.nc"
        if path is not None and path.exists():
            ds = xr.load_dataset(path)
        else:
            prepared = prepared or prepare(mesh, body)
            ds = _frequency_dataset(
                solve_frequency(mesh, body, w, beta, **solve, prepared=prepared)
            )
            if path is not None:
                save_netcdf(ds, path)  # atomic: a killed solve leaves no partial cache file
        parts.append(ds)
        bar.update()
    bar.close()
    return parts


def bem_drift(
    mesh: HullMesh,
    omega,
    beta,
    *,
    body: RigidBody | None = None,
    loading: Loading | None = None,
    rho: float = RHO_SEA,
    g: float = G,
    water_depth: float = math.inf,
    fixed: bool = False,
    cache_dir=None,
    progress: bool = False,
    theta_step: float = 0.5,
):
    """First-order solution, RAOs and far-/near-field mean drift over (ω, β) for ``mesh``,
    one frequency at a time, as an xarray Dataset (variables in `_frequency_dataset`, the
    mesh, solver, versions and assumptions in its attributes).

    ``omega`` rad/s (> 0), ``beta`` rad in jaxtow's convention. ``body`` defaults to
    `rigid_body(mesh, loading)` (``loading`` a `jaxtow.Loading`; None: the documented
    estimate). With ``cache_dir`` each frequency
    is stored in its own NetCDF file named by a hash of every input, so a rerun (or an
    interrupted run) only solves what is missing. ``progress`` prints a bar on stderr.
    """

    omega = np.atleast_1d(np.asarray(omega, float))
    beta = np.atleast_1d(np.asarray(beta, float))
    if omega.ndim != 1 or not np.all(omega > 0) or not np.all(np.isfinite(omega)):
        raise ValueError("parameter 'omega' must be a 1-D array of positive frequencies [rad/s]")
    if not np.all(np.diff(beta) > 0):
        raise ValueError("parameter 'beta' must be strictly ascending [rad]")
    require_capytaine()
    if body is None and not fixed:
        body = rigid_body(mesh, loading, rho=rho, g=g)
    if body is None:
        body = fixed_body()
    solve = dict(rho=rho, g=g, water_depth=water_depth, fixed=fixed, theta_step=theta_step)
    parts = _solve_frequencies(mesh, body, omega, beta, solve, cache_dir, progress)
    out = xr.concat(
        parts,
        dim="omega",
        data_vars="minimal",
        coords="minimal",
        compat="override",
        join="override",
    )
    out.attrs.update(_attrs(mesh, body, rho, g, water_depth, fixed, theta_step))
    # validity: waves must be resolved by the panels (about 6 or more panels per wavelength)
    out["panels_per_wavelength"] = 2 * math.pi / out["wavenumber"] / mesh.panel_size
    out["resolved"] = out["panels_per_wavelength"] >= MIN_PANELS_PER_WAVELENGTH
    out["resolved"].attrs["note"] = (
        f"wavelength / nominal panel size >= {MIN_PANELS_PER_WAVELENGTH}; "
        "results at unresolved frequencies are unreliable"
    )
    return out


def rao(ds):
    """Complex RAOs (omega, beta, dof) from a `bem_drift` dataset [m/m, rad/m]."""
    return ds["rao_real"] + 1j * ds["rao_imag"]


def qtf_from_bem(ds, method: str = "far_field", *, symmetric: bool = False):
    """A jaxtow `QTF` (SI, per ζa²) from a `bem_drift` dataset; ``method`` 'far_field' or
    'near_field'. ``symmetric=True`` (a port-starboard symmetric hull with β from 0) completes
    the table to negative headings with `QTF.symmetric`, setting the head-sea (and
    following-sea) sway and yaw, which vanish by symmetry, to exactly zero. The sectional
    moments (M_x,1, M_y,1, M_y,2) of the pressure integration (``sectional_moments``) come
    with the table, for the yaw-rate wave-drift damping (`jaxtow.drift.yaw_rate_damping`)."""

    if method not in ("far_field", "near_field"):
        raise ValueError(f"parameter 'method' must be 'far_field' or 'near_field', got {method!r}")
    v = np.asarray(ds[method].transpose("omega", "beta", "component"))
    w, b = np.asarray(ds.omega, float), np.asarray(ds.beta, float)
    fx, fy, nz = v[..., 0], v[..., 1].copy(), v[..., 2].copy()
    sec = None
    if "sectional_moments" in ds:
        sm = ds["sectional_moments"].transpose("omega", "beta", "axis", "order")
        sec = [
            np.asarray(sm.sel(axis=a, order=k), float).copy()
            for a, k in (("x", 1), ("y", 1), ("y", 2))
        ]
    if symmetric:
        for j in np.flatnonzero(np.isclose(b, 0.0) | np.isclose(np.abs(b), math.pi)):
            for arr in [fy, nz] + (sec[1:] if sec else []):
                arr[:, j] = 0.0
        return QTF.symmetric(omega=w, beta=b, fx=fx, fy=fy, nz=nz, sectional=sec)
    return QTF(omega=w, beta=b, fx=fx, fy=fy, nz=nz, sectional=sec)


def qtf_attrs(ds, method: str) -> dict:
    """The provenance attributes to store with a QTF made by `qtf_from_bem`."""
    keep = {k: v for k, v in ds.attrs.items()}
    keep["qtf_method"] = method
    keep["qtf_source"] = f"jaxtow.bem {method.replace('_', '-')} mean drift"
    return keep


def box_barge_drift(
    length: float,
    breadth: float,
    draft: float,
    omega,
    beta,
    *,
    loading: Loading | None = None,
    panel_size: float = 2.0,
    rake: float = 0.0,
    **kwargs,
):
    """Panel-method mean drift of a (raked) box barge: `BEMDrift` with ``far_field`` and
    ``near_field`` jaxtow `QTF` (SI per ζa², β = 0 head seas; completed by symmetry when β
    starts at 0) and the full ``dataset``. ``loading``: a `jaxtow.Loading` (None: the
    documented estimate); other keywords go to `bem_drift` (cache_dir, progress, ...)."""

    mesh = raked_barge_mesh(
        length,
        breadth,
        draft,
        rake,
        panel_size=panel_size,
        name="box_barge" if rake == 0 else "raked_barge",
    )
    ds = bem_drift(mesh, omega, beta, loading=loading, **kwargs)
    sym = bool(np.isclose(float(np.min(ds.beta)), 0.0))
    return BEMDrift(
        qtf_from_bem(ds, "far_field", symmetric=sym),
        qtf_from_bem(ds, "near_field", symmetric=sym),
        ds,
    )


@dataclasses.dataclass(frozen=True)
class BEMDrift:
    """Far-field and near-field `QTF` of one hull and the `bem_drift` dataset behind them."""

    far_field: object
    near_field: object
    dataset: object
