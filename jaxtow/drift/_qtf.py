"""Mean-drift QTF database over (ω, β) with a smooth, differentiable interpolant.

Values are mean drift forces per unit wave amplitude squared, SI: Fx, Fy [N/m²] and
Nz [N·m/m²], in body axes (x forward, y to port, Nz counter-clockwise seen from above),
with the thesis's heading convention: β = 0 head seas, β measured counter-clockwise from
the bow to the direction the waves come *from* (so head waves on a vessel at heading ψ
have β = −ψ, docs/model.md section 4).

Interpolant: tensor-product cubic Hermite, first in ω then in β, with node slopes from the
three-point (quadratic-exact) finite-difference formula. It is C¹ in ω and β, and at an
interior node its derivative equals the three-point difference of the table.
Extrapolation rules (explicit):

* ω → 0: a virtual node at ω = 0 with value 0 and slope 0 (drift vanishes in long waves);
* ω > ω_max: the value at ω_max, held constant (short-wave asymptote); the slope at ω_max
  is set to 0 so that the continuation is C¹ (the last tabulated frequency must lie in
  the short-wave range);
* β: a table covering the full circle [−π, π] (equal values at both ends) is periodic; a
  partial table is clamped at its ends and `in_table` reports it.
"""

from __future__ import annotations

import math

import equinox as eqx
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Float

from .._interp import HermiteAxis
from .._program_cache import host_program

_COMPONENTS = ("fx", "fy", "nz")

#: Tolerance of the symmetry test of `QTF.symmetric` and the file readers: the head- and
#: following-sea sway force and yaw moment of a port-starboard symmetric hull, relative to
#: the table's scale. Panel codes give them to round-off (1e-9 to 2e-6 of the scale in the
#: WAMIT files users have); the asymmetric hulls among them exceed 1e-2.
SYMMETRY_TOL = 1e-4


def symmetry_residual(beta, fx, fy, nz, *, length: float = 1.0) -> float:
    """The largest head-sea (β = 0) or following-sea (β = ±π) |Fy| or |Nz| of a table
    ((nω, nβ) arrays, β in radians), relative to the scales of `QTF.symmetric`. Zero for a
    port-starboard symmetric hull; inf if the table has neither heading."""
    b = np.asarray(beta, float)
    fx, fy, nz = (np.asarray(v, float) for v in (fx, fy, nz))
    cols = np.flatnonzero(np.isclose(b, 0.0, atol=1e-9) | np.isclose(np.abs(b), math.pi, atol=1e-9))
    if cols.size == 0:
        return math.inf
    sf = max(float(np.max(np.abs(fx))), float(np.max(np.abs(fy))), 1e-300)
    sn = max(float(np.max(np.abs(nz))), float(length) * sf, 1e-300)
    return max(float(np.max(np.abs(fy[:, cols]))) / sf, float(np.max(np.abs(nz[:, cols]))) / sn)


def _check_components(omega, beta, components) -> None:
    """Eager: each of (fx, fy, nz) has shape (len(omega), len(beta)) and is finite; the
    error names the component, and for a non-finite value its (omega, beta) place."""
    w, b = np.ravel(np.asarray(omega, float)), np.ravel(np.asarray(beta, float))
    for name, v in zip(_COMPONENTS, components):
        v = np.asarray(v, float)
        if v.shape != (w.size, b.size):
            raise ValueError(
                f"parameter {name!r} must have shape (len(omega), len(beta)) = "
                f"{(w.size, b.size)}, got {v.shape}"
            )
        bad = np.argwhere(~np.isfinite(v))
        if bad.size:
            i, j = bad[0]
            raise ValueError(
                f"parameter {name!r} must be finite: {v[i, j]} at omega = {w[i]:g} rad/s, "
                f"beta = {math.degrees(b[j]):g} deg ({len(bad)} non-finite values)"
            )


class QTF(eqx.Module):
    """Mean-drift QTF table: ``omega`` (nω,) rad/s ascending > 0, ``beta`` (nβ,) rad
    ascending, ``values`` (3, nω, nβ) = (Fx, Fy, Nz) per ζa² [N/m², N·m/m²].

    Build with ``QTF(omega=..., beta=..., fx=..., fy=..., nz=...)`` (each (nω, nβ)), or
    `QTF.symmetric` from half a table of a port-starboard symmetric hull.
    ``q(omega, beta)`` returns (Fx, Fy, Nz) per ζa²; it is differentiable in ω, β and in the
    table values.

    ``sectional`` (optional, a panel database's): the sectional drift moments
    (M_x,1, M_y,1, M_y,2) per ζa² [N·m/m², N·m/m², N·m²/m²] on the same grid, shape
    (3, nω, nβ) (thesis eqs 2.43-2.48: M_x,j = ∫ x^j f_x dx, M_y,j = ∫ x^j f_y dx, x from the
    CoG). They give the yaw-rate column of the wave-drift damping
    (`jaxtow.drift.yaw_rate_damping`); ``q.moments(omega, beta)`` interpolates them.

    The interpolation tables of the two grids (``omega_axis``, ``beta_axis``) are built with
    the table: the grids are fixed at construction; build a new table for other grids.
    """

    omega: Float[Array, " nw"]
    beta: Float[Array, " nb"]
    values: Float[Array, "3 nw nb"]
    periodic: bool = eqx.field(static=True)
    omega_axis: HermiteAxis  # the interpolation tables of the grids, built with the table
    beta_axis: HermiteAxis
    sectional: Float[Array, "3 nw nb"] | None = None

    def __init__(self, *, omega, beta, fx, fy, nz, sectional=None):
        w = np.asarray(omega, float)
        b = np.asarray(beta, float)
        if w.ndim != 1 or w.size < 2 or not np.all(np.diff(w) > 0) or w[0] <= 0:
            raise ValueError(
                "parameter 'omega' must be a 1-D ascending grid of >= 2 positive frequencies"
            )
        if b.ndim != 1 or b.size < 2 or not np.all(np.diff(b) > 0):
            raise ValueError("parameter 'beta' must be a 1-D ascending grid of >= 2 headings [rad]")
        _check_components(w, b, (fx, fy, nz))
        vals = np.stack([np.asarray(v, float) for v in (fx, fy, nz)])
        full = bool(abs(b[0] + math.pi) < 1e-9 and abs(b[-1] - math.pi) < 1e-9)
        scale = float(np.max(np.abs(vals))) if vals.size else 0.0
        if full and not np.allclose(vals[..., 0], vals[..., -1], rtol=1e-12, atol=1e-12 * scale):
            raise ValueError("a full-circle table must have equal values at beta = -pi and +pi")
        if sectional is not None:
            sec = np.stack([np.asarray(v, float) for v in sectional])
            if sec.shape != vals.shape:
                raise ValueError(
                    "parameter 'sectional' must hold (M_x,1, M_y,1, M_y,2), each of shape "
                    f"(len(omega), len(beta)) = {(w.size, b.size)}, got {sec.shape}"
                )
            if not np.all(np.isfinite(sec)):
                raise ValueError("parameter 'sectional' must be finite")
            if full and not np.allclose(sec[..., 0], sec[..., -1], rtol=1e-12, atol=0.0):
                raise ValueError(
                    "parameter 'sectional': a full-circle table must have equal values at "
                    "beta = -pi and +pi"
                )
            self.sectional = jnp.asarray(sec)
        else:
            self.sectional = None
        self.omega, self.beta, self.values, self.periodic = (
            jnp.asarray(w),
            jnp.asarray(b),
            jnp.asarray(vals),
            full,
        )
        # in ω a virtual node at ω = 0 (value 0) and zero slope at both end nodes
        self.omega_axis = HermiteAxis(np.concatenate([[0.0], w]), "flat")
        self.beta_axis = HermiteAxis(b, "periodic" if full else "one_sided")

    @property
    def has_sectional(self) -> bool:
        """True when the table carries the sectional moments (the yaw-rate damping needs them)."""
        return self.sectional is not None

    @classmethod
    def symmetric(
        cls,
        *,
        omega,
        beta,
        fx,
        fy,
        nz,
        sectional=None,
        tol: float | None = None,
        length: float = 1.0,
    ):
        """Complete a table given for 0 <= β <= βmax (radians) of a hull symmetric about its
        centreline: Fx(−β) = Fx(β), Fy(−β) = −Fy(β), Nz(−β) = −Nz(β); the sectional moments
        (M_x,1, M_y,1, M_y,2), if given, have the same parities (even, odd, odd).

        The head-sea (β = 0) and, if given, following-sea (β = π) sway and yaw must vanish by
        symmetry; a panel code gives them to round-off, not to zero, so they must lie within
        ``tol`` (default `SYMMETRY_TOL`) of the table's scale: |Fy| <= tol·max(|Fx|, |Fy|)
        and |Nz| <= tol·max(max|Nz|, ``length``·max(|Fx|, |Fy|)) (``length`` [m] keeps
        the test meaningful for bodies with no yaw moment at all, e.g. a sphere). They are
        then set to exactly zero. A table outside the tolerance is an asymmetric hull and is
        refused (`symmetry_residual` measures it)."""
        b = np.asarray(beta, float)
        if b.ndim != 1 or b.size < 2 or b[0] != 0.0 or np.any(np.diff(b) <= 0):
            raise ValueError("parameter 'beta' must ascend from 0 for symmetry completion")
        fx, fy, nz = (np.asarray(v, float) for v in (fx, fy, nz))
        _check_components(omega, b, (fx, fy, nz))
        tol = SYMMETRY_TOL if tol is None else float(tol)
        res = symmetry_residual(b, fx, fy, nz, length=length)
        if not res <= tol:
            raise ValueError(
                "not a port-starboard symmetric hull: the head/following-sea sway force or yaw "
                f"moment is {res:.2e} of the table's scale (tolerance {tol:.0e}, parameter "
                "'tol'); give the full heading circle instead of symmetry completion"
            )
        bb = np.concatenate([-b[:0:-1], b])
        following = abs(b[-1] - math.pi) < 1e-9

        def complete(even, *odd):
            out = [np.concatenate([even[:, :0:-1], even], axis=1)]
            for v in odd:
                vv = np.concatenate([-v[:, :0:-1], v], axis=1)
                vv[:, b.size - 1] = 0.0
                if following:  # following seas: also zero by symmetry
                    vv[:, [0, -1]] = 0.0
                out.append(vv)
            return out

        fxx, fyy, nzz = complete(fx, fy, nz)
        sec = None
        if sectional is not None:
            sec = complete(*(np.asarray(v, float) for v in sectional))
        return cls(omega=np.asarray(omega, float), beta=bb, fx=fxx, fy=fyy, nz=nzz, sectional=sec)

    def smoothed(self, harmonics: int = 8) -> QTF:
        """The table smoothed in heading: at every frequency each component (and sectional
        moment) is replaced by its least-squares Fourier series in β truncated at
        ``harmonics`` (a C^∞ periodic fit), evaluated at the same nodes; the interpolant is
        then built from it as usual. For a panel table whose heading slopes are noisy
        (docs/bem.md, "Shipped databases"). Needs a full-circle table with more than
        2·harmonics + 1 distinct headings."""
        if not isinstance(harmonics, int) or harmonics < 1:
            raise ValueError(f"parameter 'harmonics' must be an integer >= 1, got {harmonics!r}")
        if not self.periodic:
            raise ValueError("QTF.smoothed needs a full-circle table (beta from -pi to pi)")
        b = np.asarray(self.beta)[:-1]  # distinct headings (the last repeats the first)
        if b.size <= 2 * harmonics + 1:
            raise ValueError(
                f"parameter 'harmonics': {harmonics} harmonics need more than {2 * harmonics + 1} "
                f"distinct headings, the table has {b.size}"
            )
        k = np.arange(1, harmonics + 1)
        basis = np.concatenate(
            [np.ones((b.size, 1)), np.cos(np.outer(b, k)), np.sin(np.outer(b, k))], axis=1
        )
        full = np.asarray(self.beta)
        at = np.concatenate(
            [np.ones((full.size, 1)), np.cos(np.outer(full, k)), np.sin(np.outer(full, k))], axis=1
        )

        def fit(v):  # (3, nω, nβ)
            v = np.asarray(v)[..., :-1]
            coef, *_ = np.linalg.lstsq(basis, v.reshape(-1, b.size).T, rcond=None)
            out = (at @ coef).T.reshape(v.shape[:-1] + (full.size,))
            out[..., -1] = out[..., 0]  # beta = +pi is beta = -pi
            return out

        fx, fy, nz = fit(self.values)
        sec = None if self.sectional is None else list(fit(self.sectional))
        return QTF(omega=self.omega, beta=self.beta, fx=fx, fy=fy, nz=nz, sectional=sec)

    def in_table(self, beta):
        """True where β lies inside the table's heading range (always for a full circle)."""
        beta = jnp.asarray(beta)
        if self.periodic:
            return jnp.ones_like(beta, dtype=bool)
        return (beta >= self.beta[0]) & (beta <= self.beta[-1])

    def __call__(self, omega, beta) -> Float[Array, "3"]:
        """(Fx, Fy, Nz) per ζa² at one (ω, β); vmap for grids.

        Only the 4 × 4 table entries the point needs are touched: the interpolant is linear
        in the table, so it is the ω weights and the β weights
        contracted with that block (`jaxtow._interp.HermiteAxis`). The result equals the tensor-product interpolant of the
        module docstring built from the full slope tables."""
        return _qtf_values(self, omega, beta)

    def moments(self, omega, beta) -> Float[Array, "3"]:
        """Sectional moments (M_x,1, M_y,1, M_y,2) per ζa² at one (ω, β), with the same
        interpolant as the forces; zero when the table has none (`has_sectional`)."""
        if self.sectional is None:
            return jnp.zeros(3, dtype=jnp.result_type(self.values.dtype, omega, beta))
        return self._interpolate(self.sectional, omega, beta)

    def forces_and_moments(self, omega, beta) -> Float[Array, "6"]:
        """(Fx, Fy, Nz, M_x,1, M_y,1, M_y,2) per ζa² at one (ω, β): the forces and the
        sectional moments from one look-up (the moments zero without them)."""
        if self.sectional is None:
            f = self(omega, beta)
            return jnp.concatenate([f, jnp.zeros_like(f)])
        return self._interpolate(jnp.concatenate([self.values, self.sectional]), omega, beta)

    def _interpolate(self, values, omega, beta):
        beta = jnp.asarray(beta)
        if self.periodic:
            beta = jnp.mod(beta + jnp.pi, 2 * jnp.pi) - jnp.pi
        cols, wb = self.beta_axis.weights(beta)
        rows, ww = self.omega_axis.weights(jnp.maximum(omega, 0.0))
        ww = jnp.where(rows > 0, ww, 0.0)  # the virtual row's value is 0
        block = values[:, jnp.maximum(rows - 1, 0)[:, None], cols[None, :]]  # (3, 4, 4)
        return jnp.sum(block * (ww[:, None] * wb[None, :]), axis=(1, 2))


@host_program()
def _qtf_values(q: QTF, omega, beta):
    """`QTF.__call__`: one compiled program where it is called eagerly."""
    return q._interpolate(q.values, omega, beta)


class FullQTF(eqx.Module):
    """Difference-frequency QTF of the slowly varying drift: ``values`` (3, nω, nω, nβ)
    complex, T_c(ω_i, ω_j, β) per ζa² [N/m², N·m/m²] for c = surge, sway, yaw, β the
    unidirectional heading (jaxtow convention, radians), such that a sea of components
    ζ = Re Σ_i A_i e^{iω_i t} gives F_c(t) = Re Σ_i Σ_j A_i A_j* T_c(ω_i, ω_j) e^{i(ω_i − ω_j)t}
    (WAMIT's .12d convention). Hermitian: T(ω_j, ω_i) = conj T(ω_i, ω_j), so its diagonal is
    real and is the mean drift (`diagonal`, `mean_drift`). `QTF` stays the mean-drift
    container; this one drives `jaxtow.forces.SlowDriftForce` instead of Newman's
    approximation."""

    omega: Float[Array, " nw"]
    beta: Float[Array, " nb"]
    values: Array

    def __init__(self, *, omega, beta, values):
        w = np.asarray(omega, float)
        b = np.atleast_1d(np.asarray(beta, float))
        v = np.asarray(values, complex)
        if w.ndim != 1 or w.size < 2 or not np.all(np.diff(w) > 0) or w[0] <= 0:
            raise ValueError(
                "parameter 'omega' must be a 1-D ascending grid of >= 2 positive frequencies"
            )
        if b.ndim != 1 or not np.all(np.diff(b) > 0):
            raise ValueError("parameter 'beta' must be a 1-D ascending grid of headings [rad]")
        if v.shape != (3, w.size, w.size, b.size):
            raise ValueError(
                f"parameter 'values' must have shape (3, nω, nω, nβ) = {(3, w.size, w.size, b.size)}, "
                f"got {v.shape}"
            )
        if not np.all(np.isfinite(v)):
            raise ValueError("parameter 'values' must be finite")
        scale = max(float(np.max(np.abs(v))), 1e-300)
        herm = float(np.max(np.abs(v - np.conj(np.swapaxes(v, 1, 2))))) / scale
        if herm > 1e-6:
            raise ValueError(
                "parameter 'values': a difference-frequency QTF is Hermitian, T(w_j, w_i) = "
                f"conj T(w_i, w_j); this one departs by {herm:.1e} of its scale"
            )
        self.omega, self.beta, self.values = jnp.asarray(w), jnp.asarray(b), jnp.asarray(v)

    def diagonal(self):
        """The mean drift T(ω, ω, β), real, shape (3, nω, nβ)."""
        v = np.asarray(self.values)
        return np.real(np.diagonal(v, axis1=1, axis2=2)).transpose(0, 2, 1)

    def mean_drift(self) -> QTF:
        """The diagonal as a mean-drift `QTF` (needs >= 2 headings)."""
        d = self.diagonal()
        if d.shape[-1] < 2:
            raise ValueError(
                "FullQTF.mean_drift: the QTF has one heading; a QTF table needs two or more "
                "(use diagonal(), or read the file's mean-drift output)"
            )
        return QTF(omega=self.omega, beta=self.beta, fx=d[0], fy=d[1], nz=d[2])

    def at(self, omega):
        """The table at component frequencies ``omega`` (n,) by bilinear interpolation in
        (ω_i, ω_j): complex (3, n, n, nβ), and a mask (n,) of the components inside the
        table's frequency range (outside it the values are those of the nearest edge)."""
        w = np.asarray(omega, float)
        t = np.asarray(self.omega)
        inside = (w >= t[0]) & (w <= t[-1])
        k = np.clip(np.searchsorted(t, w, side="right") - 1, 0, t.size - 2)
        f = np.clip((w - t[k]) / (t[k + 1] - t[k]), 0.0, 1.0)
        v = np.asarray(self.values)
        # interpolate rows then columns
        rows = v[:, k] * (1 - f)[None, :, None, None] + v[:, k + 1] * f[None, :, None, None]
        out = (
            rows[:, :, k] * (1 - f)[None, None, :, None]
            + rows[:, :, k + 1] * f[None, None, :, None]
        )
        return out, inside
