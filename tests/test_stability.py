"""Linear stability: eigenvalues, Routh-Hurwitz, gradients (thesis section 2.1.2, fig 6.4)."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from helpers import central_derivative, model

import jaxtow as jt
from jaxtow._stability import routh_first_column


@pytest.mark.slow  # default-suite time
def test_fig_6_4_stability_over_towline_length(barge_2a, barge_2b):
    """x_p' = 0.5, 0.2 <= l0' <= 2.5: Barge 2b straight-behind stable, its side
    equilibria unstable; Barge 2a straight-behind unstable (thesis fig. 6.4)."""
    l0 = np.linspace(0.2, 2.5, 24)
    for vessel, straight_sign in ((barge_2a, 1), (barge_2b, -1)):
        ds = jt.sweep(model(vessel), {"l0": l0}, max_roots=4)
        valid = ds["valid"].values
        br, st = ds["branch"].values, ds["stability"].values
        straight = valid & (br == 0)
        assert straight.sum(axis=1).tolist() == [1] * l0.size
        assert np.all(st[straight] == straight_sign)
        side = valid & (br != 0)
        if vessel is barge_2b:
            assert side.sum(axis=1).tolist() == [2] * l0.size
            assert np.all(st[side] == 1)
        else:
            assert side.sum() == 0


@pytest.mark.slow  # default-suite time
def test_routh_hurwitz_agrees_with_eigenvalues(barge_2a, barge_2b):
    for v in (barge_2a, barge_2b):
        ds = jt.sweep(model(v), {"xp": np.linspace(0.0, 0.6, 13), "l0": np.array([0.3, 1.0, 2.5])})
        ok = ds["valid"].values & (np.abs(ds["max_real"].values) > 1e-6)
        assert ok.sum() > 40
        np.testing.assert_array_equal(
            ds["routh_hurwitz"].values[ok], ds["stability"].values[ok] < 0
        )


def test_characteristic_polynomial_matches_eigenvalues(barge_2b):
    m = model(barge_2b)
    y = jt.equilibria(m).state[1]
    A = jt.jacobian(m, y)
    c = jt.characteristic_polynomial(A)
    np.testing.assert_allclose(
        np.sort_complex(np.roots(np.asarray(c))),
        np.sort_complex(np.asarray(jt.eigenvalues(m, y))),
        rtol=1e-8,
        atol=1e-10,
    )


def test_classification_and_marginal():
    assert jt.classify(-0.1) == -1 and jt.classify(0.1) == 1 and jt.classify(0.0) == 0


@pytest.mark.parametrize(
    "name",
    ["Nr"]
    + [
        pytest.param(n, marks=pytest.mark.slow)
        for n in ("l0", "xp", "EA", "a22", "a66", "Yv", "R0")
    ],
)
def test_gradient_of_max_real_eigenvalue_matches_fd(barge_2a, name):
    """d(max Re λ)/dθ through the numerical equilibrium (implicit differentiation of the
    optimistix root) and the eigenvalues equals central finite differences."""
    base = model(barge_2a, l0=1.5, xp=0.3)

    def margin(theta):
        m = jt.with_parameters(base, **{name: theta})
        eqs = jt.equilibria_fixed(m, max_roots=3)
        return jt.max_real_eigenvalue(m, eqs.state[2])  # the ψ > 0 side equilibrium

    theta0 = float(jt.get_parameter(base, name))
    margin = jax.jit(margin)  # one program for the derivative, one for the differences
    g = float(jax.jit(jax.grad(margin))(theta0))
    h = 1e-6 * max(1.0, abs(theta0))
    fd = central_derivative(margin, theta0, h=h)
    assert abs(g - fd) <= 1e-5 * max(abs(fd), 1e-3), (name, g, fd)


def _routh_stable(roots):
    c = np.real(np.poly(roots))
    return bool(np.all(np.asarray(routh_first_column(jnp.asarray(c))) > 0))


def test_routh_array_on_known_polynomials():
    assert _routh_stable([-1.0] * 6)
    assert _routh_stable([-0.1 + 2j, -0.1 - 2j, -1, -3, -0.5 + 0.1j, -0.5 - 0.1j])
    assert not _routh_stable([0.05 + 1j, 0.05 - 1j, -1, -2, -3, -4])  # unstable complex pair
    assert not _routh_stable([0.2, -1, -2, -3, -4, -5])  # unstable real root
    assert not _routh_stable([1j, -1j, -1, -2, -3, -4])  # marginal: not asymptotically stable


def test_polynomial_eigenvalues_match_lapack(barge_2a, barge_2b):
    """The LAPACK-free eigenvalues (characteristic polynomial + Aberth) agree with LAPACK."""
    for v in (barge_2a, barge_2b):
        for xp, l0 in ((0.3, 0.4), (0.5, 2.5), (0.1, 1.0)):
            m = model(v, l0=l0, xp=xp)
            for y in jt.equilibria(m).state:
                a = np.asarray(jt.eigenvalues(m, y))
                b = np.asarray(jt.eigenvalues(m, y, method="polynomial"))
                dist = np.abs(a[:, None] - b[None, :])  # match each eigenvalue to its nearest
                assert dist.min(axis=1).max() < 1e-8 and dist.min(axis=0).max() < 1e-8
    with pytest.raises(ValueError, match="'method'"):
        jt.eigenvalues(m, y, method="qr")
