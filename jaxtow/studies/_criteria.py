"""The decision of a tow study: the guideline's criteria (`jaxtow.guidelines`), each with one
of four verdicts, and one overall verdict with one sentence of why.

Every criterion is on the table, also the ones that cannot be judged:

* **pass** / **fail**: the value against the limit, where the theory behind the value holds
  or the bounds that still hold give the same answer;
* **not determined**: the value rests on a theory outside its validity and a bound that still
  holds gives the other answer (the yaw criterion where the forward-speed drift is outside
  its validity, `jaxtow.studies.BOUND_FORMS`), or the equilibrium itself lies outside the
  model (stern first, a slack line, a heading outside the drift table);
* **not checked**: an input the criterion needs is missing (the reason names it).

The overall verdict is NOT ACCEPTABLE where any criterion fails, else NOT DETERMINED where any
is not determined or not checked, else ACCEPTABLE. Numbers only; the report and the console
print the records."""

from __future__ import annotations

import math

from .. import guidelines, resistance
from .._units import TONNE_FORCE
from ..guidelines import Check
from ..resistance import SeaState
from ._conditions import BOUND_FORMS, SPEED_FLAGS
from ._records import (
    Assessment,
    CheckRow,
    Condition,
    OperatingRow,
    StudySummary,
)
from ._resistance import worst_over_tp

__all__ = ["assessment", "weather_pull", "UNDETERMINING_FLAGS"]

#: Validity flags of the straight-behind equilibrium that leave its yaw verdict not
#: determined whatever the bounds say: the equilibrium lies outside the model itself.
UNDETERMINING_FLAGS = ("moving_ahead", "heading_in_table", "line_taut")


def weather_pull(tow, c: guidelines.Criteria, n_tp: int = 41) -> tuple[float, float]:
    """(towing force [N], worst Tp [s]) to hold the tow at zero speed in the weather
    criterion, the worst over the physical Tp range of its Hs (thesis eq. 3.5)."""
    tr = tow.resistance()
    sea = SeaState(
        name="criterion",
        hs=c.hs,
        tp=10.0,  # the worst over the physical range replaces it where Hs > 0
        wind_speed=c.wind_speed,
        current_speed=c.current_speed,
    )
    if c.hs <= 0:
        return float(resistance.required_pull(tr, sea).towing_force), math.nan
    return worst_over_tp(tr, sea, n_tp=n_tp)


def _row(chk: Check, key: str, condition: str = "", **kw) -> CheckRow:
    """A determined `CheckRow` of a guideline `Check`."""
    finite = all(math.isfinite(x) for x in (chk.value, chk.limit))
    verdict = kw.pop("verdict", None) or ("pass" if finite and chk.passed else "fail")
    return CheckRow(
        key=key,
        criterion=chk.criterion,
        condition=condition,
        kind=chk.kind,
        units=chk.units,
        verdict=verdict,
        value=chk.value if math.isfinite(chk.value) else None,
        limit=chk.limit if math.isfinite(chk.limit) else None,
        margin=chk.margin if finite else None,
        source=chk.source,
        estimate=chk.estimate,
        **kw,
    )


def _not_checked(key: str, criterion: str, reason: str, condition: str = "", kind="min", units="-"):
    return CheckRow(
        key=key,
        criterion=criterion,
        condition=condition,
        kind=kind,
        units=units,
        verdict="not checked",
        reason=reason,
    )


def _pull_checks(tow, s: StudySummary, c: guidelines.Criteria) -> list[CheckRow]:
    """The weather criterion and each sea state: the tug's bollard pull against the pull the
    resistance table requires (its worst over Tp)."""
    names = [x.name for x in tow.sea_states]
    crit = "bollard pull (hold the tow in the weather criterion)"
    if tow.tug is None or not tow.has_model:
        why = (
            "no [tug] in the tow file"
            if tow.tug is None
            else "the tow has no manoeuvring model (the hull's load comes from its derivatives)"
        )
        return [_not_checked("bollard_pull_criterion", crit, why, units="t")] + [
            _not_checked(
                f"pull:{n}", f"bollard pull, sea state {n}", why, f"sea state {n}", units="t"
            )
            for n in names
        ]
    out = []
    eff = float(tow.tug.efficiency)
    bp_t = float(tow.tug.bollard_pull) / TONNE_FORCE
    force, tp = weather_pull(tow, c)
    need = force / eff / TONNE_FORCE
    estimate = any(k == "tug_efficiency" for k, _ in tow.assumed)
    source = ("estimate: " if estimate else "[tug] efficiency ") + f"{eff:g}"
    chk = guidelines.check_bollard_pull(need, bp_t, c, efficiency_source=source)
    detail = (
        f"wind {c.wind_speed:g} m/s, Hs {c.hs:g} m"
        + (f" (worst Tp {tp:.1f} s)" if math.isfinite(tp) else "")
        + f", current {c.current_speed:g} m/s; tug efficiency {eff:g}"
    )
    out.append(_row(chk, "bollard_pull_criterion", "weather criterion", detail=detail))
    for r in s.resistance:
        chk = Check(
            f"bollard pull, sea state {r.sea_state} (hold the tow, worst over Tp)",
            bp_t,
            r.required / TONNE_FORCE,
            "min",
            "t",
            "the tow's resistance budget at zero speed with the tug's efficiency",
            estimate,
        )
        detail = f"worst at Tp {r.required_tp:.1f} s; tug efficiency {r.efficiency:g}"
        out.append(_row(chk, f"pull:{r.sea_state}", f"sea state {r.sea_state}", detail=detail))
    return out


_NO_MAKE = (
    "the towline names no catalogue line: give [towline] line and diameter_mm (or segments) "
    "to check its breaking load"
)


def _line_checks(tow, s: StudySummary, c: guidelines.Criteria) -> list[CheckRow]:
    """Towline MBL and length against the bollard pull, its largest mean tension, the
    connecting parts against the line, and the catenary against the water depth."""
    return _strength_checks(tow, s, c) + [_connection_check(tow, c), _seabed_check(tow, s, c)]


def _strength_checks(tow, s: StudySummary, c: guidelines.Criteria) -> list[CheckRow]:
    make = tow.make
    if make is None or tow.tug is None:
        why = (
            _NO_MAKE
            if make is None
            else "no [tug] in the tow file (the limits scale with its bollard pull)"
        )
        return [
            _not_checked("mbl", "towline MBL against the bollard pull", why, units="t"),
            _not_checked("length", "towline length", why, units="m"),
            _not_checked("tension", "largest mean towline tension against the MBL", why, units="t"),
        ]
    bp = float(tow.tug.bollard_pull)
    main = make.main
    out = [
        _row(guidelines.check_mbl(main.mbl / TONNE_FORCE, bp / TONNE_FORCE, c), "mbl"),
        _row(guidelines.check_towline_length(make.length, bp, main.mbl, c), "length"),
    ]
    strength = s.towline.strength if s.towline is not None else None
    if strength is None or strength.max_end_tension is None:
        why = "the study found no valid equilibrium to take the tension of"
        crit = "largest mean towline tension against the MBL"
        return out + [_not_checked("tension", crit, why, units="t")]
    factor = guidelines.mbl_factor(bp / TONNE_FORCE, c)
    chk = Check(
        f"largest mean towline tension (<= MBL / {factor:.2f})",
        strength.max_end_tension / TONNE_FORCE,
        make.weakest.mbl / factor / TONNE_FORCE,
        "max",
        "t",
        "the guideline's MBL factor applied to the largest mean end tension of calm water and "
        "every sea state, as it applies it to the bollard pull (the dynamic loads come on top)",
    )
    where = strength.max_tension_condition or ""
    return out + [_row(chk, "tension", where, detail=f"weakest piece {make.weakest.name}")]


def _connection_check(tow, c: guidelines.Criteria) -> CheckRow:
    make = tow.make
    crit = "connecting parts (bridle, pennant, shackles) against the towline"
    if make is None:
        return _not_checked("connections", crit, _NO_MAKE, units="t")
    if make.bridle and make.bridle_leg is None:
        why = "the bridle's legs have no make: give [towline] bridle line and diameter_mm"
        return _not_checked("connections", crit, why, units="t")
    if not make.connections:
        why = "the tow file names no connecting part (a pennant segment, a bridle's legs)"
        return _not_checked("connections", crit, why, units="t")
    weakest = min(make.connections, key=lambda x: x.mbl)
    chk = guidelines.check_connections(weakest.mbl / TONNE_FORCE, make.main.mbl / TONNE_FORCE, c)
    return _row(chk, "connections", detail=weakest.name)


def _seabed_check(tow, s: StudySummary, c: guidelines.Criteria) -> CheckRow:
    crit = "towline clear of the seabed (water depth - catenary sag)"
    cat = s.towline.catenary if s.towline is not None else None
    if tow.water_depth is None:
        return _not_checked("seabed", crit, "[route] water_depth not given", units="m")
    if cat is None:
        why = (
            "the towline has no weight (a line given by EA alone): name its make ([towline] "
            "line and diameter_mm) or give its weight"
        )
        return _not_checked("seabed", crit, why, units="m")
    chk = guidelines.check_seabed_clearance(cat.sag_m, tow.water_depth, c)
    return _row(chk, "seabed", "calm water at the design speed")


def _yaw_check(cond: Condition) -> CheckRow:
    """The yaw criterion of one condition, four-valued (module docstring)."""
    row = cond.straight
    value = math.nan if row is None else row.max_real
    chk = guidelines.check_yaw(value, cond.name)
    key = {"calm": "yaw:calm", "sea state": f"yaw:sea:{cond.sea_state}"}.get(
        cond.kind, f"yaw:operating:{cond.sea_state}"
    )
    time_s = None if row is None or row.max_real == 0 else math.log(2.0) / abs(row.max_real)
    passed = row is not None and row.max_real <= 0.0
    outside = [] if row is None else list(row.outside)
    words = [w for f, w in zip(cond.outside_validity, cond.outside_text) if f in outside]
    bad = [f for f in outside if f in UNDETERMINING_FLAGS]
    speed = [f for f in outside if f in SPEED_FLAGS]
    verdict, reason = ("pass" if passed else "fail"), ""
    if bad:
        verdict = "not determined"
        reason = "the straight-behind equilibrium lies outside the model: " + "; ".join(
            w for f, w in zip(cond.outside_validity, cond.outside_text) if f in bad
        )
    elif speed and cond.bounds is not None:
        flips = {f: v for f, v in cond.bounds.verdicts.items() if (v == "follows") != passed}
        if flips:
            verdict = "not determined"
            reason = (
                "the forward-speed drift theory is outside its validity here ("
                + "; ".join(words)
                + "), and a bound that still holds gives the other answer ("
                + ", ".join(f"{_bound_words(f)}: {v}" for f, v in flips.items())
                + "): the irregular-sea risk study decides (jaxtow.risk)"
            )
        else:
            reason = (
                "outside the forward-speed drift theory's validity, but the bounds that "
                "still hold give the same answer"
            )
    elif speed:
        verdict = "not determined"
        reason = "the forward-speed drift theory is outside its validity here: " + "; ".join(words)
    elif row is None:
        reason = "no equilibrium straight behind the tug"
    return _row(
        chk,
        key,
        cond.name,
        verdict=verdict,
        reason=reason,
        detail=cond.verdict_text,
        time_s=time_s,
    )


def _bound_words(form: str) -> str:
    return BOUND_FORMS.get(form, form)


def _operating(s: StudySummary) -> list[OperatingRow]:
    """The operating point of every sea state: the speed, the pull the tug gives there and
    the towline tension of the stability model at that speed."""
    out = []
    for r in s.resistance:
        speed = r.operating_speed if r.status in ("successful", "froude_too_high") else None
        tension = None
        if speed is not None:
            cond = s.sea(r.sea_state, "operating speed") or s.sea(r.sea_state)
            if cond is not None and abs(cond.speed - speed) < 1e-3 and cond.straight is not None:
                tension = cond.straight.tension
        out.append(
            OperatingRow(
                sea_state=r.sea_state,
                speed=speed,
                available_pull=r.available_pull if speed is not None else None,
                towline_tension=tension,
                status=r.status,
                message=r.message,
                transit_time_h=r.transit_time_h,
            )
        )
    return out


def _findings(
    tow, s: StudySummary, checks: list[CheckRow], operating: list[OperatingRow]
) -> list[str]:
    """What a planner must read beside the table, most serious first."""
    out = []
    for ch in checks:
        if ch.key == "seabed" and ch.verdict == "fail" and ch.value is not None:
            out.append(
                f"the towline touches the seabed: its catenary sags {-ch.value:.1f} m below it"
            )
    for op in operating:
        if op.speed is None:
            out.append(f"sea state {op.sea_state}: the tug cannot hold the tow ({op.message})")
    out += [f"the tow file: {f.text}" for f in s.plausibility]
    for ch in checks:
        if ch.verdict == "not determined":
            out.append(f"{ch.condition or ch.criterion}: not determined: {ch.reason}")
    for c in s.conditions:
        if c.outside_validity and not any(
            ch.condition == c.name and ch.verdict == "not determined" for ch in checks
        ):
            out.append(f"{c.name}: outside the model's validity: " + "; ".join(c.outside_text))
    for ch in checks:
        if ch.estimate and ch.verdict == "fail":
            out.append(f"'{ch.criterion}' fails against a documented estimate: {ch.source}")
    out += [str(w) for w in tow.warnings]
    return out


def _reason(checks: list[CheckRow], conditions: list[Condition]) -> tuple[str, str]:
    """(verdict, the one sentence of why)."""
    n = len(checks)
    fails = [c for c in checks if c.verdict == "fail"]
    nd = [c for c in checks if c.verdict == "not determined"]
    nc = [c for c in checks if c.verdict == "not checked"]
    parts = []
    yaw_fail = [c for c in fails if c.key.startswith("yaw:")]
    by_condition = {c.name: c for c in conditions}
    if yaw_fail:
        groups: dict[str, list[str]] = {}
        for ch in yaw_fail:
            cond = by_condition.get(ch.condition)
            word = cond.verdict if cond is not None else "fishtails"
            word = {"invalid": "has no equilibrium", "marginal": "is marginal"}.get(word, word)
            groups.setdefault(word, []).append(ch.condition)
        parts += [f"{word} in {_join(names)}" for word, names in groups.items()]
    other = [c for c in fails if not c.key.startswith("yaw:")]
    if other:
        parts.append("fails " + _join([c.criterion.split(" (")[0] for c in other]))
    if fails:
        verdict = "not acceptable"
        tail = (
            f"{len(fails)} of {n} criteria fail"
            + (f", {len(nd)} not determined" if nd else "")
            + (f", {len(nc)} not checked" if nc else "")
        )
    elif nd or nc:
        verdict = "not determined"
        if nd:
            parts.append(
                "not determined where the theory is outside its validity: "
                + _join([c.condition or c.criterion for c in nd])
            )
        counts = [
            f"{k} {word}"
            for k, word in ((len(nd), "not determined"), (len(nc), "not checked"))
            if k
        ]
        tail = (
            f"of {n} criteria {n - len(nd) - len(nc)} pass, "
            + ", ".join(counts)
            + (f" ({_join(sorted({c.reason.split(':')[0] for c in nc}))})" if nc else "")
        )
    else:
        verdict = "acceptable"
        tail = f"all {n} criteria pass"
    sentence = verdict.upper() + ": " + "; ".join(parts + [tail])
    return verdict, sentence


def _join(words: list[str]) -> str:
    words = list(dict.fromkeys(words))
    if len(words) <= 1:
        return "".join(words)
    return ", ".join(words[:-1]) + " and " + words[-1]


def assessment(tow, s: StudySummary) -> Assessment:
    """The decision (`Assessment`) of a study summary ``s`` of ``tow``: the guideline's
    criteria (four-valued), the operating points, the findings and the overall verdict."""
    c = tow.criteria
    checks = _pull_checks(tow, s, c) + _line_checks(tow, s, c)
    if tow.has_model:
        checks += [_yaw_check(cond) for cond in s.conditions]
    else:
        checks.append(
            _not_checked(
                "yaw:calm",
                "follows the tug (max Re lambda, straight behind)",
                "the tow has no manoeuvring model ([vessel] derivatives or preset, and [towline])",
                "calm water",
                kind="max",
                units="1/s",
            )
        )
    operating = _operating(s)
    verdict, reason = _reason(checks, s.conditions)
    return Assessment(
        verdict=verdict,
        reason=reason,
        guideline=c.name,
        checks=checks,
        operating=operating,
        findings=_findings(tow, s, checks, operating),
    )
