"""Towline laws and the bow-hawser attachment point.

A towline carries no compression: the tension is exactly zero while the line is shorter
than its unstretched length (slack). The switch is exact (not smoothed), so a slack line is
never hidden inside a stability result; equilibria report whether the line is taut.
"""

from __future__ import annotations

import abc

import equinox as eqx
import jax.numpy as jnp
from jaxtyping import Array, Float

from . import _validate as V

_f = dict(converter=jnp.asarray)

#: Documented range of the bow-hawser attachment point x_p' (distance of the attachment
#: point ahead of the CoG in ship lengths): from the CoG (0) to a bridle apex half a ship
#: length ahead of the bow of a vessel with its CoG amidships (1.0).
XP_RANGE = (0.0, 1.0)


class AbstractTowline(eqx.Module):
    """A towline of unstretched length ``l0`` attached at ``xp`` ahead of the CoG.

    Subclasses define `tension` (T' as a function of the current length l') and its inverse
    `length_at_tension`, used to place equilibria (thesis eq. 6.13 generalised).
    """

    l0: eqx.AbstractVar[Float[Array, ""]]
    xp: eqx.AbstractVar[Float[Array, ""]]

    @abc.abstractmethod
    def tension(self, l) -> Float[Array, ""]:
        """Towline tension T'(l') >= 0."""

    @abc.abstractmethod
    def length_at_tension(self, T) -> Float[Array, ""]:
        """Stretched length l' carrying tension T' > 0."""

    @abc.abstractmethod
    def checks(self) -> list:
        """Run-time (traceable) parameter checks, see `jaxtow._validate.guard`."""


def _check_common(l0, xp):
    V.check_positive("l0", l0)
    V.check_range("xp", xp, *XP_RANGE)


def _checks_common(line):
    return [V.check("l0", V.bad_not_positive(line.l0)),
            V.check("xp", V.bad_outside(line.xp, *XP_RANGE))]


class Towline(AbstractTowline):
    """Linear elastic towline, thesis eq. 2.11: T' = EA' (l'/l0' − 1) when taut, else 0.

    ``l0``: unstretched length / L; ``xp``: attachment point ahead of the CoG / L;
    ``EA``: axial stiffness / (½ρTLU_tug²).
    """

    l0: Float[Array, ""] = eqx.field(**_f)
    xp: Float[Array, ""] = eqx.field(**_f)
    EA: Float[Array, ""] = eqx.field(**_f)

    def __check_init__(self):
        _check_common(self.l0, self.xp)
        V.check_positive("EA", self.EA)

    def tension(self, l):
        return self.EA * jnp.maximum(l / self.l0 - 1.0, 0.0)

    def length_at_tension(self, T):
        return self.l0 * (1.0 + T / self.EA)

    def checks(self):
        return _checks_common(self) + [V.check("EA", V.bad_not_positive(self.EA))]


class PowerLawTowline(AbstractTowline):
    """Bernitsas & Kekridis synthetic-line law, thesis eq. 2.22: T' = Sb' (l'/l0' − 1)^q.

    Used for nylon and polyester lines (q > 1 stiffens with stretch). ``Sb``: stiffness
    scale / (½ρTLU_tug²); ``q``: exponent (> 0).
    """

    l0: Float[Array, ""] = eqx.field(**_f)
    xp: Float[Array, ""] = eqx.field(**_f)
    Sb: Float[Array, ""] = eqx.field(**_f)
    q: Float[Array, ""] = eqx.field(**_f)

    def __check_init__(self):
        _check_common(self.l0, self.xp)
        V.check_positive("Sb", self.Sb)
        V.check_positive("q", self.q)

    def tension(self, l):
        strain = l / self.l0 - 1.0
        taut = strain > 0.0
        safe = jnp.where(taut, strain, 1.0)  # keeps the gradient finite where slack
        return jnp.where(taut, self.Sb * safe**self.q, 0.0)

    def length_at_tension(self, T):
        Tpos = T > 0.0
        safe = jnp.where(Tpos, T, 1.0)
        return self.l0 * (1.0 + jnp.where(Tpos, (safe / self.Sb) ** (1.0 / self.q), 0.0))

    def checks(self):
        return _checks_common(self) + [V.check("Sb", V.bad_not_positive(self.Sb)),
                                       V.check("q", V.bad_not_positive(self.q))]
