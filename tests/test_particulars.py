"""A vessel from its particulars: Clarke, Gedling & Hine's linear derivatives, and what they
give for Barge 2a/2b against the measured Table 3.7."""

import math

import numpy as np
import pytest

import jaxtow as jt

P = jt.presets


def test_clarke_regressions_by_hand_on_barge2():
    """The four regressions evaluated by hand (S = π(T/L)², Clarke's ½ρL²U scales) and
    converted to the Hong et al. scales by L/T."""
    L, B, T, cb = 76.2, 24.4, 5.0, 0.928
    S = math.pi * (T / L) ** 2
    d = P.clarke_linear_derivatives(L, B, T, cb)
    assert d.Yv == pytest.approx(-S * (1 + 0.40 * 0.928 * 4.88) * 15.24, rel=1e-12)
    assert d.Yr == pytest.approx(-S * (-0.5 + 2.2 * 24.4 / 76.2 - 0.08 * 4.88) * 15.24, rel=1e-12)
    assert d.Nv == pytest.approx(-S * (0.5 + 2.4 * 5 / 76.2) * 15.24, rel=1e-12)
    assert d.Nr == pytest.approx(-S * (0.25 + 0.039 * 4.88 - 0.56 * 24.4 / 76.2) * 15.24, rel=1e-12)
    assert d.lb_in_range
    assert not P.clarke_linear_derivatives(200.0, 10.0, 5.0, 0.7).lb_in_range


@pytest.mark.slow
def test_clarke_against_table_3_7_and_the_verdicts():
    """The documented comparison (docs/estimates.md): the regressions give c = -0.044 for
    both hulls (course unstable: they know no skegs), so Barge 2b's straight-behind
    equilibrium turns unstable on them, while 2a stays unstable."""
    cb = P.block_coefficient_from_mass(0.5943, P.BARGE2_LENGTH, P.BARGE2_BREADTH)
    d = P.clarke_linear_derivatives(P.BARGE2_LENGTH, P.BARGE2_BREADTH, 5.0, cb)
    out = {}
    for version in ("2a", "2b"):
        table = P.VESSELS[f"barge_{version}"]()
        vals = {k: float(getattr(table, k)) for k in jt.VESSEL_PARAMETERS}
        derivs = "\n".join(f"{k} = {vals[k]!r}" for k in vals if k not in ("Yv", "Yr", "Nv", "Nr"))
        tow = jt.tow.loads(
            f"""[tow]
name = "est{version}"
[vessel]
length = 76.2
breadth = 24.4
draft = 5.0
block_coefficient = {cb!r}
[vessel.derivatives]
{derivs}
[towline]
l0 = 2.5
xp = 0.5
EA_N = 2.6e8
""",
            source="particulars",
        )
        for k in ("Yv", "Yr", "Nv", "Nr"):
            assert float(getattr(tow.vessel, k)) == pytest.approx(getattr(d, k), rel=1e-12)
            assert "Clarke" in dict(tow.assumed)[k]
        c = float(tow.vessel.stability_coefficient())
        st = jt.stability(tow.model(), jt.equilibria(tow.model()).state)
        out[version] = (c, np.asarray(st.max_real))
    assert out["2a"][0] == pytest.approx(-0.0442, abs=5e-4)
    assert out["2b"][0] == pytest.approx(out["2a"][0], rel=0.02)
    assert out["2b"][1][1] > 0  # 2b's straight-behind equilibrium: unstable on the regression
    assert float(P.barge_2b().stability_coefficient()) > 0  # ... stable on the measured table


def test_kijima_regressions_by_hand_on_barge2():
    """Kijima et al. (1990), k = 2T/L, already on the Hong et al. scales; Y_r' carries the
    surge added mass (their Y_r' − m_x' = πk/4)."""
    L, B, T, cb = 76.2, 24.4, 5.0, 0.928
    k = 2 * T / L
    d = P.kijima_linear_derivatives(L, B, T, cb, a11=0.03)
    assert d.Yv == pytest.approx(-(math.pi * k / 2 + 1.4 * cb * B / L), rel=1e-12)
    assert d.Yr == pytest.approx(math.pi * k / 4 + 0.03, rel=1e-12)
    assert d.Nv == pytest.approx(-k, rel=1e-12)
    assert d.Nr == pytest.approx(-0.54 * k + k * k, rel=1e-12)


def test_particulars_estimate_every_parameter():
    vals, notes = P.particulars_derivatives(76.2, 24.4, 5.0, 0.928, "kijima")
    assert set(jt.VESSEL_PARAMETERS) | {"a11", "a22", "a66"} <= set(vals)
    assert vals["m"] == pytest.approx(2 * 0.928 * 24.4 / 76.2, rel=1e-12)
    assert vals["Izz"] == pytest.approx(vals["m"] * 0.25**2, rel=1e-12)
    assert vals["Yvvv"] == float(P.barge_2a().Yvvv) and "Barge 2a" in notes["Yvvv"]
    assert "Kijima" in notes["Nr"]
    v = P.vessel_from_particulars(76.2, 24.4, 5.0, 0.928, "kijima")
    assert float(v.Nr) == vals["Nr"] and dict(v.assumed)["Yvvv"] == notes["Yvvv"]
    with pytest.raises(ValueError, match="regression"):
        P.particulars_derivatives(76.2, 24.4, 5.0, 0.928, "holtrop")
    with pytest.raises(ValueError, match="block_coefficient"):
        P.particulars_derivatives(76.2, 24.4, 5.0, 1.4)


def _particulars_tow(regression, extra=""):
    return jt.tow.loads(
        f"""[tow]
name = "est"
[vessel]
length = 76.2
breadth = 24.4
draft = 5.0
block_coefficient = 0.928
regression = "{regression}"
{extra}
[towline]
l0 = 2.5
xp = 0.5
EA_N = 2.6e8
""",
        source="particulars",
    )


def test_a_tow_file_from_particulars_alone():
    t = _particulars_tow("kijima")
    vals, _ = P.particulars_derivatives(76.2, 24.4, 5.0, 0.928, "kijima")
    for k in jt.VESSEL_PARAMETERS:
        assert float(getattr(t.vessel, k)) == pytest.approx(vals[k], rel=1e-12)
    assumed = dict(t.assumed)
    assert all(k in assumed for k in ("m", "Izz", "Yv", "Yvvv", "R0", "a22"))
    with pytest.raises(jt.tow.TowFileError, match="regression"):
        _particulars_tow("holtrop")


@pytest.mark.parametrize("regression", ["clarke", "kijima"])
def test_a_particulars_tow_round_trips_through_show(regression):
    """`jaxtow tow show` writes the regression back (and no empty derivatives table), so
    the shown file loads back to the same tow: the same resolved file, vessel and towline."""
    t = _particulars_tow(regression, extra="")
    text = jt.tow.show(t)
    assert f'regression = "{regression}"' in text and "derivatives" not in text
    again = jt.tow.loads(text, source="shown")
    assert again.resolved == t.resolved
    for k in jt.VESSEL_PARAMETERS:
        assert float(getattr(again.vessel, k)) == float(getattr(t.vessel, k)), k
    assert float(again.towline.EA) == float(t.towline.EA)


@pytest.mark.slow
def test_particulars_vessels_on_barge2_and_their_verdicts():
    """The documented comparison (docs/estimates.md): Barge 2 from its particulars alone on
    the 2.5 L wire. Both regressions call the hull course unstable (Clarke c = -0.044,
    Kijima c = -0.027) and its straight tow unstable, like the measured 2a and unlike 2b."""
    out = {}
    for reg in ("clarke", "kijima"):
        t = _particulars_tow(reg)
        m = t.model()
        e = jt.equilibria(m)
        st = jt.stability(m, e.state)
        k = int(np.argmin(np.abs(np.asarray(e.psi))))
        out[reg] = (float(t.vessel.stability_coefficient()), float(st.max_real[k]), len(e.psi))
    assert out["clarke"][0] == pytest.approx(-0.0442, abs=5e-4)
    assert out["kijima"][0] == pytest.approx(-0.0272, abs=5e-4)
    assert out["clarke"][1] == pytest.approx(0.212, abs=2e-3)
    assert out["kijima"][1] == pytest.approx(0.136, abs=2e-3)
    assert out["clarke"][2] == out["kijima"][2] == 1  # Barge 2a's cubic terms: no side equilibria
