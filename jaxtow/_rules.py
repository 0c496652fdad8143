"""Validation rules: one declaration per parameter gives both the eager and the traced check.

A `Rule` is a predicate with the words of its requirement. Declared once on a field,

    EA: Float[Array, ""] = rule_field(rule=POSITIVE)

it yields

* the **eager** check: when the value is concrete (construction, `with_parameters` on
  numbers, the grids of a sweep before anything runs), a `ValueError` that names the
  parameter, says what was expected and what was given;
* the **traced** check: a ``(predicate, message)`` pair with the same words, which `guard`
  attaches to an output with `equinox.error_if`, so that invalid values arriving as tracers
  raise under `jax.jit` and `jax.vmap`.

Every parameter class derives from `Checked`: its ``__check_init__`` runs the eager rule of
every declared field, and its ``checks()`` returns the traced rules of its own fields and of
every `Checked` module inside it (a `TowModel` covers its vessel, towline and external force,
down to the spectrum of an irregular sea). `rule_of` finds the rule of a field by name, for
the eager check of a sweep grid. Changing a rule changes both checks.

Sweeps do not use the traced checks per point (one bad point would abort the batch); they
validate the whole grid eagerly before running (see `jaxtow.sweep`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jax.core import Tracer
from jaxtyping import Array, Bool, Int


class ParameterError(ValueError):
    """A bad value of a named parameter: ``parameter`` is its name, so that a caller (a tow
    file's reader naming its key) need not read the message."""

    def __init__(self, parameter: str, message: str):
        super().__init__(message)
        self.parameter = parameter


def is_concrete(x) -> bool:
    """True if ``x`` holds concrete values (not a JAX tracer)."""
    return not isinstance(x, Tracer)


def holds_tracers(tree) -> bool:
    """True if any leaf of ``tree`` is a tracer (a model traced by the caller's own jit or
    vmap: only a run-time check sees its values)."""
    return not all(is_concrete(x) for x in jax.tree_util.tree_leaves(tree))


@dataclasses.dataclass(eq=False)
class Rule:
    """A validation rule: ``ok(xp, x)`` is the elementwise predicate written once for both
    array namespaces (``xp`` is `numpy` eagerly, `jax.numpy` when traced); ``requirement``
    completes the sentence "parameter 'name' ..."."""

    requirement: str
    ok: Callable[[Any, Any], Any]

    def check(self, name: str, x) -> None:
        """Eager: raise a `ValueError` naming ``name`` if a concrete ``x`` breaks the rule."""
        if not is_concrete(x):
            return
        try:
            v = np.asarray(x, dtype=float)
        except (TypeError, ValueError):
            raise ParameterError(name, f"parameter {name!r} must be a number, got {x!r}") from None
        with np.errstate(invalid="ignore"):
            good = np.all(self.ok(np, v))
        if not good:
            raise ParameterError(name, f"parameter {name!r} {self.requirement}, got {v!r}")

    def traced(self, name: str, x) -> tuple:
        """Traced: the ``(predicate, message)`` pair for `guard` (predicate True = bad). A
        concrete ``x`` (an eager check: `check_now`, `guard`) is tested with NumPy, which
        compiles nothing (each eager `jax.numpy` operation is a program of its own)."""
        message = f"parameter {name!r} {self.requirement}"
        if is_concrete(x):
            with np.errstate(invalid="ignore"):
                return np.any(~self.ok(np, np.asarray(x))), message
        return jnp.any(~self.ok(jnp, jnp.asarray(x))), message


FINITE = Rule("must be finite", lambda xp, x: xp.isfinite(x))
POSITIVE = Rule("must be > 0 and finite", lambda xp, x: xp.isfinite(x) & (x > 0))
NONNEGATIVE = Rule("must be >= 0 and finite", lambda xp, x: xp.isfinite(x) & (x >= 0))


def in_range(lo: float, hi: float) -> Rule:
    """The rule lo <= x <= hi (finite)."""
    return Rule(f"must lie in [{lo}, {hi}]", lambda xp, x: xp.isfinite(x) & (x >= lo) & (x <= hi))


def at_least(lo: float) -> Rule:
    """The rule x >= lo (finite)."""
    return Rule(f"must be >= {lo} and finite", lambda xp, x: xp.isfinite(x) & (x >= lo))


def _asarray(x):
    try:
        return jnp.asarray(x)
    except (TypeError, ValueError):
        return x  # not numeric: left for the eager check, which names the field


def _is_scalar_field(f) -> bool:
    """A field annotated as a scalar array (``Float[Array, ""]``)."""
    return 'Array, ""]' in str(f.type) or "Array, '']" in str(f.type)


def _rule_field(*, rule: Rule, **kwargs):
    """An array field (converted with `jnp.asarray`) validated by ``rule``."""
    kwargs.setdefault("converter", _asarray)
    metadata = dict(kwargs.pop("metadata", {}), rule=rule)
    return eqx.field(metadata=metadata, **kwargs)


if TYPE_CHECKING:  # a field specifier to type checkers (dataclass_transform), like eqx.field
    rule_field = eqx.field
else:
    rule_field = _rule_field


def _rules(obj) -> list:
    return [(f.name, f.metadata["rule"]) for f in dataclasses.fields(obj) if "rule" in f.metadata]


def rule_of(obj, name: str) -> Rule | None:
    """The rule declared on field ``name`` of module ``obj`` (None if it has none)."""
    return dict(_rules(obj)).get(name)


def _children(value):
    if isinstance(value, Checked):
        return [value]
    if isinstance(value, (tuple, list)):
        return [c for v in value for c in _children(v)]
    return []


class Checked(eqx.Module):
    """Base of every parameter class: the eager checks at construction and the traced
    ``checks()``, both from the rules declared on its fields (`rule_field`)."""

    def __check_init__(self):
        scalar = {f.name for f in dataclasses.fields(self) if _is_scalar_field(f)}
        for name, rule in _rules(self):
            value = getattr(self, name)
            if value is None:  # an optional field left out
                continue
            rule.check(name, value)
            if name in scalar and is_concrete(value) and np.ndim(value) != 0:
                raise ParameterError(
                    name,
                    f"parameter {name!r} must be a single number, got shape {np.shape(value)} "
                    "(to evaluate many values, sweep it: jaxtow.sweep, or jax.vmap over "
                    "jaxtow.with_parameters)",
                )

    def checks(self) -> list:
        """Traced ``(predicate, message)`` checks of this module's fields and of every
        `Checked` module inside it; apply them to an output with `guard`."""
        out = [
            rule.traced(name, getattr(self, name))
            for name, rule in _rules(self)
            if getattr(self, name) is not None
        ]
        for f in dataclasses.fields(self):
            for child in _children(getattr(self, f.name, None)):
                out += child.checks()
        return out


def check_now(module: Checked) -> None:
    """Eager: raise a `ValueError` with the first failing rule of a concrete module and every
    module inside it (one edited with `eqx.tree_at`, which bypasses the constructor's check;
    nothing is checked for traced values, which `guard` covers)."""
    for pred, msg in module.checks():
        if is_concrete(pred) and bool(pred):
            raise ValueError(msg)


def check_type(name: str, value, cls: type) -> None:
    """Eager: a `TypeError` naming ``name`` unless ``value`` is a ``cls``."""
    if not isinstance(value, cls):
        raise TypeError(
            f"parameter {name!r} must be a {cls.__module__.split('._')[0]}.{cls.__name__}, "
            f"got {type(value).__name__} {value!r}"
        )


# eager checks of function arguments, from the same rules
def check_finite(name: str, x) -> None:
    FINITE.check(name, x)


def check_positive(name: str, x) -> None:
    POSITIVE.check(name, x)


def check_nonnegative(name: str, x) -> None:
    NONNEGATIVE.check(name, x)


def check_range(name: str, x, lo: float, hi: float) -> None:
    in_range(lo, hi).check(name, x)


def guard(tree, checks):
    """Attach run-time checks to every leaf of ``tree`` (an output pytree).

    `eqx.error_if` is applied to the whole output, so the check cannot be removed as dead
    code while any output is used, and it raises under jit and vmap with the message that
    names the parameter. A concrete predicate (an eager call) is checked here instead, with
    a `ValueError`: an eager `eqx.error_if` compiles a small program holding a host
    callback on every call, which JAX's persistent cache never stores (63 of them in each
    ``jaxtow calm``).
    """
    for pred, msg in checks:
        if is_concrete(pred):
            if bool(np.any(np.asarray(pred))):
                raise ValueError(msg)
        else:
            tree = eqx.error_if(tree, pred, msg)
    return tree


class ParameterStatus(eqx.Module):
    """The result code of a model's parameter checks (`parameter_status`): ``code`` 0 when
    every rule holds, else 1 + the index of the first failing check in ``messages`` (the
    sentences of `Checked.checks`, in order). Jittable and vmappable (``code`` then has the
    batch shape); read it with ``ok`` and, eagerly, `message` or `raise_if_invalid`."""

    code: Int[Array, "..."]
    messages: tuple[str, ...] = eqx.field(static=True)

    @property
    def ok(self) -> Bool[Array, "..."]:
        """True where every parameter is valid."""
        return self.code == 0

    def message(self) -> str | None:
        """Eager: the sentence of the first failing check (of the first failing member of a
        batch), None when all hold."""
        codes = np.ravel(np.asarray(self.code))
        bad = codes[codes > 0]
        return self.messages[int(bad[0]) - 1] if bad.size else None

    def raise_if_invalid(self) -> None:
        """Eager: a `ValueError` with `message` if any check fails."""
        msg = self.message()
        if msg is not None:
            raise ValueError(msg)


def parameter_status(model: Checked) -> ParameterStatus:
    """The result code of every parameter check of ``model`` (and of every module inside it),
    without a host callback: the way to see the checks from inside a plain `jax.jit`, where
    an `equinox.error_if` message stands below XLA's "CpuCallback error" line. Call the
    numerical functions with ``throw=False`` and return this beside their outputs::

        @jax.jit
        def run(model):
            return jaxtow.equilibria_fixed(model, throw=False), jaxtow.parameter_status(model)

        eqs, status = run(model)
        status.raise_if_invalid()  # "parameter 'EA' must be > 0 and finite"
    """
    checks = model.checks()
    if not checks:
        return ParameterStatus(code=jnp.asarray(0, jnp.int32), messages=())
    bad = jnp.stack([jnp.asarray(p, bool) for p, _ in checks])
    code = jnp.where(jnp.any(bad), jnp.argmax(bad) + 1, 0).astype(jnp.int32)
    return ParameterStatus(code=code, messages=tuple(m for _, m in checks))
