"""Bridle / transverse attachment offset, design optimisation and sensitivities."""

import math

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
from jaxtow import design as D


@pytest.fixture(scope="module")
def model_2a():
    return jt.TowModel(
        vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline(l0=1.0, xp=0.5)
    )


def test_centred_offset_is_the_foundation_model(model_2a):
    y = jnp.array([0.9, 0.1, -0.05, 1.01, 0.2, -0.15])
    m0 = jt.with_parameters(model_2a, yp=0.0)
    assert float(model_2a.towline.yp) == 0.0
    np.testing.assert_array_equal(
        np.asarray(jt.vector_field(0.0, y, m0)), np.asarray(jt.vector_field(0.0, y, model_2a))
    )
    np.testing.assert_array_equal(
        np.asarray(jt.jacobian(m0, y)), np.asarray(jt.jacobian(model_2a, y))
    )
    # with an offset the towline moment gains -T' yp cos(gamma + psi)
    m1 = jt.with_parameters(model_2a, yp=0.1)
    fb0, fb1 = jt.force_breakdown(0.0, y, m0), jt.force_breakdown(0.0, y, m1)
    assert float(fb1.towline[2] - fb0.towline[2]) == pytest.approx(
        -float(fb0.tension) * 0.1 * math.cos(0.2 - 0.15), rel=1e-13
    )


def test_offset_kinematics_move_the_cog_with_its_body_velocity(model_2a):
    """The CoG position reconstructed from (l, gamma, psi) and (xp, yp) must move with the
    body velocity (u, v) rotated by psi: checks the derived l-dot, gamma-dot terms."""
    m = jt.with_parameters(model_2a, l0=0.5, xp=0.4, yp=0.08)
    sim = jt.simulate(m, jt.initial_state(m, psi0=0.2, y0=0.1), t1=10.0, n_save=2001)
    tr = jt.trajectory(m, sim)
    y = np.asarray(sim.ys)
    u, v, psi = y[:, 0], y[:, 1], y[:, 5]
    err = max(
        np.max(np.abs(np.gradient(tr.cog_x, tr.t) - (u * np.cos(psi) - v * np.sin(psi)))[5:-5]),
        np.max(np.abs(np.gradient(tr.cog_y, tr.t) - (u * np.sin(psi) + v * np.cos(psi)))[5:-5]),
    )
    wrong = jt.trajectory(jt.with_parameters(m, yp=0.0), sim)  # the same run read with yp ignored
    err_wrong = np.max(
        np.abs(np.gradient(wrong.cog_x, tr.t) - (u * np.cos(psi) - v * np.sin(psi)))[5:-5]
    )
    assert err < 2e-3 and err_wrong > 20 * err


def test_offset_equilibria_are_mirror_images(model_2a):
    a, b = jt.with_parameters(model_2a, yp=0.1), jt.with_parameters(model_2a, yp=-0.1)
    ea, eb = jt.equilibria(a), jt.equilibria(b)
    assert np.all(ea.residual < 1e-12) and np.all(
        eb.residual < 1e-12
    )  # the residual F(psi) balances all 6 equations
    np.testing.assert_allclose(
        np.sort(np.asarray(ea.psi)), np.sort(-np.asarray(eb.psi)), atol=1e-12
    )
    ya, psa, oka = D.straight_equilibrium(a)
    yb, psb, okb = D.straight_equilibrium(b)
    assert bool(oka) and float(psa) == pytest.approx(-float(psb), abs=1e-12) and float(psa) < 0
    assert float(D.spectral_abscissa(a, ya)) == pytest.approx(
        float(D.spectral_abscissa(b, yb)), abs=1e-10
    )
    with pytest.raises(ValueError, match="'yp' must lie in"):
        jt.Towline(l0=1.0, xp=0.5, EA=100.0, yp=0.7)


def test_bridle_equivalent_point_and_leg_tensions():
    b = jt.Bridle.symmetric(x_legs=0.5, half_spread=0.16, apex_x=0.9)
    line = b.towline(l0=1.0, EA=300.0)
    assert float(line.xp) == 0.9 and float(line.yp) == 0.0
    cos_leg = 0.4 / math.hypot(0.4, 0.16)
    np.testing.assert_allclose(
        np.asarray(b.leg_tensions(2.0, 0.0)), [1 / cos_leg, 1 / cos_leg], rtol=1e-14
    )
    half_angle = math.atan2(0.16, 0.4)
    assert bool(b.taut(1.0, 0.9 * half_angle)) and not bool(b.taut(1.0, 1.1 * half_angle))
    t = np.asarray(b.leg_tensions(1.0, 0.3))  # the legs balance the towline at the apex
    e = (np.asarray(b.legs) - np.asarray(b.apex)) / np.asarray(b.leg_lengths)[:, None]
    np.testing.assert_allclose(t @ e, -np.array([math.cos(0.3), -math.sin(0.3)]), atol=1e-14)
    with pytest.raises(ValueError, match="parallel"):
        jt.Bridle(legs=[[0.5, 0.1], [0.7, 0.1]], apex=[0.9, 0.1])


def _fd4(f, x, i, h):
    e = jnp.zeros_like(x).at[i].set(h)
    return float((8 * (f(x + e) - f(x - e)) - (f(x + 2 * e) - f(x - 2 * e))) / (12 * h))


def test_sensitivity_gradients_match_finite_differences(model_2a):
    m = jt.with_parameters(model_2a, yp=0.1)  # off-centre: the equilibrium sits at psi != 0
    names, x, g, a, _ = D.sensitivity_arrays(m)
    assert {"a22", "Nv", "EA", "l0", "xp", "yp"} <= set(names)
    f = jax.jit(lambda xx: D.spectral_abscissa(jt.with_parameters(m, **dict(zip(names, xx)))))
    x0 = jnp.asarray(x[0])
    scale = np.max(np.abs(g))
    for i, n in enumerate(names):
        fd = _fd4(f, x0, i, 1e-3 * max(abs(float(x0[i])), 1e-2))
        assert abs(g[0, i] - fd) <= 1e-5 * max(abs(fd), 1e-3 * scale), n
    ds = jt.sensitivities(m, ["a22", "a66", "Nv", "Yv", "EA"], sweep={"l0": [0.8, 1.2]})
    assert ds.gradient.shape == (2, 5) and sorted(ds.importance.values.tolist()) == [1, 2, 3, 4, 5]
    np.testing.assert_allclose(ds.elasticity, ds.value * ds.gradient)


def test_smoothing_at_an_eigenvalue_crossing(model_2a):
    """At l0' = 0.3 the slow sway-yaw pair and the towline-stretch pair exchange the max of
    Re lambda near x_p' = 0.805: max Re lambda has a kink there, the log-sum-exp smoothing
    does not."""
    m = jt.with_parameters(model_2a, l0=0.3)

    def gap(xp):
        mm = jt.with_parameters(m, xp=xp)
        lam = jt.eigenvalues(mm, D.straight_equilibrium(mm)[0])
        slow = jnp.max(jnp.where(jnp.abs(lam.imag) < 10, lam.real, -jnp.inf))
        fast = jnp.max(jnp.where(jnp.abs(lam.imag) >= 10, lam.real, -jnp.inf))
        return slow - fast

    gap = jax.jit(gap)
    lo, hi = 0.78, 0.83
    assert float(gap(lo)) > 0 > float(gap(hi))
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if float(gap(mid)) > 0 else (lo, mid)
    xs = 0.5 * (lo + hi)
    exact = jax.jit(lambda xp: D.spectral_abscissa(jt.with_parameters(m, xp=xp)))
    smooth = jax.jit(lambda xp: D.smooth_abscissa(jt.with_parameters(m, xp=xp)))
    h = 1e-4
    left = (float(exact(xs)) - float(exact(xs - h))) / h
    right = (float(exact(xs + h)) - float(exact(xs))) / h
    assert abs(left - right) > 0.05  # a genuine kink
    ds = float(jax.grad(smooth)(xs))
    fd = (float(smooth(xs + 1e-6)) - float(smooth(xs - 1e-6))) / 2e-6
    assert ds == pytest.approx(fd, rel=1e-5)
    assert min(left, right) - 1e-9 <= ds <= max(left, right) + 1e-9
    for xp in (xs, xs - 0.01, xs + 0.01):  # the documented bound
        e, s = float(exact(xp)), float(smooth(xp))
        assert e <= s <= e + D.SMOOTHING * math.log(6) + 1e-15


@pytest.mark.slow  # the default suite's wall time (2 cores)
def test_optimiser_beats_grid_with_far_fewer_evaluations_and_stabilises_2a(model_2a):
    """Bridle attachment (x_p', y_p') for Barge 2a at l0' = 1 in calm water, |psi_eq| <= 10 deg."""
    r = D.optimise_towline(model_2a, variables=("xp", "yp"), x0=dict(xp=0.5, yp=0.02))
    g = D.grid_search(model_2a, dict(xp=np.linspace(0.3, 1.0, 61), yp=np.linspace(-0.15, 0.15, 61)))
    assert r.converged
    assert r.objective <= g.objective + 0.01 * abs(
        g.objective
    )  # within 1 % of the grid optimum (or better)
    assert 10 * r.n_evaluations <= g.n_evaluations
    centred = D.spectral_abscissa(model_2a)
    assert float(centred) > 0.1  # the plain centred towline of the same length fishtails
    assert r.stable and r.abscissa[0] < -0.03
    assert (
        abs(math.degrees(r.psi[0])) < 10.1
    )  # the heading limit holds (penalty: 0.05 deg overshoot)
    ds = jt.io.design_dataset(r)
    assert float(ds.design_yp) == pytest.approx(r.params["yp"]) and ds.attrs["method"] == "BFGS"
    # time domain agrees near the equilibrium: a 3 deg disturbance of the design dies out
    designed = jt.with_parameters(model_2a, **r.params)
    y_eq = D.straight_equilibrium(designed)[0]
    met = jt.fishtail_metrics(
        designed, jt.simulate(designed, y_eq.at[5].add(math.radians(3.0)), t1=300.0)
    )
    assert met.outcome == "converged"
