"""jaxtow's own drift-table files: a `QTF` as NetCDF (with its grids, sectional moments and
provenance) or CSV, and `read_qtf`, which reads any drift file by its content."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from ..drift._qtf import QTF
from ._atomic import save_netcdf
from ._netcdf import read_netcdf, table_variables
from .capytaine import read_capytaine_drift
from .wamit import read_drift_file

#: The sectional drift moments a QTF dataset may carry (name, units, long name).
SECTIONAL_VARIABLES = (
    ("mx1", "N m m-2", "first moment of the sectional surge drift, M_x,1, per zeta_a^2"),
    ("my1", "N m m-2", "first moment of the sectional sway drift, M_y,1, per zeta_a^2"),
    ("my2", "N m2 m-2", "second moment of the sectional sway drift, M_y,2, per zeta_a^2"),
)


def qtf_to_dataset(q: QTF, attrs: dict | None = None):
    """A `QTF` as an xarray Dataset with units (jaxtow's own NetCDF format); ``attrs``
    (provenance: mesh, solver, versions) are stored with it."""

    ds = xr.Dataset(
        {
            name: (("omega", "beta"), np.asarray(q.values[i]), {"units": u, "long_name": ln})
            for i, (name, u, ln) in enumerate(
                (
                    ("fx", "N m-2", "mean surge drift per zeta_a^2"),
                    ("fy", "N m-2", "mean sway drift per zeta_a^2"),
                    ("nz", "N m m-2", "mean yaw drift moment per zeta_a^2"),
                )
            )
        },
        coords={
            "omega": ("omega", np.asarray(q.omega), {"units": "rad s-1"}),
            "beta": (
                "beta",
                np.asarray(q.beta),
                {"units": "rad", "long_name": "wave heading, 0 = head seas, from-direction CCW"},
            ),
        },
    )
    if q.sectional is not None:
        for i, (name, u, ln) in enumerate(SECTIONAL_VARIABLES):
            ds[name] = (
                ("omega", "beta"),
                np.asarray(q.sectional[i]),
                {"units": u, "long_name": ln},
            )
    ds.attrs.update(attrs or {})
    ds.attrs["jaxtow_qtf"] = 1
    return ds


def save_qtf(q: QTF, path, attrs: dict | None = None) -> None:
    """NetCDF (``.nc``, with ``attrs`` and the sectional moments mx1, my1, my2 if the table
    has them) or CSV (``.csv``: columns omega, beta, fx, fy, nz; SI; ``attrs`` as ``#``
    header lines; no sectional moments) by extension."""
    path = Path(path)
    if path.suffix == ".csv":
        W, B = np.meshgrid(np.asarray(q.omega), np.asarray(q.beta), indexing="ij")
        v = np.asarray(q.values)
        table = np.column_stack([W.ravel(), B.ravel(), v[0].ravel(), v[1].ravel(), v[2].ravel()])
        head = [f"{k}: {v}" for k, v in (attrs or {}).items()]
        np.savetxt(
            path,
            table,
            delimiter=",",
            fmt="%.17e",
            header="\n".join(head + ["omega [rad/s],beta [rad],fx [N/m2],fy [N/m2],nz [N m/m2]"]),
        )
    else:
        save_netcdf(qtf_to_dataset(q, attrs), path)


def load_qtf(path) -> QTF:
    """A QTF saved by `save_qtf` (``.nc`` or ``.csv``); a CSV's rows may come in any order,
    every (ω, β) pair exactly once."""
    path = Path(path)
    if path.suffix == ".csv":
        try:
            t = np.atleast_2d(np.loadtxt(path, delimiter=","))
        except (ValueError, UnicodeDecodeError) as e:
            raise ValueError(
                f"{path}: not a jaxtow CSV drift table (omega, beta, fx, fy, nz): "
                f"{str(e).splitlines()[0]}"
            ) from None
        if t.shape[1] != 5:
            raise ValueError(
                f"{path}: expected 5 columns (omega, beta, fx, fy, nz), got {t.shape[1]}"
            )
        ws, bs = np.unique(t[:, 0]), np.unique(t[:, 1])
        i, j = np.searchsorted(ws, t[:, 0]), np.searchsorted(bs, t[:, 1])
        cnt = np.zeros((ws.size, bs.size), int)
        np.add.at(cnt, (i, j), 1)
        if np.any(cnt != 1):
            bad = np.argwhere(cnt != 1)[0]
            raise ValueError(
                f"{path}: every (omega, beta) pair must appear exactly once; (omega "
                f"{ws[bad[0]]:g}, beta {bs[bad[1]]:g}) appears {cnt[tuple(bad)]} times"
            )
        v = np.zeros((3, ws.size, bs.size))
        v[:, i, j] = t[:, 2:].T
        return QTF(omega=ws, beta=bs, fx=v[0], fy=v[1], nz=v[2])

    ds = read_netcdf(path, "a jaxtow QTF file (save_qtf)")
    names = [n for n, _, _ in SECTIONAL_VARIABLES]
    table = table_variables(ds, path, ("fx", "fy", "nz"), ("omega", "beta"))
    sec = (
        list(table_variables(ds, path, names, ("omega", "beta")).values())
        if all(n in ds for n in names)
        else None
    )
    return QTF(omega=ds.omega.values, beta=ds.beta.values, **table, sectional=sec)


def read_qtf(path, **options):
    """Any drift file by its content: jaxtow NetCDF/CSV (`load_qtf`), a Capytaine drift
    NetCDF (`read_capytaine_drift`), WAMIT .8/.9 (`read_drift_file`). Returns (QTF, info)."""
    path = Path(path)
    if not path.exists():
        raise ValueError(f"{path}: no such file")
    if path.suffix == ".csv":
        if options:
            raise ValueError(
                f"{path}: a jaxtow CSV table takes no reader options, got {sorted(options)}"
            )
        return load_qtf(path), dict(file=str(path), format="jaxtow CSV")
    if path.suffix == ".nc":
        own = "jaxtow_qtf" in read_netcdf(path, "a drift table").attrs
        if own:
            if options:
                raise ValueError(
                    f"{path}: a jaxtow QTF file takes no reader options, got {sorted(options)}"
                )
            return load_qtf(path), dict(file=str(path), format="jaxtow NetCDF")
        allowed = {"symmetry", "symmetry_tol", "reference_point", "length"}
        bad = set(options) - allowed
        if bad:
            raise ValueError(f"{path}: options {sorted(bad)} do not apply to a Capytaine file")
        return read_capytaine_drift(path, **options), dict(
            file=str(path), format="Capytaine drift NetCDF", **options
        )
    return read_drift_file(path, **options)
