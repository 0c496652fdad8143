"""Analytic reference: mean drift on a fixed bottom-mounted vertical cylinder (MacCamy & Fuchs 1954).

A circular cylinder of radius a standing on the sea floor in water of depth h, in regular
waves of unit amplitude travelling along +x (time dependence e^{−iωt}, ω² = g k tanh kh).
The linear diffraction solution is exact (MacCamy & Fuchs, 1954, "Wave forces on piles: a
diffraction theory", US Army Beach Erosion Board TM 69). On the wall r = a:

    φ(θ, z) = −(i g / ω) C(z) f(θ),   C = cosh k(z+h) / cosh kh,
    f(θ) = Σ_m ε_m i^m · 2i / (π k a H_m^(1)'(ka)) · cos mθ      (ε_0 = 1, ε_m = 2),

using the Wronskian J_m H_m' − J_m' H_m = 2i/(π ka). The body is fixed, so the mean drift
force is parts I and II of the near-field formula (`jaxtow.bem.nearfield`) with
ζ = f(θ) on the waterline and ∇φ = (φ_θ/a) e_θ + φ_z e_z on the wall:

    F_x = −¼ρg a ∮ |f|² cos θ dθ
          + ¼ρ (g/ω)² a [ (I_C / a²) ∮ |f'|² cos θ dθ + k² I_S ∮ |f|² cos θ dθ ],
    I_C = (h/2 + sinh 2kh / 4k) / cosh² kh,   I_S = (sinh 2kh / 4k − h/2) / cosh² kh,

(in deep water, h = inf, I_C = I_S = 1/2k), evaluated here with the z integrals in closed form and the θ integrals by the trapezoidal
rule on 4(M + 1) points, exact for the truncated series of M + 1 terms (M = ka + 40).
Per unit wave amplitude squared [N/m²]. Needs SciPy (Hankel functions), which Capytaine
brings in.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import h1vp

from .._units import RHO_SEA, G


def wavenumber(omega, depth, g: float = G) -> float:
    """Root of ω² = g k tanh(k h) (Newton from the deep-water value)."""
    k = omega**2 / g
    if not math.isfinite(depth):
        return k
    for _ in range(100):
        t = math.tanh(k * depth)
        f = g * k * t - omega**2
        df = g * t + g * k * depth * (1 - t * t)
        k_new = k - f / df
        if abs(k_new - k) < 1e-15 * k:
            return k_new
        k = k_new
    return k


def _series(ka, n_terms):
    m = np.arange(n_terms)
    eps = np.where(m == 0, 1.0, 2.0)
    return m, eps * (1j) ** m * 2j / (math.pi * ka * h1vp(m, ka))


def _vertical(k, z, depth):
    """cosh k(z+h) / cosh kh and sinh k(z+h) / cosh kh without overflow (h may be inf)."""
    if not math.isfinite(depth):
        return np.exp(k * z), np.exp(k * z)
    a, b = np.exp(-2 * k * (z + depth)), math.exp(-2 * k * depth)
    return np.exp(k * z) * (1 + a) / (1 + b), np.exp(k * z) * (1 - a) / (1 + b)


def cylinder_wall_fields(radius, depth, omega, theta, z, *, g: float = G):
    """φ and ∇φ (Cartesian) on the wall at angles ``theta`` and heights ``z`` (broadcast
    together), per unit wave amplitude; returns (phi, velocity[..., 3])."""
    k = wavenumber(omega, depth, g)
    ka = k * radius
    m, coef = _series(ka, int(ka) + 40)
    th = np.asarray(theta, float)[..., None]
    f = np.sum(coef * np.cos(m * th), axis=-1)
    fp = np.sum(-m * coef * np.sin(m * th), axis=-1)
    th = th[..., 0]
    z = np.asarray(z, float)
    C, S = _vertical(k, z, depth)
    amp = -1j * g / omega
    phi = amp * C * f
    u_th = amp * C * fp / radius
    u_z = amp * k * S * f
    vel = np.stack([-np.sin(th) * u_th, np.cos(th) * u_th, u_z], axis=-1)
    return phi, vel


def cylinder_drift(radius, depth, omega, *, rho: float = RHO_SEA, g: float = G) -> float:
    """Exact mean surge drift F_x per ζa² [N/m²] on the fixed bottom-mounted cylinder (waves along +x)."""
    k = wavenumber(omega, depth, g)
    ka = k * radius
    n_terms = int(ka) + 40
    m, coef = _series(ka, n_terms)
    th = np.linspace(0.0, 2 * math.pi, 4 * (n_terms + 1), endpoint=False)
    f = np.cos(np.outer(th, m)) @ coef
    fp = (-np.sin(np.outer(th, m)) * m) @ coef
    w = 2 * math.pi / th.size
    ic = np.sum(np.abs(f) ** 2 * np.cos(th)) * w
    ip = np.sum(np.abs(fp) ** 2 * np.cos(th)) * w
    th = 1.0 if not math.isfinite(depth) else math.tanh(k * depth)
    e = 0.0 if not math.isfinite(depth) else math.exp(-2 * k * depth)
    h_sech2 = 0.0 if not math.isfinite(depth) else depth * 4 * e / (1 + e) ** 2  # h / cosh² kh
    I_C, I_S = 0.5 * h_sech2 + th / (2 * k), th / (2 * k) - 0.5 * h_sech2
    return float(
        -0.25 * rho * g * radius * ic
        + 0.25 * rho * (g / omega) ** 2 * radius * (I_C / radius**2 * ip + k**2 * I_S * ic)
    )
