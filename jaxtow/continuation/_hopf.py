"""Hopf test functions (Hurwitz determinants) and Hopf points/curves of the straight-behind equilibrium."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from .._dynamics import TowModel
from .._equilibrium import state_from_heading
from .._roots import bisect
from .._stability import characteristic_polynomial, hurwitz_determinants, jacobian
from ._curve import Curve, parameter_setter


def hopf_test(A):
    """Δ_{n−1}, the Hopf test function of a real n×n matrix (zero when a pair λ = ±iω or ±μ),
    from `jaxtow._stability.hurwitz_determinants`."""
    return hurwitz_determinants(characteristic_polynomial(A))[-2]


# ------------------------------------------------------------------ Hopf curves


def hopf_curve(
    model: TowModel,
    parameters=("xp", "l0"),
    *,
    start,
    ranges,
    ds: float = 0.01,
    max_points: int = 2000,
):
    """Two-parameter continuation of the Hopf condition Δ₅ = 0 of the straight-behind
    equilibrium (ψ = 0) in the plane of ``parameters`` = (p₁, p₂), from ``start`` = (p₁, p₂)
    on or near the curve (it is first corrected onto it at fixed p₂), within ``ranges`` =
    ((lo₁, hi₁), (lo₂, hi₂)). Returns an (n, 2) array of (p₁, p₂) points."""
    s1, s2 = (parameter_setter(p) for p in parameters)

    def G(x):
        m = s2(s1(model, x[0]), x[1])
        return hopf_test(jacobian(m, state_from_heading(jnp.asarray(0.0), m)[0], throw=False))

    x0 = np.asarray(start, float)
    # Δ₅ carries the stiff towline modes (values ~1e11): scale it by its gradient at the start
    # so that residuals and tolerances are in parameter units
    scale = float(np.linalg.norm(np.asarray(jax.grad(G)(jnp.asarray(x0)))))
    if not (np.isfinite(scale) and scale > 0):
        raise ValueError(
            f"parameter 'start' = {start}: the Hopf test function has no gradient there"
        )
    curve = Curve(lambda x: G(x) / scale)
    x0, res = curve.point(x0, np.array([1.0, 0.0]), 0.0)
    if not res < 1e-9:
        raise ValueError(f"parameter 'start' = {start} is not near a Hopf curve (|Δ5| = {res:.3g})")
    (l1, h1), (l2, h2) = ranges

    def inside(x):
        return l1 <= x[0] <= h1 and l2 <= x[1] <= h2

    t0 = curve.tangent(x0)
    a, _ = curve.follow(x0, -t0, ds=ds, n_max=max_points // 2, inside=inside)
    b, _ = curve.follow(x0, t0, ds=ds, n_max=max_points // 2, inside=inside)
    return np.concatenate([a[::-1], b[1:]])


def straight_behind_hopf(model: TowModel, parameter, bracket, *, set_model=None):
    """Hopf point of the straight-behind equilibrium in ``parameter`` within ``bracket`` =
    (lo, hi), where Δ₅ changes sign: bisection to machine precision. Returns the value."""
    s = set_model or parameter_setter(parameter)

    def h(p):
        m = s(model, p)
        return hopf_test(jacobian(m, state_from_heading(jnp.asarray(0.0), m)[0], throw=False))

    lo, hi = (float(v) for v in bracket)
    if np.sign(float(h(lo))) == np.sign(float(h(hi))):
        raise ValueError(
            f"parameter 'bracket' {bracket}: the Hopf test function does not change sign"
        )
    p, _ = jax.jit(lambda a, b: bisect(lambda q, _: h(q), a, b, max_steps=200))(lo, hi)
    return float(p)
