"""One self-contained HTML report of a tow study (figures embedded as PNG data; no external
file, script or style sheet), for a surveyor to read: the verdicts first, then resistance
and speed, stability, the map, the time-domain check, the wave drift, the validity warnings
in plain words, and every estimate the numbers depend on."""

from __future__ import annotations

import base64
import datetime
import html

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

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;max-width:1000px;margin:2em auto;
padding:0 1em;color:#222;line-height:1.45}
h1{border-bottom:3px solid #1f4e79;padding-bottom:.2em}h2{color:#1f4e79;margin-top:1.8em}
table{border-collapse:collapse;margin:.6em 0;font-size:.92em}
table.kv td{text-align:left}
th,td{border:1px solid #bbb;padding:.25em .6em;text-align:right}th{background:#eef3f8}
td:first-child,th:first-child{text-align:left}
.ok{background:#e3f4e3}.bad{background:#fbe3e3}.warn{background:#fff4d6}
.note{color:#555;font-size:.9em}img{max-width:100%;border:1px solid #ddd;margin:.5em 0}
li{margin:.2em 0}
"""

_TONNE = 9.80665e3


def _e(x) -> str:
    return html.escape(str(x))


def _table(head, rows, classes=None, kv=False) -> str:
    out = [
        ("<table class='kv'>" if kv else "<table>")
        + "<tr>"
        + "".join(f"<th>{_e(h)}</th>" for h in head)
        + "</tr>"
    ]
    for i, r in enumerate(rows):
        cls = f' class="{classes[i]}"' if classes and classes[i] else ""
        out.append(f"<tr{cls}>" + "".join(f"<td>{_e(c)}</td>" for c in r) + "</tr>")
    return "\n".join(out) + "</table>"


def _img(figures: dict, name: str, alt: str) -> str:
    if name not in figures:
        return ""
    data = base64.b64encode(figures[name]).decode("ascii")
    return f'<img id="fig-{_e(name)}" alt="{_e(alt)}" src="data:image/png;base64,{data}">'


def _verdict_class(key: str, outside) -> str:
    if key == "follows" and not outside:
        return "ok"
    return "warn" if key == "follows" else "bad"


def _fmt(x, f="{:.3g}"):
    return "-" if x is None else f.format(x)


def tow_report_html(summary: dict, figures: dict, *, version: str = "") -> str:
    """The report's HTML text from a `jaxtow.studies.TowStudy` summary and PNG figures
    (name → bytes, from `jaxtow.plotting.tow.study_figures`)."""
    s = summary
    parts = [
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
        f"<title>jaxtow tow study: {_e(s['tow'])}</title><style>{_CSS}</style></head><body>",
        f"<h1>Tow study: {_e(s['tow'])}</h1>",
        f"<p>{_e(s.get('description', ''))}</p>",
    ]
    # ------------------------------------------------------------------ verdicts
    parts.append('<section id="verdict"><h2>Verdict</h2>')
    rows, cls = [], []
    if "calm" in s:
        c = s["calm"]
        rows.append(["calm water", c["verdict_text"]])
        cls.append(_verdict_class(c["verdict"], c["outside_validity"]))
    for name, r in s.get("sea_states", {}).items():
        rows.append([f"sea state {name} (Hs {r['hs']:g} m, Tp {r['tp']:g} s)", r["verdict_text"]])
        cls.append(_verdict_class(r["verdict"], r["outside_validity"]))
    for r in s.get("resistance", []):
        if "operating_speed" in r:
            txt = (
                f"operating speed {r['operating_speed']:.2f} m/s "
                f"({r['operating_speed'] / 0.514444:.1f} kn)"
                + (f", transit {r['transit_time_h']:.0f} h" if "transit_time_h" in r else "")
            )
        else:
            txt = f"no operating speed: {r['message']}"
        rows.append([f"speed in {r['sea_state']}", txt])
        cls.append("ok" if r["status"] == "successful" else "bad")
    if rows:
        parts.append(
            f"<p>At the design tow speed {s['design_speed']:g} m/s "
            f"(stability: equilibria of the tow and their eigenvalues).</p>"
        )
        parts.append(_table(["condition", "verdict"], rows, cls, kv=True))
    for k, why in s.get("skipped", {}).items():
        parts.append(f"<p class='note'>Not assessed: {_e(k)}, because {_e(why)}.</p>")
    parts.append("</section>")
    # ------------------------------------------------------------------ the tow
    parts.append('<section id="tow"><h2>The tow</h2>')
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
        t = s["towline"]
        rows.append(["towline length", f"{t['length_m']:.1f} m (l0' = {t['l0']:g})"])
        rows.append(["attachment", f"x_p' = {t['xp']:g}, y_p' = {t['yp']:g}"])
        rows.append(["stiffness EA'", f"{t['EA_nd']:.1f}"])
        g = t.get("strength")
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
            rows.append(
                [
                    "catenary in calm water",
                    f"span {c['span_m']:.1f} m, sag {c['sag_m']:.1f} m, end tension "
                    f"{c['end_tension'] / 1e3:.1f} kN, effective stiffness "
                    f"{c['effective_stiffness_nd']:.3g} (elastic EA'/l0' "
                    f"{c['elastic_stiffness_nd']:.3g})"
                    + (
                        f", seabed clearance {c['seabed_clearance_m']:.1f} m in "
                        f"{c['water_depth']:g} m of water"
                        if "water_depth" in c
                        else ""
                    ),
                ]
            )
    if "tug" in s:
        g = s["tug"]
        rows.append(
            [
                "tug",
                f"bollard pull {g['bollard_pull'] / _TONNE:.1f} t, free speed "
                f"{g['free_speed']:g} m/s, efficiency {g['efficiency']:g}",
            ]
        )
    parts.append(_table(["", ""], rows, kv=True))
    parts.append(f"<p class='note'>From {_e(s['source'])}.</p></section>")
    # ------------------------------------------------------------------ resistance
    parts.append('<section id="resistance"><h2>Resistance, bollard pull and speed</h2>')
    if "resistance" in s:
        head, rows = resistance_table(s["resistance"])
        parts.append(_table(head, rows))
        parts.append(
            "<p class='note'>hold: towing force at zero speed; req. BP: the tug's rated "
            "bollard pull for it (divided by the efficiency); worst: over the physical Tp "
            "range of the Hs (thesis eq. 3.5).</p>"
        )
        for name in s.get("sea_states", {}) or [r["sea_state"] for r in s["resistance"]]:
            parts.append(_img(figures, f"operating_point_{name}", f"operating point, {name}"))
    else:
        parts.append("<p>Not assessed (see the verdict).</p>")
    parts.append("</section>")
    # ------------------------------------------------------------------ stability
    parts.append('<section id="stability"><h2>Equilibria and stability</h2>')
    conds = ([("calm water", s["calm"])] if "calm" in s else []) + [
        (f"sea state {k}", v) for k, v in s.get("sea_states", {}).items()
    ]
    for label, rec in conds:
        parts.append(f"<h3>{_e(label)}</h3><p>{_e(rec['verdict_text'])}</p>")
        rows = [
            [
                f"{e['psi_deg']:+.3f}",
                f"{e['gamma_deg']:+.3f}",
                f"{e['tension']:.4f}",
                f"{e['max_real']:+.5f}",
                e["stability"],
                "yes" if e["valid"] else "NO: " + ", ".join(e["failed_flags"]),
            ]
            for e in rec["equilibria"]
        ]
        parts.append(
            _table(["psi deg", "gamma deg", "T'", "max Re lambda", "stability", "valid"], rows)
        )
        for n in rec.get("notes", []):
            parts.append(f"<p class='note'>{_e(n)}</p>")
    if not conds:
        parts.append("<p>Not assessed (see the verdict).</p>")
    parts.append("</section>")
    # ------------------------------------------------------------------ map
    parts.append('<section id="map"><h2>Stability map around the design point</h2>')
    if "map" in s:
        m = s["map"]
        parts.append(
            f"<p>x_p' from {m['xp'][0]:g} to {m['xp'][1]:g} ({m['xp'][2]} points), l0' from "
            f"{m['l0'][0]:g} to {m['l0'][1]:g} ({m['l0'][2]} points), calm water: the "
            f"straight-behind equilibrium is stable at {100 * m['straight_stable_share']:.0f} % "
            "of the points (blue: stable).</p>"
        )
        parts.append(_img(figures, "map", "stability map"))
    else:
        parts.append("<p>Not assessed.</p>")
    parts.append("</section>")
    # ------------------------------------------------------------------ time domain
    parts.append('<section id="time-domain"><h2>Time-domain check</h2>')
    if "time_domain" in s:
        t = s["time_domain"]
        yr = t["yaw_range"]
        parts.append(
            _table(
                ["outcome", "path width [L]", "yaw range deg", "slewing period", "ended early"],
                [
                    [
                        t["outcome"],
                        _fmt(t["path_width"]),
                        "-" if not yr else f"{yr[0]:.1f} .. {yr[1]:.1f}",
                        _fmt(t["slewing_period"]),
                        "yes" if t["ended_early"] else "no",
                    ]
                ],
            )
        )
        parts.append(
            f"<p class='note'>Calm water, from heading {t['psi0_deg']:g} deg and sway offset "
            f"{t['y0']:g} L, run length {t['t1']:g} L/U.</p>"
        )
        parts.append(_img(figures, "time_domain", "time traces"))
    else:
        parts.append("<p>Not run.</p>")
    parts.append("</section>")
    # ------------------------------------------------------------------ drift
    parts.append('<section id="drift"><h2>Wave drift</h2>')
    parts.append(f"<p>Source: {_e(s['drift_source'])}.</p>")
    r = s.get("head_sea_surge_at_highest_omega_over_wall_limit")
    if r is not None:
        parts.append(
            f"<p>Head-sea surge drift at the table's highest frequency: {r:.3f} of the "
            "short-wave wall limit ρgB/2 (Faltinsen; 1 for a wall-sided bow in short waves, "
            "less for a raked one).</p>"
        )
    if s.get("mean_drift"):
        parts.append(
            _table(
                [
                    "sea state",
                    "Hs m",
                    "Tp s",
                    "Fx at rest kN",
                    f"Fx at {s['design_speed']:g} m/s kN",
                ],
                [
                    [
                        r["sea_state"],
                        f"{r['hs']:g}",
                        f"{r['tp']:g}",
                        f"{r['fx_stationary'] / 1e3:.1f}",
                        f"{r['fx_design_speed'] / 1e3:.1f}",
                    ]
                    for r in s["mean_drift"]
                ],
            )
        )
    parts.append(_img(figures, "drift", "head-sea drift"))
    parts.append("</section>")
    # ------------------------------------------------------------------ validity
    parts.append('<section id="validity"><h2>Validity warnings</h2><ul>')

    n = 0
    for label, rec in conds:
        for k in rec["outside_validity"]:
            parts.append(f"<li class='warn'>{_e(label)}: {_e(plain.get(k, k))}.</li>")
            n += 1
    for r in s.get("resistance", []):
        if r.get("message"):
            parts.append(f"<li class='warn'>{_e(r['sea_state'])}: {_e(r['message'])}</li>")
            n += 1
    cat = s.get("towline", {}).get("catenary", {})
    if cat and not cat.get("seabed_clear", True):
        parts.append(
            f"<li class='bad'>the towline's lowest point ({cat['sag_m']:.0f} m below the "
            f"ends) is below the seabed ({cat['water_depth']:g} m): it drags on the bottom.</li>"
        )
        n += 1
    for w in s.get("warnings", []):
        parts.append(f"<li class='warn'>{_e(w)}</li>")
        n += 1
    td = s.get("time_domain", {}).get("validity", {})
    for k, v in td.items():
        if not v:
            parts.append(f"<li class='warn'>time-domain run: {_e(plain.get(k, k))}.</li>")
            n += 1
    if not n:
        parts.append("<li>None: every result is inside the model's validity limits.</li>")
    parts.append("</ul></section>")
    # ------------------------------------------------------------------ assumptions
    parts.append(
        '<section id="assumptions"><h2>Assumptions and estimates</h2>'
        "<p>The results depend on these values, which are not from the tow's own data:</p><ul>"
    )
    for k, note in s["assumed"]:
        parts.append(f"<li><b>{_e(k)}</b>: {_e(note)}</li>")
    parts.append("</ul></section>")
    # ------------------------------------------------------------------ provenance
    when = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    times = s.get("step_times_s", {})
    parts.append(
        '<section id="provenance"><h2>Provenance</h2>'
        f"<p>jaxtow {_e(version)}, {when}; tow file {_e(s['source'])}.</p>"
    )
    if times:
        parts.append(_table(["step", "time s"], [[k, f"{v:.1f}"] for k, v in times.items()]))
    parts.append("</section></body></html>")
    return "\n".join(parts)
