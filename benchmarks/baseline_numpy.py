"""Plain NumPy/SciPy implementation of the calm-water stability map, for benchmarks.

The same physics as jaxtow (thesis eqs 6.1-6.13), written the way a MATLAB/NumPy workflow
does it: a Python loop over grid points, the analytic equilibria (eqs 6.7-6.13), a central
finite-difference Jacobian and `numpy.linalg.eigvals`.
"""

from __future__ import annotations

import math

import numpy as np


def vector_field(y, p):
    u, v, r, l, g, psi = y
    T = p["EA"] * max(l / p["l0"] - 1.0, 0.0)
    a = g + psi
    sa, ca = math.sin(a), math.cos(a)
    X = (
        -p["R0"] * u * abs(u)
        + p["Xvv"] * v * v
        + p["Xrr"] * r * r
        + T * ca
        + (p["m"] + p["a22"]) * v * r
    )
    Y = (
        p["Yv"] * v
        + p["Yr"] * r
        + p["Yvvv"] * v**3
        + p["Yrrr"] * r**3
        - T * sa
        - (p["m"] + p["a11"]) * u * r
    )
    N = p["Nv"] * v + p["Nr"] * r + p["Nvvv"] * v**3 - T * p["xp"] * sa
    xp = p["xp"]
    ldot = -u * ca + v * sa + math.cos(g) + r * xp * sa
    gdot = (u * sa + v * ca - math.sin(g) + r * xp * ca) / l
    return np.array(
        [X / (p["m"] + p["a11"]), Y / (p["m"] + p["a22"]), N / (p["Izz"] + p["a66"]), ldot, gdot, r]
    )


def fd_jacobian(y, p, h=1e-6, field=None):
    """Central finite-difference Jacobian of ``field`` (default: the calm-water field)."""
    f = vector_field if field is None else field
    J = np.empty((6, 6))
    for i in range(6):
        e = np.zeros(6)
        e[i] = h
        J[:, i] = (f(y + e, p) - f(y - e, p)) / (2 * h)
    return J


def analytic_equilibria(p):
    """Eqs 6.7-6.13; returns a list of (slot, state) for slots (ψ<0, straight, ψ>0)."""
    out = []
    rad = (p["Nv"] - p["Yv"] * p["xp"]) / (p["Yvvv"] * p["xp"] - p["Nvvv"])
    vs = [0.0]
    slots = [1]
    if 0 < rad < 1:
        vs = [math.sqrt(rad), 0.0, -math.sqrt(rad)]
        slots = [0, 1, 2]
    for slot, v in zip(slots, vs):
        psi = math.asin(-v)
        u = math.cos(psi)
        num = p["R0"] * u * u - p["Xvv"] * v * v
        g = math.atan((p["Yvvv"] * v**3 + p["Yv"] * v) / num) - psi
        T = num / math.cos(g + psi)
        l = (T / p["EA"] + 1.0) * p["l0"]
        out.append((slot, np.array([u, v, 0.0, l, g, psi])))
    return out


def stability_map(params: dict, xp: np.ndarray, l0: np.ndarray) -> np.ndarray:
    """max Re λ per (point, slot) for flat arrays xp, l0 (NaN where a slot is empty)."""
    res = np.full((xp.size, 3), np.nan)
    p = dict(params)
    for k in range(xp.size):  # the baseline's Python loop over grid points
        p["xp"], p["l0"] = float(xp[k]), float(l0[k])
        for slot, y in analytic_equilibria(p):
            res[k, slot] = np.linalg.eigvals(fd_jacobian(y, p)).real.max()
    return res
