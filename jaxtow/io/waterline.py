"""The thesis's half-waterline text format (appendix C.1): `read_waterline` mirrors half a
waterline about the centreline into a `jaxtow.drift.Waterline`; `write_waterline` writes one
back."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..drift._waterline import GEOMETRY_TOL, Waterline, mirror_half, waterline


def read_waterline(
    path, *, draft: float, block_coefficient=None, name: str | None = None
) -> Waterline:
    """Read half a waterline from a text file and mirror it about the centreline (the thesis's
    input format, appendix C.1).

    One vertex per line, whitespace separated: ``x y [flare_deg [local_draft]]`` [m, m, °, m],
    from the bow on the centreline along one side to the stern on the centreline; the flare
    and local draft belong to the segment that starts at that vertex (ignored on the last
    line). ``#`` starts a comment.
    """
    rows = []
    for n, line in enumerate(Path(path).read_text().splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if line:
            try:
                rows.append([float(v) for v in line.split()])
            except ValueError:
                raise ValueError(
                    f"waterline file {path}, line {n}: expected numbers (x y [flare_deg "
                    f"[local_draft]]), got {line!r}"
                ) from None
    if len(rows) < 2:
        raise ValueError(f"waterline file {path}: needs at least two vertices")
    width = max(len(r) for r in rows)
    if min(len(r) for r in rows[:-1]) < width or width not in (2, 3, 4):
        raise ValueError(
            f"waterline file {path}: every line needs the same columns: x y [flare_deg [local_draft]]"
        )
    a = np.array([r + [np.nan] * (width - len(r)) for r in rows])
    flare = np.radians(a[:-1, 2]) if width >= 3 else 0.0
    local = a[:-1, 3] if width == 4 else None
    pts, fl, ld = mirror_half(a[:, :2], flare, local)
    return waterline(
        pts,
        draft=draft,
        flare=fl,
        local_draft=ld,
        block_coefficient=block_coefficient,
        name=name or Path(path).stem,
    )


def write_waterline(path, wl: Waterline) -> None:
    """Write the port half (y ≥ 0) of a symmetric waterline in `read_waterline`'s format."""
    p = np.asarray(wl.points)
    fl, ld = np.degrees(np.asarray(wl.flare)), np.asarray(wl.local_draft)
    n = p.shape[0]
    i0 = int(np.argmax(np.where(np.abs(p[:, 1]) < GEOMETRY_TOL * 1e3, p[:, 0], -np.inf)))
    lines = ["# x [m]  y [m]  flare [deg]  local_draft [m]  (half waterline, bow to stern)"]
    i = i0
    while True:
        lines.append(f"{p[i, 0]:.12g} {p[i, 1]:.12g} {fl[i]:.12g} {ld[i]:.12g}")
        i = (i + 1) % n
        if abs(p[i, 1]) < GEOMETRY_TOL * 1e3 and i != i0:
            lines.append(f"{p[i, 0]:.12g} {p[i, 1]:.12g}")
            break
    Path(path).write_text("\n".join(lines) + "\n")
