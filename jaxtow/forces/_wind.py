"""Wind on the towed vessel as a tow-model force (thesis eqs 2.23-2.27)."""

from __future__ import annotations

import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Float

from .._rules import FINITE, NONNEGATIVE, rule_field
from .._units import Scales
from ..resistance._flow import OCIMFLoad, relative_flow
from ..waves import GUST_BAND, npd_wind_spectrum
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


class GustWindForce(AbstractExternalForce):
    """Wind with gusts, for time-domain runs: the quasi-steady OCIMF load of ``wind`` (a
    `WindForce`) at the instantaneous wind speed U(t) = U0 + Σ a_k cos(ω_k t + φ_k), the
    components drawn from the NPD gust spectrum (`jaxtow.waves.npd_wind_spectrum`) about the
    mean speed U0 of ``wind`` (taken as the one-hour mean at 10 m), a_k = √(2 S(ω_k) Δω_k),
    one random frequency in each of ``n`` log-spaced bins over `jaxtow.waves.GUST_BAND`, and
    never below zero. The gusts are longitudinal (along the mean wind); its direction is
    the mean wind's. Build with `seeded`; `steady` is the mean wind."""

    wind: WindForce
    omega: jnp.ndarray  # (n,) component frequencies [rad/s]
    amplitude: jnp.ndarray  # (n,) a_k [m/s]
    phase: jnp.ndarray  # (n,) φ_k [rad]

    @classmethod
    def seeded(cls, wind: WindForce, *, seed: int = 0, n: int = 128, height: float = 10.0):
        """Components from ``seed``: ``n`` log-spaced bins over the gust band."""
        if not (isinstance(n, int) and n >= 2):
            raise ValueError(f"parameter 'n' must be an integer >= 2, got {n!r}")
        rng = np.random.default_rng(seed)
        edges = np.geomspace(*GUST_BAND, n + 1)
        w = edges[:-1] + rng.uniform(size=n) * np.diff(edges)
        S = np.asarray(npd_wind_spectrum(w, wind.speed, height))
        return cls(
            wind=wind,
            omega=jnp.asarray(w),
            amplitude=jnp.asarray(np.sqrt(2.0 * S * np.diff(edges))),
            phase=jnp.asarray(rng.uniform(0.0, 2 * np.pi, n)),
        )

    def speed(self, t) -> Float[Array, ""]:
        """U(t) [m/s] at non-dimensional time t."""
        sc = self.wind.scales
        ts = t * sc.length / sc.u_tug
        gust = jnp.sum(self.amplitude * jnp.cos(self.omega * ts + self.phase))
        return jnp.maximum(self.wind.speed + gust, 0.0)

    def dimensional(self, t, y: Float[Array, "6"]) -> Float[Array, "3"]:
        U = self.wind.scales.u_tug
        return self.wind.load(y[0] * U, y[1] * U, self.speed(t), self.wind.angle - y[5])

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.wind.scales.nondimensional(self.dimensional(t, y))

    def steady(self) -> WindForce:
        return self.wind

    def validity(self, y: Float[Array, "6"]) -> dict:
        return self.wind.validity(y)
