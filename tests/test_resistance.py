"""Tow resistance budget, required pull and operating speed."""

import math

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt
from jaxtow import resistance as R
from jaxtow._units import RHO_SEA

TF = 9.80665e3


@pytest.fixture(scope="module")
def tow():
    return jt.presets.barge2_resistance("2a")


@pytest.fixture(scope="module")
def calm(tow):
    return R.TowResistance(hull=tow.hull)


CALM_SEA = R.SeaState(hs=0.0, tp=8.0)


def test_relative_wind_is_eqs_2_23_2_24():
    uv, W = 2.5, 12.0
    for a in np.radians([0.0, 30.0, 90.0, 150.0, 180.0, -60.0]):
        U2, alpha = R.relative_flow(uv, 0.0, W, a)
        assert float(U2) == pytest.approx(uv**2 + W**2 + 2 * uv * W * math.cos(a), rel=1e-13)
        assert float(alpha) == pytest.approx(
            math.atan2(W * math.sin(a), uv + W * math.cos(a)), abs=1e-13
        )
    # zero relative flow: zero load and a finite gradient
    g = jax.grad(lambda u: jt.presets.barge2_resistance().wind(u, 0.0, 3.0, math.pi)[0])(3.0)
    assert np.isfinite(float(g))


def test_coefficient_table_nodes_symmetry_and_errors():
    t = jt.presets.barge2_wind_table()
    src = jt.presets.BARGE2_WIND_TABLE
    for a, cx, cy, cn in zip(src["angle_deg"], src["cx"], src["cy"], src["cn"]):
        c = np.asarray(t(math.radians(a)))
        np.testing.assert_allclose(c, [cx, cy, cn], atol=1e-14)
        np.testing.assert_allclose(np.asarray(t(-math.radians(a))), [cx, -cy, -cn], atol=1e-14)
    # periodic: continuous with continuous slope through 180 deg
    d = jax.jacfwd(t)
    np.testing.assert_allclose(
        np.asarray(d(math.pi - 1e-9)), np.asarray(d(-math.pi + 1e-9)), atol=1e-6
    )
    assert t.illustrative and "ILLUSTRATIVE" in t.label
    with pytest.raises(ValueError, match="'cy' must be 0"):
        R.CoefficientTable.symmetric([0, 90, 180], [1, 0, -1], [0.1, 1, 0], [0, 0, 0])
    with pytest.raises(ValueError, match="'angle'"):
        R.CoefficientTable([0.0, 1.0, 2.0, 3.0], *np.zeros((3, 4)))


def test_coefficient_table_interpolates_with_tables_built_once():
    """The table's interval tables are built with it (`HermiteAxis`): an evaluation is a
    lookup of a few operations whatever the table's size, and equals the interpolant built
    from the grid inside the evaluation (`jaxtow._interp.hermite`)."""
    from jaxtow._interp import hermite

    t = jt.presets.barge2_wind_table()
    alpha = np.linspace(-3.0, 3.0, 41)
    got = np.asarray(jax.vmap(t)(alpha))
    ref = np.asarray(jax.vmap(lambda a: hermite(t.angle, t.values, a, "periodic"))(alpha))
    np.testing.assert_allclose(got, ref, rtol=1e-13, atol=1e-15)
    n_ops = len(jax.make_jaxpr(t)(0.3).eqns)
    n_ref = len(jax.make_jaxpr(lambda a: hermite(t.angle, t.values, a, "periodic"))(0.3).eqns)
    assert n_ops < 0.5 * n_ref, (n_ops, n_ref)


def test_current_load_from_manoeuvring_derivatives(tow, barge_2a):
    L, B, T = jt.presets.BARGE2_LENGTH, jt.presets.BARGE2_BREADTH, 5.0
    c = np.asarray(tow.hull.coefficients(0.0))
    assert c[0] == pytest.approx(-float(barge_2a.R0) * L / B, rel=1e-14)  # fig. 7.1b: -0.218
    assert c[1] == c[2] == 0.0
    # head current of 1.5 m/s on a stationary barge = calm-water resistance at 1.5 m/s
    F = np.asarray(tow.hull(0.0, 0.0, 1.5, 0.0))
    assert F[0] == pytest.approx(-0.5 * RHO_SEA * T * L * float(barge_2a.R0) * 1.5**2, rel=1e-13)
    # beam current from port (alpha = 90 deg): sway force = Yv' + Yvvv' on the L T area
    F = np.asarray(tow.hull(0.0, 0.0, 1.0, math.pi / 2))
    assert F[1] == pytest.approx(
        0.5 * RHO_SEA * L * T * float(barge_2a.Yv + barge_2a.Yvvv), rel=1e-13
    )


def test_operating_speed_closed_form_quadratic_pull(calm, barge_2a):
    """Calm water only: R = k U², pull η BP (1 − U²/U_f²) − c U²  ⇒  U* = √(ηBP / (k + c + ηBP/U_f²))."""
    k = 0.5 * RHO_SEA * 5.0 * jt.presets.BARGE2_LENGTH * float(barge_2a.R0)
    for bp, uf, eta, c in ((40 * TF, 7.0, 0.75, 0.0), (25 * TF, 6.0, 0.8, 4.0e3)):
        tug = R.Tug(bollard_pull=bp, free_speed=uf, efficiency=eta, resistance_coefficient=c)
        p = R.operating_speed(calm, tug, CALM_SEA)
        exact = math.sqrt(eta * bp / (k + c + eta * bp / uf**2))
        assert float(p.speed) == pytest.approx(exact, rel=1e-10)
        assert p.result == R.RESULTS.successful
        assert float(p.pull) == pytest.approx(float(p.budget.total), rel=1e-9)
        assert float(p.transit_time(500 * 1852.0)) == pytest.approx(500 * 1852.0 / exact, rel=1e-9)


def test_budget_sums_and_trends(tow):
    sea = jt.presets.sea_state("sailing", tp=7.0)
    speeds = jnp.linspace(0.0, 3.5, 8)
    b = R.resistance_grid(tow, sea, speeds, jnp.array([6.0, 7.0, 8.0]))
    r = np.asarray(b.resistance)
    np.testing.assert_allclose(r.sum(-1), np.asarray(b.total), rtol=1e-14)
    np.testing.assert_allclose(np.asarray(b.shares).sum(-1), 100.0, rtol=1e-12)
    waves = r[:, :, R.COMPONENTS.index("waves")]
    assert np.all(
        np.diff(waves, axis=0) > 0
    )  # wave drift rises with speed in absolute terms (thesis 7.2)
    current = r[:, 1, R.COMPONENTS.index("hull")]
    np.testing.assert_allclose(current, current[-1] * (np.asarray(speeds) / 3.5) ** 2, rtol=1e-12)
    # body loads: along-course resistance of a head-on budget is −Fx
    np.testing.assert_allclose(r[..., :3], -np.asarray(b.body)[..., :3, 0], rtol=1e-14)


@pytest.mark.slow  # the default suite's wall time (2 cores)
def test_operating_speed_falls_with_hs_and_gradients_match_fd(tow):
    def speed(hs, wind, bp):
        tug = jt.presets.illustrative_tug(bollard_pull=bp)
        return R.operating_speed(
            tow, tug, jt.presets.sea_state("sailing", hs=hs, wind_speed=wind)
        ).speed

    x0 = (2.4, 10.0, 40 * TF)
    u = [float(speed(h, 10.0, 40 * TF)) for h in (1.0, 2.4, 4.0)]
    assert u[0] > u[1] > u[2]
    grads = jax.grad(speed, argnums=(0, 1, 2))(*x0)
    assert float(grads[0]) < 0 and float(grads[1]) < 0 and float(grads[2]) > 0
    for i, h in enumerate((1e-4, 1e-3, 1.0)):
        xp, xm = list(x0), list(x0)
        xp[i] += h
        xm[i] -= h
        fd = (float(speed(*xp)) - float(speed(*xm))) / (2 * h)
        assert float(grads[i]) == pytest.approx(fd, rel=1e-5)


def test_required_pull(tow):
    sea = jt.presets.sea_state("survival")
    tug = jt.presets.illustrative_tug()
    req = R.required_pull(tow, sea, tug=tug)
    b = R.resistance(tow, sea, 0.0)
    assert float(req.towing_force) == pytest.approx(float(b.total), rel=1e-14)
    assert float(req.bollard_pull) == pytest.approx(float(b.total) / 0.75, rel=1e-14)
    assert float(b.resistance[0]) == 0.0  # no current, no speed: no hull resistance (fig. 7.2)
    # at a speed: the tug with exactly that bollard pull makes exactly that speed
    req2 = R.required_pull(tow, jt.presets.sea_state("sailing"), speed=2.5, tug=tug)
    p = R.operating_speed(
        tow,
        jt.presets.illustrative_tug(bollard_pull=req2.bollard_pull),
        jt.presets.sea_state("sailing"),
    )
    assert float(p.speed) == pytest.approx(2.5, rel=1e-9)


def test_worst_bollard_pull_is_the_required_pull_at_each_tp(tow):
    """One compiled program over the Tp grid gives what `required_pull` gives at each Tp
    (eagerly, with the sea's own Tp replaced), under a caller's jit too; a bad Tp is refused
    with 'tps' named."""
    import equinox as eqx

    sea, tug = jt.presets.sea_state("survival"), jt.presets.illustrative_tug()
    tps = np.array([6.0, 9.0, 12.0])
    got = np.asarray(R.worst_bollard_pull(tow, sea, tps, tug=tug))
    want = [
        float(R.required_pull(tow, eqx.tree_at(lambda s: s.tp, sea, t), tug=tug).bollard_pull)
        for t in tps
    ]
    np.testing.assert_allclose(got, want, rtol=1e-12)
    traced = jax.jit(lambda t: R.worst_bollard_pull(tow, sea, t, tug=tug))(jnp.asarray(tps))
    np.testing.assert_allclose(np.asarray(traced), want, rtol=1e-12)
    with pytest.raises(ValueError, match="'tps'"):
        R.worst_bollard_pull(tow, sea, np.array([6.0, -1.0]), tug=tug)


def test_invalid_inputs_give_clear_messages(tow, calm):
    with pytest.raises(ValueError, match="cannot hold the tow.*bollard_pull"):
        R.operating_speed(
            tow, jt.presets.illustrative_tug(bollard_pull=5 * TF), jt.presets.sea_state("survival")
        )
    with pytest.raises(ValueError, match=r"Froude number Fn = 0\.\d+ >= 0.15"):
        R.operating_speed(calm, jt.presets.illustrative_tug(bollard_pull=300 * TF), CALM_SEA)
    following = R.SeaState(hs=0.0, tp=8.0, current_speed=9.0, current_angle=math.pi)
    with pytest.raises(ValueError, match="no intersection .* below the tug's top speed"):
        R.operating_speed(calm, jt.presets.illustrative_tug(), following)
    p = R.operating_speed(calm, jt.presets.illustrative_tug(), following, throw=False)
    assert p.result == R.RESULTS.no_crossing and not bool(p.valid) and np.isfinite(float(p.speed))
    with pytest.raises(ValueError, match="'bollard_pull' must be > 0"):
        R.Tug(bollard_pull=-1.0, free_speed=6.0)
    with pytest.raises(ValueError, match="'pulls' must be >= 0"):
        R.Tug.from_table([0.0, 3.0, 6.0], [3e5, 1e5, -2e4])
    with pytest.raises(ValueError, match="'hs' must be >= 0"):
        R.SeaState(hs=-1.0, tp=8.0)
    with pytest.raises(ValueError, match="'method'"):
        jt.presets.barge2_resistance(method="nope")
    # under jit: the result code becomes an error that names it, not a NaN
    f = jax.jit(
        lambda bp: (
            R.operating_speed(calm, jt.presets.illustrative_tug(bollard_pull=bp), CALM_SEA).speed
        )
    )
    with pytest.raises(Exception, match="Froude"):
        f(300 * TF)


def test_tabulated_pull_curve_matches_quadratic(calm):
    s = np.linspace(0.0, 7.0, 29)
    quad = jt.presets.illustrative_tug()
    tab = R.Tug.from_table(s, 40 * TF * (1 - (s / 7.0) ** 2), efficiency=0.75)
    a = R.operating_speed(calm, quad, CALM_SEA).speed
    b = R.operating_speed(calm, tab, CALM_SEA).speed
    assert float(b) == pytest.approx(
        float(a), rel=1e-6
    )  # cubic Hermite of a quadratic: exact to rounding


@pytest.mark.slow  # default-suite time (the operating-speed solve compiles for 40 s)
def test_cli_table():
    from jaxtow.cli.resistance import build, format_table, read_config
    from jaxtow.studies import evaluate_resistance

    tow, tug, seas, heading, route = build(read_config("barge2"))
    row = evaluate_resistance(tow, tug, seas[1], heading, route, n_tp=5)
    text = format_table([row], tug, route)
    assert row.operating_speed is not None and row.physical_tp_range is not None
    assert "sailing" in text and f"{row.operating_speed:.2f}" in text
    assert row.operating_speed < row.physical_tp_range[1]  # a speed in m/s, a range in s


def test_cli_config_errors(tmp_path):
    from jaxtow.cli.resistance import build, read_config

    cfg = read_config("barge2")
    tow, tug, seas, heading, route = build(cfg)
    assert [s.name for s in seas] == ["survival", "sailing"] and route == pytest.approx(
        500 * 1852.0
    )
    bad = dict(cfg, tug=dict(cfg["tug"], bolard_pull_t=3.0))
    with pytest.raises(ValueError, match=r"unknown key\(s\) \['bolard_pull_t'\]"):
        build(bad)
    with pytest.raises(ValueError, match="no such file"):
        read_config(tmp_path / "missing.toml")


@pytest.mark.slow
def test_cli_resistance_writes_outputs(tmp_path, capsys):
    from jaxtow.cli import main

    main(["resistance", "barge2a", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert "survival" in out and "ILLUSTRATIVE" in out
    ds = jt.io.load_dataset(tmp_path / "resistance_sailing.nc")
    np.testing.assert_allclose(ds.resistance.sum("component"), ds.total, rtol=1e-12)
    assert "ILLUSTRATIVE" in ds.attrs["assumed_wind_table"]
    for f in (
        "budget_vs_tp_survival.png",
        "budget_vs_speed_sailing.png",
        "operating_point_sailing.png",
        "summary.json",
    ):
        assert (tmp_path / f).is_file()


def test_no_load_gives_zero_shares_not_nan(calm):
    b = R.resistance(calm, CALM_SEA, 0.0)
    assert float(b.total) == 0.0 and np.all(np.asarray(b.shares) == 0.0)


def test_calm_sea_has_no_wave_resistance_and_the_tp_grid_is_checked(tow):
    """Hs = 0 is a calm sea (`SeaState` allows it): no wave drift and nothing overtaken,
    not an error. `resistance_grid` checks its Tp grid before its compiled call (under a
    caller's tracing, on the result), so the compiled grid holds no run-time check: JAX's
    persistent cache stores it."""
    b = R.resistance(tow, CALM_SEA, 2.0)
    assert float(b.as_dict()["waves"]) == 0.0 and float(b.overtaken_energy) == 0.0
    sea = jt.presets.sea_state("survival")
    with pytest.raises(ValueError, match="'tps' must be > 0"):
        R.resistance_grid(tow, sea, [1.0], [0.0, 7.0])
    with pytest.raises(Exception, match="'tps' must be > 0"):
        jax.jit(lambda t: R.resistance_grid(tow, sea, jnp.array([1.0]), t).total)(
            jnp.array([-1.0])
        ).block_until_ready()
    from jaxtow.resistance._budget import _resistance_grid

    grid = jax.jit(lambda s, t: _resistance_grid(tow, sea, s, t, heading=0.0, tug=None).total)
    text = grid.lower(jnp.array([1.0, 2.0]), jnp.array([6.0, 8.0])).as_text()
    assert "stablehlo" in text and "callback" not in text
