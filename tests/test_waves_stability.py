"""Towing stability in waves and wind: force hooks, parameter paths, the report."""

import math

import numpy as np
import pytest

import jaxtow as jt
from jaxtow import resistance as R
from jaxtow.presets import approximate_qtf
from jaxtow.studies import nearest_straight


@pytest.fixture(scope="module")
def qtf():
    return approximate_qtf()


def test_qtf_from_method_reproduces_the_method_at_the_nodes(qtf):
    wl = jt.presets.barge2_waterline()
    for w, b in ((0.5, 0.0), (1.3, math.radians(30.0)), (2.1, math.radians(-60.0))):
        ref = np.asarray(jt.drift.kashiwagi(wl, w, abs(b)).force)
        ref = ref * np.array([1.0, math.copysign(1.0, b), math.copysign(1.0, b)])
        np.testing.assert_allclose(
            np.asarray(qtf(w, b)), ref, rtol=1e-10, atol=1e-9 * np.max(np.abs(ref))
        )


def test_wind_force_in_the_tow_model():
    sc = jt.presets.barge2_scales()
    tow = jt.presets.barge2_resistance()
    wind = jt.forces.WindForce(load=tow.wind, speed=10.0, scales=sc)
    y = np.array([1.0, 0.0, 0.0, 2.5, 0.0, 0.0])  # straight behind, moving with the tug
    X = float(wind(0.0, y, None)[0])
    cx = float(tow.wind.coefficients(0.0)[0])
    expected = (
        0.5 * R.RHO_AIR * cx * (10.0 + float(sc.u_tug)) ** 2 * 24.4 * 10.0 / float(sc.force)
    )  # eqs 2.23, 2.25
    assert X == pytest.approx(expected, rel=1e-12)
    # head wind adds to the towline tension of the straight-behind equilibrium, by exactly its drag
    line = jt.presets.default_towline(l0=2.5, xp=0.5)
    calm = jt.TowModel(vessel=jt.presets.barge_2b(), towline=line)
    windy = jt.TowModel(
        vessel=jt.presets.barge_2b(),
        towline=line,
        external=jt.forces.CombinedForce((wind, jt.forces.ConstantBodyForce(np.zeros(3)))),
    )
    t0 = jt.equilibria(calm).select(jt.equilibria(calm).branch == 0).tension[0]
    e = jt.equilibria(windy)
    t1 = e.select(e.branch == 0).tension[0]
    assert float(t1 - t0) == pytest.approx(-expected, rel=1e-10)
    with pytest.raises(ValueError, match="'speed'"):
        jt.forces.WindForce(load=tow.wind, speed=-1.0, scales=sc)


def test_parameter_paths_into_the_force_model(qtf):
    m = jt.presets.barge2_wave_model("2a", omega=1.0, zeta_a=1.25, qtf=qtf)
    m2 = jt.with_parameters(m, **{"external.omega": 1.4, "external.zeta_a": 0.5, "l0": 1.0})
    assert float(jt.get_parameter(m2, "external.omega")) == 1.4 and float(m2.external.zeta_a) == 0.5
    assert float(m2.towline.l0) == 1.0
    with pytest.raises(ValueError, match="'zeta_a'"):
        jt.sweep_arrays(m, {"external.zeta_a": [0.5, -1.0]})
    with pytest.raises(ValueError, match="no such field path"):
        jt.with_parameters(m, **{"external.nope": 1.0})
    comb = jt.TowModel(
        vessel=m.vessel, towline=m.towline, external=jt.forces.CombinedForce((m.external,))
    )
    assert (
        float(
            jt.get_parameter(
                jt.with_parameters(comb, **{"external.forces.0.omega": 0.7}),
                "external.forces.0.omega",
            )
        )
        == 0.7
    )


def test_nearest_straight_reduction():
    """The straight-behind equilibrium is the found one nearest ψ = 0 within
    `jaxtow.STRAIGHT_LIMIT` (1°): none where every found one is further off (a sheer)."""
    arrays = dict(
        valid=np.array([[True, True, False], [False, False, False], [True, True, False]]),
        psi=np.array([[-0.3, 0.01, 0.0], [0.0, 0.0, 0.0], [-0.3, 0.1, 0.0]]),
        max_real=np.array([[1.0, -2.0, 5.0], [1.0, 1.0, 1.0], [1.0, -2.0, 5.0]]),
    )
    out = nearest_straight(arrays)
    assert out[0] == -2.0 and np.isnan(out[1]) and np.isnan(out[2])
    mask = jt.straight_behind(arrays["psi"], arrays["valid"])
    assert mask.tolist() == [[False, True, False], [False] * 3, [False] * 3]
