"""A hull's offsets table (CSV) for strip theory: `read_offsets` reads it into a
`jaxtow.strip.Hull`."""

from __future__ import annotations

import csv
from pathlib import Path

import jax.numpy as jnp
import numpy as np

from ..strip import Hull, resample_contour

__all__ = ["read_offsets"]


def read_offsets(path, *, n_points: int = 12) -> Hull:
    """A hull from an offsets table (CSV): the first row is ``x`` and the waterline heights z
    [m] (0 at the still waterline, negative below; they must include 0); each further row is
    a station, its x [m] from midships (+ forward) and the half-breadths [m] at those
    waterlines. Each station's contour through those points, closed to the centreline at
    its keel, is resampled to ``n_points`` offsets along its arc length
    (`jaxtow.strip.resample_contour`). Stations whose breadth at the waterline is zero are
    left out (they carry no section); strips follow the stations' spacing (half-way to each
    neighbour). The hull ends in a transom when the first (aftmost) station of the file has
    breadth at the waterline and depth below it. Errors name the file and the row."""
    path = Path(path)
    with path.open(newline="") as fh:
        rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
    if len(rows) < 3:
        raise ValueError(f"offsets file {path}: needs a header row and at least two stations")
    ragged = [i + 2 for i, r in enumerate(rows[1:]) if len(r) != len(rows[0])]
    if ragged:
        raise ValueError(
            f"offsets file {path}: each station needs x and {len(rows[0]) - 1} half-breadths "
            f"(row {ragged[0]} of the table has {len(rows[ragged[0] - 1])} values)"
        )
    table = []
    for i, r in enumerate(rows):
        try:
            table.append([float(v) for v in (r[1:] if i == 0 else r)])
        except ValueError:
            raise ValueError(
                f"offsets file {path}: row {i + 1} of the table is not all numbers: {r!r}"
            ) from None
    zs, table = np.array(table[0]), np.array(table[1:])
    if not np.any(zs == 0.0) or np.any(zs > 0):
        raise ValueError(
            f"offsets file {path}: waterline heights must include 0 and be <= 0 (z up from the "
            "waterline; are they given positive downwards?)"
        )
    order = np.argsort(-zs)
    zs, half = zs[order], table[:, 1:][:, order]
    x_all = table[:, 0]
    if np.any(np.diff(x_all) <= 0):
        raise ValueError(f"offsets file {path}: station x must increase down the file")
    if np.any(half < 0) or not np.all(np.isfinite(half)):
        raise ValueError(f"offsets file {path}: half-breadths must be finite and >= 0")
    edges = np.r_[x_all[0], 0.5 * (x_all[1:] + x_all[:-1]), x_all[-1]]
    dx_all = np.diff(edges)
    keep = half[:, 0] > 0
    sections = [resample_contour(h, zs, n_points) for h in half[keep]]
    ys = np.array([c[0] for c in sections])
    zz = np.array([c[1] for c in sections])
    return Hull(
        jnp.asarray(x_all[keep]),
        jnp.asarray(dx_all[keep]),
        jnp.asarray(ys),
        jnp.asarray(zz),
        path.stem,
        bool(half[0, 0] > 0 and np.any(half[0, 1:] > 0)),
    )
