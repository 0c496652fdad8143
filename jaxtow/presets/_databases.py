"""The panel-method drift databases that ship with jaxtow (the drift sources that name them are
in `jaxtow.presets._sources`).

Barge 1 (the 76.2 × 24.4 × 5 m box) and Barge 2 (the raked barge) were solved with
``jaxtow bem`` (Capytaine, docs/bem.md) at the mesh chosen by the stability-verdict mesh study
(docs/bem.md, "Shipped databases"); each file records its mesh, solver, versions and every
estimate used in its NetCDF attributes (`database_attrs`). Far field: Maruo/Newman momentum
conservation from the Kochin functions; near field: Pinkster pressure integration, with the
sectional moments the yaw-rate column of the wave-drift damping needs. The near field is the
default, as the thesis advises for the yaw moment (its far-field counterpart is the most
mesh-sensitive of the three).
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

import numpy as np
import xarray as xr

from ..drift import QTF, qtf_from_method
from ..io import load_qtf
from ._barge2 import barge2_waterline

#: The shipped hulls and the two drift methods of each.
DATABASES = ("barge1", "barge2")
DATABASE_METHODS = ("far_field", "near_field")
#: The method `database` and every default drift source use.
DEFAULT_METHOD = "near_field"
#: The stand-in drift source's name (a QTF tabulated from the Kashiwagi waterline method).
STANDIN = "standin"


#: Grid of the stand-in QTF (rad/s; headings 0-180 deg completed by symmetry).
QTF_OMEGA = np.linspace(0.1, 2.5, 49)
QTF_BETA_DEG = np.linspace(0.0, 180.0, 19)
APPROXIMATE_QTF = (
    "APPROXIMATE drift forces: QTF tabulated from the Kashiwagi waterline method "
    "(diffraction only, no motion-induced drift) on the estimated Barge 2 rake, "
    "with Aranha's wave-drift damping; the thesis used Delfrac near-field QTFs"
)


def approximate_qtf(method: str = "kashiwagi", draft=None):
    """The documented stand-in QTF of Barge 2: a QTF tabulated from a waterline method
    (`jaxtow.drift.qtf_from_method`, default Kashiwagi: Fujii-Takahashi diffraction, no
    motion-induced drift, which matters where L/λ < 1, ω below about 0.9 rad/s for Barge 2)
    on `barge2_waterline`, over `QTF_OMEGA` and `QTF_BETA_DEG` (`APPROXIMATE_QTF` says so)."""
    return qtf_from_method(method, barge2_waterline(draft), QTF_OMEGA, np.radians(QTF_BETA_DEG))


def _check(name: str, method: str) -> None:
    if name not in DATABASES:
        raise ValueError(f"parameter 'name': shipped databases are {DATABASES}, got {name!r}")
    if method not in DATABASE_METHODS:
        raise ValueError(f"parameter 'method': one of {DATABASE_METHODS}, got {method!r}")


def database_file(name: str = "barge2", method: str = DEFAULT_METHOD):
    """Path of a shipped database (NetCDF, `jaxtow.io.load_qtf` reads it)."""
    _check(name, method)
    return resources.files("jaxtow") / "data" / "qtf" / f"{name}_{method}.nc"


@cache
def _load(name: str, method: str):
    path = database_file(name, method)
    with resources.as_file(path) as p:
        attrs = dict(xr.load_dataset(p).attrs)
        return load_qtf(p), attrs


def database(name: str = "barge2", method: str = DEFAULT_METHOD) -> QTF:
    """The shipped panel-method mean-drift `QTF` of ``name`` ("barge1" | "barge2") by
    ``method`` ("far_field" | "near_field"), SI per ζa², β = 0 head seas over the full circle,
    with the sectional moments. See the module docstring and `database_attrs`."""
    return _load(name, method)[0]


def database_attrs(name: str = "barge2", method: str = DEFAULT_METHOD) -> dict:
    """The provenance of a shipped database: mesh, panel size and count, solver and versions,
    the mass estimates, the mesh-study verdict, the command that reproduces it."""
    out = dict(_load(name, method)[1])
    for k in ("assumptions", "mesh_params"):
        if isinstance(out.get(k), str):
            try:
                out[k] = json.loads(out[k])
            except ValueError:
                pass
    return out


def describe_database(name: str = "barge2", method: str = DEFAULT_METHOD) -> str:
    """One line naming a shipped database for ``drift_source`` attributes and figures."""
    a = database_attrs(name, method)
    label = "near-field (pressure integration)" if method == "near_field" else "far-field"
    return (
        f"shipped {name} {label} panel QTF (jaxtow bem, Capytaine {a.get('capytaine_version', '?')}, "
        f"{a.get('panel_size_m', '?')} m panels, {a.get('n_panels', '?')} hull panels)"
    )
