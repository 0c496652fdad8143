"""Journée's (1992) Wigley experiments against jaxtow's strip theory.

The measured values (``benchmarks/data/strip/journee1992_measured.json``: Journée, Delft
report 909, as quoted with the report's normalisations by the open strip code michell,
beside that code's own figures) are recomputed by `jaxtow.strip` at the same points:

* model III at Fn 0.3, forced heave: A33/(ρ∇) and B33√(L/g)/(ρ∇) at the oscillation
  frequency (strip theory's heave coefficients do not depend on the speed);
* model III at Fn 0.3, restrained in head waves: |X3|/(C33 ζa) and |X5|/(k C55 ζa), with
  C33 = ρgA_w and C55 = ρgI_L of the strips' waterplane;
* heave RAOs of models III (Fn 0.2, 0.3) and I (Fn 0.3), and the zero-speed heave and
  pitch θa L/(2πζa) of models III and IV;
* the added-resistance peaks R/(ρgζa²B²/L) of the four models, the largest value on a
  λ/L grid of 0.7-2.5 in steps of 0.025, by Gerritsma-Beukelman, by the far field, and by
  Gerritsma-Beukelman with the bow's short-wave reflection (`strip.WithReflection`: jaxtow's
  `drift.liu` on the Wigley waterline); beside it, as a check of that reflection part, the
  head-sea reflection of Liu & Papanikolaou's own form (`wedge_reflection`: a wedge bow), and
  their whole semi-empirical method (`liu_papanikolaou_motion` plus that wedge), a method
  the ITTC lists for speed trials.

Head seas, fresh water (ρ = 1000 kg/m³), k_yy = 0.25 L, G on the waterline. Writes
``benchmarks/data/strip/journee1992_compared.json`` and, with ``--docs``, the tables into
docs/strip.md.

    python benchmarks/strip_journee.py --docs
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

import jaxtow as jt
import jaxtow.strip as strip

HERE = Path(__file__).parent
MEASURED = HERE / "data" / "strip" / "journee1992_measured.json"
OUT = HERE / "data" / "strip" / "journee1992_compared.json"
DOCS = HERE.parent / "docs" / "strip.md"
BEGIN = "<!-- journee table: python benchmarks/strip_journee.py --docs -->"
END = "<!-- end of journee table -->"
RHO, G = 1000.0, 9.81
WATER = jt.Water(rho=RHO, g=G)
PEAK_GRID = np.arange(0.7, 2.5001, 0.025)


def setup(data, name):
    m = data["models"][name]
    L, T, kyy = data["length"], data["draft"], data["k_yy"]
    hull = strip.wigley(L, m["breadth"], T, alpha=m["alpha"])
    loading = jt.Loading(z_g=0.0, radii=(0.35 * m["breadth"], kyy, kyy))
    return hull, loading, L, m


def omega_of(lam_over_l, L):
    return np.sqrt(2 * np.pi * G / (np.asarray(lam_over_l, float) * L))


def heave_coefficients(data):
    d = data["heave_coefficients"]
    hull, _, L, m = setup(data, d["model"])
    rows = np.array(d["rows"])
    w = rows[:, 0] / np.sqrt(L / G)
    c = strip.hull_coefficients(hull, w, water=WATER)
    vol = float(strip.hydrostatics(hull).volume)
    a = np.asarray(c.added_mass)[:, 1, 1] / (RHO * vol)
    b = np.asarray(c.damping)[:, 1, 1] * np.sqrt(L / G) / (RHO * vol)
    return [
        dict(omega_nd=r[0], a33=r[1], b33=r[2], jaxtow_a33=float(ai), jaxtow_b33=float(bi))
        for r, ai, bi in zip(rows, a, b, strict=True)
    ]


def restrained_loads(data):
    d = data["restrained_loads"]
    hull, loading, L, m = setup(data, d["model"])
    rows = np.array(d["rows"])
    w = omega_of(rows[:, 0], L)
    k = w**2 / G
    u = d["froude"] * np.sqrt(G * L)
    mo = strip.motions(hull, w, [0.0], u, loading=loading, water=WATER)
    hs = strip.hydrostatics(hull)
    x = np.asarray(mo.exciting)[:, 0]
    x3 = np.abs(x[:, 1]) / (RHO * G * float(hs.area))
    x5 = np.abs(x[:, 3]) / (k * RHO * G * float(hs.i_xx))
    return [
        dict(lambda_over_l=r[0], x3=r[1], x5=r[2], jaxtow_x3=float(a), jaxtow_x5=float(b))
        for r, a, b in zip(rows, x3, x5, strict=True)
    ]


def raos(data):
    out = []
    for model, fn, lam, heave, anchor in data["heave_rao"]["rows"]:
        hull, loading, L, _ = setup(data, model)
        mo = strip.motions(
            hull, omega_of([lam], L), [0.0], fn * np.sqrt(G * L), loading=loading, water=WATER
        )
        out.append(
            dict(
                model=model,
                froude=fn,
                lambda_over_l=lam,
                heave=heave,
                anchor=anchor,
                jaxtow=float(abs(np.asarray(mo.rao)[0, 0, 1])),
            )
        )
    return out


def zero_speed(data):
    out = []
    for model, lam, heave, pitch in data["zero_speed"]["rows"]:
        hull, loading, L, _ = setup(data, model)
        mo = strip.motions(hull, omega_of([lam], L), [0.0], 0.0, loading=loading, water=WATER)
        r = np.asarray(mo.rao)[0, 0]
        out.append(
            dict(
                model=model,
                lambda_over_l=lam,
                heave=heave,
                pitch=pitch,
                jaxtow_heave=float(abs(r[1])),
                jaxtow_pitch=float(abs(r[3]) * L / (2 * np.pi)),
            )
        )
    return out


def resistance_peaks(data):
    out = []
    for model, fn, measured, a_gb, a_far in data["added_resistance_peaks"]["rows"]:
        hull, loading, L, m = setup(data, model)
        w = omega_of(PEAK_GRID, L)
        u = fn * np.sqrt(G * L)
        scale = RHO * G * m["breadth"] ** 2 / L
        row = dict(model=model, froude=fn, measured=measured, anchor_gb=a_gb, anchor_far=a_far)
        wl = strip.wigley_waterline(L, m["breadth"], data["draft"], alpha=m["alpha"])
        methods = (
            ("gb", strip.GerritsmaBeukelman()),
            ("far", strip.FarField()),
            ("gb_reflection", strip.WithReflection(wl)),
        )
        for key, method in methods:
            r = strip.added_resistance(
                hull, w, [0.0], u, loading=loading, water=WATER, method=method
            )
            raw = np.asarray(r.resistance)[:, 0] / scale
            i = int(np.argmax(raw))
            row[f"jaxtow_{key}"] = float(raw[i])
            row[f"jaxtow_{key}_at"] = float(PEAK_GRID[i])
            if key == "gb":
                gb = raw
        reflection = wedge_reflection(L, m["breadth"], data["draft"], wl, fn, PEAK_GRID) / scale
        row["check_gb_wedge"] = float(np.max(gb + reflection))
        motion = liu_papanikolaou_motion(
            L, m["breadth"], data["draft"], float(wl.block_coefficient), fn, PEAK_GRID
        )
        row["check_liu_papanikolaou"] = float(np.max(motion + reflection))
        out.append(row)
    return out


def wedge_reflection(L, B, T, wl, fn, lam_over_l):
    """A check of the reflection part, not a jaxtow method: Liu & Papanikolaou's head-sea
    reflection in its own form, as their 2020 formula is written in a public implementation
    (we could not read the paper itself): a wedge bow of half-angle E = atan(0.495B/L_E), L_E
    the length of entrance (bow to 99 % of the breadth, on ``wl``), the draft factor
    α_T = 1 − exp(−4π(T/λ − T/(2.5L))) and a factor 2.25 on Faltinsen's wedge,

        R = (2.25/2) ρgζa² B α_T sin²E (1 + 2ωU/g) (0.87/C_B)^(1 + 4√Fn)   [N per ζa²]."""
    pts = np.asarray(wl.points)
    ahead = pts[pts[:, 0] >= 0.0]
    x99 = np.max(ahead[ahead[:, 1] >= 0.99 * 0.5 * B, 0])
    entrance = L / 2 - x99
    e = np.arctan(0.495 * B / entrance)
    lam = np.asarray(lam_over_l, float) * L
    omega = np.sqrt(2 * np.pi * G / lam)
    u = fn * np.sqrt(G * L)
    alpha_t = np.where(lam <= 2.5 * L, 1 - np.exp(-4 * np.pi * (T / lam - T / (2.5 * L))), 0.0)
    cb = float(wl.block_coefficient)
    factor = (0.87 / cb) ** (1 + 4 * np.sqrt(fn))
    return 2.25 / 2 * RHO * G * B * alpha_t * np.sin(e) ** 2 * (1 + 2 * omega * u / G) * factor


def liu_papanikolaou_motion(L, B, T, cb, fn, lam_over_l, k_yy=0.25):
    """A check, not a jaxtow method: the motion part of Liu & Papanikolaou's (2020)
    semi-empirical added resistance in head seas (even keel), R_AWM/(ρgζa²B²/L) =
    4 a1 a2 ω̄^b1 exp((b1/d1)(1 − ω̄^d1)), as their formula is written in a public
    implementation (we could not read the paper itself), with

        a1 = 60.3 C_B^1.34 (4 k_yy)² (0.87/C_B)^(1 + Fn) / ln(B/T),
        a2 = Fn^1.5 exp(−3.5 Fn) (Fn ≥ 0.12),
        ω̄ = 2.142 k_yy^(1/3) √(L/λ) [1 − (0.111/C_B)(ln(B/T) − ln 2.75)] (C_B/0.65)^0.17
             [−1.377 Fn² + 1.157 Fn + 0.618],
        b1 = 11, d1 = 566 (L C_B/B)^−2.66 (ω̄ < 1);  b1 = −8.5, d1 = −4·566 (L/B)^−2.66 else;

    k_yy the radius of gyration by L. With `wedge_reflection` it is their whole method."""
    lam = np.asarray(lam_over_l, float) * L
    a1 = 60.3 * cb**1.34 * (4 * k_yy) ** 2 * (0.87 / cb) ** (1 + fn) / np.log(B / T)
    a2 = 0.0072 + 0.1676 * fn if fn < 0.12 else fn**1.5 * np.exp(-3.5 * fn)
    w = (
        2.142
        * k_yy ** (1 / 3)
        * np.sqrt(L / lam)
        * (1 - 0.111 / cb * (np.log(B / T) - np.log(2.75)))
        * (cb / 0.65) ** 0.17
        * (-1.377 * fn**2 + 1.157 * fn + 0.618)
    )
    b1 = np.where(w < 1, 11.0, -8.5)
    d1 = np.where(w < 1, 566 * (L * cb / B) ** -2.66, -566 * (L / B) ** -2.66 * 4)
    return 4 * a1 * a2 * w**b1 * np.exp(b1 / d1 * (1 - w**d1))


def pct(a, b):
    return f"{100 * (a / b - 1):+.0f} %"


def tables(res) -> str:
    lines = [
        "**Forced heave, model III, Fn 0.3** (A33/(ρ∇), B33√(L/g)/(ρ∇); the anchor states its "
        "coefficients within 10-15 %):",
        "",
        "| ω√(L/g) | A33 measured | jaxtow | B33 measured | jaxtow |",
        "|---|---|---|---|---|",
    ]
    for r in res["heave_coefficients"]:
        lines.append(
            f"| {r['omega_nd']:.2f} | {r['a33']:.3f} | {r['jaxtow_a33']:.3f} "
            f"({pct(r['jaxtow_a33'], r['a33'])}) | {r['b33']:.3f} | {r['jaxtow_b33']:.3f} "
            f"({pct(r['jaxtow_b33'], r['b33'])}) |"
        )
    lines += [
        "",
        "**Restrained model III in head waves, Fn 0.3** (|X3|/(C33ζa), |X5|/(kC55ζa)):",
        "",
        "| λ/L | X3 measured | jaxtow | X5 measured | jaxtow |",
        "|---|---|---|---|---|",
    ]
    for r in res["restrained_loads"]:
        lines.append(
            f"| {r['lambda_over_l']:g} | {r['x3']:.3f} | {r['jaxtow_x3']:.3f} "
            f"({pct(r['jaxtow_x3'], r['x3'])}) | {r['x5']:.3f} | {r['jaxtow_x5']:.3f} "
            f"({pct(r['jaxtow_x5'], r['x5'])}) |"
        )
    lines += [
        "",
        "**Heave RAO |η₃|/ζa with forward speed**:",
        "",
        "| model | Fn | λ/L | measured | anchor | jaxtow |",
        "|---|---|---|---|---|---|",
    ]
    for r in res["heave_rao"]:
        anchor = "" if r["anchor"] is None else f"{r['anchor']:.2f}"
        lines.append(
            f"| {r['model']} | {r['froude']:g} | {r['lambda_over_l']:g} | {r['heave']:.2f} | "
            f"{anchor} | {r['jaxtow']:.2f} ({pct(r['jaxtow'], r['heave'])}) |"
        )
    lines += [
        "",
        "**Zero speed** (heave |η₃|/ζa, pitch θa L/(2πζa); the anchor states its zero-speed "
        "pitch 10-20 % low):",
        "",
        "| model | λ/L | heave measured | jaxtow | pitch measured | jaxtow |",
        "|---|---|---|---|---|---|",
    ]
    for r in res["zero_speed"]:
        lines.append(
            f"| {r['model']} | {r['lambda_over_l']:g} | {r['heave']:.2f} | "
            f"{r['jaxtow_heave']:.2f} ({pct(r['jaxtow_heave'], r['heave'])}) | "
            f"{r['pitch']:.2f} | {r['jaxtow_pitch']:.2f} ({pct(r['jaxtow_pitch'], r['pitch'])}) |"
        )
    lines += [
        "",
        "**Added-resistance peaks** R/(ρgζa²B²/L) (jaxtow's largest value on λ/L 0.7-2.5, "
        "step 0.025; its λ/L in brackets; GB + reflection: `WithReflection`, with Liu & "
        "Papanikolaou's wedge form of the reflection as a check, and their whole "
        "semi-empirical method, motion part and wedge, as a second check in the last "
        "column):",
        "",
        "| model | Fn | measured | anchor GB | jaxtow GB | anchor far field | jaxtow far field "
        "| jaxtow GB + reflection | check: GB + wedge | check: Liu & Papanikolaou 2020 |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in res["added_resistance_peaks"]:
        lines.append(
            f"| {r['model']} | {r['froude']:g} | {r['measured']:.1f} | {r['anchor_gb']:.1f} "
            f"({pct(r['anchor_gb'], r['measured'])}) | {r['jaxtow_gb']:.1f} "
            f"({pct(r['jaxtow_gb'], r['measured'])}; {r['jaxtow_gb_at']:.3g}) | "
            f"{r['anchor_far']:.1f} ({pct(r['anchor_far'], r['measured'])}) | "
            f"{r['jaxtow_far']:.1f} ({pct(r['jaxtow_far'], r['measured'])}; "
            f"{r['jaxtow_far_at']:.3g}) | {r['jaxtow_gb_reflection']:.1f} "
            f"({pct(r['jaxtow_gb_reflection'], r['measured'])}; "
            f"{r['jaxtow_gb_reflection_at']:.3g}) | {r['check_gb_wedge']:.1f} "
            f"({pct(r['check_gb_wedge'], r['measured'])}) | "
            f"{r['check_liu_papanikolaou']:.1f} "
            f"({pct(r['check_liu_papanikolaou'], r['measured'])}) |"
        )
    return "\n".join(lines)


def write_docs(text: str) -> None:
    from _docs_block import write_block  # beside this script

    write_block(DOCS, BEGIN, END, text)


def main(argv=None):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--json", default=str(OUT))
    ap.add_argument("--docs", action="store_true", help="write the tables into docs/strip.md")
    args = ap.parse_args(argv)
    data = json.loads(MEASURED.read_text())
    t0 = time.perf_counter()
    res = dict(
        heave_coefficients=heave_coefficients(data),
        restrained_loads=restrained_loads(data),
        heave_rao=raos(data),
        zero_speed=zero_speed(data),
        added_resistance_peaks=resistance_peaks(data),
        command="python benchmarks/strip_journee.py --docs",
        jaxtow=jt.__version__,
    )
    Path(args.json).write_text(json.dumps(res, indent=1) + "\n")
    text = tables(res)
    print(text)
    print(f"\n{time.perf_counter() - t0:.0f} s")
    if args.docs:
        write_docs(text)


if __name__ == "__main__":
    main()
