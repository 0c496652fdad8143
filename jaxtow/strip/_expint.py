"""The exponential integral of the 2-D deep-water wave source, written for JAX.

The pulsating source needs f(w) = e^{−w} Ei(w) for complex w in the closed right half
plane (Re w ≥ 0: w = −ν(y + η) + iν(x − ξ) for a field point and a source below the free
surface), with Ei(w) = γ + Ln w + Σ_{k≥1} w^k/(k·k!) (principal log: the cut lies on the
negative real axis, which this half plane never reaches; on the positive real axis Ei is the
Cauchy principal value). `jax.scipy.special` has no complex Ei, so it is evaluated here by

* the power series (110 terms) where |w| ≤ 8, or where |w| ≤ 30 and |arg w| ≤ π/4 (there
  the terms' phases turn slowly, so the cancellation costs at most e^{0.3|w|}: 10⁻¹²
  relative at 30);
* the asymptotic series e^{−w}Ei(w) ~ Σ_{k<K} k!/w^{k+1} where |w| > 30 and |arg w| ≤ π/4
  (K = 30, the optimal truncation: the error is about e^{−30}√(2π/30) ≈ 10⁻¹³), plus
  the term iπ sgn(Im w) e^{−w} that Ei carries off the real axis;
* the continued fraction of E1 (modified Lentz, 60 terms) elsewhere, |w| > 8 with
  |arg w| > π/4, through Ei(w) = −E1(−w) + iπ sgn(Im w).

The three are compared with `scipy.special.expi` in the tests (relative error below 1e-11 over
the half plane). The derivative is a rule of its own (`jax.custom_jvp`), f'(w) = 1/w − f(w),
so gradients never pass through the branch selection or the loops.
"""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

_EULER = 0.57721566490153286061
_N_SERIES = 110
_K = np.arange(1, _N_SERIES + 1, dtype=float)
_SERIES_COEF = tuple(float(c) for c in 1.0 / (_K * np.cumprod(_K)))  # 1/(k·k!)
_N_ASYMPT = 30
_FACT = tuple(float(c) for c in np.cumprod(np.r_[1.0, np.arange(1, _N_ASYMPT, dtype=float)]))
_N_CF = 60
#: The Horner loops' unroll factor: a trade between compile time (the loop body's size) and
#: run time (the passes over the array). On 1.5 million arguments, 2 cores: unrolled in full,
#: 0.9 s to compile and 0.58 s to run; 1, 5, 10, 30 terms a step: 0.33, 0.38, 0.43, 0.54 s to
#: compile and 0.65–0.79 s to run (docs/strip.md).
UNROLL = 5


def _horner(coef, x):
    """Σ coef[k] x^k by Horner's rule, as a loop over the coefficients (a program of one
    step, not of one step per term: the unrolled sums took most of the section solve's
    compile time), with no (…, terms) array."""
    c = jnp.asarray(coef[::-1])
    return jax.lax.fori_loop(
        1, c.shape[0], lambda k, s: s * x + c[k], jnp.full_like(x, c[0]), unroll=UNROLL
    )


def _series(w):
    """e^{−w}(γ + Ln w + Σ w^k/(k·k!)), the sum by Horner's rule."""
    return jnp.exp(-w) * (_EULER + jnp.log(w) + _horner(_SERIES_COEF, w) * w)


def _asymptotic(w):
    """Σ_{k<K} k!/w^{k+1} + iπ sgn(Im w) e^{−w} (the sum by Horner's rule in 1/w)."""
    inv = 1.0 / w
    return _horner(_FACT, inv) * inv + 1j * jnp.pi * jnp.sign(w.imag) * jnp.exp(-w)


def _cf(w):
    """−e^{z}E1(z) + iπ sgn(Im w) e^{−w} with z = −w: E1 by its continued fraction
    e^{z}E1(z) = 1/(z + 1 − 1²/(z + 3 − 2²/(z + 5 − …)))."""
    z = -w
    tiny = 1e-300
    b = z + 1.0
    c = jnp.full_like(z, 1.0 / tiny)
    d = 1.0 / b
    h = d

    def body(i, carry):
        b, c, d, h = carry
        an = -(i * i).astype(z.real.dtype)
        b = b + 2.0
        d = 1.0 / (an * d + b)
        c = b + an / c
        h = h * c * d
        return b, c, d, h

    _, _, _, h = jax.lax.fori_loop(1, _N_CF, body, (b, c, d, h))
    return -h + 1j * jnp.pi * jnp.sign(w.imag) * jnp.exp(-w)


@jax.custom_jvp
def exp_ei(w):
    """e^{−w} Ei(w) for complex w with Re w ≥ 0, w ≠ 0 (see the module docstring)."""
    w = jnp.asarray(w, dtype=complex)
    r = jnp.abs(w)
    near_axis = jnp.abs(w.imag) <= w.real  # |arg w| <= pi/4
    use_series = (r <= 8.0) | (near_axis & (r <= 30.0))
    use_asym = near_axis & (r > 30.0)
    # each branch on safe arguments only, so no branch makes a NaN that where() would keep
    ws = jnp.where(use_series, w, 1.0 + 0.0j)
    wa = jnp.where(use_asym, w, 40.0 + 0.0j)
    wc = jnp.where(use_series | use_asym, 20.0 + 20.0j, w)
    return jnp.where(use_series, _series(ws), jnp.where(use_asym, _asymptotic(wa), _cf(wc)))


@exp_ei.defjvp
def _exp_ei_jvp(primals, tangents):
    (w,), (dw,) = primals, tangents
    w = jnp.asarray(w, dtype=complex)
    f = exp_ei(w)
    return f, (1.0 / w - f) * jnp.asarray(dw, dtype=complex)
