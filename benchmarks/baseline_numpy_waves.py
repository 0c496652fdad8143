"""Plain NumPy/SciPy stability map of the tow in regular head waves, for benchmarks.

The same physics as jaxtow's `WaveDriftForce` tow model (thesis eqs 6.1-6.6, 6.14-6.23,
2.35-2.41) written the way a MATLAB/NumPy workflow does it: a Python loop over the grid
points, `scipy.optimize.fsolve` on the six steady-state equations from several starting
headings, a central finite-difference Jacobian, `numpy.linalg.eigvals`; the QTF is the same
cubic Hermite interpolant (ported to NumPy) and the forward-speed drift is Aranha's finite
form (jaxtow's default), with the yaw-rate column when the table has sectional moments.
"""

from __future__ import annotations

import math

import numpy as np
from baseline_numpy import fd_jacobian, vector_field as calm_field
from scipy.optimize import fsolve

G = 9.80665


def _slopes(x, y, periodic=False):
    h = np.diff(x)
    h0, h1 = h[:-1], h[1:]
    mid = (h0**2 * y[..., 2:] - h1**2 * y[..., :-2] + (h1**2 - h0**2) * y[..., 1:-1]) / (
        h0 * h1 * (h0 + h1)
    )
    if periodic:
        a, b = h[-1], h[0]
        first = last = (a**2 * y[..., 1] - b**2 * y[..., -2] + (b**2 - a**2) * y[..., 0]) / (
            a * b * (a + b)
        )
    else:
        first = (y[..., 1] - y[..., 0]) / h[0]
        last = (y[..., -1] - y[..., -2]) / h[-1]
    return np.concatenate([np.asarray(first)[..., None], mid, np.asarray(last)[..., None]], axis=-1)


def _hermite(x, y, m, xq):
    xq = min(max(xq, x[0]), x[-1])
    i = min(max(int(np.searchsorted(x, xq, side="right")) - 1, 0), x.size - 2)
    h = x[i + 1] - x[i]
    t = (xq - x[i]) / h
    t2, t3 = t * t, t * t * t
    return (
        (2 * t3 - 3 * t2 + 1) * y[..., i]
        + (t3 - 2 * t2 + t) * h * m[..., i]
        + (-2 * t3 + 3 * t2) * y[..., i + 1]
        + (t3 - t2) * h * m[..., i + 1]
    )


class NumpyQTF:
    """jaxtow's QTF interpolant in NumPy (ω → 0 virtual node, flat ends, periodic β)."""

    def __init__(self, omega, beta, values, periodic):
        self.w = np.concatenate([[0.0], omega])
        self.v = np.moveaxis(np.concatenate([np.zeros_like(values[:, :1]), values], axis=1), 1, -1)
        self.m = _slopes(self.w, self.v)
        self.m[..., 0] = 0.0
        self.m[..., -1] = 0.0
        self.b, self.periodic = beta, periodic

    def __call__(self, omega, beta):
        along = _hermite(self.w, self.v, self.m, max(omega, 0.0))
        if self.periodic:
            beta = (beta + math.pi) % (2 * math.pi) - math.pi
        return _hermite(self.b, along, _slopes(self.b, along, self.periodic), beta)


def _aranha(q, omega0, beta, u, v):
    c, s = math.cos(beta), math.sin(beta)
    along, across = u * c + v * s, -u * s + v * c
    we = omega0 + omega0**2 / G * along
    be = beta + 2 * omega0 / G * across
    return (1 + 4 * omega0 * along / G) * q(we, be)


def sailing_drift(q, omega0, beta, u, v, r=0.0, moments=None, h=1e-6):
    """Aranha's finite form [1 + (4ω/g) U·ê] F(ω_e, β_e) (jaxtow's default) plus, with the
    sectional ``moments`` table, the yaw-rate column r ∂_v(M_x1, M_y1, M_y2) (a central
    difference here, autodiff in jaxtow)."""
    F = _aranha(q, omega0, beta, u, v)
    if moments is not None:
        col = (_aranha(moments, omega0, beta, 0.0, h) - _aranha(moments, omega0, beta, 0.0, -h)) / (
            2 * h
        )
        F = F + col * r
    return F


def vector_field(y, p):
    """Calm-water field plus the wave-drift force (non-dimensional, eqs 6.14-6.16)."""
    f = calm_field(y, p)
    U = p["u_tug"]
    F = p["zeta_a"] ** 2 * sailing_drift(
        p["qtf"],
        p["omega"],
        -y[5],
        y[0] * U,
        y[1] * U,
        y[2] * U / p["length"],
        p.get("moments"),
    )
    f[0] += F[0] / p["force"] / (p["m"] + p["a11"])
    f[1] += F[1] / p["force"] / (p["m"] + p["a22"])
    f[2] += F[2] / p["moment"] / (p["Izz"] + p["a66"])
    return f


def equilibria(p, starts=(-1.0, -0.5, -0.2, 0.0, 0.2, 0.5, 1.0)):
    """fsolve from several headings; unique converged roots (taut line, behind the tug)."""
    roots = []
    for psi0 in starts:
        y0 = np.array([math.cos(psi0), -math.sin(psi0), 0.0, p["l0"] * 1.01, -psi0 * 0.5, psi0])
        y, info, ok, _ = fsolve(lambda x: vector_field(x, p), y0, full_output=True, xtol=1e-12)
        if (
            ok == 1
            and np.max(np.abs(vector_field(y, p))) < 1e-9
            and y[3] > p["l0"]
            and math.cos(y[4]) > 0
            and abs(y[5]) < math.pi / 2
            and not any(abs(y[5] - r[5]) < 1e-6 for r in roots)
        ):
            roots.append(y)
    return sorted(roots, key=lambda r: r[5])


def stability_map(params: dict, l0: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """max Re λ of the equilibrium nearest straight behind, per point (flat arrays)."""
    out = np.full(l0.size, np.nan)
    p = dict(params)
    for k in range(l0.size):  # the baseline's Python loop over grid points
        p["l0"], p["omega"] = float(l0[k]), float(omega[k])
        roots = equilibria(p)
        if roots:
            y = min(roots, key=lambda r: abs(r[5]))
            out[k] = np.linalg.eigvals(fd_jacobian(y, p, field=vector_field)).real.max()
    return out
