"""Equilibria (thesis eqs 6.7-6.13 and the heading residual of docs/model.md section 4)."""

import dataclasses

import jax
import jax.numpy as jnp
import numpy as np
import pytest
from helpers import central_derivative, model

import jaxtow as jt


def test_fig_6_3_equilibrium_structure(barge_2a, barge_2b):
    e = jt.equilibria(model(barge_2a, xp=0.5))
    assert len(e) == 1 and e.branch.tolist() == [0]
    e = jt.equilibria(model(barge_2a, xp=0.3))
    assert len(e) == 3 and e.branch.tolist() == [-1, 0, 1]
    assert np.degrees(e.psi[2]) == pytest.approx(18.6, abs=0.1)  # docs/model.md: ≈ ∓18.6°
    e = jt.equilibria(model(barge_2b, xp=0.5))
    assert len(e) == 3 and e.branch.tolist() == [-1, 0, 1]
    np.testing.assert_allclose(np.degrees(np.abs(np.asarray(e.psi)[[0, 2]])), 76.0, atol=1.0)
    assert np.all(e.valid)


def test_side_equilibria_appear_at_analytic_pitchfork(barge_2a, barge_2b):
    """Side equilibria exist for x_p' < N_v'/Y_v' (0.4227, 0.1040) and not beyond."""
    for v, xc in ((barge_2a, 0.4227), (barge_2b, 0.1040)):
        xc_exact = float(v.Nv / v.Yv)
        assert xc_exact == pytest.approx(xc, abs=5e-5)
        below = jt.equilibria(model(v, xp=xc_exact - 0.01))
        above = jt.equilibria(model(v, xp=xc_exact + 0.01))
        n_below, n_above = len(below), len(above)
        # 2a: side pair exists below the pitchfork; 2b: the pair exists above it
        if v is barge_2a:
            assert (n_below, n_above) == (3, 1)
        else:
            assert (n_below, n_above) == (1, 3)


@pytest.mark.parametrize("xp", [0.0, 0.1, 0.3, 0.45, 0.5, 0.6])
@pytest.mark.parametrize("l0", [0.2, 1.0, 2.5])
def test_numerical_equals_analytic_and_residual_small(barge_2a, barge_2b, xp, l0):
    for v in (barge_2a, barge_2b):
        m = model(v, l0=l0, xp=xp)
        num = jt.equilibria(m)
        ana = jt.analytic_equilibria(m).compact()
        assert len(num) == len(ana)
        np.testing.assert_allclose(num.state, ana.state, rtol=0, atol=1e-10)
        assert np.all(num.residual < 1e-12)
        assert np.all(num.converged)


def test_power_law_towline_equilibria(barge_2b):
    m = jt.TowModel(vessel=barge_2b, towline=jt.PowerLawTowline(l0=2.0, xp=0.5, Sb=60.0, q=1.7))
    e = jt.equilibria(m)
    assert len(e) == 3
    assert np.all(e.residual < 1e-12)
    np.testing.assert_allclose(jax.vmap(m.towline.tension)(e.length), e.tension, rtol=1e-12)


def test_external_force_shifts_equilibrium(barge_2a):
    """A constant sway force moves the straight-behind equilibrium off ψ = 0 and the
    solver still lands on |f| < 1e-12."""
    m = model(barge_2a, **{"external": jt.forces.ConstantBodyForce(jnp.array([0.0, 0.01, 0.0]))})
    e = jt.equilibria(m)
    assert len(e) == 1
    assert abs(float(e.psi[0])) > 1e-3
    assert np.all(e.residual < 1e-12)


def test_slack_equilibrium_is_flagged(barge_2a):
    """An external force that exactly cancels the resistance needs no towline pull."""
    m = model(
        barge_2a,
        xp=0.5,
        external=jt.forces.ConstantBodyForce(jnp.array([float(barge_2a.R0), 0.0, 0.0])),
    )
    e = jt.equilibria(m)
    straight = e.select(e.branch == 0)
    assert not bool(straight.taut[0]) and not bool(straight.valid[0])
    assert np.isfinite(straight.state).all()
    # pushed forward harder than the resistance: the vessel would have to be ahead of the tug
    m = model(barge_2a, xp=0.5, external=jt.forces.ConstantBodyForce(jnp.array([0.2, 0.0, 0.0])))
    e = jt.equilibria(m)
    assert not bool(e.select(e.branch == 0).behind_tug[0])


def test_heading_range_flag(barge_2b):
    m = model(barge_2b, xp=0.5, psi_max=np.radians(60.0))
    e = jt.equilibria(m)
    assert e.in_range.tolist() == [False, True, False]
    assert e.valid.tolist() == [False, True, False]


def test_equilibrium_implicit_gradient(barge_2a):
    """dψ_eq/dx_p through the optimistix root (implicit differentiation) = FD."""
    m = model(barge_2a, xp=0.3)

    @jax.jit
    def side_psi(xp):
        mm = jt.with_parameters(m, xp=xp)
        return jt.equilibria_fixed(mm, max_roots=3).psi[2]

    g = float(jax.grad(side_psi)(0.3))
    fd = central_derivative(lambda x: side_psi(x), 0.3, h=1e-6)
    assert g == pytest.approx(fd, rel=1e-6)


def test_bisected_root_has_the_implicit_derivative():
    """The fixed halvings of a bracket (`bisected_root`): the root to the bracket's final
    width, a derivative with respect to the parameters equal to the implicit one
    (−∂_a f / ∂_x f) at the root, forward and reverse, also under vmap over brackets; a
    program that is not differentiated traces the function only for its value."""
    from jaxtow._roots import bisect, bisected_root

    def f(x, a):
        return x**3 - a

    root = 2.0 ** (1 / 3)
    x = bisected_root(f, 1.0, 2.0, 2.0, steps=52)
    assert float(x) == pytest.approx(root, abs=4e-16)
    falling = bisected_root(lambda x, a: a - x**3, 1.0, 2.0, 2.0, steps=52)
    assert float(falling) == pytest.approx(root, abs=4e-16)
    implicit = 1 / (3 * root**2)
    assert float(jax.grad(lambda a: bisected_root(f, 1.0, 2.0, a, steps=52))(2.0)) == (
        pytest.approx(implicit, rel=1e-12)
    )
    assert float(jax.jacfwd(lambda a: bisected_root(f, 1.0, 2.0, a, steps=52))(2.0)) == (
        pytest.approx(implicit, rel=1e-12)
    )
    many = jax.vmap(
        jax.grad(lambda lo, a: bisected_root(f, lo, 2.0, a, steps=52), argnums=1),
        in_axes=(0, None),
    )(jnp.array([0.5, 1.0, 1.2]), 2.0)
    np.testing.assert_allclose(np.asarray(many), implicit, rtol=1e-12)
    calls = []

    def counted(x, a):
        calls.append(1)
        return f(x, a)

    jax.make_jaxpr(lambda a: bisected_root(counted, 1.0, 2.0, a, steps=52))(2.0)
    assert len(calls) == 3  # the values at the bracket's ends and the halvings' step
    calls.clear()
    jax.make_jaxpr(lambda a: bisected_root(counted, 1.0, 2.0, a, steps=52, f_lo=-1.0, f_hi=6.0))(
        2.0
    )
    assert len(calls) == 1  # given the ends' values: the step's only
    # a root on the bracket's end is found exactly; a parameter that fn ignores moves nothing
    assert float(bisected_root(lambda x, a: x, -1.0, 0.0, 2.0, steps=52)) == 0.0
    assert (
        float(jax.grad(lambda a: bisected_root(lambda x, b: x, -1.0, 0.5, a, steps=52))(2.0)) == 0.0
    )
    # the bisection given the end values it would otherwise evaluate: the same root
    x1, ok1 = bisect(f, 1.0, 2.0, 2.0, atol=1e-14)
    x2, ok2 = bisect(f, 1.0, 2.0, 2.0, atol=1e-14, f_lo=f(1.0, 2.0), f_hi=f(2.0, 2.0))
    assert bool(ok1) and bool(ok2) and float(x1) == float(x2)


def test_the_residual_is_the_full_vector_field_at_the_state():
    """`Equilibria.residual` is computed from the hull forces the state is built from (one
    evaluation of the force model): it equals max |f(y)| of `jaxtow.vector_field` evaluated
    afresh at the state, off the equilibria as well as on them, in calm water and in a sea
    state with waves, wind and current from the side."""
    from jaxtow._equilibrium import _state_and_residual, _steady, state_from_heading

    tow = jt.tow.load("barge2a")
    sea = tow.sea_states[0]
    sea = dataclasses.replace(sea, wave_angle=0.4, wind_angle=-0.3, current_angle=0.2)
    for m in (tow.model(), tow.sea_model(sea)):
        for psi in (-0.6, -0.05, 0.0, 0.2):
            state, gamma, T, length, residual = _state_and_residual(jnp.asarray(psi), m)
            expected = state_from_heading(jnp.asarray(psi), m)
            np.testing.assert_array_equal(state, expected[0])
            np.testing.assert_array_equal(T, expected[2])
            f = jt.vector_field(0.0, state, _steady(m), throw=False)
            np.testing.assert_allclose(residual, jnp.max(jnp.abs(f)), rtol=1e-13, atol=1e-16)
