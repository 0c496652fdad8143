"""The decision a tow planner signs: the guideline functions against hand calculations; one
overall verdict (ACCEPTABLE, NOT ACCEPTABLE, NOT DETERMINED) with its sentence; criteria that
are pass, fail, not determined or not checked; one tug efficiency; plausibility findings at
load; forces that agree (the tug's pull equals the towline tension at every operating
speed); the way forward, re-checked; the page and the JSON contract."""

from __future__ import annotations

import json
import re
from html.parser import HTMLParser
from pathlib import Path

import msgspec
import numpy as np
import pytest
from helpers import count_compiles

import jaxtow as jt
from jaxtow import guidelines as G
from jaxtow.cli import main
from jaxtow.studies import (
    Assessment,
    CheckRow,
    Condition,
    EquilibriumRow,
    StudySummary,
)
from jaxtow.tow import TowFileError

ROOT = Path(__file__).parents[1]
BASE = jt.tow.builtin_text("barge2a")
DECK = ROOT / "docs" / "examples" / "deck-cargo-barge.toml"
SMALL = dict(
    map_xp=(0.4, 0.6, 2),
    map_l0=(2.0, 2.5, 2),
    time_domain=False,
    speeds=(0.0, 3.0, 4),
    risk="never",
)

# A user's tow: a 91.4 x 27.4 m barge on 600 m of 64 mm wire with a chain bridle, 60 t tug.
USER_BRIDLE = """
[tow]
name = "user-bridle"
speed = 2.0
[vessel]
length = 91.4
breadth = 27.4
draft = 3.7
block_coefficient = 0.95
regression = "clarke"
[hull]
waterline = "box"
[towline]
line = "wire"
diameter_mm = 64.0
length = 600.0
bridle = {x_legs = 0.5, half_spread = 0.12, apex_x = 0.7, line = "chain", diameter_mm = 58.0}
[tug]
bollard_pull_t = 60.0
free_speed = 7.0
efficiency = 0.75
[route]
length_nm = 500.0
water_depth = 80.0
[[sea_state]]
builtin = "survival"
[[sea_state]]
builtin = "sailing"
"""


# ------------------------------------------------------------------ guideline functions


def test_mbl_factor_is_the_piecewise_law_by_hand():
    c = G.criteria()
    assert G.mbl_factor(20.0, c) == 3.0 and G.mbl_factor(40.0, c) == 3.0
    assert G.mbl_factor(90.0, c) == 2.0 and G.mbl_factor(150.0, c) == 2.0
    for bp in np.linspace(40.0, 90.0, 11):  # in between: 3.8 - BP/50
        assert G.mbl_factor(bp, c) == pytest.approx(3.8 - bp / 50.0, rel=1e-12)
    with pytest.raises(ValueError, match="parameter 'bollard_pull_t' must be > 0"):
        G.mbl_factor(0.0, c)


def test_length_pull_and_line_checks_by_hand():
    c = G.criteria()
    assert G.minimum_towline_length(60.0, 180.0, c) == pytest.approx(600.0)  # 1800 BP/MBL
    ch = G.check_bollard_pull(18.4, 8.0, c, efficiency_source="estimate: 0.75")
    assert not ch.passed and ch.margin == pytest.approx(-10.4) and ch.estimate
    ch = G.check_mbl(mbl_t=150.0, bollard_pull_t=60.0, c=c)  # 60 t: factor 2.6, need 156 t
    assert ch.limit == pytest.approx(156.0) and not ch.passed
    ch = G.check_seabed_clearance(sag_m=105.7, water_depth_m=60.0, c=c)
    assert ch.value == pytest.approx(-45.7) and not ch.passed
    ch = G.check_connections(weakest_connection_t=300.0, towline_mbl_t=264.5, c=c)
    assert ch.passed and ch.margin == pytest.approx(35.5)
    assert G.check_yaw(-1e-3, "calm").passed and not G.check_yaw(1e-3, "calm").passed


def test_criteria_overrides_say_where_the_value_came_from():
    c = G.criteria("dnv-st-n001", hs=4.0)
    assert c.hs == 4.0 and c.sources["hs"] == "set in the tow file"
    with pytest.raises(ValueError, match="parameter 'guideline' must be one of"):
        G.criteria("nope")
    tow = jt.tow.loads(BASE + '\n[criteria]\nguideline = "dnv-st-n001"\nhs = 4.0\n')
    assert tow.criteria.hs == 4.0 and tow.criteria.name.startswith("DNV-ST-N001")
    assert tow.resolved["criteria"]["wind_speed"] == 20.0  # every limit in the resolved file
    shown = jt.tow.loads(tow.show(), source="shown")
    assert shown.criteria == tow.criteria  # the guideline's own values stay its own


# ------------------------------------------------------------------ one efficiency


def test_one_tug_efficiency_for_the_sea_states_and_the_weather_criterion():
    """[tug] efficiency is the one value; the deprecated [criteria] tug_efficiency must agree
    with it (else loading refuses, naming both), and a sea state may give its own."""
    half = BASE.replace("efficiency = 0.75", "efficiency = 0.5")
    tow = jt.tow.loads(half, source="half")
    assert float(tow.tug.efficiency) == 0.5
    with pytest.raises(TowFileError, match=r"key criteria.tug_efficiency: .*differs from \[tug\]"):
        jt.tow.loads(half + "\n[criteria]\ntug_efficiency = 0.75\n", source="both")
    with pytest.warns(jt.tow.TowFileWarning, match="deprecated"):
        same = jt.tow.loads(half + "\n[criteria]\ntug_efficiency = 0.5\n", source="same")
    assert float(same.tug.efficiency) == 0.5 and "tug_efficiency" not in same.resolved["criteria"]
    none = jt.tow.loads(BASE.replace("efficiency = 0.75\n", ""), source="none")
    assert float(none.tug.efficiency) == 0.75 and "tug_efficiency" in dict(none.assumed)
    own = jt.tow.loads(
        BASE.replace('builtin = "sailing"', 'builtin = "sailing"\ntug_efficiency = 0.6'),
        source="own",
    )
    assert float(own.tug_in(own.sea_states[1]).efficiency) == 0.6
    assert float(own.tug_in(own.sea_states[0]).efficiency) == 0.75


@pytest.mark.slow
def test_tug_efficiency_reaches_the_weather_criterion():
    """The weather criterion divides the towing force by [tug] efficiency: 0.5 asks 1.5 times
    the bollard pull 0.75 asks (the report's row, by its own number)."""
    rows = {}
    for eff in (0.75, 0.5):
        tow = jt.tow.loads(BASE.replace("efficiency = 0.75", f"efficiency = {eff}"), source="e")
        s = StudySummary(**_parts(tow))
        a = jt.studies.assessment(tow, s)
        rows[eff] = next(c for c in a.checks if c.key == "bollard_pull_criterion")
        force, _ = jt.studies.weather_pull(tow, tow.criteria)
        assert rows[eff].limit == pytest.approx(force / eff / jt.TONNE_FORCE, rel=1e-12)
    assert rows[0.5].limit == pytest.approx(1.5 * rows[0.75].limit, rel=1e-12)
    assert "0.5" in rows[0.5].detail


# ------------------------------------------------------------------ plausibility at load


def test_a_thousandfold_EA_slip_is_a_named_finding():
    """EA_N = 1.65e5 (kN typed for N) for a 64 mm wire whose catalogue EA is 1.65e8 N: the
    tow loads (the values are valid one by one) with two named findings, the unit slip and a
    static stretch no line bears; `tow show` prints them."""
    text = USER_BRIDLE.replace("diameter_mm = 64.0\n", "diameter_mm = 64.0\nEA_N = 1.65e5\n", 1)
    tow = jt.tow.loads(text, source="slip")
    keys = {f.key: f for f in tow.findings}
    assert {"EA_catalogue", "static_stretch"} <= set(keys)
    assert "unit slip (kN typed where N are expected)" in keys["EA_catalogue"].text
    assert keys["EA_catalogue"].parameter == "towline.EA_N"
    assert "FINDING (towline.EA_N)" in tow.show()
    clean = jt.tow.loads(USER_BRIDLE, source="clean")
    assert not clean.findings


def test_mass_and_speed_against_the_particulars_and_the_tug():
    heavy = BASE.replace('preset = "barge_2a"', 'preset = "barge_2a"')
    tow = jt.tow.loads(heavy, source="b")
    assert not tow.findings  # Barge 2a: m' gives C_B 0.928
    fast = jt.tow.loads(BASE.replace("speed = 2.0", "speed = 7.5"), source="fast")
    assert any(f.key == "tug_speed" and "free speed" in f.text for f in fast.findings)
    odd = USER_BRIDLE.replace(
        'regression = "clarke"', 'regression = "clarke"\n[vessel.derivatives]\nm = 2.0'
    )
    tow = jt.tow.loads(odd, source="odd")
    f = next(f for f in tow.findings if f.key == "block_coefficient")
    assert "block coefficient of 3.336" in f.text


# ------------------------------------------------------------------ four-valued criteria


def _row(psi=0.0, max_real=-0.01, outside=(), straight=True):
    return EquilibriumRow(
        psi_deg=psi,
        gamma_deg=0.0,
        tension=1e5,
        tension_nd=0.07,
        max_real=max_real,
        max_real_nd=max_real * 38.1,
        stability="stable" if max_real < 0 else "unstable",
        found=True,
        valid=not outside,
        outside=list(outside),
        straight=straight,
    )


def _condition(max_real, outside=(), bounds=None, kind="sea state"):
    words = [jt.studies.VALIDITY_WORDS[k] for k in outside]
    return Condition(
        name="sea state survival",
        kind=kind,
        sea_state="survival",
        speed=2.0,
        force_scale=1.0,
        time_scale=38.1,
        hs=5.0,
        tp=10.5,
        wind_speed=20.0,
        current_speed=0.0,
        equilibria=[_row(max_real=max_real, outside=outside)],
        verdict="follows" if max_real < 0 else "fishtails",
        verdict_text="",
        outside_validity=list(outside),
        outside_text=words,
        bounds=bounds,
    )


def test_yaw_criteria_are_pass_fail_not_determined():
    """Inside validity: pass or fail. Outside the forward-speed theory: the bounds that still
    hold decide; where one of them gives the other answer, NOT DETERMINED (never a pass).
    An equilibrium outside the model itself (stern first): NOT DETERMINED."""
    from jaxtow.studies._criteria import _yaw_check

    assert _yaw_check(_condition(-0.01)).verdict == "pass"
    assert _yaw_check(_condition(+0.01)).verdict == "fail"
    same = jt.studies.Bounds(verdicts={"stationary": "follows"}, changes=False)
    flip = jt.studies.Bounds(verdicts={"stationary": "fishtails"}, changes=True)
    c = _yaw_check(_condition(-0.01, ["no_separation"], same))
    assert c.verdict == "pass" and "same answer" in c.reason
    c = _yaw_check(_condition(-0.01, ["no_separation"], flip))
    assert c.verdict == "not determined" and "zero-speed drift: fishtails" in c.reason
    assert "no_separation" not in c.reason and "orbital velocity" in c.reason  # plain words
    c = _yaw_check(_condition(-0.01, ["moving_ahead"]))
    assert c.verdict == "not determined" and "stern first" in c.reason
    c = _yaw_check(_condition(+0.01))
    assert c.time_s == pytest.approx(np.log(2) / 0.01) and c.units == "1/s"


def _check(key, verdict, **kw):
    return CheckRow(
        key=key,
        criterion=key,
        condition=kw.pop("condition", ""),
        kind="max",
        units="-",
        verdict=verdict,
        **kw,
    )


def test_one_overall_verdict_and_its_sentence():
    from jaxtow.studies._criteria import _reason

    cond = [_condition(+0.01, kind="calm")]
    cond[0] = msgspec.structs.replace(cond[0], name="calm water")
    checks = [
        _check("yaw:calm", "fail", condition="calm water"),
        _check("mbl", "not checked", reason="no make: give line"),
        _check("length", "pass"),
    ]
    verdict, sentence = _reason(checks, cond)
    assert verdict == "not acceptable"
    assert sentence.startswith("NOT ACCEPTABLE: fishtails in calm water")
    assert "1 of 3 criteria fail" in sentence and "1 not checked" in sentence
    verdict, sentence = _reason(
        [_check("yaw:sea:x", "not determined", condition="sea state x"), _check("a", "pass")], []
    )
    assert verdict == "not determined" and "sea state x" in sentence
    assert sentence.endswith("of 2 criteria 1 pass, 1 not determined")  # no "0 not checked"
    verdict, sentence = _reason(
        [_check("a", "pass"), _check("b", "not checked", reason="r: x")], []
    )
    assert sentence == "NOT DETERMINED: of 2 criteria 1 pass, 1 not checked (r)"
    verdict, sentence = _reason([_check("a", "pass"), _check("b", "pass")], [])
    assert (verdict, sentence) == ("acceptable", "ACCEPTABLE: all 2 criteria pass")


# ------------------------------------------------------------------ the page and the JSON


def _summary(checks, verdict="not acceptable", reason="NOT ACCEPTABLE: x"):
    tow = jt.tow.load("barge2a")
    a = Assessment(
        verdict=verdict, reason=reason, guideline="g", checks=checks, operating=[], findings=["f"]
    )
    return StudySummary(**_parts(tow), assessment=a)


def _parts(tow) -> dict:
    from jaxtow.studies._assessment import _particulars

    return dict(_particulars(tow), skipped={})


class _Cells(HTMLParser):
    def __init__(self):
        super().__init__()
        self.rows, self.row, self.cell, self.texts = [], None, None, []

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self.row = []
        elif tag in ("td", "th") and self.row is not None:
            self.cell = ""

    def handle_data(self, data):
        self.texts.append(data)
        if self.cell is not None:
            self.cell += data

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self.row is not None and self.cell is not None:
            self.row.append(self.cell)
            self.cell = None
        elif tag == "tr" and self.row is not None:
            self.rows.append(self.row)
            self.row = None


def test_the_page_opens_with_the_decision_and_shows_four_verdicts():
    checks = [
        _check("a", "pass", value=1.0, limit=2.0),
        _check("b", "fail", value=3.0, limit=2.0),
        _check(
            "c", "not determined", value=1.0, limit=2.0, reason="a bound gives the other answer"
        ),
        _check("d", "not checked", reason="no make named"),
    ]
    html = jt.reports.tow_report_html(_summary(checks), {}, version="test")
    p = _Cells()
    p.feed(html)
    text = " ".join(t.strip() for t in p.texts if t.strip())
    first = text.index("NOT ACCEPTABLE")
    assert first < text.index("The tow") and first < text.index("criterion")
    table = [r for r in p.rows if len(r) == 6 and r[0] in "abcd"]
    # failures first (above the fold), then what cannot be decided, then the passes
    assert [r[3] for r in table] == ["FAIL", "NOT DETERMINED", "NOT CHECKED", "PASS"]
    assert "a bound gives the other answer" in table[1][5] and "no make named" in table[2][5]
    for flag in jt.studies.VALIDITY_WORDS:  # the page never shows a flag's name
        assert flag not in text


def test_the_json_contract():
    """assessment.verdict; each check's verdict; assessment.operating with sea_state, speed
    (null where the tug cannot hold the tow), available_pull and towline_tension."""
    op = jt.studies.OperatingRow(
        sea_state="survival",
        speed=None,
        available_pull=None,
        towline_tension=None,
        status="cannot_hold",
        message="m",
    )
    s = _summary([_check("a", "not checked", reason="r")])
    s = msgspec.structs.replace(s, assessment=msgspec.structs.replace(s.assessment, operating=[op]))
    data = json.loads(jt.studies.to_json(s))
    a = data["assessment"]
    assert a["verdict"] in jt.studies.VERDICTS
    assert all(c["verdict"] in jt.studies.CHECK_VERDICTS for c in a["checks"])
    assert a["operating"][0] == dict(
        sea_state="survival",
        speed=None,
        available_pull=None,
        towline_tension=None,
        status="cannot_hold",
        message="m",
        transit_time_h=None,
    )
    back = msgspec.json.decode(jt.studies.to_json(s), type=StudySummary)
    assert back == s  # the typed records round-trip through their JSON


# ------------------------------------------------------------------ forces that agree


@pytest.mark.slow
def test_the_towline_tension_is_the_tugs_pull_at_the_operating_speed():
    """Barge 2a in the survival sea: the resistance budget's operating speed and the
    stability model at that speed evaluate one drift source (and the same wind): the tug's
    pull on the towline and the tension of the straight-behind equilibrium are one number."""
    tow = jt.tow.load("barge2a")
    sea = tow.sea_states[0]
    row = jt.studies.evaluate_resistance(tow.resistance(), tow.tug_in(sea), sea, 0.0, None)
    model = jt.at_tug_speed(tow.sea_model(sea), row.operating_speed)
    cond = jt.studies.condition(model, "x", "operating speed", sea)
    assert cond.straight.tension == pytest.approx(row.available_pull, rel=1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("which", ["deck", "user_bridle"])
def test_tension_equals_pull_for_user_tows_with_current_and_a_bridle(which):
    """The docs' deck-cargo tow (a 0.5 m/s current in its survival sea) and a user's tow on a
    bridle: at every operating speed the tension equals the pull the tug gives (the current
    enters the stability model as it enters the budget)."""
    tow = jt.tow.load(DECK) if which == "deck" else jt.tow.loads(USER_BRIDLE, source="u")
    for sea in tow.sea_states:
        row = jt.studies.evaluate_resistance(tow.resistance(), tow.tug_in(sea), sea, 0.0, None)
        if row.operating_speed is None:
            continue
        model = jt.at_tug_speed(tow.sea_model(sea), row.operating_speed)
        cond = jt.studies.condition(model, "x", "operating speed", sea)
        assert cond.straight.tension == pytest.approx(row.available_pull, rel=1e-9), sea.name


# ------------------------------------------------------------------ whole studies

#: The programs `tow_study` of Barge 2a on the SMALL grids compiles from empty caches (JAX's
#: backend compiles, eager operations included), as measured with jax 0.10.2 on the CPU:
#: 1156, then 1017 once the sweep kernel's validity flags were unchecked, then 863 once each
#: condition's stability and validity ran as one compiled program instead of eagerly, then
#: 856 once the model at another tug speed kept its towline's scalars weakly typed (a new
#: argument type to every kernel before), then 127 once the required pull, its worst Tp,
#: the hull's mean drift and the advice's re-checks ran as compiled programs instead of
#: eager operations, the advice's scans shared one program, the stability of every
#: condition ran on the fixed-size set of equilibria (one shape) and the resistance
#: programs took the sea state without its (static) name, then 70 once the skeg advice's
#: hulls kept the vessel's derivatives weakly typed (they ran the calm-water programs), the
#: eager checks of concrete models ran in NumPy, the seas' spectra were evaluated inside the
#: hull's drift program and the sets of equilibria were indexed on the host.
STUDY_COMPILES = 70


@pytest.mark.slow
def test_barge2a_is_not_acceptable_with_its_not_checked_rows_and_a_way_forward():
    """Barge 2a (no skegs) fishtails everywhere: NOT ACCEPTABLE; its towline names no make,
    so MBL, length, tension and connecting parts are NOT CHECKED (named, not left out), and
    the seabed too ([route] has no depth); the advice finds the twin skegs that make it
    follow the tug (re-checked), where no towline change does. The programs the study
    compiles are counted from empty caches and held to the number measured (a ratchet: a
    change that makes the study compile more kernels shows here)."""
    import jax

    jax.clear_caches()
    with count_compiles() as n:
        s = jt.studies.tow_study(jt.tow.load("barge2a"), progress=False, **SMALL).summary
    print(
        f"barge2a study: {n.compiles} programs compiled in {n.compile_s:.1f} s, "
        f"{n.traces} traced in {n.trace_s:.1f} s"
    )
    assert 0 < n.compiles <= STUDY_COMPILES, n
    a = s.assessment
    assert a.verdict == "not acceptable" and a.reason.startswith("NOT ACCEPTABLE: fishtails")
    nc = {c.key for c in a.checks if c.verdict == "not checked"}
    assert nc == {"mbl", "length", "tension", "connections", "seabed"}
    skeg = next(x for x in s.advice if x.kind == "skegs")
    assert skeg.verified and skeg.tow_file.startswith("[vessel.skegs]") and 2.0 < skeg.value < 5.0
    assert all(x.value is None for x in s.advice if x.kind == "change")
    for op in a.operating:
        assert op.towline_tension == pytest.approx(op.available_pull, rel=1e-9)


def test_auto_risk_runs_where_a_yaw_row_is_not_determined(tmp_path):
    """[study] risk = "auto" picks the sea states whose yaw row (at the design or the
    operating speed) is not determined, and only those; "never" picks none."""
    from types import SimpleNamespace as NS

    from jaxtow.studies._risk import risk_seas

    rows = [
        NS(key="yaw:sea:survival", verdict="not determined"),
        NS(key="yaw:operating:sailing", verdict="pass"),
        NS(key="seabed", verdict="not determined"),
    ]
    summary = NS(assessment=NS(checks=rows))
    assert [s.name for s in risk_seas(jt.tow.load(DECK), summary)] == ["survival"]
    rows[1] = NS(key="yaw:operating:sailing", verdict="not determined")
    assert [s.name for s in risk_seas(jt.tow.load(DECK), summary)] == ["survival", "sailing"]
    never = tmp_path / "never.toml"
    never.write_text(DECK.read_text().replace("[study]\n", '[study]\nrisk = "never"\n'))
    assert risk_seas(jt.tow.load(never), summary) == []


@pytest.mark.heavy  # 6 minutes on 2 cores: the default suite checks the verdict's rule
# (test_yaw_criteria_are_pass_fail_not_determined) and the auto risk's choice of sea states;
# the slow suite the bounds (test_outside_validity_...) and the risk's page
def test_the_deck_cargo_survival_yaw_row_is_not_a_pass(tmp_path):
    """The docs' deck-cargo barge through `jaxtow study`: its survival yaw row rests on the
    forward-speed theory outside its validity, where a bound gives the other answer, so it
    is NOT DETERMINED (never a PASS); the seabed fails (700 m of wire in 60 m of water) with
    a shorter line as the way forward, re-checked."""
    deck = tmp_path / "deck.toml"  # the example with short Monte Carlo runs (plumbing only)
    deck.write_text(DECK.read_text().replace("[study]\n", "[study]\nrisk_hours = 0.25\n"))
    main(
        ["study", "--tow", str(deck), "--out", str(tmp_path), "--quiet"]
        + ["--map-xp", "0.3", "0.7", "3", "--map-l0", "5", "9", "3", "--no-time-domain"]
        + ["--risk-budget", "10"]
    )
    s = json.loads((tmp_path / "deck-barge_summary.json").read_text())
    checks = {c["key"]: c for c in s["assessment"]["checks"]}
    assert checks["yaw:sea:survival"]["verdict"] == "not determined"
    # where the linear verdict cannot decide, the Monte Carlo ran and its probability is given
    risk = {r["sea_state"]: r for r in s["risk"]}
    assert "survival" in risk and risk["survival"]["runs"] >= 4
    assert "Monte Carlo" in checks["yaw:sea:survival"]["reason"]
    assert checks["seabed"]["verdict"] == "fail"
    # the towline's largest tension includes the sea states at their operating speeds (the
    # tug's pull there), not calm water alone
    pulls = [o["towline_tension"] for o in s["assessment"]["operating"] if o["towline_tension"]]
    assert pulls and checks["tension"]["value"] * jt.TONNE_FORCE >= max(pulls) * (1 - 1e-9)
    assert any("touches the seabed" in f for f in s["assessment"]["findings"])
    seabed = next(x for x in s["advice"] if x["kind"] == "seabed")
    assert seabed["verified"] and seabed["value"] < checks["length"]["value"] / s["length"]
    html = (tmp_path / "deck-barge_report.html").read_text()
    assert "the towline touches the seabed" in html and "NOT ACCEPTABLE" in html
    assert 'id="risk"' in html and "fishtails in a run" in html and "fig-risk_runs_survival" in html


@pytest.mark.slow
def test_the_study_runs_the_risk_where_asked_and_reports_it():
    """[study] risk = "always" runs the Monte Carlo in every sea state within the budget: its
    record holds the probability with its interval, the tension against the MBL, the
    probability at half the Hs and the design changes on the same random numbers, and the
    page shows them with their figures. (Short runs: the check is of the plumbing.)"""
    import dataclasses

    text = USER_BRIDLE.replace('builtin = "survival"\n[[sea_state]]\n', "")
    tow = jt.tow.loads(text)
    opts = dataclasses.replace(tow.study, risk="always", risk_budget_s=1.0, risk_hours=0.25)
    tow = dataclasses.replace(tow, study=opts)
    base = StudySummary(
        tow=tow.name, description="", source="", design_speed=2.0, length=tow.scales.length,
        breadth=tow.breadth, draft=tow.scales.draft, force_scale=float(tow.scales.force),
        time_scale=1.0, sailing_form=tow.form, drift_source="", assumed=[], warnings=[],
        plausibility=[],
    )  # fmt: skip
    records, figures = jt.studies.risk_step(tow, base)
    (r,) = records
    assert r.sea_state == "sailing" and r.runs >= 4 and r.duration_h == 0.25
    assert 0.0 <= r.fishtail.low <= r.fishtail.value <= r.fishtail.high <= 1.0
    assert r.mbl is not None and r.exceed_mbl is not None and r.design_load is not None
    assert r.largest_tension > r.static_tension > 0
    assert [p.hs for p in r.hs_curve] == [1.2, 2.4]
    assert {d.parameter for d in r.design} <= {"l0", "xp"} and r.design
    assert all(0.0 <= d.p_value <= 1.0 for d in r.design)
    s = msgspec.structs.replace(base, risk=records)
    data = json.loads(jt.studies.to_json(s))
    assert data["risk"][0]["fishtail"]["high"] == pytest.approx(r.fishtail.high)
    st = jt.studies.TowStudy(tow=tow, summary=s, risk=figures)
    figs = {k: jt.plotting.tow.png_bytes(f) for k, f in jt.plotting.tow.study_figures(st).items()}
    assert {"risk_runs_sailing", "risk_tension_sailing", "risk_hs_sailing"} <= set(figs)
    html = jt.reports.tow_report_html(s, figs)
    assert 'id="risk"' in html and "fishtails in a run" in html and "most probable maximum" in html


# ------------------------------------------------------------------ fail early


def test_problems_known_before_computing_are_refused_at_load(tmp_path):
    short = re.sub(r"^l0 = 2.5.*$", "l0 = 0.2", BASE, flags=re.M)
    with pytest.raises(TowFileError, match=r"key study.y0: the time-domain start y0' = 0.3"):
        jt.tow.loads(short, source="short.toml")
    bridle = re.sub(
        r"^xp = 0.5.*$",
        "bridle = {x_legs = 0.45, half_spread = 0.15, apex_x = 0.75}",
        re.sub(r"^l0 = 2.5.*$", "l0 = 0.31", BASE, flags=re.M),
        flags=re.M,
    )
    with pytest.raises(TowFileError, match=r"key towline.l0: the towline \(23.6 m.*shorter than"):
        jt.tow.loads(bridle, source="bridle.toml")
    missing = re.sub(r"^drift = .*$", 'drift = {file = "nope.8"}', BASE, flags=re.M)
    with pytest.raises(TowFileError, match=r"line \d+, key hull.drift: no such drift file"):
        jt.tow.loads(missing, source="d.toml", base=tmp_path)
    one = BASE.replace("l0 = 2.5", "").replace(
        "EA_N = 2.6e8", 'segments = [{line = "wire", diameter_mm = 76, length = 190}]'
    )
    with pytest.raises(TowFileError, match="for one line give line, diameter_mm and length"):
        jt.tow.loads(one, source="one.toml")


# ------------------------------------------------------------------ one command line


def test_changes_are_in_the_tow_files_units():
    tow = jt.tow.load("barge2a")
    changed = jt.tow.with_changes(tow, l0=1.0, EA_N=1.3e8, speed=1.5)
    assert float(changed.towline.l0) == 1.0 and float(changed.scales.u_tug) == 1.5
    assert float(changed.towline.EA) == pytest.approx(1.3e8 / float(changed.scales.force))
    assert "with l0 = 1" in changed.source


def _error(argv, capsys) -> str:
    with pytest.raises(SystemExit) as e:
        main(argv)
    return str(e.value.code) + capsys.readouterr().err


def test_ea_has_one_name_in_each_unit(capsys, tmp_path):
    msg = _error(["study", "--tow", "barge2a", "--EA-N", "50", "--out", str(tmp_path)], capsys)
    assert "the axial stiffness in N, got 50" in msg and "--EA-nd" in msg
    msg = _error(["equilibria", "--tow", "barge2a", "--EA-N", "50"], capsys)
    assert "--EA-nd" in msg
    msg = _error(["study", "barge2a", "--tow", "barge2b", "--out", str(tmp_path)], capsys)
    assert "give the tow once" in msg
    msg = _error(["equilibria", "--tow", "barge2a", "--EA-N", "2.6e8", "--EA-nd", "333"], capsys)
    assert "not both" in msg


def test_equilibria_take_ea_in_newtons(capsys):
    main(["equilibria", "--tow", "barge2a", "--EA-N", "2.6e8"])
    a = capsys.readouterr().out
    main(["equilibria", "--tow", "barge2a"])
    b = capsys.readouterr().out
    assert a == b  # 2.6e8 N is the built-in's EA: the same model
    main(["equilibria", "--tow", "barge2a", "--EA", "2.6e8"])
    captured = capsys.readouterr()
    assert captured.out == b and "--EA is deprecated" in captured.err


# ------------------------------------------------------------------ advice


def _follows(model) -> bool:
    eqs = jt.equilibria(model)
    st = np.asarray(jt.stability(model, eqs.state).stability)
    mask = jt.straight_behind(np.asarray(eqs.psi), np.asarray(eqs.valid))
    return bool(np.any(mask & (st == -1)))


@pytest.mark.slow
def test_advice_rerun_at_the_suggested_change_passes():
    """The deck-cargo barge fishtails in calm water; moving the attachment point forward is
    the change the advice finds. Re-run with the whole equilibrium search at the suggested
    value, the tow follows the tug (and at the present value it does not)."""
    model = jt.tow.load(DECK).model()
    assert not _follows(model)
    advice = jt.studies.yaw_advice(model, "calm water")
    found = [a for a in advice if a.value is not None]
    assert found and found[0].parameter == "xp"
    for a in found:
        changed = jt.with_parameters(model, **{a.parameter: a.value})
        assert _follows(changed), a
        assert a.verified and a.new_max_real < 0 and a.tow_file
        # the smallest change: a tenth of the way back toward the present value fails again
        back = a.value - 0.1 * (a.value - a.present)
        assert jt.design.stable_value(model, a.parameter, *sorted((a.present, back))) is None


@pytest.mark.slow
def test_outside_validity_the_verdict_is_repeated_under_the_bounds():
    """Barge 2a at 2 m/s in Hs 5 m is faster than the waves' orbital velocity: the sea state
    verdict is repeated with the zero-speed drift and the thesis's form, and says whether
    it changes."""
    from jaxtow.studies._conditions import condition, with_bounds

    tow = jt.tow.load("barge2a")
    s = tow.sea_states[0]
    rec = with_bounds(tow, s, condition(tow.sea_model(s), "sea state survival", "sea state", s))
    assert "no_separation" in rec.outside_validity
    assert set(rec.bounds.verdicts) == {"stationary", "thesis"}
    assert rec.bounds.changes == any(v != rec.verdict for v in rec.bounds.verdicts.values())
    assert "Under the bounds that still hold" in rec.verdict_text


def test_the_stationary_form_is_the_zero_speed_drift():
    q = jt.tow.load("barge2a").drift.qtf()
    for u in (0.0, 2.0, 4.0):
        F = jt.drift.sailing_drift(q, 0.8, 0.3, u, 0.1, 0.01, form="stationary")
        np.testing.assert_array_equal(np.asarray(F), np.asarray(q(0.8, 0.3)))


def test_the_study_names_a_bad_risk_option():
    with pytest.raises(jt.ParameterError, match="'risk' must be 'auto', 'always' or 'never'"):
        jt.studies.tow_study(jt.tow.load("barge2a"), risk="sometimes")
