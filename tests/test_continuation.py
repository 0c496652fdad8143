"""Bifurcation analysis: pitchfork, Hopf, Lyapunov coefficient, limit cycles."""

import jax.numpy as jnp
import numpy as np
import pytest
from helpers import model

import jaxtow as jt
from jaxtow import continuation as ct
from jaxtow._equilibrium import state_from_heading


@pytest.fixture(scope="module")
def branches(barge_2a, barge_2b):
    return {
        name: ct.equilibrium_branch(model(v, l0=0.5, xp=0.5), "xp", p_range=(0.0, 1.0))
        for name, v in (("2a", barge_2a), ("2b", barge_2b))
    }


@pytest.mark.slow  # default-suite time: the branch continuation of both barges
@pytest.mark.parametrize("name, expected", [("2a", 0.4227), ("2b", 0.1040)])
def test_pitchfork_at_nv_over_yv(branches, name, expected, barge_2a, barge_2b):
    v = barge_2a if name == "2a" else barge_2b
    bps = branches[name].points("branch_point")
    assert len(bps) == 1
    assert bps[0].parameter == pytest.approx(float(v.Nv / v.Yv), abs=1e-12)
    assert bps[0].parameter == pytest.approx(expected, abs=5e-5)
    # branch switching found the side equilibria, on the side of the pitchfork where they exist
    child = branches[name].children[0]
    assert child.psi.max() > 1.0 and child.psi.min() < -1.0
    if name == "2a":
        assert child.p.max() == pytest.approx(bps[0].parameter, abs=1e-3)
        # at x_p' = 0.3 the side equilibria are at +-18.62 deg (foundation issue, jt.equilibria)
        sel = (child.psi > 0) & (child.psi < 0.6)
        order = np.argsort(child.p[sel])
        psi_03 = np.interp(0.3, child.p[sel][order], child.psi[sel][order])
        eqs = jt.equilibria(model(v, l0=0.5, xp=0.3))
        assert np.degrees(psi_03) == pytest.approx(np.degrees(float(np.max(eqs.psi))), abs=0.05)
    else:
        assert child.p.min() == pytest.approx(bps[0].parameter, abs=1e-3)


@pytest.mark.slow  # default-suite time: the branch continuation of both barges
def test_side_branch_points_are_equilibria_and_folds_are_located(branches, barge_2b):
    child = branches["2b"].children[0]
    for p, psi in zip(child.p[::7], child.psi[::7]):
        m = model(barge_2b, l0=0.5, xp=float(p))
        assert abs(float(jt.heading_residual(psi, m))) < 1e-10
    # beyond the manoeuvring model's |psi| <= 90 deg the side branch turns back: a fold at 90 deg
    wide = ct.equilibrium_branch(
        model(barge_2b, l0=0.5, xp=0.5),
        "xp",
        p_range=(0.0, 1.0),
        psi0=float(child.psi[5]),
        p0=float(child.p[5]),
        psi_max=1.8,
        switch=False,
        ds=0.02,
    )
    folds = wide.points("fold")
    assert len(folds) == 2 and all(abs(abs(f.psi) - np.pi / 2) < 1e-9 for f in folds)
    for f in folds:
        m = model(barge_2b, l0=0.5, xp=f.parameter)
        assert abs(float(jt.heading_residual(f.psi, m))) < 1e-10
        import jax

        assert abs(float(jax.grad(jt.heading_residual)(f.psi, m))) < 1e-8


@pytest.mark.slow  # default-suite time: the branch continuation of both barges
def test_hopf_points_match_sign_change_of_sampled_max_real(branches, barge_2b):
    hopf = sorted(s.parameter for s in branches["2b"].points("hopf") if s.psi == 0.0)
    assert len(hopf) == 2 and 0.2 < hopf[0] < hopf[1] < 0.45

    import jax

    base = model(barge_2b, l0=0.5, xp=0.3)

    @jax.jit
    @jax.vmap
    def max_real_v(xp):
        m = jt.with_parameters(base, xp=xp)
        return jt.max_real_eigenvalue(m, state_from_heading(jnp.asarray(0.0), m)[0])

    def max_real(xp):
        return float(max_real_v(jnp.asarray([xp]))[0])

    grid = np.linspace(0.2, 0.45, 2001)
    vals = np.asarray(max_real_v(jnp.asarray(grid)))
    idx = np.nonzero(np.sign(vals[:-1]) != np.sign(vals[1:]))[0]
    assert len(idx) == 2
    for i, h in zip(idx, hopf):
        lo, hi = grid[i], grid[i + 1]
        flo = vals[i]
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            fm = max_real(mid)
            lo, hi, flo = (mid, hi, fm) if np.sign(fm) == np.sign(flo) else (lo, mid, flo)
        assert 0.5 * (lo + hi) == pytest.approx(h, abs=1e-8)
    for s in branches["2b"].points("hopf"):
        if s.psi == 0.0:
            assert s.frequency > 0 and s.lyapunov < 0  # supercritical: a small stable cycle is born


@pytest.mark.slow  # default-suite time: the branch continuation of both barges
def test_time_domain_onset_at_the_hopf_point(branches, barge_2b):
    h = min(s.parameter for s in branches["2b"].points("hopf") if s.psi == 0.0)

    def late_amplitude(xp):
        m = model(barge_2b, l0=0.5, xp=xp)
        y0 = state_from_heading(jnp.asarray(0.0), m)[0].at[5].set(0.01)
        sim = jt.simulate(m, y0, t1=600.0, n_save=6001)
        psi = np.asarray(sim.ys[:, 5])
        return np.abs(psi[-1000:]).max()

    assert late_amplitude(h - 0.01) < 0.005  # below the Hopf: the disturbance dies out
    assert late_amplitude(h + 0.01) > 0.01  # above: it grows into a limit cycle


@pytest.mark.slow  # default-suite time: a 3000-long time-domain run and a shooting solve
def test_limit_cycle_matches_long_time_domain_run(barge_2b):
    m = model(barge_2b, l0=0.5, xp=0.32)
    orbit = ct.limit_cycle_from_simulation(m, t1=1500.0)
    assert orbit.residual < 1e-8 and orbit.stable
    mu = np.sort(np.abs(orbit.floquet))
    assert mu[-1] == pytest.approx(1.0, abs=1e-6)  # the trivial multiplier
    y0 = state_from_heading(jnp.asarray(0.0), m)[0].at[5].set(0.05)
    sim = jt.simulate(m, y0, t1=3000.0, n_save=30001)
    met = jt.fishtail_metrics(m, sim)
    assert met.outcome == "limit_cycle"
    assert orbit.path_width == pytest.approx(met.path_width, rel=0.01)
    assert orbit.period == pytest.approx(met.slewing_period, rel=0.01)


def test_lyapunov_coefficient_of_the_normal_form():
    for a in (-0.7, 0.4):

        def f(y, a=a):
            r2 = y[0] ** 2 + y[1] ** 2
            return jnp.stack([-2.0 * y[1] + a * y[0] * r2, 2.0 * y[0] + a * y[1] * r2])

        # Kuznetsov's l1 with <q, q> = 1 equals a for this normal form (sign = criticality)
        assert ct.lyapunov_coefficient(f, jnp.zeros(2)) == pytest.approx(a, rel=1e-12)


@pytest.mark.slow  # 12 s of compile; kept out of the default run for CI time
def test_hopf_curve_passes_through_the_one_parameter_hopf_point(barge_2b):
    m = model(barge_2b, l0=0.5, xp=0.3)
    h = ct.straight_behind_hopf(m, "xp", (0.2, 0.3))
    curve = ct.hopf_curve(
        m, ("xp", "l0"), start=(h, 0.5), ranges=((0.1, 0.6), (0.3, 0.8)), ds=0.02, max_points=60
    )
    assert len(curve) > 5
    for xp, l0 in curve[::5]:
        mm = model(barge_2b, l0=float(l0), xp=float(xp))
        y = state_from_heading(jnp.asarray(0.0), mm)[0]
        ev = np.linalg.eigvals(np.asarray(jt.jacobian(mm, y)))
        assert np.min(np.abs(ev.real)) < 1e-9  # a pair on the imaginary axis


def test_bad_inputs(barge_2b):
    m = model(barge_2b, l0=0.5, xp=0.5)
    with pytest.raises(ValueError, match="p_range"):
        ct.equilibrium_branch(m, "xp", p_range=(1.0, 0.0))
    with pytest.raises(ValueError, match="psi0"):
        ct.equilibrium_branch(m, "xp", p_range=(0.0, 1.0), psi0=0.7)
    with pytest.raises(ValueError, match="p0"):
        ct.equilibrium_branch(m, lambda mm, p: mm, p_range=(0.0, 1.0))


@pytest.mark.slow  # the default suite's wall time (2 cores)
def test_cli_bifurcation(tmp_path):
    import json

    from jaxtow.cli import main

    assert (
        main(
            [
                "bifurcation",
                "--tow",
                "barge2b",
                "--range",
                "0.2",
                "0.45",
                "--out",
                str(tmp_path),
            ]
        )
        == 0
    )
    s = json.loads((tmp_path / "bifurcation_barge2b_xp.json").read_text())
    hopf = sorted(p["parameter"] for p in s["special_points"] if p["kind"] == "hopf")
    assert len(hopf) == 2 and hopf[0] == pytest.approx(0.2560, abs=1e-4)
    assert (tmp_path / "bifurcation_barge2b_xp.png").stat().st_size > 10_000


def test_hurwitz_determinants_know_stability():
    # (λ+1)(λ+2)(λ+3): all minors positive; λ³ + λ (roots 0, ±i): Δ₂ = 0 (the Hopf test)
    d = np.asarray(jt.hurwitz_determinants(jnp.array([1.0, 6.0, 11.0, 6.0])))
    assert np.all(d > 0)
    A = jnp.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -2.0]])  # eigenvalues ±i, -2
    assert abs(float(ct.hopf_test(A))) < 1e-12
