"""One self-contained HTML report of a tow study (figures embedded as PNG data; no external
file, script or style sheet), for a surveyor to read: the overall verdict and its one
sentence first, then the criteria (four-valued), the operating points, the way forward, the
findings; then resistance and speed, stability, the map, the time-domain check, the wave
drift, the validity in plain words and every estimate the numbers depend on.

The page is the jinja2 template ``templates/tow_report.html`` (autoescaped); the functions
here turn the study's typed records (`jaxtow.studies.StudySummary`) into the rows and
sentences it shows, one function a section."""

from __future__ import annotations

import base64
import datetime

import jinja2

from .._units import KNOT, TONNE_FORCE
from ..studies import VALIDITY_WORDS, StudySummary, resistance_table

__all__ = ["REPORT_SECTIONS", "tow_report_html", "criteria_lines", "VERDICT_CLASSES"]

#: Section ids of the report, in order (the tests check each is present).
REPORT_SECTIONS = (
    "verdict",
    "tow",
    "resistance",
    "stability",
    "map",
    "time-domain",
    "risk",
    "drift",
    "validity",
    "assumptions",
    "provenance",
)
#: The colour class of each verdict (overall and per criterion).
VERDICT_CLASSES = {
    "acceptable": "ok",
    "not acceptable": "bad",
    "not determined": "warn",
    "pass": "ok",
    "fail": "bad",
    "not checked": "grey",
}

_ENV = jinja2.Environment(
    loader=jinja2.PackageLoader("jaxtow.reports", "templates"),
    autoescape=True,
    undefined=jinja2.StrictUndefined,
    keep_trailing_newline=True,
)


def _number(x, units: str) -> str:
    if x is None:
        return "-"
    if units == "1/s":
        return f"{x:.3g} {units}"
    return f"{x:.1f} {units}" if units not in ("-", "") else f"{x:.3g}"


def _criteria(s: StudySummary) -> dict:
    """The guideline table: criterion, value, limit, verdict, margin, why/basis; the failures
    first, then NOT DETERMINED, NOT CHECKED and PASS (each in the study's order)."""
    a = s.assessment
    if a is None:
        return dict(rows=[], classes=[], guideline="", counts={})
    rows, classes = [], []
    # what stops the tow first: failures, then what cannot be decided, then the passes
    order = {"fail": 0, "not determined": 1, "not checked": 2, "pass": 3}
    for ch in sorted(a.checks, key=lambda c: order.get(c.verdict, 4)):
        u = ch.units
        sign = ">=" if ch.kind == "min" else "<="
        margin = _number(ch.margin, u)
        if ch.time_s is not None and ch.value is not None:
            word = "halves" if ch.value < 0 else "doubles"
            margin += f" (a disturbance {word} in {ch.time_s / 60:.1f} min)"
        basis = ch.reason or ch.detail
        if ch.estimate:
            basis = (basis + "; " if basis else "") + "the limit rests on a documented estimate"
        rows.append(
            [
                ch.criterion,
                _number(ch.value, u),
                f"{sign} {_number(ch.limit, u)}" if ch.limit is not None else "-",
                ch.verdict.upper(),
                margin,
                basis,
            ]
        )
        classes.append(VERDICT_CLASSES.get(ch.verdict, ""))
    return dict(rows=rows, classes=classes, guideline=a.guideline, counts=a.counts())


def _operating(s: StudySummary) -> list:
    """Rows of the operating table: sea state, speed, the pull the tug gives, the tension."""
    a = s.assessment
    if a is None:
        return []
    rows = []
    for op in a.operating:
        if op.speed is None:
            rows.append([op.sea_state, "the tug cannot hold the tow", "-", "-", "-"])
            continue
        rows.append(
            [
                op.sea_state,
                f"{op.speed:.2f} m/s ({op.speed / KNOT:.1f} kn)",
                _kn(op.available_pull),
                _kn(op.towline_tension),
                f"{op.transit_time_h:.0f} h" if op.transit_time_h is not None else "-",
            ]
        )
    return rows


def _kn(x) -> str:
    return "-" if x is None else f"{x / 1e3:.1f} kN"


def _advice(s: StudySummary) -> list:
    """Rows of the way forward: condition, change, now, to, the tow-file line, re-checked."""
    rows = []
    for a in s.advice:
        if a.value is None:
            to = f"no value from {a.searched_text} does it" + (f" ({a.note})" if a.note else "")
            rows.append([a.condition, a.what, a.present_text, to, "-", "-"])
            continue
        check = "passes" if a.verified else "NOT confirmed by the full check"
        if a.new_max_real is not None:
            check += f" (max Re lambda {a.new_max_real:.3g} 1/s)"
        note = f"; {a.note}" if a.note else ""
        rows.append(
            [
                a.condition,
                a.what,
                a.present_text,
                (a.value_text or "") + note,
                a.tow_file or "-",
                check,
            ]
        )
    return rows


def criteria_lines(s: StudySummary) -> list[str]:
    """The decision, the guideline table, the operating points, the findings and the advice
    as plain-text lines (the console's verdict; the same rows as the report's)."""
    a = s.assessment
    if a is None:
        return []
    out = [a.reason, f"criteria of {a.guideline}:"]
    c = _criteria(s)
    for crit, value, limit, verdict, margin, basis in c["rows"]:
        out.append(
            f"  {verdict:<15} {crit}: {value} (limit {limit}, margin {margin})"
            + (f"; {basis}" if basis else "")
        )
    for sea, speed, pull, tension, transit in _operating(s):
        out.append(
            f"  operating, sea state {sea}: {speed}; tug pull {pull}, towline tension "
            f"{tension}; transit {transit}"
        )
    out += [f"FINDING: {f}" for f in a.findings]
    for cond, what, now, to, line, checked in _advice(s):
        out.append(f"ADVICE ({cond}): {what} {now} -> {to} [{line}]; {checked}")
    return out


def _towline_rows(s: StudySummary) -> list:
    t = s.towline
    if t is None:
        return []
    rows = [
        ["towline length", f"{t.length_m:.1f} m (l0' = {t.l0:g})"],
        [
            "attachment",
            f"{t.xp * s.length:.1f} m ahead of the CoG, {t.yp * s.length:.1f} m to port "
            f"(x_p' = {t.xp:g}, y_p' = {t.yp:g})",
        ],
        ["axial stiffness EA", f"{t.EA:.3g} N (EA' = {t.EA_nd:.1f})"],
    ]
    g = t.strength
    if g is None:
        rows.append(
            [
                "towline strength",
                "no catalogue line named: give [towline] line and diameter_mm (or segments) "
                "to check the MBL against the bollard pull",
            ]
        )
    else:
        rows.append(
            [
                "towline make",
                "; ".join(f"{x.name} ({x.role}), {x.length:.0f} m" for x in g.segments),
            ]
        )
        text = f"weakest {g.weakest}, MBL {g.mbl / 1e3:.0f} kN"
        if g.max_end_tension is not None and g.utilisation is not None:
            text += (
                f"; largest mean end tension {g.max_end_tension / 1e3:.0f} kN "
                f"({g.max_tension_condition}) = {100 * g.utilisation:.1f} % of MBL (dynamic "
                "peaks come on top)"
            )
        if g.mbl_over_bollard_pull is not None:
            text += f"; MBL / bollard pull = {g.mbl_over_bollard_pull:.2f}"
        rows.append(["towline strength", text])
    c = t.catenary
    if c is not None:
        text = (
            f"span {c.span_m:.1f} m, sag {c.sag_m:.1f} m, end tension {c.end_tension / 1e3:.1f} "
            f"kN, effective stiffness {c.effective_stiffness_nd:.3g} (elastic EA'/l0' "
            f"{c.elastic_stiffness_nd:.3g})"
        )
        if c.water_depth is not None and c.seabed_clearance_m is not None:
            text += (
                f", seabed clearance {c.seabed_clearance_m:.1f} m in {c.water_depth:g} m of water"
            )
        rows.append(["catenary in calm water", text])
    return rows


def _tow_rows(s: StudySummary) -> list:
    rows = [
        ["vessel L x B x T", f"{s.length:g} m x {s.breadth:g} m x {s.draft:g} m"],
        ["design tow speed", f"{s.design_speed:g} m/s ({s.design_speed / KNOT:.1f} kn)"],
        ["wave drift", s.drift_source],
        ["sailing form of the drift", s.sailing_form],
    ]
    if s.stability_coefficient_c is not None:
        c = s.stability_coefficient_c
        rows.append(["course stability c", f"{c:+.4f} ({'stable' if c > 0 else 'unstable'})"])
    rows += _towline_rows(s)
    if s.tug is not None:
        g = s.tug
        eff = f"{g.efficiency:g}" + (" (estimate)" if g.efficiency_estimate else "")
        if g.efficiencies:
            eff += "; " + ", ".join(f"{k}: {v:g}" for k, v in g.efficiencies.items())
        rows.append(
            [
                "tug",
                f"bollard pull {g.bollard_pull / TONNE_FORCE:.1f} t, free speed "
                f"{g.free_speed:g} m/s, efficiency {eff}",
            ]
        )
    return rows


def _resistance(s: StudySummary) -> dict | None:
    if not s.resistance:
        return None
    head, rows = resistance_table(s.resistance)
    return dict(head=head, rows=rows, sea_states=[r.sea_state for r in s.resistance])


def _stability(s: StudySummary) -> list:
    out = []
    for c in s.conditions:
        rows = [
            [
                f"{e.psi_deg:+.3f}",
                f"{e.gamma_deg:+.3f}",
                f"{e.tension / 1e3:.1f}",
                f"{e.max_real:+.3g}",
                e.stability + (" (straight behind)" if e.straight else ""),
                "yes" if e.valid else "no" if not e.found else "outside its validity",
            ]
            for e in c.equilibria
        ]
        label = (
            c.name
            + (f" (Hs {c.hs:g} m, Tp {c.tp:g} s)" if c.kind != "calm" else "")
            + (f", {c.speed:.2f} m/s" if c.kind != "operating speed" else "")
        )
        out.append(dict(label=label, verdict_text=c.verdict_text, rows=rows, notes=c.notes))
    return out


def _map(s: StudySummary) -> dict | None:
    m = s.map
    if m is None:
        return None
    L = m.length
    inside = m.xp[0] <= m.design_xp <= m.xp[1] and m.l0[0] <= m.design_l0 <= m.l0[1]
    return dict(
        xp=f"{m.xp[0] * L:.1f} to {m.xp[1] * L:.1f} m ahead of the CoG ({m.xp[2]} points)",
        l0=f"{m.l0[0] * L:.0f} to {m.l0[1] * L:.0f} m ({m.l0[2]} points)",
        design=f"{m.design_xp * L:.1f} m, {m.design_l0 * L:.0f} m"
        + ("" if inside else " (outside the map)"),
        share=f"{100 * m.straight_stable_share:.0f}",
    )


def _time_domain(s: StudySummary) -> dict | None:
    t = s.time_domain
    if t is None:
        return None
    L, T = s.length, s.time_scale
    row = [
        t.outcome,
        "-" if t.path_width is None else f"{t.path_width * L:.1f}",
        "-" if not t.yaw_range else f"{t.yaw_range[0]:.1f} .. {t.yaw_range[1]:.1f}",
        "-" if t.slewing_period is None else f"{t.slewing_period * T:.0f}",
        "yes" if t.ended_early else "no",
    ]
    return dict(
        row=row,
        psi0=f"{t.psi0_deg:g}",
        y0=f"{t.y0 * L:.1f} m (y0' = {t.y0:g})",
        t1=f"{t.t1 * T / 60:.0f} min ({t.t1:g} L/U)",
    )


def _percent(p) -> str:
    return f"{100 * p.value:.0f} % ({100 * p.low:.0f}-{100 * p.high:.0f} %)"


def _risk(s: StudySummary) -> list:
    """One block per sea state of the irregular-sea Monte Carlo: its rows in words."""
    out = []
    for r in s.risk:
        rows = [
            [
                "runs",
                f"{r.runs} runs of {r.duration_h:g} h at the design speed, from the static "
                f"equilibrium (the first {float(r.settings.get('transient_s', 0)) / 60:.0f} min of "
                f"each left out)"
                + (f"; {r.failed_runs} did not reach the end" if r.failed_runs else "")
                + (
                    f"; stopped by the time budget: {r.stopped_by_budget}"
                    if r.stopped_by_budget
                    else ""
                ),
            ],
            [
                "fishtails in a run",
                f"{_percent(r.fishtail)}: yaw amplitude over {r.yaw_threshold_deg:g} deg "
                f"(over 5 deg: {_percent(r.fishtail_5deg)}; over 20 deg: {_percent(r.fishtail_20deg)})",
            ],
        ]
        if r.fishtail_exposure is not None and r.exposure_h is not None:
            rows.append(
                [
                    f"over the route ({r.exposure_h:.0f} h in this sea state)",
                    _percent(r.fishtail_exposure),
                ]
            )
        rows.append(
            [
                "towline tension",
                f"static {r.static_tension / 1e3:.0f} kN; most probable maximum in 3 h "
                f"{r.mpm_tension / 1e3:.0f} kN; largest of all runs {r.largest_tension / 1e3:.0f} kN",
            ]
        )
        if r.mbl is not None and r.exceed_mbl is not None:
            text = f"MBL {r.mbl / 1e3:.0f} kN exceeded in {_percent(r.exceed_mbl)} of the runs"
            if r.design_load is not None and r.exceed_design_load is not None:
                text += (
                    f"; the guideline's design load MBL/f(BP) {r.design_load / 1e3:.0f} kN in "
                    f"{_percent(r.exceed_design_load)}"
                )
            rows.append(["against the MBL", text])
        else:
            rows.append(["against the MBL", "not checked: no catalogue line named"])
        rows.append(["slack line (snatch)", f"{_percent(r.slack)} of the runs"])
        for d in r.design:
            rows.append(
                [
                    f"with {d.text}",
                    f"{100 * d.changed:.0f} % against {100 * d.base:.0f} % over the same "
                    f"{d.runs} runs (change {100 * d.difference.value:+.0f} %, "
                    f"{100 * d.difference.low:+.0f} to {100 * d.difference.high:+.0f} %; McNemar "
                    f"p = {d.p_value:.2g}{', significant' if d.p_value < 0.05 else ', not significant'})",
                ]
            )
        if r.outside_validity:
            rows.append(["validity at the static equilibrium", "; ".join(r.outside_validity)])
        out.append(dict(name=r.sea_state, hs=r.hs, tp=r.tp, rows=rows, seconds=f"{r.seconds:.0f}"))
    return out


def _mean_drift(s: StudySummary) -> dict | None:
    if s.drift is None or not s.drift.mean_drift:
        return None
    head = ["sea state", "Hs m", "Tp s", "Fx at rest kN", f"Fx at {s.design_speed:g} m/s kN"]
    rows = [
        [
            r.sea_state,
            f"{r.hs:g}",
            f"{r.tp:g}",
            f"{r.fx_stationary / 1e3:.1f}",
            f"{r.fx_design_speed / 1e3:.1f}",
        ]
        for r in s.drift.mean_drift
    ]
    return dict(head=head, rows=rows)


def _validity(s: StudySummary) -> list:
    """(class, sentence) of every validity warning, in plain words."""
    items = []
    for c in s.conditions:
        items += [("warn", f"{c.name}: {w}.") for w in c.outside_text]
    items += [("warn", f"{r.sea_state}: {r.message}") for r in s.resistance if r.message]
    cat = s.towline.catenary if s.towline is not None else None
    if cat is not None and cat.seabed_clearance_m is not None and cat.seabed_clearance_m < 0:
        items.append(
            (
                "bad",
                f"the towline's lowest point ({cat.sag_m:.0f} m below the ends) is below the "
                f"seabed ({cat.water_depth:g} m): it drags on the bottom.",
            )
        )
    items += [("warn", w) for w in s.warnings]
    td = s.time_domain.validity if s.time_domain is not None else {}
    items += [
        ("warn", f"time-domain run: {VALIDITY_WORDS.get(k, k)}.") for k, v in td.items() if not v
    ]
    return items


def tow_report_html(summary: StudySummary, figures: dict, *, version: str = "") -> str:
    """The report's HTML text from a `jaxtow.studies.StudySummary` and PNG figures (name →
    bytes, from `jaxtow.plotting.tow.study_figures`)."""
    s = summary
    a = s.assessment
    return _ENV.get_template("tow_report.html").render(
        s=s,
        images={k: base64.b64encode(v).decode("ascii") for k, v in figures.items()},
        verdict=None
        if a is None
        else dict(word=a.verdict.upper(), cls=VERDICT_CLASSES[a.verdict], reason=a.reason),
        findings=[] if a is None else a.findings,
        criteria=_criteria(s),
        operating=_operating(s),
        advice=_advice(s),
        skipped=list(s.skipped.items()),
        figure_errors=list(s.figure_errors.items()),
        incomplete=s.incomplete,
        tow_rows=_tow_rows(s),
        resistance=_resistance(s),
        conditions=_stability(s),
        map=_map(s),
        time_domain=_time_domain(s),
        risk=_risk(s),
        wall_ratio=None if s.drift is None else f"{s.drift.wall_limit_ratio:.3f}",
        mean_drift=_mean_drift(s),
        validity=_validity(s),
        version=version,
        when=datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        times=[[k, f"{v:.1f}"] for k, v in s.step_times_s.items()],
    )
