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

from ._dynamics import TowModel, unchecked_vector_field
from ._program_cache import host_program
from ._roots import bisect_fixed
from ._rules import guard

STABLE, MARGINAL, UNSTABLE, INVALID = -1, 0, 1, 2
STABILITY_LABELS = {
    STABLE: "stable",
    MARGINAL: "marginal",
    UNSTABLE: "unstable",
    INVALID: "invalid (NaN eigenvalues)",
}
#: The one stability tolerance of jaxtow (non-dimensional, per L/U_tug): |max Re λ| at or
#: below it counts as marginal. Every verdict (maps, reports, design, the command line) uses
#: `classify` with this value.
STABILITY_TOL = 1e-9


def jacobian(
    model: TowModel, y: Float[Array, "6"], t=0.0, *, throw: bool = True
) -> Float[Array, "6 6"]:
    """A = ∂f/∂y of the tow vector field at state y (forward-mode autodiff). ``throw``:
    check the model's parameters (see `jaxtow.vector_field`)."""
    A = _jacobian(model, y, t)
    return guard(A, model.checks()) if throw else A


@host_program()
def _jacobian(model: TowModel, y, t):
    return jax.jacfwd(unchecked_vector_field, argnums=1)(t, jnp.asarray(y), model)


EIG_METHODS = ("lapack", "polynomial")
#: Methods for max Re λ alone: the eigenvalue methods, and "routh" (`spectral_abscissa`).
ABSCISSA_METHODS = (*EIG_METHODS, "routh")


def default_eig_method(platform: str | None = None) -> str:
    """The eigenvalue method that runs well on ``platform`` (default: JAX's default backend):
    "lapack" on the CPU (LAPACK's geev, the fastest there), "polynomial" on every other
    backend. A GPU has no batched nonsymmetric eigensolver: ``jnp.linalg.eigvals`` there
    runs matrix by matrix (one 16,384-point chunk of a sweep did not finish in 200 s on an
    H200), where the characteristic polynomial's roots are plain batched arithmetic."""
    platform = jax.default_backend() if platform is None else platform
    return "lapack" if platform == "cpu" else "polynomial"


def _method(method: str | None) -> str:
    return default_eig_method() if method is None else method


def eigenvalues(
    model: TowModel, y: Float[Array, "6"], method: str | None = None, *, throw: bool = True
) -> Complex[Array, "6"]:
    """Eigenvalues of the Jacobian at y (non-dimensional, per L/U_tug).

    ``method``: None (default) picks `default_eig_method` for the backend ("lapack" on the
    CPU, "polynomial" elsewhere). ``method="lapack"``: `jnp.linalg.eigvals` (LAPACK geev).
    ``method="polynomial"``: roots of the characteristic polynomial by Aberth-Ehrlich
    iteration, pure JAX arithmetic with no library call (agrees with LAPACK to ~1e-9 on the
    tow Jacobians; slower than LAPACK on CPU). When only max Re λ is wanted,
    `spectral_abscissa` is faster than both. ``throw``: check the model's parameters (see
    `jaxtow.vector_field`).
    """
    lam = _eigenvalues(model, y, method)
    return guard(lam, model.checks()) if throw else lam


@host_program(static_argnames=("method",))
def _eigenvalues(model: TowModel, y, method: str | None):
    return matrix_eigenvalues(jacobian(model, y, throw=False), method)


def matrix_eigenvalues(A: Float[Array, "n n"], method: str | None = None) -> Complex[Array, " n"]:
    """Eigenvalues of a given matrix by ``method`` (see `eigenvalues`)."""
    method = _method(method)
    if method == "lapack":
        return jnp.linalg.eigvals(A)
    if method == "polynomial":
        return polynomial_roots(characteristic_polynomial(A))
    raise ValueError(f"parameter 'method' must be one of {EIG_METHODS}, got {method!r}")


def matrix_max_real_eigenvalue(
    A: Float[Array, "n n"], method: str | None = None
) -> Float[Array, ""]:
    """max Re λ(A), the spectral abscissa of a given matrix, by ``method`` (one of
    `ABSCISSA_METHODS`: the eigenvalue methods of `eigenvalues`, or "routh",
    `spectral_abscissa`)."""
    method = _method(method)
    if method == "routh":
        return spectral_abscissa(A)
    if method not in EIG_METHODS:
        raise ValueError(f"parameter 'method' must be one of {ABSCISSA_METHODS}, got {method!r}")
    return jnp.max(jnp.real(matrix_eigenvalues(A, method)))


def max_real_eigenvalue(
    model: TowModel, y: Float[Array, "6"], method: str | None = None, *, throw: bool = True
) -> Float[Array, ""]:
    """max Re λ(∂f/∂y) at y: < 0 stable, > 0 unstable (thesis figs 2.6b, 6.4); ``method``:
    see `matrix_max_real_eigenvalue`; ``throw``: see `jaxtow.vector_field`."""
    mr = _max_real_eigenvalue(model, y, method)
    return guard(mr, model.checks()) if throw else mr


@host_program(static_argnames=("method",))
def _max_real_eigenvalue(model: TowModel, y, method: str | None):
    return matrix_max_real_eigenvalue(jacobian(model, y, throw=False), method)


#: Bisection steps of `spectral_abscissa`: the bracket [−R, R] (R a bound on |λ|) shrinks
#: to R·2⁻⁵², the resolution of float64 relative to the spectral radius bound.
ABSCISSA_ITERATIONS = 52


def _taylor_shift(c, s):
    """Coefficients of q(μ) = p(μ + s) from those of p (highest first), by repeated
    synthetic division (Horner): n(n+1)/2 multiply-adds, unrolled over the static degree."""
    c = [c[i] for i in range(c.shape[0])]
    n = len(c) - 1
    for i in range(n):
        for j in range(1, n + 1 - i):
            c[j] = c[j] + s * c[j - 1]
    return c


def _hurwitz(c) -> Bool[Array, ""]:
    """True when every root of the monic polynomial c (highest first, a Python list) has
    Re < 0: all entries of the Routh array's first column positive (a zero or negative
    pivot stops the test: not Hurwitz)."""
    n = len(c) - 1
    zero = jnp.zeros_like(c[0])
    prev2, prev1 = list(c[0::2]), list(c[1::2])
    ok = prev1[0] > 0
    for _ in range(n - 1):  # static n: the rows of the array
        piv = jnp.where(prev1[0] > 0, prev1[0], 1.0)
        row = [
            (piv * prev2[k + 1] - prev2[0] * (prev1[k + 1] if k + 1 < len(prev1) else zero)) / piv
            for k in range(len(prev2) - 1)
        ]
        if not row:
            break
        ok = ok & (row[0] > 0)
        prev2, prev1 = prev1, row
    return ok


def _bisect_abscissa(c, iterations: int):
    """max Re of the roots of the monic polynomial c by bisection on the shift σ."""
    n = c.shape[0] - 1
    radius = 2 * jnp.max(jnp.abs(c[1:]) ** (1.0 / jnp.arange(1, n + 1)))  # ≥ Fujiwara's bound
    radius = jnp.where(radius > 0, radius, 1.0)
    scaled = c / radius ** jnp.arange(n + 1)  # roots μ = λ / R, |μ| ≤ 1
    one = jnp.ones((), c.dtype)

    # every Re μ < mid (a Hurwitz-stable shifted polynomial): the abscissa lies below mid
    lo, hi = bisect_fixed(lambda mid: _hurwitz(_taylor_shift(scaled, mid)), -one, one, iterations)
    return jnp.where(jnp.all(jnp.isfinite(c)), radius * 0.5 * (lo + hi), jnp.nan)


@jax.custom_jvp
def spectral_abscissa(A: Float[Array, "n n"]) -> Float[Array, ""]:
    """max Re λ(A) with no eigenvalue solver: bisection on the shift σ, each step a
    Routh-Hurwitz test of the shifted characteristic polynomial p(μ + σ) (all roots left of
    σ ⇔ the abscissa is below σ).

    Pure JAX arithmetic (no LAPACK: runs on any backend and under sharding), a fixed
    `ABSCISSA_ITERATIONS` steps (vmaps with no divergence). Agrees with LAPACK's max Re λ to
    1e-9 on the tow Jacobians (calm and wave maps, towlines up to 100x the thesis's EA';
    ~1e-12 of the spectral radius beyond) and costs about a third of LAPACK's eigenvalues
    on CPU (`benchmarks/bench_abscissa.py`). Its limit is that of every polynomial method:
    an m-fold rightmost eigenvalue, well conditioned in the matrix, is ill-conditioned in
    the polynomial, and its error grows like R·ε^(1/m) (a double root ~1e-8·R). Differentiable: the
    tangent is that of the rightmost eigenvalue, dλ = −dp(λ)/p′(λ), with λ from the
    polynomial roots (`polynomial_roots`).
    """
    return _bisect_abscissa(characteristic_polynomial(A), ABSCISSA_ITERATIONS)


@spectral_abscissa.defjvp
def _spectral_abscissa_jvp(primals, tangents):
    (A,), (dA,) = primals, tangents
    c, dc = jax.jvp(characteristic_polynomial, (A,), (dA,))
    out = _bisect_abscissa(c, ABSCISSA_ITERATIONS)
    roots = jax.lax.stop_gradient(polynomial_roots(c))
    lam = roots[jnp.argmax(jnp.real(roots))]  # the rightmost root (either of a pair)
    n = c.shape[0] - 1
    powers = lam ** jnp.arange(n, -1, -1)
    dp = jnp.sum(dc * powers)  # dp(λ) = Σ dc_k λ^(n−k)
    p1 = jnp.sum(c[:-1] * jnp.arange(n, 0, -1) * lam ** jnp.arange(n - 1, -1, -1))
    return out, jnp.real(-dp / p1)


def classify(max_re, tol: float = STABILITY_TOL) -> Int[Array, "..."]:
    """The stability rule: −1 stable (max Re λ < −tol), 0 marginal, +1 unstable
    (max Re λ > tol), 2 invalid (max Re λ is NaN: no verdict; never "marginal"); see
    `STABILITY_LABELS`."""
    max_re = jnp.asarray(max_re)
    code = jnp.where(max_re < -tol, STABLE, jnp.where(max_re > tol, UNSTABLE, MARGINAL))
    return jnp.where(jnp.isnan(max_re), INVALID, code)


def hessenberg(A: Float[Array, "n n"]) -> Float[Array, "n n"]:
    """Upper Hessenberg form Q A Qᵀ by n − 2 Householder reflections (pure JAX, orthogonal:
    the eigenvalues are kept to a backward error of ~ε‖A‖)."""
    n = A.shape[0]
    H = A
    idx = jnp.arange(n)
    for k in range(n - 2):  # static n: one reflector per column
        x = jnp.where(idx > k, H[:, k], 0.0)
        ss = jnp.sum(x * x)
        # a column already reduced (ss = 0: structural zeros of the tow Jacobian) must not
        # give sqrt's infinite derivative at 0 (NaN gradients of everything downstream)
        alpha = jnp.where(ss > 0, jnp.sqrt(jnp.where(ss > 0, ss, 1.0)), 0.0)
        x1 = H[k + 1, k]
        v = x.at[k + 1].add(jnp.where(x1 >= 0, alpha, -alpha))
        vv = jnp.sum(v * v)
        beta = jnp.where(vv > 0, 2.0 / jnp.where(vv > 0, vv, 1.0), 0.0)
        H = H - beta * v[:, None] * (v @ H)[None, :]
        H = H - beta * (H @ v)[:, None] * v[None, :]
    return H


def characteristic_polynomial(A: Float[Array, "n n"]) -> Float[Array, " n+1"]:
    """Coefficients (1, c1, ..., cn) of det(λI − A) = λⁿ + c1 λⁿ⁻¹ + ... + cn.

    La Budde's method: a Householder reduction to Hessenberg form H, then the recurrence on
    the leading principal submatrices of H,
    p_{i+1}(λ) = (λ − h_ii) p_i(λ) − Σ_m h_{i−m,i} (h_{i,i−1} ⋯ h_{i−m+1,i−m}) p_{i−m}(λ).
    Unlike Faddeev-LeVerrier or Newton's identities on tr(Aᵏ), whose errors scale with the
    largest eigenvalue's powers and swamp the small ones, it keeps the slow modes of a stiff
    towline (spectral radius 10⁴ against an abscissa of 0.1) to ~1e-9 (Rehman & Ipsen,
    "La Budde's method for computing characteristic polynomials", 2011). Independent of
    the eigenvalue solver.
    """
    n = A.shape[0]
    H = hessenberg(A)
    lam = lambda q: jnp.concatenate([jnp.zeros(1, q.dtype), q[:-1]])  # q(λ) → λ q(λ)
    p = [jnp.zeros(n + 1, A.dtype).at[0].set(1.0)]  # ascending powers, p_0 = 1
    for i in range(n):  # static n
        new = lam(p[i]) - H[i, i] * p[i]
        prod = jnp.ones((), A.dtype)
        for m in range(1, i + 1):
            prod = prod * H[i - m + 1, i - m]
            new = new - H[i - m, i] * prod * p[i - m]
        p.append(new)
    return p[n][::-1]


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


def routh_hurwitz_stable(
    model: TowModel, y: Float[Array, "6"], *, throw: bool = True
) -> Bool[Array, ""]:
    """Routh-Hurwitz criterion: all roots in the open left half-plane (binary answer)."""
    ok = _routh_hurwitz_stable(model, y)
    return guard(ok, model.checks()) if throw else ok


@host_program()
def _routh_hurwitz_stable(model: TowModel, y):
    return matrix_routh_hurwitz_stable(jacobian(model, y, throw=False))


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


def stability(
    model: TowModel, states: Float[Array, "k 6"], *, throw: bool = True
) -> StabilityResult:
    """Eigenvalues, max Re λ, classification and Routh-Hurwitz verdict for each state;
    ``throw``: see `jaxtow.vector_field`."""
    out = _stability(model, states)
    return guard(out, model.checks()) if throw else out


@host_program()
def _stability(model: TowModel, states) -> StabilityResult:
    J = jax.vmap(lambda y: jacobian(model, y, throw=False))(jnp.asarray(states))
    lam = jax.vmap(matrix_eigenvalues)(J)
    mr = jnp.max(jnp.real(lam), axis=-1)
    rh = jax.vmap(matrix_routh_hurwitz_stable)(J)
    return StabilityResult(eigenvalues=lam, max_real=mr, stability=classify(mr), routh_hurwitz=rh)
