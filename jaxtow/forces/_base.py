"""The environmental-force hook of the tow model and the generic forces built on it."""

from __future__ import annotations

import abc
import dataclasses

import jax.numpy as jnp
from jaxtyping import Array, Float

from .._rules import FINITE, Checked, is_concrete, rule_field


class AbstractExternalForce(Checked):
    """Hook for environmental forces (waves, wind, current) on the towed vessel.

    ``__call__(t, y, model)`` returns the non-dimensional body-axis forces
    (X', Y', N') at the CoG, in the same scales as the manoeuvring forces (thesis eqs
    6.14-6.16). Forces may depend on time and on (u, v, r, ψ); they must not depend on the
    towline state (l, γ). Equilibria evaluate the hook at t = 0 and therefore assume the
    force is time-invariant (mean forces); time-varying parts belong to time-domain runs.
    """

    @abc.abstractmethod
    def __call__(self, t, y, model) -> Float[Array, "3"]: ...

    def validity(self, y) -> dict:
        """The physics' own validity limits of this force at state y, as named boolean
        flags (True = valid) and the numbers behind them; none by default."""
        return {}

    def steady(self) -> AbstractExternalForce:
        """This force for the states of a steady tow, yaw rate r = 0 (the equilibria): it
        may leave out the terms proportional to r, whose value there is zero, so that the
        equilibrium scans do not trace and compile them. Its value and its derivatives
        along steady states equal this force's; not for Jacobians or time-domain runs.
        By default the force itself."""
        return self


class NoExternalForce(AbstractExternalForce):
    """Calm water, no wind: zero environmental force."""

    def __call__(self, t, y, model):
        return jnp.zeros(3, dtype=jnp.result_type(y))


class ConstantBodyForce(AbstractExternalForce):
    """A constant body-axis force (X', Y', N'), e.g. a mean drift force in a fixed heading
    frame or a test load."""

    force: Float[Array, "3"] = rule_field(rule=FINITE)

    def __check_init__(self):
        if is_concrete(self.force) and jnp.shape(self.force) != (3,):
            raise ValueError(f"parameter 'force' must have shape (3,), got {jnp.shape(self.force)}")

    def __call__(self, t, y, model):
        return self.force.astype(jnp.result_type(y))


class CombinedForce(AbstractExternalForce):
    """The sum of several environmental forces, e.g. wave drift and wind:
    ``CombinedForce((waves, wind))``; sweep their parameters by path, e.g.
    ``external.forces.0.omega`` (see `jaxtow.with_parameters`)."""

    forces: tuple

    def steady(self) -> CombinedForce:
        return dataclasses.replace(self, forces=tuple(f.steady() for f in self.forces))

    def __call__(self, t, y, model):
        out = jnp.zeros(3, dtype=jnp.result_type(y))
        for f in self.forces:  # a static handful of forces
            out = out + f(t, y, model)
        return out

    def validity(self, y) -> dict:
        """The flags of every force, merged: a flag two forces share holds where it holds
        for both (logical and); a shared number is taken from the first force."""
        out: dict = {}
        for f in self.forces:
            for k, v in f.validity(y).items():
                if k in out and jnp.asarray(v).dtype == bool:
                    out[k] = out[k] & v
                else:
                    out.setdefault(k, v)
        return out


def force_terms(external) -> list:
    """The terms of a tow model's ``external`` force as a list (a `CombinedForce`'s forces,
    a single force, or none)."""
    if external is None:
        return []
    return list(external.forces) if isinstance(external, CombinedForce) else [external]


def combine(forces) -> AbstractExternalForce | None:
    """The one ``external`` force of a list of terms (None, the one force, or their
    `CombinedForce`): the inverse of `force_terms`."""
    forces = list(forces)
    return None if not forces else forces[0] if len(forces) == 1 else CombinedForce(tuple(forces))
