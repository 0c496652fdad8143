"""Ursell's (1949) multipole solution for the heaving semicircle: an exact reference for the
strip sections, independent of jaxtow's code (NumPy and SciPy quadrature only).

F. Ursell, "On the heaving motion of a circular cylinder on the surface of a fluid", Quart.
J. Mech. Appl. Math. 2(2), 218-231 (1949). Polar coordinates about the centre on the free
surface, θ from the downward vertical (depth r cos θ, across r sin θ), K = ω²/g. The
potential is a wave source plus wave-free multipoles,

    φ ∝ cos σt [Φc + Σ p_2m Φ_2m] + sin σt [Φs + Σ q_2m Φ_2m],
    Φc = π e^{−Kr cos θ} cos(Kr sin θ),
    Φs = −∫₀^∞ e^{−kr sin θ} [k cos(kr cos θ) − K sin(kr cos θ)]/(K² + k²) dk
         + π e^{−Kr cos θ} sin(Kr sin θ),
    Φ_2m = (a/r)^{2m} [cos 2mθ + Kr/(2m − 1) cos(2m − 1)θ],

with the stream functions Ψ likewise; the coefficients p, q make the body a streamline of
the heave motion, found by least squares at collocation angles over the quarter circle.
The added mass and damping follow from the pressure on the body:

    a₃₃/(ρπa²/2) = (4/π)(M₀B + N₀A)/(A² + B²),
    b₃₃√(a/g)/(ρπa²/2) = (4σ√(a/g)/π)(M₀A − N₀B)/(A² + B²),

as set out by R. Castro's public notes on Ursell's solution (2025), which this follows.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad

__all__ = ["ursell_heave"]


def _fourier(K: float, r: float, t: float) -> tuple[float, float]:
    """(∫ k e^{−ks} cos(kc)/(K² + k²) dk, ∫ e^{−ks} sin(kc)/(K² + k²) dk) and the two with
    cos and sin exchanged, over k from 0 to ∞ (s = r sin θ, c = r cos θ), by QUADPACK's
    Fourier integrals (QAWF), which handle the slow decay near θ = 0."""
    s, c = r * math.sin(t), r * math.cos(t)

    def f(weight, numerator):
        if abs(c) < 1e-9:  # on the free surface: cos(kc) = 1, sin(kc) = 0
            return quad(
                lambda k: (
                    numerator(k)
                    * math.exp(-k * s)
                    / (K * K + k * k)
                    * (1.0 if weight == "cos" else 0.0)
                ),
                0.0,
                np.inf,
            )[0]
        return quad(
            lambda k: numerator(k) * math.exp(-k * s) / (K * K + k * k),
            0.0,
            np.inf,
            weight=weight,
            wvar=c,
        )[0]

    def kk(k):
        return k

    def one(k):
        return 1.0

    return f("cos", kk), f("sin", one), f("sin", kk), f("cos", one)


def _phi_s(K: float, r: float, t: float) -> float:
    kc, s1, _, _ = _fourier(K, r, t)
    return -(kc - K * s1) + math.pi * math.exp(-K * r * math.cos(t)) * math.sin(K * r * math.sin(t))


def _psi_s(K: float, r: float, t: float) -> float:
    _, _, ks, c1 = _fourier(K, r, t)
    return (ks + K * c1) - math.pi * math.exp(-K * r * math.cos(t)) * math.cos(K * r * math.sin(t))


def _psi_c(K: float, r: float, t: float) -> float:
    return math.pi * math.exp(-K * r * math.cos(t)) * math.sin(K * r * math.sin(t))


def _phi_c(K: float, r: float, t: float) -> float:
    return math.pi * math.exp(-K * r * math.cos(t)) * math.cos(K * r * math.sin(t))


def ursell_heave(omega_nd: float, *, n_multipoles: int = 12, n_angles: int = 40):
    """(a₃₃/(ρπa²/2), b₃₃/(ρπa²/2)·√(a/g)) of the heaving semicircle at ω√(a/g) (radius a
    = 1, g = 1: K = ω²)."""
    a = 1.0
    K = omega_nd**2
    Ka = K * a
    ms = np.arange(1, n_multipoles + 1)
    thetas = np.linspace(0.0, math.pi / 2, n_angles + 2)[1:-1]

    def f2m(m, t):
        return -math.sin(2 * m * t) - Ka / (2 * m - 1) * (
            math.sin((2 * m - 1) * t) - math.sin(t) * math.sin(math.pi * m - math.pi / 2)
        )

    F = np.array([[f2m(m, t) for m in ms] for t in thetas])
    rhs_c = np.array([_psi_c(K, a, t) - _psi_c(K, a, math.pi / 2) * math.sin(t) for t in thetas])
    rhs_s = np.array([_psi_s(K, a, t) - _psi_s(K, a, math.pi / 2) * math.sin(t) for t in thetas])
    p = np.linalg.lstsq(F, rhs_c, rcond=None)[0]
    q = np.linalg.lstsq(F, rhs_s, rcond=None)[0]
    sign = np.array([(-1.0) ** (m - 1) for m in ms])
    A = _psi_c(K, a, math.pi / 2) + np.sum(sign * Ka / (2 * ms - 1) * p)
    B = _psi_s(K, a, math.pi / 2) + np.sum(sign * Ka / (2 * ms - 1) * q)
    int_s = quad(lambda t: _phi_s(K, a, t) * math.cos(t), 0.0, math.pi / 2, limit=200)[0]
    int_c = quad(lambda t: _phi_c(K, a, t) * math.cos(t), 0.0, math.pi / 2, limit=200)[0]
    M0 = int_s + math.pi / 4 * Ka * q[0] + np.sum(sign * q / (4 * ms**2 - 1))
    N0 = int_c + math.pi / 4 * Ka * p[0] + np.sum(sign * p / (4 * ms**2 - 1))
    added = 4 / math.pi * (M0 * B + N0 * A) / (A * A + B * B)
    damping = 4 * omega_nd / math.pi * (M0 * A - N0 * B) / (A * A + B * B)
    return float(added), float(damping)
