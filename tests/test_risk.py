"""The irregular-sea Monte Carlo (`jaxtow.risk`): checks that do not depend on its
implementation (calm water settles on the static equilibrium; the runs' standard deviations
match the linearised tow's frequency-domain response to the same slow drift; the interval's
coverage on a known Bernoulli case), its determinism, and its inputs."""

from __future__ import annotations

import math

import numpy as np
import pytest

import jaxtow as jt
from jaxtow import risk

CALM = jt.resistance.SeaState(hs=0.0, tp=8.0, name="calm")
#: Short runs for the default suite: the statistics need only the record after the start-up.
FAST = risk.RiskSettings(transient=600.0, chunk_size=4, n_components=64, nodes=32, n_gusts=32)


def test_wilson_interval_covers_a_known_bernoulli_proportion():
    """95 % Wilson intervals of 20,000 binomial samples (n = 200) hold the true p in
    93-97 % of them, at a small and a middling p; no run in n gives (0, ≈3.8/n)."""
    rng = np.random.default_rng(0)
    for p in (0.05, 0.3):
        ks = rng.binomial(200, p, 20_000)
        lo_hi = np.array([risk.wilson_interval(k, 200) for k in ks])
        cover = np.mean((lo_hi[:, 0] <= p) & (p <= lo_hi[:, 1]))
        assert 0.93 <= cover <= 0.97, (p, cover)
    lo, hi = risk.wilson_interval(0, 100)
    assert lo == 0.0 and 0.03 < hi < 0.04
    with pytest.raises(ValueError, match="'k', 'n'"):
        risk.wilson_interval(5, 3)


def test_gumbel_fit_and_exposure():
    """The moment fit recovers a Gumbel sample's location and scale; the maximum of m records
    shifts the mode by scale·ln m; the exposure probability compounds independent records."""
    rng = np.random.default_rng(1)
    x = rng.gumbel(10.0, 2.0, 50_000)
    fit = risk.gumbel_fit(x)
    assert fit.location == pytest.approx(10.0, abs=0.05) and fit.scale == pytest.approx(
        2.0, abs=0.05
    )
    assert fit.over(4.0).mode == pytest.approx(fit.location + fit.scale * math.log(4.0))
    assert float(fit.exceedance(fit.quantile(0.9))) == pytest.approx(0.1)
    assert float(risk.exposure_probability(0.1, 3.0, 6.0)) == pytest.approx(1 - 0.9**2)


def test_the_npd_gust_spectrum_is_the_published_form():
    """At 0.01 Hz, U0 = 20 m/s, z = 10 m: S(f) = 320·2²/(1 + f̃^0.468)^3.561 with
    f̃ = 172·0.01·2^-0.75 (ISO 19901-1); and the synthesised gusts have its variance."""
    f = 0.01
    ft = 172 * f * 2.0**-0.75
    S_f = 320 * 4.0 / (1 + ft**0.468) ** (5 / (3 * 0.468))
    S_w = float(jt.waves.npd_wind_spectrum(2 * math.pi * f, 20.0, 10.0))
    assert S_w * 2 * math.pi == pytest.approx(S_f, rel=1e-12)
    tow = jt.tow.load("barge2a")
    wind = jt.forces.WindForce(load=tow.resistance().wind, speed=20.0, scales=tow.scales)
    g = jt.forces.GustWindForce.seeded(wind, seed=3, n=128)
    w = np.geomspace(*jt.waves.GUST_BAND, 20_001)
    var = np.trapezoid(np.asarray(jt.waves.npd_wind_spectrum(w, 20.0)), w)
    assert float(np.sum(np.asarray(g.amplitude) ** 2) / 2) == pytest.approx(var, rel=0.05)
    assert 0.08 < math.sqrt(var) / 20.0 < 0.15  # a turbulence intensity of about 11 %


@pytest.mark.parametrize("vessel, expected", [("barge2b", 0.0), ("barge2a", 1.0)])
def test_calm_water_runs_settle_or_fishtail(vessel, expected):
    """With Hs = 0 (no wind, no current) the runs start within ±2° of the static
    straight-behind equilibrium: Barge 2b settles on it (probability 0, the yaw amplitude
    dies away), Barge 2a leaves it for its limit cycle (probability 1)."""
    tow = jt.tow.load(vessel)
    r = risk.irregular_sea(tow, CALM, n_runs=8, duration=2400.0, seed=0, settings=FAST)
    assert r.n == 8 and r.fishtail_probability == expected
    if expected == 0.0:
        assert np.max(r.yaw_amplitude) < 0.5 and r.confidence_interval[1] < 0.4
    else:
        assert np.min(r.yaw_amplitude) > 20.0 and r.confidence_interval[0] > 0.6


@pytest.mark.slow  # the default suite's wall time (2 cores)
def test_a_tiny_sea_settles_like_calm_water():
    """Hs → 0: Barge 2b in a 5 cm sea stays within a fraction of a degree of the calm
    equilibrium, and its tension at the static value."""
    tow = jt.tow.load("barge2b")
    sea = jt.resistance.SeaState(hs=0.05, tp=8.0, name="tiny")
    r = risk.irregular_sea(tow, sea, n_runs=4, duration=1800.0, seed=0, settings=FAST)
    calm = risk.irregular_sea(tow, CALM, n_runs=4, duration=1800.0, seed=0, settings=FAST)
    assert r.fishtail_probability == 0.0 and np.max(r.yaw_amplitude) < 0.5
    np.testing.assert_allclose(r.max_tension, calm.max_tension, rtol=0.01)
    assert np.max(calm.yaw_amplitude) < 0.5  # the start's ±2° dying away


@pytest.mark.slow
def test_a_seed_gives_the_same_runs_whatever_the_chunking(tmp_path):
    """Deterministic for a seed: chunks of 2 or 4, and a run resumed from its checkpoint, give
    the same numbers; another seed gives other numbers."""
    tow = jt.tow.load("barge2b")
    sea = jt.resistance.SeaState(hs=1.0, tp=8.0, name="small")
    kw = dict(n_runs=4, duration=900.0, seed=5)
    a = risk.irregular_sea(tow, sea, settings=FAST, **kw)
    b = risk.irregular_sea(
        tow, sea, settings=risk.RiskSettings(**{**FAST.__dict__, "chunk_size": 2}), **kw
    )
    np.testing.assert_array_equal(a.yaw_amplitude, b.yaw_amplitude)
    np.testing.assert_array_equal(a.max_tension, b.max_tension)
    ck = jt.io.Checkpoint(tmp_path / "ck")
    c = risk.irregular_sea(tow, sea, settings=FAST, checkpoint=ck, **kw)
    d = risk.irregular_sea(tow, sea, settings=FAST, checkpoint=ck, **kw)  # read back
    np.testing.assert_array_equal(c.yaw_std, d.yaw_std)
    np.testing.assert_array_equal(a.yaw_std, c.yaw_std)
    e = risk.irregular_sea(tow, sea, settings=FAST, **{**kw, "seed": 6})
    assert not np.array_equal(a.yaw_std, e.yaw_std)


def test_common_random_numbers_make_a_difference_exact():
    """The same change twice is no difference at all; the paired interval is narrow where
    the two variants agree run by run."""
    tow = jt.tow.load("barge2a")
    d = risk.compare(tow, CALM, {"l0": 2.5}, n_runs=4, duration=1800.0, settings=FAST)
    assert d.difference == 0.0 and d.interval == (0.0, 0.0) and d.p_value == 1.0
    np.testing.assert_array_equal(d.base.yaw_amplitude, d.changed.yaw_amplitude)


def test_mcnemar_exact_test_by_hand():
    """Five discordant pairs all one way: p = 2·(1/2)^5 = 0.0625, not significant; six: 0.03125."""
    import dataclasses

    def result(fish):
        n = len(fish)
        z = np.zeros(n)
        return risk.RiskResult(
            settings=risk.RiskSettings(n_runs=n), described={}, fishtails=np.array(fish, bool),
            yaw_amplitude=z, max_yaw=z, sway_amplitude=z, yaw_std=z, sway_std=z, max_tension=z,
            min_tension=z, slack_events=z.astype(int), completed=np.ones(n, bool),
            static_tension=1.0, validity={},
        )  # fmt: skip

    for k, p in ((5, 0.0625), (6, 0.03125)):
        d = risk.difference(result([1] * k + [0] * 4), result([0] * (k + 4)))
        assert d.p_value == pytest.approx(p) and d.difference == pytest.approx(-k / (k + 4))
        assert d.significant == (p < 0.05) and d.interval[0] >= -1.0
    assert dataclasses.is_dataclass(d)


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        (dict(n_runs=1), "n_runs"),
        (dict(duration=300.0), "duration"),
        (dict(yaw_threshold=0.0), "yaw_threshold"),
        (dict(uncertain=(("Nr", 1.0, 0.5),)), "uncertain"),
    ],
)
def test_bad_settings_are_named(kwargs, parameter):
    tow = jt.tow.load("barge2b")
    with pytest.raises(jt.ParameterError, match=parameter) as e:
        if set(kwargs) <= {"n_runs", "duration"}:
            risk.irregular_sea(tow, CALM, **kwargs)
        else:
            risk.RiskSettings(**kwargs)
    assert e.value.parameter == parameter


def test_bad_tows_and_sea_states_are_named():
    tow = jt.tow.load("barge2b")
    with pytest.raises(jt.ParameterError, match="'gale' is not one of the tow's"):
        risk.irregular_sea(tow, "gale")
    with pytest.raises(TypeError, match="parameter 'tow'"):
        risk.irregular_sea("barge2b", CALM)
    model = jt.TowModel(vessel=jt.presets.barge_2b(), towline=jt.presets.default_towline())
    with pytest.raises(ValueError, match="no IrregularWaveDriftForce"):
        risk.irregular_sea(model, jt.resistance.SeaState(hs=2.0, tp=8.0))


@pytest.mark.slow
def test_runs_match_the_linearised_frequency_domain_response():
    """Barge 2b (course stable) in a small sea from 20° off the bow (Hs 1 m, Tp 8 s, no wind;
    in head seas the slow drift moves sway and yaw only at second order): the standard
    deviations of yaw and sway offset over 48 three-hour runs are within 5 % of the
    linearised tow's response to the same slow-drift components (`jaxtow.risk.linear_response`,
    an exact pair sum: no time stepping)."""
    tow = jt.tow.load("barge2b")
    sea = jt.resistance.SeaState(hs=1.0, tp=8.0, wave_angle=math.radians(20.0), name="small")
    s = risk.RiskSettings(chunk_size=16)
    r = risk.irregular_sea(tow, sea, n_runs=48, duration=3 * 3600.0, seed=11, settings=s)
    model, _ = risk.risk_model(tow.sea_model(sea), r.settings)
    lin = risk.linear_response(model)
    assert lin.max_real < 0
    yaw = math.sqrt(np.mean(r.yaw_std**2))
    sway = math.sqrt(np.mean(r.sway_std**2))
    assert yaw == pytest.approx(lin.yaw_std, rel=0.05), (yaw, lin.yaw_std)
    assert sway == pytest.approx(lin.sway_std, rel=0.05), (sway, lin.sway_std)
    assert r.fishtail_probability == 0.0
