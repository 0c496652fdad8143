"""Comparing drift estimation methods (thesis section 3.3, eqs 3.7-3.8, chapters 4-5).

* `compare_methods`: every waterline method on one (ω) grid for a heading and speed, as
  arrays, in one vmapped pass per method;
* `irregular_drift`: a method's mean drift in a JONSWAP sea, 2∫S(ω)F(ω)dω (eq. 2.29),
  vmappable over (Hs, Tp);
* `relative_mse`, `relative_mse_by_zone`: the relative mean-square error against a base
  method, over all points or per motion/transition/reflection zone (L/λ, eq. 3.7). The
  thesis's eq. 3.8 is lost in the extracted text; jaxtow uses
  E = Σ (F − F_base)² / Σ F_base² over the points compared (0 for a perfect match,
  1 for a method that predicts zero).
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from .._rules import guard
from ..waves import DEFAULT_OMEGA, Jonswap, mean_drift
from ._methods import WATERLINE_METHODS, ZONE_EDGES, ZONE_NAMES, zone
from ._qtf import QTF


def relative_mse(estimate, base, mask=None) -> float:
    """Σ (F − F_base)² / Σ F_base² over the points where ``mask`` holds (all by default).

    Raises ValueError if no point is selected or the base is identically zero there."""
    e, b = np.asarray(estimate, float), np.asarray(base, float)
    m = np.ones(b.shape, bool) if mask is None else np.broadcast_to(np.asarray(mask, bool), b.shape)
    if not m.any():
        raise ValueError("relative_mse: no points selected")
    den = np.sum(b[m] ** 2)
    if den == 0:
        raise ValueError("relative_mse: the base method is zero at every selected point")
    return float(np.sum((e[m] - b[m]) ** 2) / den)


def relative_mse_by_zone(estimate, base, omega, length, edges=ZONE_EDGES) -> dict:
    """Relative MSE per zone {"motion", "transition", "reflection"}; a zone with no grid
    points, or where the base is zero, maps to None."""
    z = np.asarray(zone(jnp.asarray(omega, float), length, edges))
    out = {}
    for i, name in enumerate(ZONE_NAMES):
        m = z == i
        b = np.asarray(base, float)
        out[name] = relative_mse(estimate, base, m) if m.any() and np.any(b[m] != 0) else None
    return out


def compare_methods(wl, omega, beta, u=0.0, v=0.0, *, methods=None, options=None) -> dict:
    """Run waterline methods on one ω grid at heading β and speed (u, v).

    ``methods``: names from `WATERLINE_METHODS` (default all); ``options``: {name: kwargs} (e.g.
    ``{"faltinsen": {"speed_factor": (4.0, 2.0)}}``). Returns {name: DriftEstimate} with
    arrays over ω."""
    methods = list(WATERLINE_METHODS) if methods is None else list(methods)
    options = options or {}
    omega = jnp.asarray(omega, float)
    out = {}
    for name in methods:
        if name not in WATERLINE_METHODS:
            raise ValueError(
                f"parameter 'methods': unknown method {name!r}; choose from {sorted(WATERLINE_METHODS)}"
            )
        out[name] = WATERLINE_METHODS[name](wl, omega, beta, u, v, **options.get(name, {}))
    return out


def irregular_drift(method, wl, hs, tp, beta, u=0.0, v=0.0, *, omega=None, gamma=3.3, **kwargs):
    """Mean drift (Fx, Fy, Nz) [N, N, N·m] of a waterline method in a JONSWAP sea (Hs, Tp, γ):
    F̄ = 2∫ S(ω) F(ω) dω (eq. 2.29) on the grid ``omega`` (default `jaxtow.waves.DEFAULT_OMEGA`). Differentiable and vmappable in hs, tp, beta, u, v; ``method`` is a function
    from `WATERLINE_METHODS` or its name."""
    w = jnp.asarray(DEFAULT_OMEGA if omega is None else omega, float)
    sea = Jonswap(hs=hs, tp=tp, gamma=gamma)  # checks concrete values
    # traced ones are checked on the result, with the same rules
    return guard(method_mean_drift(method, wl, w, sea(w), beta, u, v, **kwargs), sea.checks())


def method_function(method):
    """The waterline method ``method`` (a function of `WATERLINE_METHODS` or its name); a name that is
    not one is an error that lists them."""
    if not isinstance(method, str):
        return method
    if method not in WATERLINE_METHODS:
        raise ValueError(
            f"parameter 'method': {method!r} is not a waterline drift method; choose from "
            f"{', '.join(WATERLINE_METHODS)}"
        )
    return WATERLINE_METHODS[method]


def method_mean_drift(method, wl, omega, S, beta, u=0.0, v=0.0, **kwargs):
    """`irregular_drift` for a spectrum ``S`` already evaluated on ``omega`` (unchecked:
    the caller holds a checked sea state)."""
    fn = method_function(method)
    return mean_drift(omega, S, fn(wl, omega, beta, u, v, **kwargs).force)


def qtf_from_method(method, wl, omega, beta, **kwargs):
    """A stationary mean-drift `QTF` tabulated from a waterline method (``method``: a function
    of `WATERLINE_METHODS` or its name) on ``omega`` [rad/s] × ``beta`` [rad, 0 … π, ascending from 0]
    for a port-starboard symmetric waterline, completed to ±β by symmetry. A documented
    stand-in for a panel-method QTF in the tow model (the waterline methods miss the
    motion-induced drift in the motion zone); the forward-speed effect then comes from the
    encounter frequency and Aranha's wave-drift damping of the QTF."""

    fn = method_function(method)
    w = jnp.asarray(omega, float)
    b = np.asarray(beta, float)
    F = np.array(jax.vmap(lambda bb: fn(wl, w, bb, **kwargs).force)(jnp.asarray(b)))  # (nb, nw, 3)
    F[np.isclose(b, 0.0), :, 1:] = 0.0  # exact symmetry in head and following seas
    F[np.isclose(b, np.pi), :, 1:] = 0.0
    return QTF.symmetric(
        omega=np.asarray(w), beta=b, fx=F[..., 0].T, fy=F[..., 1].T, nz=F[..., 2].T
    )
