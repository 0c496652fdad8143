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
  the continuation corrector, the straight-behind equilibrium of the design module and the
  shooting of periodic orbits (least squares when the Jacobian is singular,
  ``well_posed=False``);
* `bisected_root`: a bracketed scalar root by a fixed number of halvings (the final
  bracket's end of smaller |f|), with the implicit derivative as its own rule (no termination test and no solver, so the residual is traced
  once for the value; its derivative only where a program is differentiated: inside the
  sweep kernels and the equilibria this is what keeps their tracing and compilation short);
* `bisect_fixed`: a fixed number of halvings of a bracket on a monotone predicate, for the
  kernels that carry their own derivative rule and must take the same steps in every
  member of a batch (the catenary's tension, the spectral abscissa's Routh tests).

All are pure and jittable; under `jax.vmap` every member of a batch takes as many
steps as the slowest.
"""

from __future__ import annotations

import equinox as eqx
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


@eqx.filter_custom_jvp
def _bisected(lo, hi, f_lo, f_hi, args, *, fn, steps):
    sign = jnp.where(f_lo < 0, 1.0, -1.0)  # sign * fn rises through the bracket

    def step(_, bracket):
        a, b, fa, fb = bracket
        m = 0.5 * (a + b)
        fm = fn(m, args)
        low = sign * fm >= 0  # the root is in [a, m]
        return (
            jnp.where(low, a, m),
            jnp.where(low, m, b),
            jnp.where(low, fa, fm),
            jnp.where(low, fm, fb),
        )

    a, b, fa, fb = jax.lax.fori_loop(0, steps, step, (lo, hi, f_lo, f_hi))
    return jnp.where(jnp.abs(fa) <= jnp.abs(fb), a, b)


@_bisected.def_jvp
def _bisected_jvp(primals, tangents, *, fn, steps):
    lo, hi, f_lo, f_hi, args = primals
    x = _bisected(lo, hi, f_lo, f_hi, args, fn=fn, steps=steps)
    t_args = tangents[4]
    f_args = None
    if t_args is not None:
        # implicit function: fn(x(θ), θ) = 0, so dx = −(∂_θ fn · dθ) / ∂_x fn at the root
        _, f_args = eqx.filter_jvp(lambda a: fn(x, a), (args,), (t_args,))
    if f_args is None:  # the parameters that move do not enter fn: the root stays
        return x, jnp.zeros_like(x)
    _, f_x = jax.jvp(lambda z: fn(z, args), (x,), (jnp.ones_like(x),))
    return x, -f_args / jnp.where(f_x == 0, 1.0, f_x)


def bisected_root(fn, lo, hi, args, *, steps: int, f_lo=None, f_hi=None):
    """The root of a scalar ``fn(x, args) = 0`` in the bracket [``lo``, ``hi``] (``fn``
    changes sign across it; ``f_lo``, ``f_hi`` its values there, evaluated when not given)
    after ``steps`` halvings: the end of the final bracket where |fn| is smaller (a root on
    a bracket's end, such as ψ = 0 of a symmetric tow, is found exactly). No tolerance
    test, no solver: the value traces ``fn`` once. Its derivative with respect to ``args``
    is the implicit one, −∂_args fn / ∂_x fn at the root, by its own rule, so a program that
    is not differentiated holds no derivative of ``fn`` at all (the Newton steps this
    replaced carried one in every program: 1.3 s of the 3.2 s compile of a sea state's
    equilibria)."""
    lo, hi = jnp.asarray(lo, dtype=float), jnp.asarray(hi, dtype=float)
    f_lo = fn(lo, args) if f_lo is None else f_lo
    f_hi = fn(hi, args) if f_hi is None else f_hi
    return _bisected(lo, hi, f_lo, f_hi, args, fn=fn, steps=steps)
