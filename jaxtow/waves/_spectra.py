"""Wave spectra: JONSWAP (thesis eq. 3.1), Pierson-Moskowitz, moments and periods.

All spectra are single-sided energy densities S(ω) in m²·s/rad over ω in rad/s, pure and
differentiable in their parameters (Hs, Tp, γ), vmappable over ω and over parameters.
"""

from __future__ import annotations

import abc
import math

import equinox as eqx
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Float

from .._program_cache import host_program
from .._rules import (
    FINITE,
    POSITIVE,
    Checked,
    at_least,
    check_positive,
    guard,
    is_concrete,
    rule_field,
)

#: g used by the thesis's sea-state relations (127.53 = 13 g and 294.30 = 30 g, eq. 3.5).
G_THESIS = 9.81


def _positive_omega(omega):
    omega = jnp.asarray(omega)
    pos = omega > 0
    return pos, jnp.where(pos, omega, 1.0)


def _bretschneider(omega, hs, tp):
    """320 Hs²/Tp⁴ ω⁻⁵ exp(−1950 ω⁻⁴ / Tp⁴): the base of thesis eq. 3.1 (Journée & Massie)."""
    pos, w = _positive_omega(omega)
    s = 320.0 * hs**2 / tp**4 * w**-5 * jnp.exp(-1950.0 / tp**4 * w**-4)
    return jnp.where(pos, s, 0.0)


def _peak_enhancement(omega, tp, gamma, sigma_a, sigma_b):
    wp = 2 * jnp.pi / tp
    sigma = jnp.where(omega <= wp, sigma_a, sigma_b)
    A = jnp.exp(-(((omega / wp - 1.0) / (sigma * jnp.sqrt(2.0))) ** 2))
    return gamma**A


def check_ascending(omega, name: str = "omega") -> None:
    """Eager check of an integration grid (skipped when traced): a finite 1-D array of at
    least two strictly ascending values. On a descending grid the trapezoidal rule changes
    sign; ValueError naming ``name`` instead."""
    if not is_concrete(omega):
        return
    w = np.asarray(omega, dtype=float)
    if w.ndim != 1 or w.size < 2 or not np.all(np.isfinite(w)):
        raise ValueError(
            f"parameter {name!r} must be a finite 1-D grid of at least 2 frequencies, got "
            f"shape {w.shape}"
        )
    if not np.all(np.diff(w) > 0):
        raise ValueError(f"parameter {name!r} must be strictly ascending")


def integrate_density(omega, y):
    """Trapezoidal rule over the given ω grid (last axis)."""
    check_ascending(omega)
    omega = jnp.asarray(omega)
    return jnp.sum(0.5 * (y[..., 1:] + y[..., :-1]) * jnp.diff(omega), axis=-1)


def jonswap_density(omega, hs, tp, gamma=3.3, sigma_a=0.07, sigma_b=0.09, normalise: bool = False):
    """The JONSWAP formula of `jonswap`, unchecked (the `Jonswap` sea state's fields are
    checked by their rules)."""
    if normalise:
        check_ascending(omega)  # eagerly, before the program (which sees no values)
    return _jonswap_density(omega, hs, tp, gamma, sigma_a, sigma_b, normalise=normalise)


@host_program(static_argnames=("normalise",))
def _jonswap_density(omega, hs, tp, gamma, sigma_a, sigma_b, *, normalise: bool):
    s = _bretschneider(omega, hs, tp) * _peak_enhancement(
        jnp.asarray(omega), tp, gamma, sigma_a, sigma_b
    )
    if normalise:
        s = s * (hs**2 / 16.0) / integrate_density(omega, s)
    return s


def jonswap(omega, *, hs, tp, gamma=3.3, sigma_a=0.07, sigma_b=0.09, normalise: bool = False):
    """JONSWAP spectrum S(ω) [m²s/rad], thesis eq. 3.1 (Journée & Massie form).

    S = 320 Hs²/Tp⁴ ω⁻⁵ exp(−1950 ω⁻⁴/Tp⁴) γ^A, A = exp(−((ω/ωp − 1)/(σ√2))²),
    σ = sigma_a (ω ≤ ωp) or sigma_b (ω > ωp). In this (thesis) form 4√m0 is not exactly Hs
    for γ ≠ 1. With ``normalise=True`` the spectrum is scaled so that 4√m0 = Hs exactly on the
    given ω grid (trapezoidal m0), as wavespectra does; the choice is explicit.
    Concrete invalid inputs (Hs <= 0, Tp <= 0, γ < 1) raise ValueError naming the parameter.
    """
    POSITIVE.check("hs", hs)
    POSITIVE.check("tp", tp)
    GAMMA_RULE.check("gamma", gamma)
    FINITE.check("omega", omega)
    s = jonswap_density(omega, hs, tp, gamma, sigma_a, sigma_b, normalise)
    # under jit or vmap the eager checks cannot see the values: the same rules, traced
    return guard(
        s,
        [
            POSITIVE.traced("hs", hs),
            POSITIVE.traced("tp", tp),
            GAMMA_RULE.traced("gamma", gamma),
            FINITE.traced("omega", omega),
        ],
    )


def pierson_moskowitz(omega, *, hs, tp):
    """Pierson-Moskowitz (Bretschneider / ITTC two-parameter) spectrum,
    S = 5/16 Hs² ωp⁴ ω⁻⁵ exp(−5/4 (ωp/ω)⁴), so that 4√m0 = Hs exactly.

    Note: the thesis form of eq. 3.1 with γ = 1 is *not* this spectrum: its constant 320
    (= 487/1.52) already holds the JONSWAP γ = 3.3 normalisation, and with γ = 1 it gives
    4√m0 = 0.81 Hs.
    """
    POSITIVE.check("hs", hs)
    POSITIVE.check("tp", tp)
    return guard(
        _pierson_moskowitz(omega, hs, tp),
        [POSITIVE.traced("hs", hs), POSITIVE.traced("tp", tp)],
    )


@host_program()
def _pierson_moskowitz(omega, hs, tp):
    """The formula of `pierson_moskowitz`, unchecked."""
    pos, w = _positive_omega(omega)
    wp = 2 * jnp.pi / tp
    return jnp.where(pos, 5.0 / 16.0 * hs**2 * wp**4 * w**-5 * jnp.exp(-1.25 * (wp / w) ** 4), 0.0)


class AbstractSpectrum(Checked):
    """A sea state as a pytree: ``spectrum(omega)`` → S(ω) [m²s/rad].

    Its fields are checked by their rules: eagerly at construction, and under tracing by
    the ``checks()`` of the model that holds it (`jaxtow.equilibria`, `jaxtow.eigenvalues`
    and the other entry points guard them; a sweep or `jaxtow.simulate` checks its values
    before it runs). Called by a user, ``spectrum(omega)`` checks its own fields (eagerly, or
    with `equinox.error_if` when traced; ``throw=False``: no check, see
    `jaxtow.parameter_status`). jaxtow's compiled programs evaluate `density`, which adds no
    check: a run-time check inside a compiled program is a host callback, and JAX's
    persistent cache never stores such a program."""

    hs: eqx.AbstractVar[Float[Array, ""]]
    tp: eqx.AbstractVar[Float[Array, ""]]

    @abc.abstractmethod
    def density(self, omega) -> Float[Array, "..."]:
        """S(ω) [m²s/rad], without a parameter check."""

    def __call__(self, omega, *, throw: bool = True) -> Float[Array, "..."]:
        S = self.density(omega)
        return guard(S, self.checks()) if throw else S

    @property
    def omega_peak(self):
        return 2 * jnp.pi / self.tp


#: The rule of the JONSWAP peak-enhancement factor γ (γ = 1 is Pierson-Moskowitz).
GAMMA_RULE = at_least(1.0)


class Jonswap(AbstractSpectrum):
    """JONSWAP sea state (thesis eq. 3.1); ``normalise`` as in `jonswap`."""

    hs: Float[Array, ""] = rule_field(rule=POSITIVE)
    tp: Float[Array, ""] = rule_field(rule=POSITIVE)
    gamma: Float[Array, ""] = rule_field(rule=GAMMA_RULE, default=3.3)
    sigma_a: Float[Array, ""] = rule_field(rule=POSITIVE, default=0.07)
    sigma_b: Float[Array, ""] = rule_field(rule=POSITIVE, default=0.09)
    normalise: bool = eqx.field(static=True, default=False)

    def density(self, omega):
        return jonswap_density(
            omega, self.hs, self.tp, self.gamma, self.sigma_a, self.sigma_b, self.normalise
        )


class PiersonMoskowitz(AbstractSpectrum):
    """Pierson-Moskowitz sea state (see `pierson_moskowitz`)."""

    hs: Float[Array, ""] = rule_field(rule=POSITIVE)
    tp: Float[Array, ""] = rule_field(rule=POSITIVE)

    def density(self, omega):
        return _pierson_moskowitz(omega, self.hs, self.tp)


def spectral_moment(omega, S, n):
    """m_n = ∫ ωⁿ S(ω) dω (trapezoidal rule on the given grid)."""
    omega = jnp.asarray(omega)
    return integrate_density(omega, omega**n * jnp.asarray(S))


class SpectralPeriods(eqx.Module):
    """`spectral_periods`'s answer: the significant wave height ``hs`` = 4√m0 [m], the mean
    period ``t1`` = 2π m0/m1, the zero-crossing period ``t2`` = 2π √(m0/m2) and the peak
    period ``tp`` [s] (thesis eq. 3.4)."""

    hs: Array
    t1: Array
    t2: Array
    tp: Array


def spectral_periods(omega, S) -> SpectralPeriods:
    """Hs = 4√m0, T1 = 2π m0/m1, T2 = 2π √(m0/m2) and the peak period Tp (thesis eq. 3.4).
    A spectrum of zero area (no sea: the periods are undefined) is refused eagerly."""
    m0, m1, m2 = (spectral_moment(omega, S, n) for n in (0, 1, 2))
    if is_concrete(m0) and not bool(np.all(np.asarray(m0) > 0)):
        raise ValueError(
            "parameter 'S' must have a positive area (m0 > 0): the periods of a calm sea are "
            "undefined"
        )
    omega = jnp.asarray(omega)
    return SpectralPeriods(
        hs=4 * jnp.sqrt(m0),
        t1=2 * jnp.pi * m0 / m1,
        t2=2 * jnp.pi * jnp.sqrt(m0 / m2),
        tp=2 * jnp.pi / omega[jnp.argmax(jnp.asarray(S), axis=-1)],
    )


def physical_tp_range(hs):
    """Physical peak-period range for a given Hs, thesis eq. 3.5 [s]:
    √(127.53 Hs/g) ≤ Tp ≤ √(294.30 Hs/g) (i.e. √(13 Hs) ≤ Tp ≤ √(30 Hs) with g = 9.81)."""
    check_positive("hs", hs)
    hs = jnp.asarray(hs)
    return jnp.sqrt(127.53 * hs / G_THESIS), jnp.sqrt(294.30 * hs / G_THESIS)


def hz_to_omega(f):
    """Frequency in Hz → rad/s."""
    return 2 * jnp.pi * jnp.asarray(f)


def period_to_omega(T):
    """Period in s → rad/s."""
    check_positive("T", T)
    return 2 * jnp.pi / jnp.asarray(T)


def spectrum_per_hz(S_omega):
    """S(f) [m²/Hz] = 2π S(ω) [m²s/rad]."""
    return 2 * jnp.pi * jnp.asarray(S_omega)


def check_frequency_grid(omega, tp, *, points_per_peak_width: float = 2.0) -> None:
    """Eager check that an ω grid resolves a spectrum with peak period ``tp``.

    Requires ascending positive ω covering 0.7 ωp … 2.5 ωp (the bulk of the energy), and a
    spacing near the peak of at most σa·ωp / points_per_peak_width (σa = 0.07 is the peak
    width of the JONSWAP enhancement). Raises ValueError naming 'omega' otherwise.
    """
    POSITIVE.check("tp", tp)
    w = np.asarray(omega, dtype=float)
    wp = 2 * math.pi / float(tp)
    if w.ndim != 1 or w.size < 3 or not np.all(np.isfinite(w)):
        raise ValueError("parameter 'omega' must be a finite 1-D grid of at least 3 frequencies")
    if not np.all(np.diff(w) > 0) or w[0] <= 0:
        raise ValueError("parameter 'omega' must be positive and strictly ascending")
    if w[0] > 0.7 * wp or w[-1] < 2.5 * wp:
        raise ValueError(
            f"parameter 'omega' must cover 0.7*wp..2.5*wp = {0.7 * wp:.3f}..{2.5 * wp:.3f} "
            f"rad/s for tp={float(tp)} s; got {w[0]:.3f}..{w[-1]:.3f}"
        )
    near = (w >= 0.8 * wp) & (w <= 1.2 * wp)
    dw = np.diff(w)[(near[:-1] | near[1:])]
    limit = 0.07 * wp / points_per_peak_width
    if dw.size == 0 or dw.max() > limit:
        got = float(dw.max()) if dw.size else float(np.max(np.diff(w)))
        raise ValueError(
            f"parameter 'omega' does not resolve the spectral peak: spacing {got:.4f} rad/s "
            f"near wp={wp:.3f} exceeds {limit:.4f} rad/s"
        )
