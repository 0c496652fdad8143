"""Cubic Hermite interpolation: the one interpolant of jaxtow's tables.

Every tabulated input (mean-drift QTFs over (ω, β), wind/current coefficient tables over the
relative angle, tug pull curves over speed) is interpolated by piecewise cubic Hermite
curves whose node slopes come from the three-point (quadratic-exact) difference formula.
The curves are C¹, differentiable in the query point and in the table values, and at an
interior node their derivative equals the three-point difference of the table (see
``docs/model.md``, "Interpolation").

The interpolant is linear in the table values: at a query point ``xq`` in the interval
``[x_i, x_{i+1}]`` it is ``Σ_k w_k y[rows_k]`` over the four nodes ``rows = (i−1, i, i+1,
i+2)`` (wrapped or clamped at the ends), and each weight is a cubic polynomial in
``xq − x_i`` whose coefficients depend on the grid alone. `interval_tables` computes those
coefficients for every interval of a grid once; `HermiteAxis` holds them with the grid (a
table's axis, built when the table is), and an evaluation is then a cell lookup, one small
gather and a contraction: no whole-table array is formed, and the traced and compiled
program of an evaluation is a few operations whatever the size of the table (the wave
kernels evaluate a drift table at a dozen places). `hermite` is the same for a grid that is
only known under tracing (it builds the coefficients in the traced program).

End rules (``ends``), the slope at the first and last node:

* ``"one_sided"``: the two-point difference into the table;
* ``"periodic"``: ``x[0]`` and ``x[-1]`` are one point (equal values); its slope is the
  three-point slope across the seam;
* ``"flat"``: zero (a C¹ continuation by a constant beyond the ends).
"""

from __future__ import annotations

import equinox as eqx
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Float, Int

ENDS = ("one_sided", "periodic", "flat")


def cell_index(x: Float[Array, " n"], xq):
    """The interval ``i`` (0 … n − 2) with ``x[i] <= xq < x[i + 1]`` (clamped at both ends)
    of an ascending grid. By comparison with every node: for the short grids of jaxtow's
    tables this costs a few vector operations, where `jax.numpy.searchsorted`'s default
    traces a loop that dominated the tracing time of the sweep kernels."""
    i = jnp.searchsorted(x, xq, side="right", method="compare_all") - 1
    return jnp.clip(i, 0, x.shape[0] - 2)


def interval_tables(x: Float[Array, " n"], ends: str = "one_sided"):
    """Per-interval rows and weight polynomials of the cubic Hermite interpolant with
    three-point node slopes on the ascending grid ``x``: ``rows`` (n − 1, 4) node indices and
    ``poly`` (n − 1, 4, 4) such that on interval ``i``, at ``d = xq − x_i``, the interpolant of
    a table ``y`` is ``Σ_k y[rows[i, k]] Σ_p poly[i, k, p] d^p``. ``ends``: one of `ENDS`.

    On the interval of width ``h``, at ``t = d/h``, with the Hermite basis H00, H10, H01, H11
    and the node slopes ``m_k = a_k y_{k−1} + b_k y_k + c_k y_{k+1}`` (three-point formula;
    the end rule at the ends),

        y(xq) = H00 y_i + H01 y_{i+1} + h H10 m_i + h H11 m_{i+1},

    which collects onto the four rows ``(k⁻(i), i, i+1, k⁺(i+1))`` (k± a node's neighbours,
    wrapped across the seam for ``"periodic"``). With a NumPy ``x`` the tables are NumPy
    arrays (a table's axis, built eagerly); otherwise JAX arrays (inside a traced program)."""
    if ends not in ENDS:
        raise ValueError(f"parameter 'ends' must be one of {ENDS}, got {ends!r}")
    xp = np if isinstance(x, np.ndarray) else jnp  # NumPy for a table's concrete grid
    n = x.shape[0]
    k = xp.arange(n)
    first, last = k == 0, k == n - 1
    end = first | last
    if ends == "periodic":  # the end nodes are one point: neighbours across the seam
        km, kp = xp.where(end, n - 2, k - 1), xp.where(end, 1, k + 1)
        h0 = xp.where(end, x[n - 1] - x[n - 2], x - x[km])
        h1 = xp.where(end, x[1] - x[0], x[kp] - x)
    else:
        km, kp = xp.maximum(k - 1, 0), xp.minimum(k + 1, n - 1)
        h0 = xp.where(first, 1.0, x - x[km])
        h1 = xp.where(last, 1.0, x[kp] - x)
    d = h0 * h1 * (h0 + h1)
    a, b, c = -(h1**2) / d, (h1**2 - h0**2) / d, h0**2 / d  # three-point slope coefficients
    zero = xp.zeros_like(a)
    if ends == "one_sided":  # (y1 − y0)/h at the first node, (y_n − y_{n−1})/h at the last
        a = xp.where(first, zero, xp.where(last, -1.0 / h0, a))
        b = xp.where(first, -1.0 / h1, xp.where(last, 1.0 / h0, b))
        c = xp.where(first, 1.0 / h1, xp.where(last, zero, c))
    elif ends == "flat":
        a, b, c = (xp.where(end, zero, v) for v in (a, b, c))
    h = xp.diff(x)[:, None]
    # coefficients of 1, t, t², t³
    h00, h01 = xp.array([1.0, 0.0, -3.0, 2.0]), xp.array([0.0, 0.0, 3.0, -2.0])
    g0, g1 = h * xp.array([0.0, 1.0, -2.0, 1.0]), h * xp.array([0.0, 0.0, -1.0, 1.0])
    a0, b0, c0 = (v[:-1, None] for v in (a, b, c))  # node i of interval i
    a1, b1, c1 = (v[1:, None] for v in (a, b, c))  # node i + 1
    poly = xp.stack([g0 * a0, h00 + g0 * b0 + g1 * a1, h01 + g0 * c0 + g1 * b1, g1 * c1], axis=1)
    poly = poly / h[:, None] ** xp.arange(4)  # powers of t = d/h -> powers of d
    i = k[:-1]
    rows = xp.stack([km[:-1], i, i + 1, kp[1:]], axis=1)
    return rows, poly


def _pack(x, rows, poly):
    """Per interval, everything an evaluation reads: [x_i, the 4 rows (as floats, exact),
    the 4 × 4 weight polynomial], so that a lookup is one gather."""
    xp = np if isinstance(x, np.ndarray) else jnp
    n = x.shape[0]
    return xp.concatenate([x[:-1, None], rows.astype(x.dtype), poly.reshape(n - 1, 16)], axis=1)


def _lookup(x, cells, xq, uniform_from=None):
    xq = jnp.clip(xq, x[0], x[-1])
    n = x.shape[0]
    if uniform_from is None:
        i = cell_index(x, xq)
    else:  # x[s:] uniform: the cell by division (no search; fuses with its consumers)
        s = uniform_from
        k = s + jnp.floor((xq - x[s]) / (x[s + 1] - x[s])).astype(jnp.int32)
        i = jnp.clip(k, 0, n - 2) if s == 0 else jnp.where(xq < x[1], 0, jnp.clip(k, 1, n - 2))
    c = cells[i]
    d = xq - c[0]
    p = c[5:].reshape(4, 4)  # (4 rows, 4 powers); Horner in d, elementwise (no small dot)
    return c[1:5].astype(jnp.int32), p[:, 0] + d * (p[:, 1] + d * (p[:, 2] + d * p[:, 3]))


def _uniform_from(x: np.ndarray) -> int | None:
    """0 when the grid is uniform, 1 when it is uniform after its first node (a table with a
    virtual node at 0), else None (relative tolerance 1e-9 on the spacing)."""
    for s in (0, 1):
        h = np.diff(x[s:])
        if h.size >= 1 and np.all(np.abs(h - h[0]) <= 1e-9 * h[0]):
            return s
    return None


class HermiteAxis(eqx.Module):
    """One axis of a table: the ascending grid ``x`` with its `interval_tables` for the end
    rule ``ends``, built once (from a concrete grid) when the table is; a uniform grid (or
    one uniform after its first node) finds the cell by division instead of a search.
    ``weights(xq)`` gives the rows and weights at ``xq`` (clamped to [x0, xn]);
    ``axis(y, xq)`` interpolates along the last axis of ``y``. The grid is fixed at
    construction: build a new axis (a new table) for another grid."""

    x: Float[Array, " n"]
    cells: Float[Array, "n1 21"]  # per interval: x_i, the 4 rows, the 4 × 4 polynomial
    ends: str = eqx.field(static=True)
    uniform_from: int | None = eqx.field(static=True)

    def __init__(self, x, ends: str = "one_sided"):
        xa = np.asarray(x, float)
        if xa.ndim != 1 or xa.size < 2 or np.any(np.diff(xa) <= 0):
            raise ValueError("parameter 'x' must be a 1-D ascending grid of at least 2 nodes")
        self.cells = jnp.asarray(_pack(xa, *interval_tables(xa, ends)))
        self.x, self.ends, self.uniform_from = jnp.asarray(xa), ends, _uniform_from(xa)

    def weights(self, xq) -> tuple[Int[Array, "4"], Float[Array, "4"]]:
        return _lookup(self.x, self.cells, xq, self.uniform_from)

    def __call__(self, y: Float[Array, "... n"], xq) -> Float[Array, "..."]:
        rows, w = self.weights(xq)
        return y[..., rows] @ w


def hermite(x: Float[Array, " n"], y: Float[Array, "... n"], xq, ends: str = "one_sided"):
    """Cubic Hermite interpolation with three-point node slopes along the last axis of ``y``
    at scalar ``xq`` (clamped to [x0, xn]); ``ends``: one of `ENDS`. For a grid known only
    under tracing; a table with a fixed grid holds a `HermiteAxis` instead."""
    rows, w = _lookup(x, _pack(x, *interval_tables(x, ends)), xq)
    return y[..., rows] @ w
