"""WAMIT mean-drift files (.8 momentum / control-surface, .9 pressure integration).

Layout (WAMIT User Manual, section 4: "mean drift force" output), one record per line:

    PER  BETA1  BETA2  I  MOD(F)  PHA(F)  Re(F)  Im(F)

PER: wave period [s] (a non-positive value denotes ω = 0 or ∞ and is skipped); BETA1,
BETA2: wave headings [deg] (mean drift is the diagonal BETA1 = BETA2); I: mode (1 surge,
2 sway, 6 yaw); values non-dimensional by ρ g A² L^k with k = 1 for forces (I = 1, 2, 3) and
k = 2 for moments (I = 4, 5, 6), L = ULEN.

Headings: WAMIT's β is the direction the waves travel *to*, counter-clockwise from +x
(β = 180° is head seas on a bow at +x); jaxtow's is the direction they come *from*,
counter-clockwise from the bow (β = 0 head seas). So β_jaxtow = β_WAMIT − 180°, wrapped
to (−180°, 180°].
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from .._units import RHO_SEA, G
from ..drift._qtf import QTF

_MODES = {1: 0, 2: 1, 6: 2}


def _wrap_deg(b):
    return (np.asarray(b) + 180.0) % 360.0 - 180.0


def read_wamit_drift(path, *, ulen: float = 1.0, rho: float = RHO_SEA, g: float = G) -> QTF:
    """Read a WAMIT .8/.9 mean-drift file into a `QTF` (SI per ζa², jaxtow headings).

    ``ulen``: WAMIT's length scale ULEN [m] used in the normalisation.
    """
    rows = []
    for line in Path(path).read_text().splitlines():
        parts = line.split()
        if len(parts) < 8:
            continue
        try:
            rows.append([float(p) for p in parts[:8]])
        except ValueError:
            continue  # header or comment
    if not rows:
        raise ValueError(f"no mean-drift records in {path}")
    a = np.array(rows)
    a = a[(a[:, 0] > 0) & np.isclose(a[:, 1], a[:, 2]) & np.isin(a[:, 3], list(_MODES))]
    omega = 2 * math.pi / a[:, 0]
    beta = np.radians(_wrap_deg(a[:, 1] - 180.0))
    ws, bs = np.unique(omega), np.unique(np.round(beta, 12))
    vals = np.full((3, ws.size, bs.size), np.nan)
    for w, b, mode, re in zip(omega, np.round(beta, 12), a[:, 3].astype(int), a[:, 6]):
        k = 1 if mode <= 3 else 2
        vals[_MODES[mode], np.searchsorted(ws, w), np.searchsorted(bs, b)] = re * rho * g * ulen**k
    if np.isnan(vals).any():
        raise ValueError(
            f"{path}: the table is incomplete (every period needs modes 1, 2, 6 at every heading)"
        )
    return QTF(omega=ws, beta=bs, fx=vals[0], fy=vals[1], nz=vals[2])


def write_wamit_drift(
    q: QTF, path, *, ulen: float = 1.0, rho: float = RHO_SEA, g: float = G
) -> None:
    """Write a `QTF` in the WAMIT mean-drift layout (see module docstring)."""
    omega = np.asarray(q.omega)
    beta_w = _wrap_deg(np.degrees(np.asarray(q.beta)) + 180.0)
    vals = np.asarray(q.values)
    lines = []
    for i in np.argsort(-omega):  # WAMIT lists periods ascending
        per = 2 * math.pi / omega[i]
        for j, bw in enumerate(beta_w):
            for mode, c in _MODES.items():
                k = 1 if mode <= 3 else 2
                re = vals[c, i, j] / (rho * g * ulen**k)
                lines.append(
                    f"{per:.17e} {bw:.17e} {bw:.17e} {mode:d} {abs(re):.17e} "
                    f"{0.0 if re >= 0 else 180.0:.1f} {re:.17e} {0.0:.17e}"
                )
    Path(path).write_text("\n".join(lines) + "\n")


#: The sectional drift moments a QTF dataset may carry (name, units, long name).
SECTIONAL_VARIABLES = (
    ("mx1", "N m m-2", "first moment of the sectional surge drift, M_x,1, per zeta_a^2"),
    ("my1", "N m m-2", "first moment of the sectional sway drift, M_y,1, per zeta_a^2"),
    ("my2", "N m2 m-2", "second moment of the sectional sway drift, M_y,2, per zeta_a^2"),
)


def qtf_to_dataset(q: QTF, attrs: dict | None = None):
    """A `QTF` as an xarray Dataset with units (jaxtow's own NetCDF format); ``attrs``
    (provenance: mesh, solver, versions) are stored with it."""
    import xarray as xr

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
        qtf_to_dataset(q, attrs).to_netcdf(path)


def load_qtf(path) -> QTF:
    path = Path(path)
    if path.suffix == ".csv":
        t = np.loadtxt(path, delimiter=",")
        ws, bs = np.unique(t[:, 0]), np.unique(t[:, 1])
        shape = (ws.size, bs.size)
        return QTF(
            omega=ws,
            beta=bs,
            fx=t[:, 2].reshape(shape),
            fy=t[:, 3].reshape(shape),
            nz=t[:, 4].reshape(shape),
        )
    import xarray as xr

    ds = xr.load_dataset(path)
    names = [n for n, _, _ in SECTIONAL_VARIABLES]
    sec = [ds[n].values for n in names] if all(n in ds for n in names) else None
    return QTF(
        omega=ds.omega.values,
        beta=ds.beta.values,
        fx=ds.fx.values,
        fy=ds.fy.values,
        nz=ds.nz.values,
        sectional=sec,
    )


def qtf_from_capytaine(fx, fy, nz) -> QTF:
    """QTF from Capytaine mean-drift results (e.g. `capytaine.far_field_mean_drift_force`).

    Each argument is an xarray DataArray per unit wave amplitude with dims ``omega`` and
    ``wave_direction`` (optionally a second heading dim, of which the diagonal is taken,
    and complex values, of which the real part is taken: see docs/bem.md).
    Capytaine's ``wave_direction`` is the direction the waves travel *to*, counter-clockwise
    from +x (π = head seas on a bow at +x), so β_jaxtow = wave_direction − π, wrapped.
    """
    arrays = []
    for name, da in (("fx", fx), ("fy", fy), ("nz", nz)):
        extra = [d for d in da.dims if d not in ("omega", "wave_direction")]
        if len(extra) == 1 and da.sizes[extra[0]] == da.sizes["wave_direction"]:
            vals = np.diagonal(
                np.asarray(da.transpose("omega", "wave_direction", extra[0])), axis1=1, axis2=2
            )
        elif not extra:
            vals = np.asarray(da.transpose("omega", "wave_direction"))
        else:
            raise ValueError(
                f"{name}: expected dims (omega, wave_direction[, second heading]), got {da.dims}"
            )
        arrays.append(np.real(vals))
    omega = np.asarray(fx["omega"].values, float)
    beta = (np.asarray(fx["wave_direction"].values, float) - math.pi + math.pi) % (
        2 * math.pi
    ) - math.pi
    order_w, order_b = np.argsort(omega), np.argsort(beta)
    vals = [a[order_w][:, order_b] for a in arrays]
    return QTF(omega=omega[order_w], beta=beta[order_b], fx=vals[0], fy=vals[1], nz=vals[2])
