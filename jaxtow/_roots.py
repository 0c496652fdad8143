"""Root finding: the one implementation behind every root jaxtow solves.

Every root problem of jaxtow goes through these helpers; the iterations that stop on a
tolerance go through optimistix (`optimistix.root_find`, whose implicit adjoint gives exact
derivatives of a root with respect to the parameters):

* `brackets`: scan-then-refine, step one — the sign changes of a sampled function (the
  equilibrium headings of the heading residual, the operating speed of the pull balance);
* `bisect`: refine one bracket with `optimistix.Bisection` (to machine precision by
  default; the tolerance is the caller's);
* `newton`: Newton's method with `optimistix.Newton` for scalar or vector problems, with
  the residual checked by the caller (optimistix terminates on the change of the iterate):
  the polish of a bracketed root, the continuation corrector, the straight-behind
  equilibrium of the design module and the shooting of periodic orbits (least squares when
  the Jacobian is singular, ``well_posed=False``);
* `polish`: a fixed number of scalar Newton steps after `bisect` (no termination test, so
  no solver is needed, and the residual is traced once: inside the sweep kernels this is
  what keeps their tracing and compilation short);
* `bisect_fixed`: a fixed number of halvings of a bracket on a monotone predicate, for the
  kernels that carry their own derivative rule and must take the same steps in every
  member of a batch (the catenary's tension, the spectral abscissa's Routh tests).

All are pure and jittable; under `jax.vmap` every member of a batch takes as many
steps as the slowest.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import lineax as lx
import optimistix as optx
from jaxtyping import Array, Bool, Int


def brackets(
    values, max_roots: int
) -> tuple[Int[Array, " k"], Bool[Array, " k"], Bool[Array, " k"], Int[Array, ""]]:
    """Sign changes of a sampled function ``values`` (n,): interval indices i with
    values[i] == 0 (an exact root at node i) or values[i]·values[i+1] < 0, in ascending
    order. Returns ``(index, found, exact, count)`` with ``max_roots`` slots: slots beyond
    ``count`` are not ``found`` and repeat the first index (so that their refinement stays
    finite); ``count`` > ``max_roots`` means roots were dropped."""
    exact = values[:-1] == 0
    change = exact | (values[:-1] * values[1:] < 0)
    count = jnp.sum(change)
    idx = jnp.nonzero(change, size=max_roots, fill_value=0)[0]
    found = jnp.arange(max_roots) < count
    idx = jnp.where(found, idx, idx[0])
    return idx, found, exact[idx], count


def bisect(
    fn,
    lo,
    hi,
    args=None,
    *,
    atol: float = 0.0,
    rtol: float = 0.0,
    max_steps: int = 256,
    f_lo=None,
    f_hi=None,
):
    """Root of ``fn(x, args)`` in the bracket [lo, hi] (a sign change) by
    `optimistix.Bisection`; returns ``(x, successful)``. The default tolerances (0) run to
    the floating-point limit of the bracket and stop at ``max_steps`` (then ``successful``
    is False but ``x`` is the converged midpoint): pass the accuracy you need. A bracket
    without a sign change gives ``successful`` False.

    The orientation of the bracket is taken from fn(lo) and fn(hi) here, not by the
    solver's ``flip="detect"``: that check is an `equinox.error_if`, a host callback, and a
    compiled program holding one is never written to JAX's persistent compilation cache
    (`jaxtow.enable_compile_cache`). ``f_lo``, ``f_hi``: fn(lo) and fn(hi) where the
    caller has them already (the scan of `brackets`), saving two traces of ``fn``."""
    f_lo = fn(lo, args) if f_lo is None else f_lo
    f_hi = fn(hi, args) if f_hi is None else f_hi
    sign = jnp.where(f_lo < 0, 1.0, -1.0)  # sign * fn rises through the bracket
    solver = optx.Bisection(rtol=rtol, atol=atol, flip=False)
    sol = optx.root_find(
        lambda x, a: sign * fn(x, a),
        solver,
        0.5 * (lo + hi),
        args,
        options=dict(lower=lo, upper=hi),
        max_steps=max_steps,
        throw=False,
    )
    bracketed = (f_lo < 0) != (f_hi < 0)
    return sol.value, (sol.result == optx.RESULTS.successful) & bracketed


def newton(
    fn,
    x0,
    args=None,
    *,
    rtol: float = 1e-12,
    atol: float = 1e-12,
    max_steps: int = 256,
    lower=None,
    upper=None,
    well_posed: bool | None = True,
):
    """Newton iteration on ``fn(x, args) = 0`` from ``x0`` by `optimistix.Newton`; returns
    ``(x, successful)``. ``lower``/``upper`` clip the iterates of a scalar problem;
    ``well_posed=False`` solves each step in the least-squares sense (a singular Jacobian).
    Newton stops on a small change of the iterate: check the residual where it matters.
    ``rtol = atol = 0`` runs exactly ``max_steps`` steps (a polish of a bracketed root)."""
    solver = optx.Newton(
        rtol=rtol, atol=atol, linear_solver=lx.AutoLinearSolver(well_posed=well_posed)
    )
    options = {} if lower is None else dict(lower=lower, upper=upper)
    sol = optx.root_find(fn, solver, x0, args, options=options, max_steps=max_steps, throw=False)
    return sol.value, sol.result == optx.RESULTS.successful


def bisect_fixed(below, lo, hi, steps: int):
    """``steps`` halvings of the bracket [lo, hi] of a monotone predicate: ``below(x)`` is
    True where the sought point lies below x (so [lo, mid] is kept) and False above it.
    Returns the final bracket (lo, hi). No tolerance test and no derivative: for kernels
    with their own JVP rule that run in lockstep under `jax.vmap`. With a bracket of Python
    numbers it runs on the host, for a predicate that is no JAX function (a full
    equilibrium search at each point)."""
    if isinstance(lo, (int, float)) and isinstance(hi, (int, float)):
        a, b = float(lo), float(hi)
        for _ in range(steps):
            m = 0.5 * (a + b)
            a, b = (a, m) if below(m) else (m, b)
        return a, b

    def step(_, bracket):
        a, b = bracket
        m = 0.5 * (a + b)
        keep_low = below(m)
        return jnp.where(keep_low, a, m), jnp.where(keep_low, m, b)

    return jax.lax.fori_loop(0, steps, step, (lo, hi))


def polish(fn, x, args=None, *, steps: int = 2, lower=None, upper=None):
    """``steps`` Newton steps on a scalar ``fn(x, args) = 0`` from a bracketed root ``x``
    (clipped to [``lower``, ``upper``]): the final polish after `bisect`. A fixed number of
    steps needs no termination test, linear solver or adjoint, so the residual is traced
    once (`newton` traces it several times: the cost that dominated the tracing of the sweep
    kernels). Derivatives pass through the steps; at a root the derivative of a Newton step
    with respect to the parameters is the implicit one, −∂_θ fn / ∂_x fn."""

    def step(_, x):
        f, df = jax.jvp(lambda z: fn(z, args), (x,), (jnp.ones_like(x),))
        x_new = x - f / jnp.where(df == 0, 1.0, df)
        x_new = jnp.where(df == 0, x, x_new)
        if lower is not None:
            x_new = jnp.clip(x_new, lower, upper)
        return x_new

    return jax.lax.fori_loop(0, steps, step, x)
