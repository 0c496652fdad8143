"""The wind gust spectrum: the NPD (Frøya) spectrum of ISO 19901-1 and DNV-RP-C205.

    S(f) = 320 (U0/10)² (z/10)^0.45 / (1 + f̃^n)^(5/(3n))   [m²/s² per Hz],
    f̃ = 172 f (z/10)^(2/3) (U0/10)^(−3/4),   n = 0.468,

for the longitudinal gusts at height z [m] about the one-hour mean wind speed U0 at 10 m
[m/s] (Andersen & Løvseth's fit to the Frøya measurements, adopted by the Norwegian
Petroleum Directorate, ISO 19901-1 and DNV-RP-C205 section 2.3). jaxtow uses it in rad/s:
S(ω) = S(f)/(2π).
"""

from __future__ import annotations

import math

import jax.numpy as jnp
from jaxtyping import Array, ArrayLike, Float

from .._rules import NONNEGATIVE, POSITIVE, Checked, rule_field

__all__ = ["NPD_EXPONENT", "GUST_BAND", "npd_wind_spectrum", "NPDWind"]

#: The exponent n of the NPD spectrum.
NPD_EXPONENT = 0.468
#: The band of gust frequencies [rad/s] jaxtow synthesises: periods from 2,500 s (slower
#: changes are the mean wind's) to 2 s (faster gusts do not move a barge on its towline).
GUST_BAND = (2 * math.pi / 2500.0, 2 * math.pi / 2.0)


def _float(x):
    return jnp.asarray(x, dtype=float)


def npd_wind_spectrum(
    omega: Float[ArrayLike, "..."], mean_speed: ArrayLike, height: ArrayLike = 10.0
) -> Float[Array, "..."]:
    """The NPD gust spectrum S(ω) [m²/s² per rad/s] at ``omega`` [rad/s] for the one-hour
    mean wind ``mean_speed`` U0 at 10 m [m/s] and the ``height`` z [m] (module docstring)."""
    f = jnp.asarray(omega, dtype=float) / (2 * math.pi)
    u = jnp.asarray(mean_speed, dtype=float) / 10.0
    z = jnp.asarray(height, dtype=float) / 10.0
    n = NPD_EXPONENT
    ft = 172.0 * jnp.abs(f) * z ** (2.0 / 3.0) * jnp.maximum(u, 1e-12) ** (-0.75)
    S = 320.0 * u**2 * z**0.45 / (1.0 + ft**n) ** (5.0 / (3.0 * n))
    return S / (2 * math.pi)


class NPDWind(Checked):
    """The gusts of a wind: one-hour mean ``mean_speed`` U0 at 10 m [m/s] and the ``height``
    [m] where they act (`npd_wind_spectrum`)."""

    mean_speed: jnp.ndarray = rule_field(rule=NONNEGATIVE, converter=_float)
    height: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float, default=10.0)

    def density(self, omega):
        """S(ω) [m²/s² per rad/s]."""
        return npd_wind_spectrum(omega, self.mean_speed, self.height)
