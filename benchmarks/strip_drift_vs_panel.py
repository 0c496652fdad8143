"""Zero-speed mean drift of the box (Barge 1) and the raked Barge 2 by strip theory
(`jaxtow.strip.drift_qtf`: Gerritsma-Beukelman or the strips' far field (Maruo) plus the
R-function short-wave part) against
the shipped panel-method databases (Capytaine far field, `jaxtow.presets.database`), by
zone; and the speed of the full strip table (21 sections, 40 frequencies, 13 headings, RAOs
and added resistance at 2 m/s) with compile separate, against the panel pipeline for the
same box hull and grid at zero speed (`jaxtow.bem.box_barge_drift`, when Capytaine is
installed and ``--capytaine`` is given). Writes ``benchmarks/data/strip/drift_vs_panel.json``;
the test suite recomputes the strip side and checks it against the file.

    python benchmarks/strip_drift_vs_panel.py [--capytaine] [--json PATH]
"""

from __future__ import annotations

import argparse
import json
import math
import time
from pathlib import Path

import jax
import numpy as np

import jaxtow as jt
import jaxtow.strip as strip
from jaxtow import presets

OUT = Path(__file__).parent / "data" / "strip" / "drift_vs_panel.json"
L, B, T = 76.2, 24.4, 5.0
#: the panel databases' centre of gravity above the waterline (`ASSUMPTIONS['cog_z']` above
#: the keel); their radii of gyration and roll damping are the strip defaults
Z_G = float(presets.ASSUMPTIONS["cog_z"]["value"]) - T
LOADING = jt.Loading(z_g=Z_G)
OMEGA = [0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2, 1.4, 1.7, 2.0, 2.5]
BETA_DEG = [0.0, 45.0, 90.0, 135.0, 180.0]
TABLE = dict(n_omega=40, n_beta=13, u=2.0)
#: frequencies of the RAO comparison (head and beam seas; needs Capytaine)
RAO_OMEGA = [0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.4]
#: (strip mode index, Capytaine dof) of the compared RAOs (angles, and heave at midships)
RAO_MODES = {"heave": (1, "Heave"), "roll": (2, "Roll"), "pitch": (3, "Pitch")}


def hulls():
    return {
        "barge1": (strip.box(L, B, T), presets.box_waterline(L, B, T)),
        "barge2": (presets.barge2_hull(T), presets.barge2_waterline(T)),
    }


def drift_rows():
    rows = []
    beta = np.radians(BETA_DEG)
    for name, (hull, wl) in hulls().items():
        q = strip.drift_qtf(hull, wl, np.array(OMEGA), beta, loading=LOADING)
        gb = strip.added_resistance(hull, np.array(OMEGA), beta, loading=LOADING)
        maruo = strip.added_resistance(
            hull, np.array(OMEGA), beta, loading=LOADING, method=strip.FarField()
        )
        q_maruo = strip.drift_qtf(
            hull, wl, np.array(OMEGA), beta, loading=LOADING, method=strip.FarField()
        )
        panel = presets.database(name, "far_field")
        for i, w in enumerate(OMEGA):
            for j, b in enumerate(BETA_DEG):
                s = np.asarray(q(w, math.radians(b)))
                p = np.asarray(panel(w, math.radians(b)))
                rows.append(
                    dict(
                        hull=name,
                        omega=w,
                        beta_deg=b,
                        strip_fx=float(s[0]),
                        strip_fy=float(s[1]),
                        gerritsma_beukelman_fx=-float(gb.resistance[i, j]),
                        maruo_fx=-float(maruo.resistance[i, j]),
                        strip_maruo_fx=float(np.asarray(q_maruo(w, math.radians(b)))[0]),
                        panel_fx=float(p[0]),
                        panel_fy=float(p[1]),
                    )
                )
    return rows


def table_speed():
    hull = strip.box(L, B, T)
    om = np.linspace(0.2, 1.5, TABLE["n_omega"])
    beta = np.radians(np.linspace(0.0, 180.0, TABLE["n_beta"]))
    times = []
    for rep in range(4):
        t0 = time.perf_counter()
        ar = strip.added_resistance(hull, om + 1e-12 * rep, beta, TABLE["u"], loading=LOADING)
        jax.block_until_ready((ar.resistance, ar.motions.rao))
        times.append(time.perf_counter() - t0)
    warm = float(np.median(times[1:]))
    far = []
    for rep in range(2):
        t0 = time.perf_counter()
        ar = strip.added_resistance(
            hull, om + 1e-12 * rep, beta, TABLE["u"], loading=LOADING, method=strip.FarField()
        )
        jax.block_until_ready(ar.resistance)
        far.append(time.perf_counter() - t0)
    return dict(first=times[0], warm=warm, compile=times[0] - warm, maruo=far[1])


def capytaine_speed():
    from jaxtow.bem import box_barge_drift

    om = np.linspace(0.2, 1.5, TABLE["n_omega"])
    beta = np.radians(np.linspace(0.0, 180.0, TABLE["n_beta"]))
    t0 = time.perf_counter()
    box_barge_drift(L, B, T, om, beta, loading=LOADING, panel_size=2.0)
    return time.perf_counter() - t0


def rao_rows():
    """Heave, roll and pitch RAOs of both hulls in head and beam seas: strip theory against
    the panel pipeline (`jaxtow.bem.box_barge_drift`, 2 m panels), same mass, CoG, radii and
    roll damping."""
    from jaxtow.bem import box_barge_drift, rao

    rows = []
    beta = np.radians([0.0, 90.0])
    rakes = {"barge1": 0.0, "barge2": presets.barge2_rake(T).extent}
    for name, (hull, _) in hulls().items():
        s = np.asarray(strip.motions(hull, np.array(RAO_OMEGA), beta, loading=LOADING).rao)
        ds = box_barge_drift(L, B, T, RAO_OMEGA, beta, loading=LOADING, rake=rakes[name]).dataset
        p = np.asarray(rao(ds))  # (omega, beta, dof)
        dofs = [str(d) for d in ds.dof.values]
        for i, w in enumerate(RAO_OMEGA):
            for j, b in enumerate((0.0, 90.0)):
                for mode, (k, dof) in RAO_MODES.items():
                    rows.append(
                        dict(
                            hull=name,
                            omega=w,
                            beta_deg=b,
                            mode=mode,
                            strip=float(abs(s[i, j, k])),
                            panel=float(abs(p[i, j, dofs.index(dof)])),
                        )
                    )
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--capytaine", action="store_true", help="time the panel pipeline too")
    ap.add_argument("--json", default=str(OUT))
    args = ap.parse_args(argv)
    speed = table_speed()
    rows = drift_rows()
    result = dict(
        hull=dict(length=L, breadth=B, draft=T),
        z_g=Z_G,
        omega=OMEGA,
        beta_deg=BETA_DEG,
        rows=rows,
        table=TABLE,
        time_s=dict(
            strip_compile=speed["compile"], strip=speed["warm"], strip_maruo=speed["maruo"]
        ),
        command="python benchmarks/strip_drift_vs_panel.py --capytaine",
    )
    if args.capytaine:
        result["raos"] = rao_rows()
        cap = capytaine_speed()
        result["time_s"]["capytaine_pipeline"] = cap
        result["ratio_capytaine_over_strip"] = cap / speed["warm"]
    path = Path(args.json)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(result, indent=1) + "\n")
    for r in rows:
        if r["beta_deg"] in (0.0, 90.0):
            f = "fx" if r["beta_deg"] == 0.0 else "fy"
            print(
                f"{r['hull']} β={r['beta_deg']:5.1f} ω={r['omega']:.2f} {f}: strip "
                f"{r['strip_' + f]:10.0f}  panel {r['panel_' + f]:10.0f}"
                + (
                    f"  (GB alone {r['gerritsma_beukelman_fx']:10.0f}, Maruo strips "
                    f"{r['maruo_fx']:10.0f}, with R-function {r['strip_maruo_fx']:10.0f})"
                    if f == "fx"
                    else ""
                )
            )
    print(
        f"strip table {speed['warm']:.2f} s (+ {speed['compile']:.1f} s compile; with the "
        f"far field instead of Gerritsma-Beukelman {speed['maruo']:.1f} s)"
        + (
            f"; panel pipeline {cap:.0f} s, ratio {cap / speed['warm']:.0f}"
            if args.capytaine
            else ""
        )
    )


if __name__ == "__main__":
    main()
