"""One self-contained HTML report of a tow study (figures embedded as PNG data; no external
file, script or style sheet), for a surveyor to read: the verdicts first, then resistance
and speed, stability, the map, the time-domain check, the wave drift, the validity warnings
in plain words, and every estimate the numbers depend on.

The page is the jinja2 template ``templates/tow_report.html`` (autoescaped); the functions
here turn a study's summary into the rows and sentences it shows, one function a section."""

from __future__ import annotations

import base64
import datetime

import jinja2

from ..studies._assessment import VALIDITY_WORDS as plain
from ..studies._resistance import resistance_table

__all__ = ["SECTIONS", "tow_report_html"]

#: Section ids of the report, in order (the tests check each is present).
SECTIONS = (
    "verdict",
    "tow",
    "resistance",
    "stability",
    "map",
    "time-domain",
    "drift",
    "validity",
    "assumptions",
    "provenance",
)

_TONNE = 9.80665e3

_ENV = jinja2.Environment(
    loader=jinja2.PackageLoader("jaxtow.reports", "templates"),
    autoescape=True,
    undefined=jinja2.StrictUndefined,
    keep_trailing_newline=True,
)


def _verdict_class(key: str, outside) -> str:
    if key == "follows" and not outside:
        return "ok"
    return "warn" if key == "follows" else "bad"


def _verdicts(s: dict) -> dict:
    rows, classes = [], []
    for label, c in _conditions(s):
        at = "" if "at_operating_speed" in label or label == "calm water" else ", design speed"
        rows.append([label + at, c["verdict_text"]])
        classes.append(_verdict_class(c["verdict"], c["outside_validity"]))
    for r in s.get("resistance", []):
        if r["status"] == "successful":
            txt = (
                f"operating speed {r['operating_speed']:.2f} m/s "
                f"({r['operating_speed'] / 0.514444:.1f} kn)"
                + (f", transit {r['transit_time_h']:.0f} h" if "transit_time_h" in r else "")
            )
        else:
            txt = f"no operating speed: {r['message']}"
        rows.append([f"speed in {r['sea_state']}", txt])
        classes.append("ok" if r["status"] == "successful" else "bad")
    return dict(rows=rows, classes=classes)


def _number(x, units: str) -> str:
    if x is None:
        return "-"
    if units == "1/s":
        return f"{x:.3g} {units}"
    return f"{x:.1f} {units}" if units not in ("-", "") else f"{x:.3g}"


def _criteria(s: dict) -> dict:
    """The guideline table of `jaxtow.studies` (``summary['assessment']``): criterion, value,
    limit, PASS/FAIL, margin, basis; and the findings."""
    a = s.get("assessment")
    if not a:
        return dict(rows=[], classes=[], guideline="", findings=[])
    rows, classes = [], []
    for ch in a["checks"]:
        u = ch["units"]
        sign = ">=" if ch["kind"] == "min" else "<="
        verdict = "PASS" if ch["passed"] else "FAIL"
        basis = ch.get("detail", "") or ""
        if ch["estimate"]:
            basis = (basis + "; " if basis else "") + "limit is a documented estimate"
        rows.append(
            [
                ch["criterion"],
                _number(ch["value"], u),
                f"{sign} {_number(ch['limit'], u)}",
                verdict,
                _number(ch["margin"], u),
                basis,
            ]
        )
        classes.append("ok" if ch["passed"] else "bad")
    return dict(rows=rows, classes=classes, guideline=a["guideline"], findings=a["findings"])


def _advice(s: dict) -> list:
    """Rows of the advice table: condition, what to change, from, to, new max Re λ, checked."""
    rows = []
    for a in s.get("advice", []):
        if a["value"] is None:
            rows.append(
                [
                    a["condition"],
                    a["what"],
                    a["present_text"],
                    f"no value from {a['searched_text']} makes it follow",
                    "-",
                    "-",
                ]
            )
            continue
        rows.append(
            [
                a["condition"],
                a["what"],
                a["present_text"],
                a["value_text"],
                f"{a['new_max_real']:.3g} 1/s",
                "follows the tug" if a["verified"] else "NOT confirmed by the full search",
            ]
        )
    return rows


def criteria_lines(summary: dict) -> list[str]:
    """The guideline table and the findings as plain-text lines (the console's verdict; the
    same rows as the report's)."""
    c = _criteria(summary)
    if not c["rows"]:
        return []
    out = [f"criteria of {c['guideline']}:"]
    for crit, value, limit, verdict, margin, basis in c["rows"]:
        out.append(
            f"  {verdict}  {crit}: {value} (limit {limit}, margin {margin})"
            + (f"; {basis}" if basis else "")
        )
    out += [f"FINDING: {f}" for f in c["findings"]]
    for cond, what, now, to, lam, checked in _advice(summary):
        out.append(
            f"ADVICE ({cond}): {what} {now} -> {to}" + (f"; {checked}" if lam != "-" else "")
        )
    return out


def _towline_rows(t: dict, s: dict) -> list:
    L, F = s["length"], s["force_scale"]
    rows = [
        ["towline length", f"{t['length_m']:.1f} m (l0' = {t['l0']:g})"],
        [
            "attachment",
            f"{t['xp'] * L:.1f} m ahead of the CoG, {t['yp'] * L:.1f} m to port "
            f"(x_p' = {t['xp']:g}, y_p' = {t['yp']:g})",
        ],
        ["axial stiffness EA", f"{t['EA_nd'] * F:.3g} N (EA' = {t['EA_nd']:.1f})"],
    ]
    g = t.get("strength")
    if not g:
        rows.append(
            [
                "towline strength",
                "MBL not given: name a catalogue line ([towline] line and diameter_mm, or "
                "segments) to check it against the bollard pull",
            ]
        )
    if g:
        rows.append(
            [
                "towline make",
                "; ".join(f"{x['name']}, {x['length_m']:.0f} m" for x in g["segments"]),
            ]
        )
        text = f"weakest {g['weakest']}, MBL {g['mbl_kN']:.0f} kN"
        if "utilisation" in g:
            text += (
                f"; largest end tension of the valid equilibria {g['max_end_tension_kN']:.0f}"
                f" kN = {100 * g['utilisation']:.1f} % of MBL (mean loads: dynamic "
                "peaks come on top)"
            )
        if "mbl_over_bollard_pull" in g:
            text += f"; MBL / bollard pull = {g['mbl_over_bollard_pull']:.2f}"
        rows.append(["towline strength", text])
    c = t.get("catenary")
    if c:
        text = (
            f"span {c['span_m']:.1f} m, sag {c['sag_m']:.1f} m, end tension "
            f"{c['end_tension'] / 1e3:.1f} kN, effective stiffness "
            f"{c['effective_stiffness_nd']:.3g} (elastic EA'/l0' "
            f"{c['elastic_stiffness_nd']:.3g})"
        )
        if "water_depth" in c:
            text += (
                f", seabed clearance {c['seabed_clearance_m']:.1f} m in "
                f"{c['water_depth']:g} m of water"
            )
        rows.append(["catenary in calm water", text])
    return rows


def _tow_rows(s: dict) -> list:
    rows = [
        ["vessel L x B x T", f"{s['length']:g} m x {s['breadth']:g} m x {s['draft']:g} m"],
        ["design tow speed", f"{s['design_speed']:g} m/s"],
        ["wave drift", s["drift_source"]],
        ["sailing form of the drift", s["sailing_form"]],
    ]
    if "stability_coefficient_c" in s:
        c = s["stability_coefficient_c"]
        rows.append(["course stability c", f"{c:+.4f} ({'stable' if c > 0 else 'unstable'})"])
    if "towline" in s:
        rows += _towline_rows(s["towline"], s)
    if "tug" in s:
        g = s["tug"]
        rows.append(
            [
                "tug",
                f"bollard pull {g['bollard_pull'] / _TONNE:.1f} t, free speed "
                f"{g['free_speed']:g} m/s, efficiency {g['efficiency']:g}",
            ]
        )
    return rows


def _resistance(s: dict) -> dict | None:
    if "resistance" not in s:
        return None
    head, rows = resistance_table(s["resistance"])
    names = list(s.get("sea_states", {}) or [r["sea_state"] for r in s["resistance"]])
    return dict(head=head, rows=rows, sea_states=names)


def _conditions(s: dict) -> list:
    """(label, record) of calm water and of each sea state assessed, at the design speed and
    at the sea state's operating speed where it differs."""
    out = [("calm water", s["calm"])] if "calm" in s else []
    for k, v in s.get("sea_states", {}).items():
        out.append((f"sea state {k} (Hs {v['hs']:g} m, Tp {v['tp']:g} s)", v))
        if "at_operating_speed" in v:
            u = v["at_operating_speed"]["speed"]
            out.append(
                (f"sea state {k} at its operating speed {u:.2f} m/s", v["at_operating_speed"])
            )
    return out


def _stability(s: dict) -> list:
    out = []
    for label, rec in _conditions(s):
        F, rate = (
            rec.get("force_scale", s["force_scale"]),
            1.0 / rec.get("time_scale", s["time_scale"]),
        )
        rows = [
            [
                f"{e['psi_deg']:+.3f}",
                f"{e['gamma_deg']:+.3f}",
                f"{e['tension'] * F / 1e3:.1f}",
                f"{e['max_real'] * rate:+.3g}",
                e["stability"],
                "yes" if e["valid"] else "NO: " + ", ".join(e["failed_flags"]),
            ]
            for e in rec["equilibria"]
        ]
        out.append(
            dict(
                label=label, verdict_text=rec["verdict_text"], rows=rows, notes=rec.get("notes", [])
            )
        )
    return out


def _map(s: dict) -> dict | None:
    if "map" not in s:
        return None
    m, L = s["map"], s["length"]
    return dict(
        xp=f"{m['xp'][0] * L:.1f} to {m['xp'][1] * L:.1f} m (x_p' {m['xp'][0]:g} to "
        f"{m['xp'][1]:g}, {m['xp'][2]} points)",
        l0=f"{m['l0'][0] * L:.0f} to {m['l0'][1] * L:.0f} m (l0' {m['l0'][0]:g} to "
        f"{m['l0'][1]:g}, {m['l0'][2]} points)",
        share=f"{100 * m['straight_stable_share']:.0f}",
    )


def _time_domain(s: dict) -> dict | None:
    if "time_domain" not in s:
        return None
    t, L, T = s["time_domain"], s["length"], s["time_scale"]
    yr = t["yaw_range"]
    width, period = t["path_width"], t["slewing_period"]
    row = [
        t["outcome"],
        "-" if width is None else f"{width * L:.1f}",
        "-" if not yr else f"{yr[0]:.1f} .. {yr[1]:.1f}",
        "-" if period is None else f"{period * T:.0f}",
        "yes" if t["ended_early"] else "no",
    ]
    return dict(
        row=row,
        psi0=f"{t['psi0_deg']:g}",
        y0=f"{t['y0'] * L:.1f} m (y0' = {t['y0']:g})",
        t1=f"{t['t1'] * T / 60:.0f} min ({t['t1']:g} L/U)",
    )


def _mean_drift(s: dict) -> dict | None:
    if not s.get("mean_drift"):
        return None
    head = ["sea state", "Hs m", "Tp s", "Fx at rest kN", f"Fx at {s['design_speed']:g} m/s kN"]
    rows = [
        [
            r["sea_state"],
            f"{r['hs']:g}",
            f"{r['tp']:g}",
            f"{r['fx_stationary'] / 1e3:.1f}",
            f"{r['fx_design_speed'] / 1e3:.1f}",
        ]
        for r in s["mean_drift"]
    ]
    return dict(head=head, rows=rows)


def _validity(s: dict) -> list:
    """(class, sentence) of every validity warning, in plain words."""
    items = []
    for label, rec in _conditions(s):
        items += [("warn", f"{label}: {plain.get(k, k)}.") for k in rec["outside_validity"]]
    items += [
        ("warn", f"{r['sea_state']}: {r['message']}")
        for r in s.get("resistance", [])
        if r.get("message")
    ]
    cat = s.get("towline", {}).get("catenary", {})
    if cat and not cat.get("seabed_clear", True):
        items.append(
            (
                "bad",
                f"the towline's lowest point ({cat['sag_m']:.0f} m below the ends) is below "
                f"the seabed ({cat['water_depth']:g} m): it drags on the bottom.",
            )
        )
    items += [("warn", w) for w in s.get("warnings", [])]
    td = s.get("time_domain", {}).get("validity", {})
    items += [("warn", f"time-domain run: {plain.get(k, k)}.") for k, v in td.items() if not v]
    return items


def tow_report_html(summary: dict, figures: dict, *, version: str = "") -> str:
    """The report's HTML text from a `jaxtow.studies.TowStudy` summary and PNG figures
    (name → bytes, from `jaxtow.plotting.tow.study_figures`)."""
    s = summary
    r = s.get("head_sea_surge_at_highest_omega_over_wall_limit")
    return _ENV.get_template("tow_report.html").render(
        s=s,
        images={k: base64.b64encode(v).decode("ascii") for k, v in figures.items()},
        design_speed=f"{s['design_speed']:g}",
        verdicts=_verdicts(s),
        criteria=_criteria(s),
        advice=_advice(s),
        skipped=list(s.get("skipped", {}).items()),
        figure_errors=list(s.get("figure_errors", {}).items()),
        incomplete=s.get("incomplete"),
        tow_rows=_tow_rows(s),
        resistance=_resistance(s),
        conditions=_stability(s),
        map=_map(s),
        time_domain=_time_domain(s),
        wall_ratio=None if r is None else f"{r:.3f}",
        mean_drift=_mean_drift(s),
        validity=_validity(s),
        version=version,
        when=datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        times=[[k, f"{v:.1f}"] for k, v in s.get("step_times_s", {}).items()],
    )
