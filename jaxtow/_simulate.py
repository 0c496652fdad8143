"""Time-domain simulation of the tow with diffrax (thesis sections 2.1.3, 6.1, 7.3).

`simulate` integrates the vector field of eqs 6.1-6.6 from an initial state and returns the
states on a save grid with the solver status; `simulate_batch` runs many initial conditions
and parameter sets in one compiled call. Post-processing (trajectory, metrics) lives in
`jaxtow.fishtail_metrics`.

Solvers: an adaptive explicit Runge-Kutta (Tsit5) by default; the implicit Kvaerno5 for
stiff towlines. ``solver="auto"`` picks Kvaerno5 when the fastest mode of the Jacobian at
the initial state, |λ|max, times the run length exceeds `STIFF_THRESHOLD` (an explicit
solver would then need of order 10⁵ steps only to stay stable: a steel wire on a short
towline has a stretch mode of |λ| ~ √(EA'/(l0'(m'+a11'))), e.g. 52 at EA' = 333, l0' = 0.2).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import diffrax
import equinox as eqx
import equinox.internal as eqxi
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Bool, Float, Int

from ._dynamics import TowModel, all_valid, unchecked_vector_field, validity
from ._parameters import check_values, with_parameters
from ._program_cache import persistent
from ._rules import check_now, guard, holds_tracers, is_concrete
from ._stability import eigenvalues
from ._sweep import without_metadata

SOLVERS = ("tsit5", "kvaerno5")
#: |λ|max · (t1 − t0) above which ``solver="auto"`` chooses the implicit solver.
STIFF_THRESHOLD = 2.0e5


class Simulation(eqx.Module):
    """Result of a run: ``ts`` (n,), ``ys`` (n, 6) in (u, v, r, l, γ, ψ), ``success``
    (the solver reached t1), ``result`` (diffrax result code), ``n_steps`` (accepted steps),
    ``validity`` ({name: (n,)}: the physics' validity flags and numbers along the run,
    `jaxtow.validity`; ``physics_valid`` is their logical and), ``valid`` (n,) (finite saved
    states: after a failure the rest of the grid is inf, as in diffrax)."""

    ts: Float[Array, " n"]
    ys: Float[Array, "n 6"]
    success: Bool[Array, ""]
    result: diffrax.RESULTS
    n_steps: Int[Array, ""]
    validity: dict

    @property
    def valid(self):
        return jnp.all(jnp.isfinite(self.ys), axis=-1)


def _solver(name: str):
    # the stages in a plain loop, as diffrax's forward-mode adjoint sets them: forward-mode
    # differentiable (its default loop is reverse-mode only), the same arithmetic
    if name == "tsit5":
        return diffrax.Tsit5(scan_kind="lax")
    if name == "kvaerno5":
        return diffrax.Kvaerno5(scan_kind="lax")
    raise ValueError(f"parameter 'solver' must be one of {SOLVERS + ('auto',)}, got {name!r}")


def choose_solver(model: TowModel, y0, t1: float, t0: float = 0.0) -> str:
    """'tsit5' or 'kvaerno5' from the stiffness estimate described in the module docstring."""
    if holds_tracers(model):
        lam = eigenvalues(model, jnp.asarray(y0))
    else:  # checked here, then one compiled program (the Jacobian traced once per model type)
        check_now(model)
        lam = _eigenvalues_program(model, jnp.asarray(y0))
    lam = np.asarray(lam)
    return "kvaerno5" if float(np.max(np.abs(lam))) * (t1 - t0) > STIFF_THRESHOLD else "tsit5"


@persistent
@eqx.filter_jit
def _eigenvalues_program(model, y):
    return eigenvalues(model, y, throw=False)


class Integration(eqx.Module):
    """What `integrate` returns: ``ts`` (n,) and ``ys`` (n, 6) on the save grid (inf after a
    failure, as diffrax fills its buffers), ``y1`` the last accepted state, ``result`` (a
    `diffrax.RESULTS`) and ``n_steps`` (accepted steps)."""

    ts: Float[Array, " n"]
    ys: Float[Array, "n 6"]
    y1: Float[Array, " 6"]
    result: diffrax.RESULTS
    n_steps: Int[Array, ""]


class _Carry(NamedTuple):
    tprev: Array
    tnext: Array
    y: Array
    solver_state: object
    controller_state: object
    result: diffrax.RESULTS
    n_steps: Array
    n_accepted: Array
    save_index: Array
    ys: Array


def integrate(
    model,
    y0,
    ts,
    *,
    solver: str = "tsit5",
    rtol: float = 1e-8,
    atol: float = 1e-8,
    max_steps: int = 200_000,
) -> Integration:
    """The one time integration of jaxtow: the tow vector field from ``y0`` over
    [ts[0], ts[-1]] with diffrax's solver and adaptive PID step-size controller, saved at the
    increasing grid ``ts`` (the caller checks it), never throwing (the caller reads
    ``result``).

    The step loop is diffrax's own (`diffrax.diffeqsolve` without events, jumps or dense
    output), written here with its public stepping API (``solver.init``/``step``,
    ``controller.init``/``adapt_step_size``) for one reason: `diffeqsolve` checks
    ``SaveAt(ts=...)`` with `equinox.error_if`, which compiles to host callbacks, and JAX's
    persistent cache never stores a program that holds one — every time-domain run was
    compiled afresh on every run of the command line. The steps taken, the interpolation at
    the save points and the result codes are diffrax's; a test holds the two equal.
    Differentiable in forward mode (`jax.jvp`/`jax.jacfwd`: the limit-cycle shooting);
    reverse mode through the adaptive loop is not supported.
    """
    term = diffrax.ODETerm(unchecked_vector_field)
    controller = diffrax.PIDController(rtol=rtol, atol=atol)
    solver_ = _solver(solver)
    if isinstance(solver_, diffrax.AbstractImplicitSolver):  # as diffeqsolve: the step's tolerances
        solver_ = eqx.tree_at(
            lambda s: (s.root_finder.rtol, s.root_finder.atol, s.root_finder.norm),
            solver_,
            (rtol, atol, controller.norm),
        )
    ts = jnp.asarray(ts, dtype=float)
    y0 = jnp.asarray(y0, dtype=float)
    t0, t1 = ts[0], ts[-1]
    n = ts.shape[0]
    order = solver_.error_order(term)
    # the first step is diffeqsolve's: its initial-step estimate sees the time-direction
    # wrapper, not an ODETerm, and falls back to a step of 0.01
    tnext, controller_state = controller.init(term, t0, t1, y0, 0.01, model, solver_.func, order)
    tnext = jnp.minimum(tnext, t1)
    # diffrax rounds a step end within 100 ulp of t1 to t1 (no sliver intervals)
    t1_floor = jax.lax.fori_loop(0, 100, lambda _, t: eqxi.prevbefore(t), t1)

    def step(c: _Carry) -> _Carry:
        y, y_error, dense, solver_state, solver_result = solver_.step(
            term, c.tprev, c.tnext, c.y, model, c.solver_state, False
        )
        y_error = jnp.where(jnp.isnan(y_error), jnp.inf, y_error)
        keep, tprev, tnext, jump, controller_state, controller_result = controller.adapt_step_size(
            c.tprev, c.tnext, c.y, y, model, y_error, order, c.controller_state
        )
        assert jump is False  # no jump times: the solver's first-same-as-last stays valid
        tprev = jnp.minimum(tprev, t1)
        tnext = jnp.where(tnext > t1_floor, jnp.where(keep, t1, tprev + 0.5 * (t1 - tprev)), tnext)
        y = jnp.where(keep, y, c.y)
        solver_state = jax.tree.map(
            lambda a, b: jnp.where(keep, a, b), solver_state, c.solver_state
        )
        solver_result = diffrax.RESULTS.where(keep, solver_result, diffrax.RESULTS.successful)
        result = diffrax.RESULTS.where(diffrax.is_okay(c.result), solver_result, c.result)
        result = diffrax.RESULTS.where(diffrax.is_okay(result), controller_result, result)
        interpolation = solver_.interpolation_cls(t0=c.tprev, t1=c.tnext, **dense)

        def save_pending(s):
            return keep & (s[0] < n) & (ts[jnp.minimum(s[0], n - 1)] <= c.tnext)

        def save_one(s):
            i, ys = s
            return i + 1, ys.at[i].set(interpolation.evaluate(ts[i]))

        save_index, ys = eqxi.while_loop(
            save_pending, save_one, (c.save_index, c.ys), buffers=lambda s: s[1], kind="lax"
        )
        return _Carry(
            tprev,
            tnext,
            y,
            solver_state,
            controller_state,
            result,
            c.n_steps + 1,
            c.n_accepted + jnp.where(keep, 1, 0),
            save_index,
            ys,
        )

    def running(c: _Carry):
        return (c.tprev < t1) & diffrax.is_successful(c.result) & (c.n_steps < max_steps)

    zero = jnp.zeros((), dtype=int)
    start = _Carry(
        t0,
        tnext,
        y0,
        solver_.init(term, t0, tnext, y0, model),
        controller_state,
        diffrax.RESULTS.successful,
        zero,
        zero,
        zero,
        jnp.full((n, y0.shape[0]), jnp.inf),
    )
    # equinox's loop (as diffrax's driver): the save grid is a buffer written in place, not
    # selected whole at every step of a batch member that has finished (under vmap)
    end = eqxi.while_loop(running, step, start, buffers=lambda c: c.ys, kind="lax")
    unfinished = (end.tprev < t1) & diffrax.is_successful(end.result)
    result = diffrax.RESULTS.where(unfinished, diffrax.RESULTS.max_steps_reached, end.result)
    saved = jnp.arange(n) < end.save_index
    return Integration(
        ts=jnp.where(saved, ts, jnp.inf),
        ys=end.ys,
        y1=end.y,
        result=result,
        n_steps=end.n_accepted,
    )


def _run(model, y0, ts, *, solver: str, rtol: float, atol: float, max_steps: int):
    sol = integrate(model, y0, ts, solver=solver, rtol=rtol, atol=atol, max_steps=max_steps)
    ok = sol.result == diffrax.RESULTS.successful
    flags = jax.vmap(lambda y: validity(model, y, throw=False))(sol.ys)
    flags["physics_valid"] = jax.vmap(all_valid)(flags)
    return Simulation(
        ts=sol.ts, ys=sol.ys, success=ok, result=sol.result, n_steps=sol.n_steps, validity=flags
    )


_run_jit = persistent(jax.jit(_run, static_argnames=("solver", "rtol", "atol", "max_steps")))


def _save_grid(t0, t1, n_save):
    if not (np.isfinite(t0) and np.isfinite(t1)):
        raise ValueError(f"parameters 't0' and 't1' must be finite, got t0 = {t0}, t1 = {t1}")
    if not t1 > t0:
        raise ValueError(f"parameter 't1' must be > t0 = {t0}, got {t1}")
    if n_save < 2:
        raise ValueError(f"parameter 'n_save' must be >= 2, got {n_save}")
    return jnp.linspace(t0, t1, n_save)


#: The step-size controller's default tolerances in float64.
DEFAULT_TOL = 1e-8


def solver_tolerances(rtol: float | None, atol: float | None) -> tuple[float, float]:
    """The step-size controller's (rtol, atol): None gives `DEFAULT_TOL` in float64 and
    1e-5 in float32 (``JAXTOW_ENABLE_X64=0``), where 1e-8 lies below the resolution (eps
    1.2e-7) and the controller shrinks the steps a hundredfold to chase it. A tolerance
    below 10 eps of the dtype is refused, naming it."""
    eps = float(jnp.finfo(jnp.result_type(float)).eps)
    default = 1e-5 if eps > 1e-10 else DEFAULT_TOL
    out = []
    for name, tol in (("rtol", rtol), ("atol", atol)):
        tol = default if tol is None else float(tol)
        if not (math.isfinite(tol) and tol >= 10 * eps):
            raise ValueError(
                f"parameter {name!r} must be finite and >= 10 eps of the float type "
                f"({10 * eps:.2g}), got {tol:g}"
                + (
                    " (float32: JAXTOW_ENABLE_X64=0; use >= 1e-6, or float64)"
                    if eps > 1e-10
                    else ""
                )
            )
        out.append(tol)
    return out[0], out[1]


def simulate(
    model: TowModel,
    y0,
    t1: float = 200.0,
    *,
    t0: float = 0.0,
    n_save: int = 2001,
    solver: str = "auto",
    rtol: float | None = None,
    atol: float | None = None,
    max_steps: int = 200_000,
    throw: bool = True,
) -> Simulation:
    """Integrate the tow from state ``y0`` over [t0, t1] (non-dimensional time, by L/U_tug).

    Returns a `Simulation`; ``success`` is False (never an exception, never a silent
    result) when the solver stops early, e.g. because ``max_steps`` ran out. The model's
    parameters are checked before the run; a model traced by the caller's own `jax.jit` or
    `jax.vmap` is checked in the program with ``throw=True`` (see `jaxtow.vector_field`).
    """
    if is_concrete(y0):  # numpy: also under the caller's jit, where jnp would stage it
        y0v = np.asarray(y0, dtype=float)
        if y0v.shape != (6,) or not np.all(np.isfinite(y0v)):
            raise ValueError(f"parameter 'y0' must be a finite state of shape (6,), got {y0v}")
        if y0v[3] <= 0:
            raise ValueError("parameter 'y0' must have a positive towline length l'")
    elif jnp.shape(y0) != (6,):
        raise ValueError(f"parameter 'y0' must be a state of shape (6,), got {jnp.shape(y0)}")
    y0 = jnp.asarray(y0, dtype=float)
    ts = _save_grid(t0, t1, n_save)
    rtol, atol = solver_tolerances(rtol, atol)
    check_now(model)
    if solver == "auto":
        if holds_tracers(model):
            raise ValueError(
                "parameter 'solver': 'auto' chooses the solver from the model's values, which "
                "a model traced by jax.jit or jax.vmap does not have; pass solver='tsit5' "
                "(non-stiff) or 'kvaerno5' (stiff towlines)"
            )
        solver = choose_solver(model, y0, t1, t0)
    sim = _run_jit(  # models differing only in metadata share the program (Barge 2a and 2b)
        without_metadata(model), y0, ts, solver=solver, rtol=rtol, atol=atol, max_steps=max_steps
    )
    return guard(sim, model.checks()) if throw and holds_tracers(model) else sim


def simulate_batch(
    model: TowModel,
    y0s,
    t1: float = 200.0,
    *,
    params: dict | None = None,
    t0: float = 0.0,
    n_save: int = 2001,
    solver: str = "tsit5",
    rtol: float | None = None,
    atol: float | None = None,
    max_steps: int = 200_000,
    batch_size: int | None = 64,
    throw: bool = True,
) -> Simulation:
    """Many runs in one compiled call: initial states ``y0s`` (B, 6) and, optionally,
    per-run model parameters ``params`` {name: (B,) values} (see `jaxtow.with_parameters`).

    Adaptive solves under `vmap` run in lockstep: every member takes as many steps as the
    slowest. ``batch_size`` bounds that cost: runs are processed by `jax.lax.map` in vmapped
    groups of ``batch_size`` (None: one vmap over all B; 1: a compiled loop). Measured on 2
    CPU cores for 1024 Barge 2b runs (``benchmarks/bench_simulate.py``): 1.9 s with groups of
    64 (the default), 2.9 s as one vmap, 3.2 s with 16, 5.5 s as a loop.
    """
    y0s = jnp.asarray(y0s, dtype=float)
    if y0s.ndim != 2 or y0s.shape[1] != 6:
        raise ValueError(f"parameter 'y0s' must have shape (B, 6), got {y0s.shape}")
    params = {k: jnp.asarray(v, dtype=float) for k, v in (params or {}).items()}
    for k, v in params.items():
        if v.shape != (y0s.shape[0],):
            raise ValueError(f"params[{k!r}] must have shape ({y0s.shape[0]},), got {v.shape}")
        check_values(model, k, np.asarray(v))
    ts = _save_grid(t0, t1, n_save)
    rtol, atol = solver_tolerances(rtol, atol)
    check_now(model)
    sims = _batch_jit(
        without_metadata(model),
        y0s,
        params,
        ts,
        solver=solver,
        rtol=rtol,
        atol=atol,
        max_steps=max_steps,
        batch_size=batch_size,
    )
    return guard(sims, model.checks()) if throw and holds_tracers(model) else sims


def _batch(model, y0s, params, ts, *, solver, rtol, atol, max_steps, batch_size):
    def one(args):
        y0, p = args
        return _run(
            with_parameters(model, **p),
            y0,
            ts,
            solver=solver,
            rtol=rtol,
            atol=atol,
            max_steps=max_steps,
        )

    if batch_size is None:
        return jax.vmap(one)((y0s, params))
    return jax.lax.map(one, (y0s, params), batch_size=batch_size)


_batch_jit = jax.jit(_batch, static_argnames=("solver", "rtol", "atol", "max_steps", "batch_size"))


def initial_state(
    model: TowModel, *, psi0: float = 0.0, y0: float = 0.0, u0: float = 1.0, stretched: bool = True
):
    """State from the thesis's initial condition (ψ0, sway offset y0' of the CoG from the
    tug's track), with the towline of length l0' (``stretched``: at the straight-ahead
    working tension T' = R0', so the run does not start with a slack or jerked line),
    surge u0 (default: moving with the tug), v = r = 0.

    From y' = l' sin γ − x_p' sin ψ (eqs 2.16, 2.18): sin γ = (y0 + x_p sin ψ0)/l'.
    """
    xp, yp = float(model.towline.xp), float(model.towline.yp)
    l = float(model.towline.l0)
    if stretched:
        l = float(model.towline.length_at_tension(model.vessel.R0))
    s = (y0 + xp * np.sin(psi0) + yp * np.cos(psi0)) / l
    if abs(s) >= 1:
        raise ValueError(f"parameter 'y0' ({y0}) is not reachable with towline length {l:.3f}")
    return jnp.array([u0, 0.0, 0.0, l, np.arcsin(s), psi0])
