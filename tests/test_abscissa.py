"""The pure-JAX spectral abscissa (`jaxtow.spectral_abscissa`) against LAPACK's eigenvalues:
random stiff and non-stiff tow Jacobians, a calm and a wave stability map, known spectra,
gradients."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from helpers import model

import jaxtow as jt
from jaxtow._equilibrium import analytic_equilibria, equilibria_fixed
from jaxtow._parameters import with_parameters


def _tow_jacobians(vessel, ea_factor, n, seed):
    """Jacobians at every analytic equilibrium of n random (x_p', l0') points."""
    rng = np.random.default_rng(seed)
    m = model(vessel)
    ea = float(jt.presets.default_towline().EA) * ea_factor

    def at(xp, l0):
        mdl = with_parameters(m, xp=xp, l0=l0, EA=ea)
        return jax.vmap(jt.jacobian, in_axes=(None, 0))(
            mdl, analytic_equilibria(mdl, throw=False).state
        )

    J = jax.jit(jax.vmap(at))(
        jnp.asarray(rng.uniform(0, 0.6, n)), jnp.asarray(rng.uniform(0.2, 2.5, n))
    )
    J = np.asarray(J).reshape(-1, 6, 6)
    return J[np.all(np.isfinite(J), axis=(1, 2))]


ABSCISSA = jax.jit(jax.vmap(jt.spectral_abscissa))


@pytest.mark.parametrize("ea_factor", [1.0, 10.0, 100.0])
def test_abscissa_matches_lapack_on_tow_jacobians(barge_2a, barge_2b, ea_factor):
    """EA' up to 100x the thesis value (spectral radius ~10³ against abscissae ~0.1): 1e-9."""
    for seed, v in enumerate((barge_2a, barge_2b)):
        J = _tow_jacobians(v, ea_factor, 300, seed)
        assert J.shape[0] > 300
        ref = np.max(np.linalg.eigvals(J).real, axis=-1)
        np.testing.assert_allclose(np.asarray(ABSCISSA(jnp.asarray(J))), ref, rtol=0, atol=1e-9)


def test_abscissa_on_very_stiff_towline(barge_2b):
    """EA' 10⁴x the thesis value (spectral radius ~10⁴): the error stays ~1e-12 of the
    spectral radius (LAPACK's own backward error is ~1e-16 of it)."""
    J = _tow_jacobians(barge_2b, 1e4, 200, 7)
    lam = np.linalg.eigvals(J)
    rho = np.abs(lam).max(axis=-1)
    assert rho.max() > 5e3
    err = np.abs(np.asarray(ABSCISSA(jnp.asarray(J))) - lam.real.max(axis=-1))
    assert np.all(err < 1e-12 * rho)


def test_abscissa_on_known_spectra():
    """Real matrices of known spectra (diagonal and 2x2 rotation blocks in a random
    orthonormal basis), repeated roots included."""
    Q = np.linalg.qr(np.random.default_rng(3).normal(size=(6, 6)))[0]

    def matrix(reals, pairs):
        D = np.zeros((6, 6))
        k = 0
        for a, b in pairs:
            D[k : k + 2, k : k + 2] = [[a, b], [-b, a]]
            k += 2
        for r in reals:
            D[k, k] = r
            k += 1
        return Q @ D @ Q.T

    cases = [
        (0.2, matrix([0.2, -1, -2, -3, -4, -5], [])),  # a real rightmost root
        (-0.05, matrix([-1, -2], [(-0.05, 0.7), (-3, 1)])),  # a rightmost pair
        (0.0, matrix([0.0, 0.0, -1, -1, -2, -2], [])),  # a double root at zero
        (0.3, matrix([], [(0.3, 2.0), (0.3, 0.5), (-1, 1)])),  # two pairs on the abscissa
    ]
    for expected, A in cases:
        assert abs(float(jt.spectral_abscissa(jnp.asarray(A))) - expected) < 1e-9, expected
    # the documented limit: an m-fold rightmost root is ill-conditioned in the polynomial
    # (not in the matrix), so its error grows like R·ε^(1/m); sixfold: R = 24, ~6e-3
    err = abs(float(jt.spectral_abscissa(-2.0 * jnp.eye(6))) + 2.0)
    assert 1e-9 < err < 24 * np.finfo(float).eps ** (1 / 6)
    assert abs(float(jt.spectral_abscissa(jnp.zeros((6, 6))))) < 1e-12
    assert np.isnan(float(jt.spectral_abscissa(jnp.full((6, 6), jnp.nan))))


def test_abscissa_on_calm_map(barge_2a):
    m = model(barge_2a)
    grid = {"xp": np.linspace(0.0, 0.6, 13), "l0": np.linspace(0.2, 2.5, 12)}
    a = jt.sweep_arrays(m, grid, jt.SweepSolver(method="analytic", eig_method="routh"))
    b = jt.sweep_arrays(m, grid, jt.SweepSolver(method="analytic", eig_method="lapack"))
    ok = b["found"]
    assert ok.sum() > 150
    np.testing.assert_allclose(a["max_real"][ok], b["max_real"][ok], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(a["stability"][ok], b["stability"][ok])


def test_abscissa_on_wave_map():
    """The (l0', ω) map of Barge 2a in head waves on the shipped panel database: both
    methods on the same Jacobians, in one compiled call."""
    m = jt.presets.barge2_wave_model("2a")

    def both(l0, omega):
        mdl = with_parameters(m, **{"l0": l0, "external.omega": omega})
        eqs = equilibria_fixed(mdl, n_grid=201, max_roots=4, throw=False)
        J = jax.vmap(jt.jacobian, in_axes=(None, 0))(mdl, eqs.state)
        lapack = jnp.max(jnp.real(jax.vmap(jnp.linalg.eigvals)(J)), axis=-1)
        return eqs.found, jax.vmap(jt.spectral_abscissa)(J), lapack

    l0, omega = (g.ravel() for g in np.meshgrid(np.linspace(0.4, 2.5, 6), np.linspace(0.4, 1.8, 6)))
    found, a, b = (
        np.asarray(x) for x in jax.jit(jax.vmap(both))(jnp.asarray(l0), jnp.asarray(omega))
    )
    assert found.sum() >= 36
    np.testing.assert_allclose(a[found], b[found], rtol=0, atol=1e-9)


def test_abscissa_gradient(barge_2b):
    """Its derivative is the rightmost eigenvalue's: against LAPACK's and finite
    differences, through the equilibrium, with respect to the attachment point."""
    m0 = model(barge_2b, l0=1.0, xp=0.3)

    def f(xp, method):
        m = with_parameters(m0, xp=xp)
        y = analytic_equilibria(m, throw=False).state[0]
        return jt.max_real_eigenvalue(m, y, method=method)

    x = jnp.asarray(0.3)
    grad = jax.jit(jax.grad(f), static_argnums=1)
    g = float(grad(x, "routh"))
    assert g == pytest.approx(float(grad(x, "lapack")), rel=1e-8)
    h = 1e-5
    value = jax.jit(f, static_argnums=1)
    fd = (float(value(x + h, "lapack")) - float(value(x - h, "lapack"))) / (2 * h)
    assert g == pytest.approx(fd, rel=1e-6)
    with pytest.raises(ValueError, match="'method'"):
        jt.max_real_eigenvalue(m0, jnp.zeros(6), method="qr")


def test_characteristic_polynomial_gradient_with_a_reduced_column():
    """A column already in Hessenberg form (structural zeros, as in the tow Jacobian) keeps
    the coefficients' derivatives finite and equal to finite differences."""
    A = np.random.default_rng(0).normal(size=(6, 6))
    A[2:, 0] = 0.0
    g = np.asarray(jax.jacfwd(jt.characteristic_polynomial)(jnp.asarray(A)))
    assert np.all(np.isfinite(np.asarray(jax.jacrev(jt.characteristic_polynomial)(jnp.asarray(A)))))
    E = np.zeros((6, 6))
    E[3, 1] = 1.0
    h = 1e-6
    cp = lambda M: np.asarray(jt.characteristic_polynomial(jnp.asarray(M)))
    np.testing.assert_allclose(g[:, 3, 1], (cp(A + h * E) - cp(A - h * E)) / (2 * h), atol=1e-7)
