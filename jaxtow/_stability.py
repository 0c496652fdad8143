"""Linear stability of equilibria (docs/model.md section 5; thesis section 2.1.2).

The full 6-state vector field is linearised by autodiff, A = ∂f/∂y, and the eigenvalues
of A decide by the one stability rule of jaxtow (`classify`): stable if
max Re λ < −`STABILITY_TOL`, unstable if max Re λ > `STABILITY_TOL`, marginal in between. The Routh-Hurwitz test on the characteristic polynomial gives an independent,
binary cross-check. Gradients of max Re λ with respect to any parameter flow through the
equilibrium (implicit differentiation of the root) and the eigenvalues.
"""

from __future__ import annotations

import equinox as eqx
import jax
import jax.numpy as jnp
from jaxtyping import Array, Bool, Complex, Float, Int

from ._dynamics import TowModel, vector_field

STABLE, MARGINAL, UNSTABLE = -1, 0, 1
STABILITY_LABELS = {STABLE: "stable", MARGINAL: "marginal", UNSTABLE: "unstable"}
#: The one stability tolerance of jaxtow (non-dimensional, per L/U_tug): |max Re λ| at or
#: below it counts as marginal. Every verdict (maps, reports, design, the command line) uses
#: `classify` with this value.
STABILITY_TOL = 1e-9


def jacobian(model: TowModel, y: Float[Array, "6"], t=0.0) -> Float[Array, "6 6"]:
    """A = ∂f/∂y of the tow vector field at state y (forward-mode autodiff)."""
    return jax.jacfwd(vector_field, argnums=1)(t, jnp.asarray(y), model)


EIG_METHODS = ("lapack", "polynomial")


def eigenvalues(
    model: TowModel, y: Float[Array, "6"], method: str = "lapack"
) -> Complex[Array, "6"]:
    """Eigenvalues of the Jacobian at y (non-dimensional, per L/U_tug).

    ``method="lapack"`` (default): `jnp.linalg.eigvals` (LAPACK geev on CPU, cuSOLVER on
    GPU). ``method="polynomial"``: roots of the characteristic polynomial by Aberth-Ehrlich
    iteration, pure JAX arithmetic with no library call (agrees with LAPACK to ~1e-9 on the
    tow Jacobians; about 4x slower on CPU). Sweeps sharded over several CPU devices use it,
    because concurrent LAPACK calls from XLA's threads into scipy's OpenBLAS deadlocked here
    (jaxlib 0.10.2).
    """
    return matrix_eigenvalues(jacobian(model, y), method)


def matrix_eigenvalues(A: Float[Array, "n n"], method: str = "lapack") -> Complex[Array, " n"]:
    """Eigenvalues of a given matrix by ``method`` (see `eigenvalues`)."""
    if method == "lapack":
        return jnp.linalg.eigvals(A)
    if method == "polynomial":
        return polynomial_roots(characteristic_polynomial(A))
    raise ValueError(f"parameter 'method' must be one of {EIG_METHODS}, got {method!r}")


def matrix_max_real_eigenvalue(A: Float[Array, "n n"], method: str = "lapack") -> Float[Array, ""]:
    """max Re λ(A), the spectral abscissa of a given matrix (eigenvalues by ``method``)."""
    return jnp.max(jnp.real(matrix_eigenvalues(A, method)))


def max_real_eigenvalue(
    model: TowModel, y: Float[Array, "6"], method: str = "lapack"
) -> Float[Array, ""]:
    """max Re λ(∂f/∂y) at y: < 0 stable, > 0 unstable (thesis figs 2.6b, 6.4)."""
    return matrix_max_real_eigenvalue(jacobian(model, y), method)


def classify(max_re, tol: float = STABILITY_TOL) -> Int[Array, "..."]:
    """The stability rule: −1 stable (max Re λ < −tol), 0 marginal, +1 unstable
    (max Re λ > tol); see `STABILITY_LABELS`."""
    max_re = jnp.asarray(max_re)
    return jnp.where(max_re < -tol, STABLE, jnp.where(max_re > tol, UNSTABLE, MARGINAL))


def characteristic_polynomial(A: Float[Array, "n n"]) -> Float[Array, " n+1"]:
    """Coefficients (1, c1, ..., cn) of det(λI − A) = λⁿ + c1 λⁿ⁻¹ + ... + cn.

    Faddeev-LeVerrier recursion; independent of the eigenvalue solver.
    """
    n = A.shape[0]
    eye = jnp.eye(n, dtype=A.dtype)
    M = jnp.zeros_like(A)
    c = [jnp.ones((), A.dtype)]
    for k in range(1, n + 1):  # n is a static shape (6): unrolled, not a grid loop
        # broadcast-multiply-sum instead of `@`: XLA fuses it (tiny batched dots are slow on CPU)
        M = jnp.sum(A[:, :, None] * M[None, :, :], axis=1) + c[-1] * eye
        c.append(-jnp.sum(A * M.T) / k)
    return jnp.stack(c)


def polynomial_roots(coeffs, iterations: int = 60) -> Complex[Array, " n"]:
    """All roots of c0 λⁿ + ... + cn by Aberth-Ehrlich iteration (pure JAX, vmappable).

    Starts from a circle of radius 2·max|ck/c0|^(1/k) (a bound on the root moduli) and
    runs a fixed number of iterations (cubically convergent; 60 is ample for n = 6).
    """
    n = coeffs.shape[0] - 1
    c = coeffs.astype(jnp.complex128 if coeffs.dtype == jnp.float64 else jnp.complex64)
    radius = 2 * jnp.max(jnp.abs(c[1:] / c[0]) ** (1.0 / jnp.arange(1, n + 1)))
    z0 = radius * jnp.exp(1j * (2 * jnp.pi * jnp.arange(n) / n + 0.4))
    off = ~jnp.eye(n, dtype=bool)

    def step(_, z):
        p, d = jnp.full_like(z, c[0]), jnp.zeros_like(z)
        for k in range(1, n + 1):  # Horner for p and p'
            d = d * z + p
            p = p * z + c[k]
        w = p / jnp.where(d == 0, 1e-300, d)
        diff = z[:, None] - z[None, :]
        s = jnp.sum(jnp.where(off, 1.0 / jnp.where(off, diff, 1.0), 0.0), axis=1)
        return z - w / (1 - w * s)

    return jax.lax.fori_loop(0, iterations, step, z0)


def routh_first_column(coeffs: Float[Array, " n+1"]) -> Float[Array, " n+1"]:
    """First column of the Routh array of a0 λⁿ + a1 λⁿ⁻¹ + ... + an.

    Pure arithmetic (no LAPACK call): equal to Δk/Δk−1 of the Hurwitz determinants.
    (Batched `jnp.linalg.det` calls, several per kernel, deadlocked XLA's CPU runtime on
    large vmapped batches here; the Routh array avoids them.) A zero pivot gives ±inf/NaN
    entries, which `routh_hurwitz_stable` counts as not stable.
    """
    n = coeffs.shape[0] - 1
    width = n // 2 + 2
    pad = lambda v: jnp.concatenate([v, jnp.zeros(width - v.shape[0], v.dtype)])
    prev2, prev1 = pad(coeffs[0::2]), pad(coeffs[1::2])
    first = [prev2[0], prev1[0]]
    for _ in range(n - 1):  # static n: the n+1 rows of the array
        piv = prev1[0]
        safe = jnp.where(piv != 0, piv, jnp.nan)
        row = (piv * prev2[1:] - prev2[0] * prev1[1:]) / safe
        row = jnp.concatenate([row, jnp.zeros(1, row.dtype)])
        first.append(row[0])
        prev2, prev1 = prev1, row
    return jnp.stack(first)


def routh_hurwitz_stable(model: TowModel, y: Float[Array, "6"]) -> Bool[Array, ""]:
    """Routh-Hurwitz criterion: all roots in the open left half-plane (binary answer)."""
    return matrix_routh_hurwitz_stable(jacobian(model, y))


def matrix_routh_hurwitz_stable(A: Float[Array, "n n"]) -> Bool[Array, ""]:
    """Routh-Hurwitz verdict for a given matrix (see `routh_hurwitz_stable`)."""
    return jnp.all(routh_first_column(characteristic_polynomial(A)) > 0)


def hurwitz_determinants(coeffs: Float[Array, " n+1"]) -> Float[Array, " n"]:
    """Leading principal minors Δ_1 … Δ_n of the Hurwitz matrix of the monic polynomial
    ``coeffs`` = (1, a₁, …, a_n), from the Routh array (Δ_k = r_1 r_2 ⋯ r_k with r the first
    column after a₀ = 1): all > 0 ⇔ every root has Re < 0. No determinant call (see
    `routh_first_column`)."""
    return jnp.cumprod(routh_first_column(jnp.asarray(coeffs))[1:])


class StabilityResult(eqx.Module):
    """Stability of a set of k states: ``eigenvalues`` (k, 6), ``max_real`` (k,),
    ``stability`` (k,) by `classify`, ``routh_hurwitz`` (k,) (the binary cross-check)."""

    eigenvalues: Array
    max_real: Float[Array, " k"]
    stability: Int[Array, " k"]
    routh_hurwitz: Bool[Array, " k"]


def stability(model: TowModel, states: Float[Array, "k 6"]) -> StabilityResult:
    """Eigenvalues, max Re λ, classification and Routh-Hurwitz verdict for each state."""
    lam = jax.vmap(eigenvalues, in_axes=(None, 0))(model, states)
    mr = jnp.max(jnp.real(lam), axis=-1)
    rh = jax.vmap(routh_hurwitz_stable, in_axes=(None, 0))(model, states)
    return StabilityResult(eigenvalues=lam, max_real=mr, stability=classify(mr), routh_hurwitz=rh)
