"""Section coefficients by Frank's close-fit method (jaxtow.strip): the exponential integral,
the Green function and its panel integrals against direct quadrature, exact limits and
identities, the irregular frequencies, Ursell's circle, and gradients in the offsets."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest
import scipy.special as sp
from scipy.integrate import quad

from jaxtow.strip import _sections as M, section_coefficients
from jaxtow.strip._expint import exp_ei

G, RHO = 9.80665, 1025.0


def semicircle(n, r=1.0):
    th = np.linspace(0.0, np.pi / 2, n + 1)
    return r * np.cos(th), -r * np.sin(th)


def rectangle(b, t, n):
    """Half offsets of a B x T rectangle, n panels on the side and n on the bottom."""
    ys = np.full(n + 1, b / 2)
    zs = np.linspace(0.0, -t, n + 1)
    yb = np.linspace(b / 2, 0.0, n + 1)[1:]
    return np.r_[ys, yb], np.r_[zs, np.full(n, -t)]


def test_exp_ei_against_scipy_over_the_right_half_plane():
    rng = np.random.default_rng(0)
    r = np.exp(rng.uniform(np.log(1e-3), np.log(200.0), 4000))
    th = rng.uniform(-np.pi / 2, np.pi / 2, 4000)
    w = np.concatenate([r * np.exp(1j * th), np.linspace(0.01, 100, 200) + 0j, 1j * r[:200]])
    ref = np.exp(-w) * sp.expi(w)
    got = np.asarray(jax.jit(exp_ei)(w))
    assert np.max(np.abs(got / ref - 1)) < 1e-10


def test_exp_ei_derivative_rule():
    w = jnp.array([0.3 + 0.2j, 5.0 - 7.0j, 30.0 + 2.0j, 12.0 + 30.0j, 60.0 - 5.0j])
    _, t = jax.jvp(exp_ei, (w,), (jnp.ones_like(w),))
    h = 1e-6
    fd = (np.asarray(exp_ei(w + h)) - np.asarray(exp_ei(w - h))) / (2 * h)
    assert np.allclose(np.asarray(t), fd, rtol=1e-6)


@pytest.mark.parametrize("x, y", [(0.0, -0.7), (0.8, -0.5), (-1.5, -0.2), (2.0, -1.5)])
def test_wave_term_equals_the_principal_value_integral(x, y):
    """2 Re f(w) = −2 PV∫_0^∞ e^{kY} cos(kX)/(k − ν) dk (Wehausen & Laitone), by quadrature."""
    nu = 1.3

    def f(k):
        return np.exp(k * y) * np.cos(k * x)

    pv = quad(f, 0, 3 * nu, weight="cauchy", wvar=nu, limit=400)[0]
    pv += quad(lambda k: f(k) / (k - nu), 3 * nu, 200, limit=400)[0]
    w = -nu * y + 1j * nu * x
    assert 2 * np.real(np.asarray(exp_ei(jnp.asarray(w)))) == pytest.approx(-2 * pv, rel=1e-9)


def test_panel_integrals_against_quadrature():
    nu, a, b, z = 1.3, 0.7 - 0.3j, 0.5 - 0.9j, 1.2 - 0.6j
    s = np.linspace(0.0, 1.0, 40001)
    zeta = a + (b - a) * s
    length = abs(b - a)
    w = 1j * nu * (z - np.conj(zeta))

    def wave(z):  # one panel a -> b, at one point
        return [v[0, 0] for v in M._wave(jnp.array([z]), (jnp.array([a, b]),), nu)]

    int_f, int_e, d_f, _ = wave(z)
    assert complex(int_f) == pytest.approx(
        np.trapezoid(np.exp(-w) * sp.expi(w), s) * length, rel=1e-8
    )
    assert complex(int_e) == pytest.approx(np.trapezoid(np.exp(-w), s) * length, rel=1e-8)
    pot, vel = M._rankine(z, a, b)
    assert float(pot) == pytest.approx(np.trapezoid(np.log(np.abs(z - zeta)), s) * length, rel=1e-8)
    h = 1e-6  # the velocities are the z-derivatives of the analytic functions
    assert (wave(z + h)[0] - wave(z - h)[0]) / (2 * h) == pytest.approx(complex(d_f), rel=1e-7)
    assert (M._rankine(z + h, a, b)[0] - M._rankine(z - h, a, b)[0]) / (2 * h) == pytest.approx(
        float(np.real(vel)), rel=1e-7
    )


def test_semicircle_sway_at_low_frequency_is_half_the_circle_added_mass():
    """ω → 0: the free surface acts as a rigid wall; the swaying semicircle and its image
    are a circle in unbounded fluid, a22 = ρπR²/2 (64 panels: 0.54 % above it)."""
    y, z = semicircle(64)
    c = section_coefficients(y, z, 0.02)
    assert float(c.added_mass[0, 0]) == pytest.approx(RHO * np.pi / 2, rel=1e-2)
    assert float(c.damping[0, 0]) < 1e-8 * float(c.added_mass[0, 0])  # no waves at ω → 0


def test_circle_has_no_roll_and_no_heave_sway_coupling():
    y, z = semicircle(16)
    c = section_coefficients(y, z, np.array([1.0, 2.0, 4.0]))
    scale = float(c.added_mass[0, 1, 1])
    assert np.max(np.abs(np.asarray(c.added_mass[:, 2, 2]))) < 1e-10 * scale
    assert np.max(np.abs(np.asarray(c.exciting[:, 2]))) < 1e-10 * scale * G
    assert np.all(np.asarray(c.added_mass[:, 0, 1]) == 0.0)


@pytest.mark.parametrize("shape", ["circle", "rectangle"])
def test_damping_equals_the_exciting_force_energy_identity(shape):
    """Haskind and energy together: b_jj = ω |X_j|² / (ρ g²) for a symmetric section in deep
    water (radiation from the radiation solve, X_j from the diffraction solve)."""
    y, z = semicircle(32) if shape == "circle" else rectangle(2.0, 1.0, 16)
    om = np.linspace(0.6, 4.0, 9)
    c = section_coefficients(y, z, om)
    for j in (0, 1):
        ratio = np.asarray(c.damping[:, j, j]) / (
            np.abs(np.asarray(c.exciting[:, j])) ** 2 * om / (RHO * G**2)
        )
        assert np.max(np.abs(ratio - 1)) < 0.025, (j, ratio)


def test_added_mass_and_damping_are_symmetric():
    y, z = rectangle(2.0, 1.0, 16)
    c = section_coefficients(y, z, np.array([1.0, 2.0, 3.0]))
    for k in ("added_mass", "damping"):
        m = np.asarray(getattr(c, k))
        assert np.allclose(m[:, 0, 2], m[:, 2, 0], rtol=5e-3), k


@pytest.mark.slow
def test_the_lid_removes_the_irregular_frequency_and_changes_nothing_else():
    """B/T = 2: the first irregular frequency is at ω²B/2g = (π/2) coth(π/2) = 1.71. Without
    the lid the heave added mass jumps there; with it the curve is smooth, and away from it
    the lid changes the coefficients by less than 0.5 % (the panels' own error)."""
    xi = np.linspace(1.6, 1.8, 21)
    om = np.sqrt(xi * 2 * G / 2.0)
    y, z = rectangle(2.0, 1.0, 16)
    bare = np.asarray(section_coefficients(y, z, om, n_lid=0).added_mass[:, 1, 1])
    lid = np.asarray(section_coefficients(y, z, om).added_mass[:, 1, 1])
    jumps = lambda a: np.max(np.abs(np.diff(a, 2)))  # noqa: E731
    assert jumps(bare) > 50 * jumps(lid)
    assert np.all(np.diff(lid) > 0)  # smooth and monotonic through ξ = 1.71
    low = np.array([0.8, 1.2, 2.0])
    a0 = section_coefficients(y, z, low, n_lid=0).added_mass
    a1 = section_coefficients(y, z, low).added_mass
    assert np.allclose(np.asarray(a0), np.asarray(a1), rtol=5e-3, atol=1e-9)


#: Ursell's (1949) heaving semicircle, read from a published plot (a public digitisation whose
#: source is Vugts 1968, Int. Shipbuilding Progress 15(167), 251-276): (ω√(R/g), a33/(ρπR²/2))
#: and (ω√(R/g), b33√(R/g)/(ρπR²/2)); the reading is good to about ±0.01.
URSELL_A33 = [(0.3093, 1.434), (0.5239, 0.840), (0.8872, 0.594), (1.2047, 0.659), (1.5319, 0.756)]
URSELL_B33 = [(0.2969, 0.524), (0.5128, 0.617), (0.9081, 0.452), (1.1888, 0.274), (1.4949, 0.137)]


def test_ursell_heaving_semicircle():
    """32 panels on the quarter circle: within 0.02 of Ursell's curves as digitised (1-3 %,
    where the method's own panel convergence is 0.4 %; docs/strip.md)."""
    y, z = semicircle(32)
    m = RHO * np.pi / 2
    for table, key in ((URSELL_A33, "added_mass"), (URSELL_B33, "damping")):
        x = np.array([p[0] for p in table])
        ref = np.array([p[1] for p in table])
        c = section_coefficients(y, z, x * np.sqrt(G))
        got = np.asarray(getattr(c, key)[:, 1, 1]) / m
        if key == "damping":
            got = got / np.sqrt(G)
        assert np.max(np.abs(got - ref)) < 0.02, (key, got, ref)


@pytest.mark.slow
def test_ursell_exact_multipole_solution_to_one_percent():
    """Against Ursell's (1949) multipole solution evaluated here (`tests/ursell.py`, SciPy
    quadrature, converged to 1e-4): 128 panels on the quarter circle give the heave added
    mass and damping within 1 % over ω√(R/g) = 0.3-1.5 (64 panels: within 0.7 %, but 1.2 %
    on the small damping at 1.5), and the error falls with the panel size (first order)."""
    from ursell import ursell_heave

    x = np.array([0.3, 0.5, 0.7, 0.9, 1.2, 1.5])
    exact = np.array([ursell_heave(float(w)) for w in x])
    m = RHO * np.pi / 2
    errs = []
    for n in (64, 128):
        y, z = semicircle(n)
        c = section_coefficients(y, z, x * np.sqrt(G))
        got = np.stack(
            [
                np.asarray(c.added_mass[:, 1, 1]) / m,
                np.asarray(c.damping[:, 1, 1]) / m / np.sqrt(G),
            ],
            axis=1,
        )
        errs.append(np.abs(got / exact - 1))
    assert np.max(errs[1]) < 0.01, errs[1]
    assert np.all(errs[1] < 0.7 * errs[0] + 1e-4)


@pytest.mark.slow
def test_gradients_in_the_offsets_equal_finite_differences():
    y, z = rectangle(2.0, 1.0, 4)
    yz = jnp.stack([jnp.asarray(y), jnp.asarray(z)])

    def f(p):
        c = section_coefficients(p[0], p[1], jnp.array([2.0, 3.0]))
        return c.added_mass[0, 1, 1] + c.damping[1, 0, 0] + 1e-6 * jnp.abs(c.exciting[1, 2]) ** 2

    grad = np.asarray(jax.grad(f)(yz))
    h = 1e-6
    for i, j in [(0, 2), (1, 3), (0, 6), (1, 7)]:
        e = np.zeros(yz.shape)
        e[i, j] = h
        fd = (float(f(yz + e)) - float(f(yz - e))) / (2 * h)
        assert grad[i, j] == pytest.approx(fd, rel=1e-5), (i, j)


@pytest.mark.parametrize(
    "kw, match",
    [
        (dict(y=[1.0, 0.0], z=[0.0, -1.0]), "at least 3"),
        (dict(y=[[1.0, 0.5, 0.0]], z=[[0.0, -0.5, -1.0]]), "1-D"),
        (dict(y=[1.0, 0.5, 0.0], z=[0.0, -1.0]), "same length"),
    ],
)
def test_bad_offsets_are_named(kw, match):
    with pytest.raises(ValueError, match=match):
        section_coefficients(kw["y"], kw["z"], 1.0)
