"""What every drift-table reader shares: a half table of a symmetric hull completed to the
full circle (`complete_table`), the headings of the codes that give the direction waves travel
to (WAMIT, Capytaine) turned into jaxtow's, the yaw moment moved to another reference point."""

from __future__ import annotations

import math

import numpy as np

from ..drift._qtf import QTF, SYMMETRY_TOL, symmetry_residual

#: Symmetry options of the readers.
SYMMETRY_OPTIONS = ("auto", "none")


def positive_number(name, v):
    v = float(v)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"parameter {name!r} must be a finite positive number, got {v!r}")
    return v


def complete_table(
    omega,
    beta_deg,
    fx,
    fy,
    nz,
    *,
    symmetry: str = "auto",
    tol: float | None = None,
    length: float = 1.0,
    origin: str = "the file",
):
    """A `QTF` from (nω, nβ) arrays on jaxtow headings ``beta_deg`` in [−180°, 180°):

    * the full circle (the last heading within a step of +180°): the −180° column is
      repeated at +180° (periodic);
    * one half ([−180°, 0°] or [0°, 180°]) with ``symmetry="auto"``: completed by
      port-starboard symmetry if `jaxtow.drift.symmetry_residual` <= ``tol``
      (default `SYMMETRY_TOL`), refused otherwise;
    * anything else, or ``symmetry="none"``: the table as it is (clamped outside its range).

    Returns (QTF, what was done)."""
    if symmetry not in SYMMETRY_OPTIONS:
        raise ValueError(
            f"parameter 'symmetry' must be one of {SYMMETRY_OPTIONS}, got {symmetry!r}"
        )
    tol = SYMMETRY_TOL if tol is None else float(tol)
    w = np.asarray(omega, float)
    b = np.asarray(beta_deg, float)
    fx, fy, nz = (np.asarray(v, float) for v in (fx, fy, nz))
    inner = b[(b > -180.0) & (b < 180.0) & (b != 0.0)]
    step = float(np.max(np.diff(b))) if b.size > 1 else 360.0
    if b[0] == -180.0 and b.size > 2 and 180.0 - b[-1] <= step + 1e-9 and np.any(inner > 0):
        cat = lambda v: np.concatenate([v, v[:, :1]], axis=1)  # noqa: E731
        q = QTF(omega=w, beta=np.radians(np.append(b, 180.0)), fx=cat(fx), fy=cat(fy), nz=cat(nz))
        return q, "full heading circle"
    half_neg = bool(np.all(b <= 0.0)) and b[-1] == 0.0 and b[0] == -180.0
    half_pos = bool(np.all((b >= 0.0) | (b == -180.0))) and 0.0 in b
    if symmetry == "auto" and (half_neg or half_pos):
        res = symmetry_residual(np.radians(b), fx, fy, nz, length=length)
        rng = "-180..0" if half_neg else "0..180"
        if not res <= tol:
            raise ValueError(
                f"{origin}: the table covers half the heading circle (jaxtow beta {rng} deg) but "
                f"the hull is not port-starboard symmetric: head/following-sea sway or yaw is "
                f"{res:.2e} of the table's scale (tolerance {tol:.0e}). Give the full circle, "
                "or pass symmetry='none' to keep the half table (clamped outside it)"
            )
        if half_neg:  # F(β) for β = −b' >= 0: Fx even, Fy and Nz odd
            order = np.argsort(-b)
            bp = -b[order]
            fx, fy, nz = fx[:, order], -fy[:, order], -nz[:, order]
        else:
            keep = b >= 0.0
            bp = np.where(b == -180.0, 180.0, b)[keep]
            order = np.argsort(bp)
            bp = bp[order]
            fx, fy, nz = (v[:, keep][:, order] for v in (fx, fy, nz))
        q = QTF.symmetric(omega=w, beta=np.radians(bp), fx=fx, fy=fy, nz=nz, tol=tol, length=length)
        return q, f"completed by port-starboard symmetry from beta {rng} deg (residual {res:.1e})"
    return (
        QTF(omega=w, beta=np.radians(b), fx=fx, fy=fy, nz=nz),
        "partial heading range, clamped outside it (in_table reports it)",
    )


def shift_yaw(fx, fy, nz, ref):
    x, y = (float(v) for v in ref)
    return nz - (x * fy - y * fx)


def heading_deg(beta_wamit_deg):
    """jaxtow headings [deg] from travel-to headings, rounded to 1e-6 deg: in [−180, 180),
    except that a following-sea column of a table on the positive side (0° … 180°, which a
    writer puts at travel-to 0°) reads as +180°, next to the headings it continues, not as
    −180° across the gap; so writing a table and reading it back returns its grid."""
    deg = np.round((np.asarray(beta_wamit_deg, float) % 360.0) - 180.0, 6)
    others = np.unique(deg[deg != -180.0])
    if others.size and (deg == -180.0).any() and others[0] + 180.0 > 180.0 - others[-1]:
        deg = np.where(deg == -180.0, 180.0, deg)
    return deg


def reference_point_of(reference_point, listing):
    if isinstance(reference_point, str):
        if reference_point == "origin":
            return (0.0, 0.0), "the file's origin"
        if reference_point == "cog":
            if "cog" in listing:
                return tuple(listing["cog"]), "the CoG from " + ", ".join(listing["files"])
            return (0.0, 0.0), (
                "the file's origin (reference_point='cog' but no CoG next to the file: "
                "pass reference_point=(x, y))"
            )
        raise ValueError(
            "parameter 'reference_point' must be 'cog', 'origin' or (x, y) [m], got "
            f"{reference_point!r}"
        )
    try:
        x, y = (float(v) for v in reference_point)
    except (TypeError, ValueError):
        raise ValueError(
            "parameter 'reference_point' must be 'cog', 'origin' or (x, y) [m], got "
            f"{reference_point!r}"
        ) from None
    if not (math.isfinite(x) and math.isfinite(y)):
        raise ValueError(f"parameter 'reference_point' must be finite, got {reference_point!r}")
    return (x, y), f"({x:g}, {y:g}) m given"
