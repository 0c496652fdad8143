"""Cubic Hermite interpolation: the one interpolant of jaxtow's tables.

Every tabulated input (mean-drift QTFs over (ω, β), wind/current coefficient tables over the
relative angle, tug pull curves over speed) is interpolated by piecewise cubic Hermite
curves whose node slopes come from the three-point (quadratic-exact) difference formula.
The curves are C¹, differentiable in the query point and in the table values, and at an
interior node their derivative equals the three-point difference of the table (see
``docs/model.md``, "Interpolation").

* `node_slope`: the three-point slope at a node from its two neighbours;
* `hermite_cell`: the cubic on one interval from its end values and slopes;
* `three_point_slopes`: all node slopes of a table (optionally periodic);
* `hermite`: interpolation along the last axis of a table with given node slopes;
* `hermite_local`: the same with three-point slopes and zero slope at both end nodes,
  touching only the four table rows an interval needs (used inside every equilibrium scan).
"""

from __future__ import annotations

from collections.abc import Callable

import jax.numpy as jnp
from jaxtyping import Array, Float


def node_slope(h0, h1, ym, yk, yp):
    """dy/dx at a node with left spacing ``h0``, right spacing ``h1`` and values ``ym``,
    ``yk``, ``yp`` at the left neighbour, the node and the right neighbour (exact for
    quadratics on non-uniform grids)."""
    return (h0**2 * yp - h1**2 * ym + (h1**2 - h0**2) * yk) / (h0 * h1 * (h0 + h1))


def hermite_cell(y0, y1, m0, m1, h, t):
    """The cubic Hermite curve on one interval of width ``h`` at the local coordinate
    ``t`` ∈ [0, 1], from the end values ``y0``, ``y1`` and end slopes ``m0``, ``m1``."""
    t2, t3 = t * t, t * t * t
    return (
        (2 * t3 - 3 * t2 + 1) * y0
        + (t3 - 2 * t2 + t) * h * m0
        + (-2 * t3 + 3 * t2) * y1
        + (t3 - t2) * h * m1
    )


def three_point_slopes(x: Float[Array, " n"], y: Float[Array, "... n"], *, periodic: bool = False):
    """dy/dx at the nodes along the last axis (`node_slope` inside; one-sided differences at
    the ends, or the periodic three-point slope when ``x[0]`` and ``x[-1]`` are one point)."""
    h = jnp.diff(x)
    mid = node_slope(h[:-1], h[1:], y[..., :-2], y[..., 1:-1], y[..., 2:])
    if periodic:
        first = last = node_slope(h[-1], h[0], y[..., -2], y[..., 0], y[..., 1])
    else:
        first = (y[..., 1] - y[..., 0]) / h[0]
        last = (y[..., -1] - y[..., -2]) / h[-1]
    return jnp.concatenate([first[..., None], mid, last[..., None]], axis=-1)


def cell_index(x: Float[Array, " n"], xq):
    """The interval ``i`` (0 … n − 2) with ``x[i] <= xq < x[i + 1]`` (clamped at both ends)
    of an ascending grid. By comparison with every node: for the short grids of jaxtow's
    tables this costs a few vector operations, where `jax.numpy.searchsorted`'s default
    traces a loop that dominated the tracing time of the sweep kernels."""
    i = jnp.searchsorted(x, xq, side="right", method="compare_all") - 1
    return jnp.clip(i, 0, x.shape[0] - 2)


def _interval(x, xq):
    xq = jnp.clip(xq, x[0], x[-1])
    i = cell_index(x, xq)
    h = x[i + 1] - x[i]
    return xq, i, h, (xq - x[i]) / h


def hermite(
    x: Float[Array, " n"], y: Float[Array, "... n"], m: Float[Array, "... n"], xq
) -> Float[Array, "..."]:
    """Cubic Hermite interpolation along the last axis at scalar ``xq`` (clamped to
    [x0, xn]) with node slopes ``m``."""
    _, i, h, t = _interval(x, xq)
    return hermite_cell(y[..., i], y[..., i + 1], m[..., i], m[..., i + 1], h, t)


def hermite_local(x: Float[Array, " n"], take: Callable, xq) -> Float[Array, "..."]:
    """`hermite` with three-point node slopes and zero slope at both end nodes, computing
    only what the interval of ``xq`` needs: ``take(rows)`` returns the table values at the
    node indices ``rows`` (4 of them) along the last axis. The same numbers as the full table
    of slopes at a fraction of the cost."""
    n = x.shape[0]
    _, i, h, t = _interval(x, xq)
    rows = jnp.stack([jnp.maximum(i - 1, 0), i, i + 1, jnp.minimum(i + 2, n - 1)])
    y = take(rows)

    def slope(k, ym, yk, yp):
        km, kp = jnp.maximum(k - 1, 0), jnp.minimum(k + 1, n - 1)
        end = (k == 0) | (k == n - 1)
        h0, h1 = jnp.where(end, 1.0, x[k] - x[km]), jnp.where(end, 1.0, x[kp] - x[k])
        return jnp.where(end, 0.0, node_slope(h0, h1, ym, yk, yp))

    m0 = slope(i, y[..., 0], y[..., 1], y[..., 2])
    m1 = slope(i + 1, y[..., 1], y[..., 2], y[..., 3])
    return hermite_cell(y[..., 1], y[..., 2], m0, m1, h, t)
