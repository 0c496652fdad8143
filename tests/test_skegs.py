"""Skegs as low-aspect-ratio lifting surfaces: Helmbold's lift slope, the four linear
increments by hand, the Barge 2a → 2b comparison of docs/estimates.md, and [vessel.skegs] in
a tow file."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import jaxtow as jt

P = jt.presets
L, B, T = 76.2, 24.4, 5.0
RAKE = 5.49  # m: Barge 2's documented stern rake (presets.ASSUMPTIONS["rake"])
#: Barge 2b − Barge 2a, thesis Table 3.7 (Hong et al. / Nam et al. captive tests).
MEASURED = {
    k: P.barge_2b().__getattribute__(k) - P.barge_2a().__getattribute__(k)
    for k in ("Yv", "Yr", "Nv", "Nr")
}


def _c(vals: dict, m: float) -> float:
    return vals["Yv"] * vals["Nr"] - vals["Nv"] * (vals["Yr"] - m)


def test_helmbold_lift_slope_limits_and_a_hand_value():
    assert P.helmbold_lift_slope(1e-4) == pytest.approx(math.pi * 1e-4 / 2, rel=1e-4)
    assert P.helmbold_lift_slope(1e5) == pytest.approx(2 * math.pi, rel=1e-4)
    assert P.helmbold_lift_slope(1.0) == pytest.approx(2 * math.pi / (2 + math.sqrt(5)))
    with pytest.raises(ValueError, match="aspect_ratio"):
        P.helmbold_lift_slope(0.0)


def test_skeg_increments_by_hand():
    """Two 3 m x 8 m skegs ending at the stern: Λ = 2·3/8, k = 2·24·C_Lα/(LT), ξ = x/L."""
    sk = P.Skegs(count=2, span=3.0, chord=8.0)
    d = P.skeg_derivatives(L, T, sk)
    lam = 0.75
    cla = 2 * math.pi * lam / (2 + math.sqrt(lam**2 + 4))
    k = 2 * 24.0 * cla / (L * T)
    xi = (-L / 2 + 4.0) / L
    assert d.aspect_ratio == pytest.approx(lam) and d.lift_slope == pytest.approx(cla)
    assert d.Yv == pytest.approx(-k, rel=1e-12)
    assert d.Yr == pytest.approx(-k * xi, rel=1e-12) and d.Nv == d.Yr
    assert d.Nr == pytest.approx(-k * xi * xi, rel=1e-12)
    # a stern skeg adds sway and yaw damping and a stabilising (positive) N_v' increment
    assert d.Yv < 0 and d.Nv > 0 and d.Nr < 0
    # a triangle of the same span and chord: half the area, twice the aspect ratio
    tri = P.skeg_derivatives(L, T, P.Skegs(2, 3.0, 8.0, area=12.0))
    assert tri.aspect_ratio == pytest.approx(1.5)


@pytest.mark.parametrize(
    "kw, match",
    [
        (dict(count=0, span=3.0, chord=8.0), "count"),
        (dict(count=1.5, span=3.0, chord=8.0), "count"),
        (dict(span=-1.0, chord=8.0), "span"),
        (dict(span=3.0, chord=float("nan")), "chord"),
        (dict(span=3.0, chord=8.0, area=0.0), "area"),
    ],
)
def test_bad_skegs_are_named(kw, match):
    with pytest.raises(ValueError, match=match):
        P.Skegs(**kw)


def test_skegs_off_the_hull_are_refused():
    with pytest.raises(ValueError, match="along the hull"):
        P.skeg_derivatives(L, T, P.Skegs(2, 3.0, 8.0, x=-60.0))


def test_barge2_skegs_one_fitted_span_predicts_the_other_three_increments():
    """Barge 2b's skeg geometry is not published in the sources jaxtow has, so the
    comparison fits one number: the span of twin 8 m skegs ending at the stern that gives the
    measured ΔY_v'. The span found is a skeg 0.71 T deep (no deeper than the draft, as a skeg
    under a raked stern must be); the other three increments are then predictions, each with
    the measured sign and within 25 % (docs/estimates.md)."""
    span = brentq(
        lambda s: P.skeg_derivatives(L, T, P.Skegs(2, s, 8.0)).Yv - MEASURED["Yv"], 0.5, 20
    )
    assert span == pytest.approx(3.559, abs=1e-3) and span < T
    d = P.skeg_derivatives(L, T, P.Skegs(2, span, 8.0))
    err = {k: getattr(d, k) / MEASURED[k] - 1 for k in ("Yr", "Nv", "Nr")}
    assert err["Yr"] == pytest.approx(0.250, abs=2e-3)
    assert err["Nv"] == pytest.approx(-0.164, abs=2e-3)
    assert err["Nr"] == pytest.approx(0.095, abs=2e-3)
    # Barge 2a's measured derivatives plus these skegs: course stable, like 2b
    a = P.barge_2a()
    vals = {k: float(getattr(a, k)) + getattr(d, k) for k in MEASURED}
    assert _c(vals, float(a.m)) == pytest.approx(0.0232, abs=5e-4)
    assert float(P.barge_2b().stability_coefficient()) == pytest.approx(0.0286, abs=1e-4)


def test_barge2_skegs_filling_the_stern_rake_unfitted():
    """No fit: twin triangular skegs that fill Barge 2's documented stern rake (5.49 m long,
    5 m deep at the transom, force at the triangle's centroid). The formulation over-predicts
    every increment (34 % on ΔY_v', 19 % on ΔN_v', 66-79 % on the rotary terms): it leaves
    out the hull's wake and flow straightening at the stern."""
    sk = P.Skegs(2, T, RAKE, area=0.5 * T * RAKE, x=-L / 2 + RAKE / 3)
    d = P.skeg_derivatives(L, T, sk)
    err = {k: getattr(d, k) / MEASURED[k] - 1 for k in MEASURED}
    assert err["Yv"] == pytest.approx(0.343, abs=2e-3)
    assert err["Nv"] == pytest.approx(0.194, abs=2e-3)
    assert err["Yr"] == pytest.approx(0.786, abs=2e-3)
    assert err["Nr"] == pytest.approx(0.663, abs=2e-3)
    assert all(v > 0 for v in err.values())  # too much, never the wrong sign


def _tow(skegs: str = "", extra_vessel: str = "") -> str:
    return f"""[tow]
name = "skegs"
[vessel]
length = 76.2
breadth = 24.4
draft = 5.0
block_coefficient = 0.927984836065574
regression = "clarke"
{extra_vessel}
{skegs}
[towline]
l0 = 2.5
xp = 0.5
EA_N = 2.6e8
"""


FITTED = "[vessel.skegs]\ncount = 2\nspan = 3.559\nchord = 8.0\n"


@pytest.mark.slow  # the default suite's wall time (2 cores)
def test_barge2b_from_particulars_plus_skegs_is_stable_again():
    """Barge 2 from its particulars (Clarke) is course unstable and its straight tow on
    2.5 L fishtails; with the fitted skegs it is course stable (c = +0.051 against the
    measured 2b's +0.029) and the straight tow is stable, 2b's verdict."""
    out = {}
    for name, sk in (("bare", ""), ("skegs", FITTED)):
        t = jt.tow.loads(_tow(sk), source="skegs")
        m = t.model()
        e = jt.equilibria(m)
        st = jt.stability(m, e.state)
        k = int(np.argmin(np.abs(np.asarray(e.psi))))
        out[name] = (float(t.vessel.stability_coefficient()), float(st.max_real[k]))
    assert out["bare"][0] == pytest.approx(-0.0442, abs=5e-4) and out["bare"][1] > 0
    assert out["skegs"][0] == pytest.approx(0.0514, abs=5e-4) and out["skegs"][1] < 0


def test_least_skeg_span_for_course_stability():
    """The span of twin 8 m stern skegs at which Barge 2 from its particulars turns course
    stable (c = 0): 2.39 m, about half the draft."""
    cb = P.block_coefficient_from_mass(0.5943, L, B)

    def c(span):
        v = P.vessel_from_particulars(L, B, T, cb, skegs=P.Skegs(2, span, 8.0))
        return float(v.stability_coefficient())

    assert c(0.1) < 0 < c(T)
    assert brentq(c, 0.1, T) == pytest.approx(2.390, abs=2e-3)


def test_tow_file_skegs_show_in_the_assumptions_and_round_trip():
    t = jt.tow.loads(_tow(FITTED), source="skegs")
    notes = dict(t.assumed)
    for k in ("Yv", "Yr", "Nv", "Nr"):
        assert "skeg" in notes[k] and "Clarke" in notes[k]
    assert t.resolved["vessel"]["skegs"] == dict(count=2, span=3.559, chord=8.0)
    text = jt.tow.show(t)
    assert "[vessel.skegs]" in text
    again = jt.tow.loads(text, source="shown")
    assert again.resolved == t.resolved
    for k in jt.VESSEL_PARAMETERS:
        assert float(getattr(again.vessel, k)) == float(getattr(t.vessel, k)), k


@pytest.mark.parametrize(
    "text, key, match",
    [
        (
            _tow(FITTED)
            .replace('block_coefficient = 0.927984836065574\nregression = "clarke"\n', "")
            .replace("[vessel.skegs]", "[vessel.derivatives]\nm = 0.5\n[vessel.skegs]"),
            "vessel.skegs",
            "block_coefficient",
        ),
        (_tow("[vessel.skegs]\nchord = 8.0\n"), "vessel.skegs.span", "missing key"),
        (_tow("[vessel.skegs]\nspan = 3.0\nchord = 8.0\nheight = 2\n"), "height", "unknown key"),
        (_tow("[vessel.skegs]\nspan = -3.0\nchord = 8.0\n"), "span", ">= 0|> 0|>"),
        (_tow("[vessel.skegs]\nspan = 3.0\nchord = 8.0\nx = 50.0\n"), "vessel.skegs", "along"),
        (
            _tow(FITTED, extra_vessel="").replace(
                "[vessel.skegs]", "[vessel.derivatives]\nYv = -0.4\n[vessel.skegs]"
            ),
            "vessel.derivatives.Yv",
            "appendages",
        ),
    ],
)
def test_tow_file_skeg_mistakes_are_named(text, key, match):
    with pytest.raises(jt.tow.TowFileError, match=match) as e:
        jt.tow.loads(text, source="bad.toml")
    assert key in str(e.value)


def test_a_preset_with_skegs_is_refused():
    text = '[tow]\nname = "p"\n[vessel]\npreset = "barge_2a"\n' + FITTED
    with pytest.raises(jt.tow.TowFileError, match="measured with its appendages") as e:
        jt.tow.loads(text + "[towline]\nl0 = 2.5\nxp = 0.5\n", source="p.toml")
    assert "vessel.skegs" in str(e.value)
