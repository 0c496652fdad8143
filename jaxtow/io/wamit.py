"""WAMIT drift files in and out: mean drift (.8 momentum, .9 pressure integration) and
difference-frequency QTF (.12d) files.

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

from .._units import RHO_SEA, G
from ..drift._qtf import QTF, FullQTF
from ._atomic import write_file
from ._tables import complete_table, heading_deg, positive_number, reference_point_of, shift_yaw

_MODES = {1: 0, 2: 1, 6: 2}
_MEAN_COLUMNS = 8
_QTF_COLUMNS = 9


def _text(path: Path) -> str:
    """The text of a numeric output file; a binary file is refused by name."""
    data = path.read_bytes()
    try:
        if b"\x00" in data[:4096]:
            raise UnicodeDecodeError("ascii", data, 0, 1, "NUL byte")
        return data.decode()
    except UnicodeDecodeError:
        raise ValueError(
            f"{path}: not a text file (a WAMIT numeric output file .1/.3/.8/.9/.12d is text; "
            "is this a binary or NetCDF file?)"
        ) from None


def _records(path, ncol: int | None = None):
    """Numeric records of a WAMIT numeric output file: (array (nrec, ncol), line numbers)."""
    path = Path(path)
    if not path.exists():
        raise ValueError(f"{path}: no such file")
    rows, lines, width = [], [], None
    first = True
    for k, line in enumerate(_text(path).splitlines(), 1):
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
        if not all(math.isfinite(x) for x in vals):
            raise ValueError(
                f"{path}, line {k}: a non-finite number in a WAMIT record ({line.strip()!r}); "
                "WAMIT writes finite values, so the file is damaged or was not written by WAMIT"
            )
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
            info[name] = (positive_number(name, given), "given")
        elif name in lst:
            info[name] = (positive_number(name, lst[name]), "from " + ", ".join(lst["files"]))
        else:
            info[name] = (default, "ASSUMED (not given, not in a WAMIT listing next to the file)")
    return info, lst


# --------------------------------------------------------------------------- mean drift
def _mean_table(path, a, lines, modes: dict, moment_set: int, r: float, gg: float, L: float):
    """(ω, WAMIT heading − 180° [deg], values (3, ω, β) in SI) of the mean-drift records
    ``a`` (columns of `_MEAN_COLUMNS`, on file ``lines``): a heading given twice (0 and
    360 deg) with equal values is one; any other duplicate or a missing record is an error
    naming the line."""
    omega = 2 * math.pi / a[:, 0]
    bdeg = heading_deg(a[:, 1])
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
    return ws, bs, vals


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
    ws, bs, vals = _mean_table(path, a, lines, modes, moment_set, r, gg, L)
    ref, ref_note = reference_point_of(reference_point, listing)
    fx, fy, nz = vals[0], vals[1], shift_yaw(vals[0], vals[1], vals[2], ref)
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
    ulen, rho, g = (
        positive_number("ulen", ulen),
        positive_number("rho", rho),
        positive_number("g", g),
    )
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
    bdeg = heading_deg(a[:, 2])
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
    ref, ref_note = reference_point_of(reference_point, listing)
    vals[2] = shift_yaw(vals[0], vals[1], vals[2], ref)
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
    ulen, rho, g = (
        positive_number("ulen", ulen),
        positive_number("rho", rho),
        positive_number("g", g),
    )
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
