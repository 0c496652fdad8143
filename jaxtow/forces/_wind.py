"""Wind on the towed vessel as a tow-model force (thesis eqs 2.23-2.27)."""

from __future__ import annotations

import jax.numpy as jnp
from jaxtyping import Array, Float

from .._rules import FINITE, NONNEGATIVE, rule_field
from .._units import Scales
from ..resistance._flow import OCIMFLoad, relative_flow
from ._base import AbstractExternalForce


def _float(x):
    return jnp.asarray(x, dtype=float)


class WindForce(AbstractExternalForce):
    """Wind on the towed vessel as a tow-model force (`jaxtow.TowModel.external`; eqs
    2.23-2.27): the OCIMF ``load`` (e.g. ``barge2_resistance().wind``) at the relative wind of
    the barge's body velocity (u'U, v'U) in a wind of ``speed`` [m/s] from ``angle`` [rad]
    relative to the tug's course (0 = head wind), i.e. from ``angle − ψ`` relative to the
    bow; non-dimensional with ½ρTLU² (forces) and ½ρTL²U² (moment) of ``scales``. The yaw
    rate's effect on the apparent wind is neglected (quasi-steady loads)."""

    load: OCIMFLoad
    speed: jnp.ndarray = rule_field(rule=NONNEGATIVE, converter=_float)
    angle: jnp.ndarray = rule_field(rule=FINITE, converter=_float, default=0.0)
    scales: Scales = None  # type: ignore[assignment]  # required: checked below

    def __check_init__(self):
        if self.scales is None:
            raise ValueError("parameter 'scales' is required (e.g. jaxtow.presets.barge2_scales())")

    def dimensional(self, y: Float[Array, "6"]) -> Float[Array, "3"]:
        U = self.scales.u_tug
        return self.load(y[0] * U, y[1] * U, self.speed, self.angle - y[5])

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.scales.nondimensional(self.dimensional(y))

    def validity(self, y: Float[Array, "6"]) -> dict:
        """The relative wind the quasi-steady OCIMF load is evaluated at: speed [m/s] and the
        angle it comes from relative to the bow [rad]. The coefficient table covers the
        full circle, so the load itself has no validity limit to flag; the numbers let a
        result show which part of the table it used."""
        U = self.scales.u_tug
        U2, alpha = relative_flow(y[0] * U, y[1] * U, self.speed, self.angle - y[5])
        return dict(relative_wind_speed=jnp.sqrt(U2), relative_wind_angle=alpha)
