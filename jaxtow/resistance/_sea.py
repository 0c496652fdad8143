"""The environment of a tow: waves, wind and current (thesis section 3.1, Table A.1)."""

from __future__ import annotations

import dataclasses

import equinox as eqx
import jax.numpy as jnp

from .._rules import FINITE, NONNEGATIVE, POSITIVE, Checked, rule_field
from ..waves._spectra import GAMMA_RULE


def _float(x):
    try:
        return jnp.asarray(x, dtype=float)
    except (TypeError, ValueError):
        return x  # not numeric: left for the eager check, which names the field


class SeaState(Checked):
    """Environment of a tow: JONSWAP waves (``hs`` [m], ``tp`` [s], ``gamma``), wind
    (``wind_speed`` [m/s] at the reference height of the wind table), current
    (``current_speed`` [m/s]) and the directions they come from relative to the course
    (``wave_angle``, ``wind_angle``, ``current_angle`` [rad], 0 = from ahead). ``hs = 0`` is
    calm water. All fields are arrays: vmap and grad over any of them."""

    hs: jnp.ndarray = rule_field(rule=NONNEGATIVE, converter=_float)
    tp: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    wind_speed: jnp.ndarray = rule_field(rule=NONNEGATIVE, converter=_float, default=0.0)
    current_speed: jnp.ndarray = rule_field(rule=NONNEGATIVE, converter=_float, default=0.0)
    gamma: jnp.ndarray = rule_field(rule=GAMMA_RULE, converter=_float, default=3.3)
    wave_angle: jnp.ndarray = rule_field(rule=FINITE, converter=_float, default=0.0)
    wind_angle: jnp.ndarray = rule_field(rule=FINITE, converter=_float, default=0.0)
    current_angle: jnp.ndarray = rule_field(rule=FINITE, converter=_float, default=0.0)
    name: str = eqx.field(static=True, default="")

    def unnamed(self) -> SeaState:
        """The same sea without its name, as the compiled programs take it: the name is
        static, so each named sea state would be a new argument type to every kernel (a
        new trace and compile of each)."""
        return dataclasses.replace(self, name="") if self.name else self
