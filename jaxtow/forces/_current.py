"""A uniform current on the towed vessel as a tow-model force: what the current adds to the
hull's own calm-water forces (thesis eqs 2.23-2.27, fig. 7.1b)."""

from __future__ import annotations

import jax.numpy as jnp
from jaxtyping import Array, Float

from .._rules import FINITE, NONNEGATIVE, check_type, rule_field
from .._units import Scales
from ..resistance._flow import OCIMFLoad
from ._base import AbstractExternalForce


def _float(x):
    return jnp.asarray(x, dtype=float)


class CurrentForce(AbstractExternalForce):
    """A current of ``speed`` [m/s] from ``angle`` [rad] relative to the tug's course (0: head
    current) on the towed vessel: the hull ``load`` (the OCIMF form of the vessel's own
    manoeuvring derivatives, `jaxtow.resistance.TowResistance.hull`) at the relative flow of
    the barge's body velocity (u'U, v'U) in the current, less the same load in still water,
    which the tow model's manoeuvring forces already hold. So a tow in a current carries the
    hull resistance of the resistance budget (`jaxtow.resistance.resistance`, its
    ``current`` component) at every speed, and at the operating speed the towline tension
    equals the tug's pull. Quasi-steady: the yaw rate's effect on the relative flow is left
    out, as in `WindForce`."""

    load: OCIMFLoad
    speed: jnp.ndarray = rule_field(rule=NONNEGATIVE, converter=_float)
    angle: jnp.ndarray = rule_field(rule=FINITE, converter=_float, default=0.0)
    scales: Scales = None  # type: ignore[assignment]  # required: checked below

    def __check_init__(self):
        if self.scales is None:
            raise ValueError("parameter 'scales' is required (e.g. jaxtow.presets.barge2_scales())")
        check_type("load", self.load, OCIMFLoad)

    def dimensional(self, y: Float[Array, "6"]) -> Float[Array, "3"]:
        U = self.scales.u_tug
        u, v, alpha = y[0] * U, y[1] * U, self.angle - y[5]
        return self.load(u, v, self.speed, alpha) - self.load(u, v, 0.0, alpha)

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.scales.nondimensional(self.dimensional(y))
