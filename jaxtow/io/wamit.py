"""Drift tables in and out: WAMIT mean drift (.8 momentum, .9 pressure integration) and
difference-frequency QTF (.12d) files, Capytaine drift output, jaxtow's own NetCDF/CSV.

WAMIT layouts (WAMIT User Manual, chapter 4, "mean drift force" and "second-order" output),
one record per line, an optional first header line (WAMIT 7 writes one):

    mean drift (.8/.9):   PER  BETA1  BETA2  I  MOD(F)  PHA(F)  Re(F)  Im(F)
    difference QTF (.12d): PER1 PER2 BETA1 BETA2 I MOD(F) PHA(F) Re(F) Im(F)

PER: wave period [s] (a non-positive value denotes ω = 0 or ∞ and is skipped); BETA1,
BETA2: wave headings [deg] (mean drift is the diagonal BETA1 = BETA2); I: mode (1 surge,
2 sway, 6 yaw; a .9 file also lists the second moment set I = −4, −5, −6 of the pressure
integration, chosen with ``moment_set``); values non-dimensional by ρ g A² L^k with k = 1
for forces (|I| = 1, 2, 3) and k = 2 for moments (|I| = 4, 5, 6), L = ULEN. Fortran ``D``
exponents are read.

Headings: WAMIT's (and Capytaine's) β is the direction the waves travel *to*,
counter-clockwise from +x (β = 180° is head seas on a bow at +x); jaxtow's is the direction
they come *from*, counter-clockwise from the bow (β = 0 head seas). So β_jaxtow = β_WAMIT −
180°: the usual WAMIT range 0–180° is jaxtow's −180° … 0°, one half of the circle.

What the readers do with a table as users have it (docs/io.md):

* **Half tables** of a port-starboard symmetric hull are completed to the full circle
  (``symmetry="auto"``) when the head- and following-sea sway and yaw are within
  `jaxtow.drift.SYMMETRY_TOL` of the table's scale; an asymmetric half table is refused
  with a message (``symmetry="none"`` keeps the half table, clamped outside its range and
  flagged by `QTF.in_table`).
* **Reference point** of the yaw moment: WAMIT and Capytaine give it about the file's
  origin; the tow model needs it about the CoG. ``reference_point="cog"`` (default) takes
  the CoG from the WAMIT listing (``.out``/``.out.gz``) or force file (``.frc``) next to the
  file, ``(x, y)`` [m] gives it, ``"origin"`` keeps the file's. N_ref = N_o − (x_r F_y −
  y_r F_x).
* **ULEN, ρ, g**: from the listing (``Length scale``, ``Gravity``) and ``.frc`` (``RHO``)
  next to the file where they are not given; otherwise 1 m, `jaxtow.RHO_SEA`, `jaxtow.G`,
  and the reader's ``info`` says which were assumed.
* **Errors** name the file, the line and the problem: a cut record, a duplicate, an
  unreadable line, a period missing a heading or a mode, a .12d file given as mean drift.
"""

from __future__ import annotations

import gzip
import math
import re
from pathlib import Path

import numpy as np
import xarray as xr

from .._units import RHO_SEA, G
from ..drift._qtf import QTF, SYMMETRY_TOL, FullQTF, symmetry_residual
from ._atomic import save_netcdf, write_file

_MODES = {1: 0, 2: 1, 6: 2}
_MEAN_COLUMNS = 8
_QTF_COLUMNS = 9
#: Symmetry options of the readers.
SYMMETRY_OPTIONS = ("auto", "none")


# --------------------------------------------------------------------------- helpers
def _positive(name, v):
    v = float(v)
    if not (math.isfinite(v) and v > 0):
        raise ValueError(f"parameter {name!r} must be a finite positive number, got {v!r}")
    return v


def _records(path, ncol: int | None = None):
    """Numeric records of a WAMIT numeric output file: (array (nrec, ncol), line numbers)."""
    path = Path(path)
    if not path.exists():
        raise ValueError(f"{path}: no such file")
    rows, lines, width = [], [], None
    first = True
    for k, line in enumerate(path.read_text().splitlines(), 1):
        parts = line.split()
        if not parts:
            continue
        try:
            vals = [float(re.sub(r"[dD]", "e", p)) for p in parts]
        except ValueError:
            if first:  # a header line (WAMIT 7: "WAMIT Numeric Output -- Filename ...")
                first = False
                continue
            raise ValueError(
                f"{path}, line {k}: not a WAMIT numeric record: {line.strip()!r}"
            ) from None
        first = False
        if width is None:
            width = len(vals)
            if ncol is not None and width != ncol:
                kind = {
                    _MEAN_COLUMNS: "a mean-drift file (.8/.9: PER BETA1 BETA2 I ...; "
                    "read it with read_wamit_drift)",
                    _QTF_COLUMNS: "a difference-frequency QTF file (.12d: PER1 PER2 BETA1 "
                    "BETA2 I ...; read it with read_wamit_qtf)",
                }.get(width, f"a file of {width} columns")
                raise ValueError(
                    f"{path}, line {k}: {width} columns where {ncol} are expected: this is {kind}"
                )
        elif len(vals) != width:
            raise ValueError(
                f"{path}, line {k}: record cut short or malformed ({len(vals)} of {width} fields)"
            )
        rows.append(vals)
        lines.append(k)
    if not rows:
        raise ValueError(f"{path}: no numeric records")
    return np.asarray(rows), np.asarray(lines)


def _listing(path):
    """The WAMIT listing (``.out`` or ``.out.gz``) and force file (``.frc``) next to a
    numeric output file: {'ulen', 'g', 'cog', 'rho'} where found, with 'files'."""
    path = Path(path)
    out: dict = {"files": []}
    for cand in (path.with_suffix(".out"), path.with_suffix(".out.gz")):
        if cand.exists():
            text = (
                gzip.decompress(cand.read_bytes()).decode(errors="replace")
                if cand.suffix == ".gz"
                else cand.read_text(errors="replace")
            )
            m = re.search(r"Gravity:\s*([-+0-9.Ee]+)\s+Length scale:\s*([-+0-9.Ee]+)", text)
            if m:
                out["g"], out["ulen"] = float(m.group(1)), float(m.group(2))
            m = re.search(r"Water density:\s*([-+0-9.Ee]+)", text)
            if m:
                out["rho"] = float(m.group(1))
            m = re.search(r"Center of Gravity\s*\(Xg,Yg,Zg\):([^\n]*)", text)
            if m:
                nums = m.group(1).split()
                # three numbers, or only Zg (force file form 1: the CoG on the z axis)
                out["cog"] = (float(nums[0]), float(nums[1])) if len(nums) >= 3 else (0.0, 0.0)
            out["files"].append(cand.name)
            break
    frc = path.with_suffix(".frc")
    if frc.exists():
        ln = [x.split() for x in frc.read_text(errors="replace").splitlines()]
        # force file form 2 (RHO; XCG YCG ZCG; IMASS; ...), told from form 1 (VCG; the
        # 3x3 radii of gyration) by the single IMASS on line 5
        try:
            if len(ln) > 4 and len(ln[4]) == 1 and len(ln[3]) >= 3:
                out.setdefault("rho", float(ln[2][0]))
                out.setdefault("cog", (float(ln[3][0]), float(ln[3][1])))
        except ValueError:
            pass
        out["files"].append(frc.name)
    return out


def _run_parameters(path, ulen, rho, g):
    lst = _listing(path)
    info: dict = {}
    for name, given, default in (("ulen", ulen, 1.0), ("rho", rho, RHO_SEA), ("g", g, G)):
        if given is not None:
            info[name] = (_positive(name, given), "given")
        elif name in lst:
            info[name] = (_positive(name, lst[name]), "from " + ", ".join(lst["files"]))
        else:
            info[name] = (default, "ASSUMED (not given, not in a WAMIT listing next to the file)")
    return info, lst


def _heading_deg(beta_wamit_deg):
    """jaxtow headings [deg] in [−180, 180) from travel-to headings, rounded to 1e-6 deg."""
    return np.round((np.asarray(beta_wamit_deg, float) % 360.0) - 180.0, 6)


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


def _shift_yaw(fx, fy, nz, ref):
    x, y = (float(v) for v in ref)
    return nz - (x * fy - y * fx)


def _reference(reference_point, listing):
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


# --------------------------------------------------------------------------- mean drift
def read_drift_file(
    path,
    *,
    ulen: float | None = None,
    rho: float | None = None,
    g: float | None = None,
    symmetry: str = "auto",
    symmetry_tol: float | None = None,
    reference_point="cog",
    moment_set: int = 6,
):
    """Read a WAMIT .8/.9 mean-drift file into a `QTF` (SI per ζa², jaxtow headings) and
    say how: returns (QTF, info) with ``info`` = {file, format, ulen, rho, g (each with
    where it came from), symmetry, reference_point, moment_set, skipped}. Options as in the
    module docstring; ``moment_set`` 6 or −6 (a .9 file's second set of moments)."""
    path = Path(path)
    if moment_set not in (6, -6):
        raise ValueError(f"parameter 'moment_set' must be 6 or -6, got {moment_set!r}")
    pars, listing = _run_parameters(path, ulen, rho, g)
    L, r, gg = pars["ulen"][0], pars["rho"][0], pars["g"][0]
    a, lines = _records(path, _MEAN_COLUMNS)
    skipped = {
        "zero_or_infinite_period": int(np.sum(a[:, 0] <= 0)),
        "cross_heading": int(np.sum(~np.isclose(a[:, 1], a[:, 2]))),
    }
    keep = (a[:, 0] > 0) & np.isclose(a[:, 1], a[:, 2])
    modes = {1: 0, 2: 1, moment_set: 2}
    have = set(a[keep, 3].astype(int))
    if moment_set not in have:
        raise ValueError(
            f"{path}: no records of mode I = {moment_set} (the file has {sorted(have)}; "
            "I = -6 is the second moment set of a .9 pressure-integration file)"
        )
    keep &= np.isin(a[:, 3], list(modes))
    a, lines = a[keep], lines[keep]
    omega = 2 * math.pi / a[:, 0]
    bdeg = _heading_deg(a[:, 1])
    ws, bs = np.unique(omega), np.unique(bdeg)
    vals = np.full((3, ws.size, bs.size), np.nan)
    where = np.zeros((3, ws.size, bs.size), int)
    raw = np.zeros((3, ws.size, bs.size))
    for w, b, bw, mode, re_, ln in zip(omega, bdeg, a[:, 1], a[:, 3].astype(int), a[:, 6], lines):
        c, i, j = modes[mode], np.searchsorted(ws, w), np.searchsorted(bs, b)
        k = 1 if abs(mode) <= 3 else 2
        if where[c, i, j]:
            prev = vals[c, i, j] / (r * gg * L**k)  # in the file's units
            same = abs(re_ - prev) <= 1e-9 * max(abs(re_), abs(prev)) + 1e-12
            if bw != raw[c, i, j] and same:  # the same heading twice, e.g. 0 and 360 deg
                continue
            raise ValueError(
                f"{path}, line {ln}: duplicate record (period {2 * math.pi / w:g} s, heading "
                f"{b + 180.0:g} deg, mode {mode}) of line {where[c, i, j]}"
            )
        where[c, i, j], raw[c, i, j] = ln, bw
        vals[c, i, j] = re_ * r * gg * L**k
    if np.isnan(vals).any():
        c, i, j = (int(v[0]) for v in np.nonzero(np.isnan(vals)))
        raise ValueError(
            f"{path}: incomplete table: period {2 * math.pi / ws[i]:g} s, WAMIT heading "
            f"{bs[j] + 180.0:g} deg has no mode {list(modes)[c]} record (every period needs "
            f"modes 1, 2, {moment_set} at every heading; is the file cut short? last record "
            f"on line {int(lines[-1])})"
        )
    ref, ref_note = _reference(reference_point, listing)
    fx, fy, nz = vals[0], vals[1], _shift_yaw(vals[0], vals[1], vals[2], ref)
    q, sym = complete_table(
        ws, bs, fx, fy, nz, symmetry=symmetry, tol=symmetry_tol, length=L, origin=str(path)
    )
    info = dict(
        file=str(path),
        format="WAMIT mean drift "
        + ("(.9 pressure integration)" if -6 in have or path.suffix == ".9" else "(.8 momentum)"),
        ulen=pars["ulen"],
        rho=pars["rho"],
        g=pars["g"],
        symmetry=sym,
        reference_point=(ref, ref_note),
        moment_set=moment_set,
        skipped=skipped,
    )
    return q, info


def read_wamit_drift(path, **options) -> QTF:
    """Read a WAMIT .8/.9 mean-drift file into a `QTF` (SI per ζa², jaxtow headings); the
    options of `read_drift_file` (ulen, rho, g, symmetry, symmetry_tol, reference_point,
    moment_set)."""
    return read_drift_file(path, **options)[0]


def _wamit_headings(q_beta):
    """Travel-to headings [deg] in [0, 360) of jaxtow headings, without the duplicate +180°
    column of a periodic table; and the column indices they come from."""
    deg = np.degrees(np.asarray(q_beta, float))
    cols = np.arange(deg.size)
    if deg.size > 1 and abs(deg[0] + 180.0) < 1e-9 and abs(deg[-1] - 180.0) < 1e-9:
        cols = cols[:-1]
    bw = np.round((deg[cols] + 180.0) % 360.0, 9)
    bw = np.where(bw >= 360.0, 0.0, bw)
    return bw, cols


def write_wamit_drift(
    q: QTF, path, *, ulen: float = 1.0, rho: float = RHO_SEA, g: float = G
) -> None:
    """Write a `QTF` in the WAMIT mean-drift layout (see module docstring): travel-to
    headings in [0°, 360°) (head seas 180°), the +180° column of a full-circle table once;
    `read_wamit_drift` returns the same grid."""
    ulen, rho, g = _positive("ulen", ulen), _positive("rho", rho), _positive("g", g)
    omega = np.asarray(q.omega)
    bw, cols = _wamit_headings(q.beta)
    vals = np.asarray(q.values)
    lines = []
    for i in np.argsort(-omega):  # WAMIT lists periods ascending
        per = 2 * math.pi / omega[i]
        for j, b in zip(cols, bw):
            for mode, c in _MODES.items():
                k = 1 if mode <= 3 else 2
                re_ = vals[c, i, j] / (rho * g * ulen**k)
                lines.append(
                    f"{per:.17e} {b:.17e} {b:.17e} {mode:d} {abs(re_):.17e} "
                    f"{0.0 if re_ >= 0 else 180.0:.1f} {re_:.17e} {0.0:.17e}"
                )
    write_file(path, "\n".join(lines) + "\n")


# --------------------------------------------------------------------------- full QTF
def read_wamit_qtf(
    path,
    *,
    ulen: float | None = None,
    rho: float | None = None,
    g: float | None = None,
    reference_point="cog",
):
    """Read a WAMIT difference-frequency QTF (.12d) into a `jaxtow.drift.FullQTF` (SI per
    ζa², jaxtow headings, unidirectional pairs BETA1 = BETA2). A file that lists one triangle
    (ω_i >= ω_j) is completed by T(ω_j, ω_i) = conj T(ω_i, ω_j). Returns (FullQTF, info)."""
    path = Path(path)
    pars, listing = _run_parameters(path, ulen, rho, g)
    L, r, gg = pars["ulen"][0], pars["rho"][0], pars["g"][0]
    a, lines = _records(path, _QTF_COLUMNS)
    keep = (
        (a[:, 0] > 0) & (a[:, 1] > 0) & np.isclose(a[:, 2], a[:, 3]) & np.isin(a[:, 4], [1, 2, 6])
    )
    skipped = int(np.sum((a[:, 0] > 0) & (a[:, 1] > 0) & ~np.isclose(a[:, 2], a[:, 3])))
    a, lines = a[keep], lines[keep]
    w1, w2 = 2 * math.pi / a[:, 0], 2 * math.pi / a[:, 1]
    bdeg = _heading_deg(a[:, 2])
    ws, bs = np.unique(np.concatenate([w1, w2])), np.unique(bdeg)
    n, nb = ws.size, bs.size
    vals = np.full((3, n, n, nb), np.nan + 0j)
    seen = np.zeros((3, n, n, nb), int)
    for x1, x2, b, mode, re_, im_, ln in zip(
        w1, w2, bdeg, a[:, 4].astype(int), a[:, 7], a[:, 8], lines
    ):
        c, i, j, kb = (
            _MODES[mode],
            np.searchsorted(ws, x1),
            np.searchsorted(ws, x2),
            np.searchsorted(bs, b),
        )
        if seen[c, i, j, kb]:
            raise ValueError(f"{path}, line {ln}: duplicate record of line {seen[c, i, j, kb]}")
        seen[c, i, j, kb] = ln
        k = 1 if mode <= 3 else 2
        vals[c, i, j, kb] = (re_ + 1j * im_) * r * gg * L**k
    miss = np.isnan(np.real(vals))
    vals = np.where(miss, np.conj(np.swapaxes(vals, 1, 2)), vals)
    if np.isnan(np.real(vals)).any():
        c, i, j, kb = (int(v[0]) for v in np.nonzero(np.isnan(np.real(vals))))
        raise ValueError(
            f"{path}: incomplete QTF: no mode {list(_MODES)[c]} record for the periods "
            f"{2 * math.pi / ws[i]:g}, {2 * math.pi / ws[j]:g} s at WAMIT heading "
            f"{bs[kb] + 180.0:g} deg (or its conjugate pair)"
        )
    ref, ref_note = _reference(reference_point, listing)
    vals[2] = _shift_yaw(vals[0], vals[1], vals[2], ref)
    info = dict(
        file=str(path),
        format="WAMIT difference-frequency QTF (.12d)",
        ulen=pars["ulen"],
        rho=pars["rho"],
        g=pars["g"],
        reference_point=(ref, ref_note),
        skipped={"bidirectional_pairs": skipped},
    )
    return FullQTF(omega=ws, beta=np.radians(bs), values=vals), info


def write_wamit_qtf(
    q: FullQTF, path, *, ulen: float = 1.0, rho: float = RHO_SEA, g: float = G
) -> None:
    """Write a `jaxtow.drift.FullQTF` in the WAMIT .12d layout (both triangles)."""
    ulen, rho, g = _positive("ulen", ulen), _positive("rho", rho), _positive("g", g)
    w = np.asarray(q.omega)
    bw, cols = _wamit_headings(q.beta)
    v = np.asarray(q.values)
    lines = []
    for i in np.argsort(-w):
        for j in np.argsort(-w):
            for kb, b in zip(cols, bw):
                for mode, c in _MODES.items():
                    k = 1 if mode <= 3 else 2
                    z = v[c, i, j, kb] / (rho * g * ulen**k)
                    lines.append(
                        f"{2 * math.pi / w[i]:.17e} {2 * math.pi / w[j]:.17e} {b:.17e} {b:.17e} "
                        f"{mode:d} {abs(z):.17e} {math.degrees(np.angle(z)):.17e} "
                        f"{z.real:.17e} {z.imag:.17e}"
                    )
    write_file(path, "\n".join(lines) + "\n")


# --------------------------------------------------------------------------- jaxtow formats
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
        t = np.atleast_2d(np.loadtxt(path, delimiter=","))
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


# --------------------------------------------------------------------------- Capytaine
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
    bdeg = _heading_deg(np.degrees(wd))
    order_w, order_b = np.argsort(w), np.argsort(bdeg)
    vx, vy, vn = (v[order_w][:, order_b] for v in (vx, vy, vn))
    ref, _ = _reference(reference_point, {})
    vn = _shift_yaw(vx, vy, vn, ref)
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
    ds = xr.load_dataset(path)
    try:
        return qtf_from_capytaine(ds, **options)
    except ValueError as e:
        raise ValueError(f"{path}: {e}") from None


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
        with xr.open_dataset(path) as ds:
            own = "jaxtow_qtf" in ds.attrs
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
