"""Input checks shared by the model classes.

Two layers, following equinox's habit:

* eager checks (`check_*`) run when a parameter is a concrete number, at construction time,
  and raise a `ValueError` that names the parameter;
* traced checks (`error_if_*`) guard jitted entry points with `equinox.error_if`, which
  raises at run time with the same message when the values arrive as tracers.

Sweeps do not use error_if per point (one bad point would abort the batch); they validate
the whole grid eagerly before running (see `jaxtow.sweep`).
"""

from __future__ import annotations

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np


def is_concrete(x) -> bool:
    """True if `x` holds concrete values (not a JAX tracer)."""
    return not isinstance(x, jax.core.Tracer)


def _values(x):
    return np.asarray(x, dtype=float)


def check_finite(name: str, x) -> None:
    if is_concrete(x):
        v = _values(x)
        if not np.all(np.isfinite(v)):
            raise ValueError(f"parameter {name!r} must be finite, got {v!r}")


def check_positive(name: str, x) -> None:
    check_finite(name, x)
    if is_concrete(x):
        v = _values(x)
        if not np.all(v > 0):
            raise ValueError(f"parameter {name!r} must be > 0, got {v!r}")


def check_nonnegative(name: str, x) -> None:
    check_finite(name, x)
    if is_concrete(x):
        v = _values(x)
        if not np.all(v >= 0):
            raise ValueError(f"parameter {name!r} must be >= 0, got {v!r}")


def check_range(name: str, x, lo: float, hi: float) -> None:
    check_finite(name, x)
    if is_concrete(x):
        v = _values(x)
        if not np.all((v >= lo) & (v <= hi)):
            raise ValueError(f"parameter {name!r} must lie in [{lo}, {hi}], got {v!r}")


def bad_not_positive(x):
    x = jnp.asarray(x)
    return ~(jnp.isfinite(x) & (x > 0)), "must be finite and > 0"


def bad_negative(x):
    x = jnp.asarray(x)
    return ~(jnp.isfinite(x) & (x >= 0)), "must be finite and >= 0"


def bad_not_finite(x):
    return ~jnp.isfinite(jnp.asarray(x)), "must be finite"


def bad_outside(x, lo: float, hi: float):
    x = jnp.asarray(x)
    return ~(jnp.isfinite(x) & (x >= lo) & (x <= hi)), f"must lie in [{lo}, {hi}]"


def check(name: str, bad_and_requirement) -> tuple:
    """(predicate, message) pair for `guard`."""
    bad, req = bad_and_requirement
    return jnp.any(bad), f"parameter {name!r} {req}"


def guard(tree, checks):
    """Attach run-time checks to every leaf of `tree` (an output pytree).

    `eqx.error_if` is applied to the whole output, so the check cannot be removed as dead
    code while any output is used, and it raises under jit and vmap with the message that
    names the parameter.
    """
    for pred, msg in checks:
        tree = eqx.error_if(tree, pred, msg)
    return tree
