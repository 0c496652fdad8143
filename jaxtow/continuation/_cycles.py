"""Limit cycles (the fishtailing orbit) by single shooting, with Floquet multipliers."""

from __future__ import annotations

import dataclasses
import functools

import jax
import jax.numpy as jnp
import numpy as np

from .._dynamics import TowModel, sway_offset
from .._equilibrium import state_from_heading
from .._roots import newton
from .._simulate import integrate
from .._stability import matrix_eigenvalues
from ._curve import parameter_setter

# ------------------------------------------------------------------ limit cycles


@dataclasses.dataclass
class PeriodicOrbit:
    """A limit cycle: initial state ``y0`` (ψ(0) = 0), period ``period`` (non-dimensional),
    ``floquet`` multipliers, the sampled orbit (``ts``, ``ys``), peak-to-peak sway offset
    ``path_width`` [L] and ``yaw_range`` (max |ψ|) [rad], Newton ``residual``."""

    parameter: float
    y0: np.ndarray
    period: float
    floquet: np.ndarray
    ts: np.ndarray
    ys: np.ndarray
    path_width: float
    yaw_range: float
    residual: float

    @property
    def stable(self) -> bool:
        mu = np.sort(np.abs(self.floquet))
        return bool(mu[-2] < 1.0)  # the largest is the trivial multiplier 1


def _flow(model, y0, T, n_save=None, rtol=1e-10, atol=1e-12):
    if n_save is None:  # the state at T only
        return integrate(model, y0, jnp.stack([0.0, T]), rtol=rtol, atol=atol).y1[None]
    return integrate(model, y0, jnp.linspace(0.0, T, n_save), rtol=rtol, atol=atol).ys


@functools.partial(jax.jit, static_argnums=(0, 3))
def _shoot(R, z, tol, max_iterations):
    return newton(
        lambda x, _: R(x), z, rtol=0.0, atol=tol, max_steps=max_iterations, well_posed=False
    )


def periodic_orbit(
    model: TowModel, y0, period, *, tol: float = 1e-8, max_iterations: int = 25, n_save: int = 4001
) -> PeriodicOrbit:
    """Limit cycle through the guess (y0, period) by single shooting: Newton on
    {φ_T(y0) − y0 = 0, ψ(0) = 0} for (y0, T) with the monodromy matrix from forward-mode
    autodiff through the integration. Raises if Newton does not reach ``tol``."""
    z = jnp.concatenate([jnp.asarray(y0, float), jnp.asarray([period], float)])

    def R(z):
        y, T = z[:6], z[6]
        return jnp.concatenate([_flow(model, y, T)[-1] - y, y[5:6]])

    # Newton with least-squares steps (the phase condition leaves the Jacobian near-singular),
    # `jaxtow._roots.newton`; the residual is checked here, not by the iteration
    z, _ = _shoot(R, z, tol, max_iterations)
    res = float(jnp.max(jnp.abs(R(z))))
    if not res < tol:
        raise RuntimeError(f"periodic_orbit: shooting did not converge (residual {res:.3g})")
    y0, T = z[:6], float(z[6])
    if float(jnp.max(jnp.abs(_flow(model, y0, T, n_save=64)[:, 5]))) < 1e-6:
        raise RuntimeError(
            "periodic_orbit: shooting collapsed onto an equilibrium (no oscillation)"
        )
    M = np.asarray(jax.jacfwd(lambda y: _flow(model, y, T)[-1])(y0))
    ys = np.asarray(_flow(model, y0, T, n_save=n_save))
    off = np.asarray(sway_offset(jnp.asarray(ys), model.towline.xp, model.towline.yp))
    return PeriodicOrbit(
        parameter=float("nan"),
        y0=np.asarray(y0),
        period=T,
        floquet=np.asarray(matrix_eigenvalues(jnp.asarray(M))),
        ts=np.linspace(0.0, T, n_save),
        ys=ys,
        path_width=float(off.max() - off.min()),
        yaw_range=float(np.abs(ys[:, 5]).max()),
        residual=res,
    )


def limit_cycle_from_simulation(
    model: TowModel, *, t1: float = 3000.0, psi0: float = 0.05, **kwargs
) -> PeriodicOrbit:
    """Converge onto an attracting limit cycle: run the tow from a small disturbance of the
    straight-behind equilibrium, take the last ψ up-crossing of zero and the period between
    the last two, and refine by shooting (`periodic_orbit`)."""
    y_eq = state_from_heading(jnp.asarray(0.0), model)[0]
    y = np.asarray(_flow(model, y_eq.at[5].set(psi0), t1, n_save=int(20 * t1) + 1))
    ts = np.linspace(0.0, t1, len(y))
    psi = y[:, 5]
    up = np.nonzero((psi[:-1] < 0) & (psi[1:] >= 0))[0]
    if len(up) < 3:
        raise RuntimeError(
            "limit_cycle_from_simulation: no sustained oscillation (is the equilibrium unstable?)"
        )
    k = up[-1]
    T = ts[up[-1]] - ts[up[-2]]
    return periodic_orbit(model, y[k], T, **kwargs)


def limit_cycle_branch(
    model: TowModel, parameter, values, *, start: PeriodicOrbit | None = None, **kwargs
) -> list:
    """Limit cycles at each value of ``parameter`` (natural continuation: each orbit starts
    from the previous one; the first from ``start`` or a simulation)."""
    set_model = parameter_setter(parameter)
    out = []
    guess = start
    for p in values:
        m = set_model(model, p)
        orbit = None
        if guess is not None:
            try:
                orbit = periodic_orbit(m, guess.y0, guess.period, **kwargs)
            except RuntimeError:
                orbit = None  # fall back on a simulation
        if orbit is None:
            orbit = limit_cycle_from_simulation(m, **kwargs)
        orbit.parameter = float(p)
        out.append(orbit)
        guess = orbit
    return out
