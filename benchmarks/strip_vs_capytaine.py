"""Zero-speed radiation coefficients and head-sea heave and pitch RAOs of the box barge
(Barge 1, 76.2 x 24.4 x 5 m): strip theory (`jaxtow.strip.hull_coefficients`,
`motions`) against the 3-D panel method (Capytaine, the same solver settings as
jaxtow's panel pipeline), in one process, with the time of each side for the radiation
coefficients (compile separate). Writes the table to ``benchmarks/data/strip/box_zero_speed.json``; the
test suite recomputes the strip side and checks it against the file.

    python benchmarks/strip_vs_capytaine.py [--panel-size 2.0] [--json PATH]
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
from jaxtow.bem import meshes
from jaxtow.bem.capytaine_mesh import symmetric_capytaine_mesh
from jaxtow.presets import ASSUMPTIONS

OUT = Path(__file__).parent / "data" / "strip" / "box_zero_speed.json"
L, B, T = 76.2, 24.4, 5.0
OMEGA = [0.3, 0.5, 0.7, 0.9, 1.1]
RAO_OMEGA = [0.2, 0.35, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2]
#: (strip mode index, Capytaine dof) for the compared diagonal terms
PAIRS = {
    "sway": (0, "Sway"),
    "heave": (1, "Heave"),
    "roll": (2, "Roll"),
    "pitch": (3, "Pitch"),
    "yaw": (4, "Yaw"),
}
STRIP = dict(n_stations=21, n_side=6, n_bottom=6)
#: the centre of gravity above the waterline: the panel pipeline's (`ASSUMPTIONS['cog_z']`
#: above the keel)
Z_G = float(ASSUMPTIONS["cog_z"]["value"]) - T


def strip_side():
    hull = strip.box(L, B, T, **STRIP)
    t0 = time.perf_counter()
    c = strip.hull_coefficients(hull, np.array(OMEGA))
    jax.block_until_ready(c.added_mass)
    first = time.perf_counter() - t0
    t0 = time.perf_counter()
    again = strip.hull_coefficients(hull, np.array(OMEGA) + 1e-9)  # warm: compile excluded
    jax.block_until_ready(again.added_mass)
    warm = time.perf_counter() - t0
    return c, first - warm, warm


def capytaine_side(panel_size):
    import capytaine as cpt

    mesh = meshes.box_barge_mesh(L, B, T, panel_size=panel_size)
    hull, lid, _ = symmetric_capytaine_mesh(mesh)
    body = cpt.FloatingBody(
        mesh=hull, lid_mesh=lid, dofs=cpt.rigid_body_dofs(rotation_center=(0.0, 0.0, 0.0))
    )
    solver = cpt.BEMSolver(method="indirect")
    t0 = time.perf_counter()
    out = []
    for w in OMEGA:
        probs = [
            cpt.RadiationProblem(body=body, radiating_dof=d, omega=w, water_depth=math.inf)
            for _, d in PAIRS.values()
        ]
        res = solver.solve_all(probs, progress_bar=False)
        out.append(
            {
                m: (r.added_mass[d], r.radiation_damping[d])
                for (m, (_, d)), r in zip(PAIRS.items(), res)
            }
        )
    elapsed = time.perf_counter() - t0
    raos = capytaine_raos(cpt, body, solver)
    return out, elapsed, raos


def capytaine_raos(cpt, body, solver):
    """Heave and pitch RAOs in head seas from Capytaine's added mass, damping and exciting
    forces (Froude-Krylov plus diffraction), with the same mass and restoring matrices as
    `jaxtow.strip.motions` (`rigid_body_matrices`) (so the two differ by their hydrodynamics only)."""
    from capytaine.bem.airy_waves import froude_krylov_force

    m5, c5 = strip.rigid_body_matrices(strip.box(L, B, T, **STRIP), jt.Loading(z_g=Z_G))
    m = np.asarray(m5)[np.ix_([1, 3], [1, 3])]
    c = np.asarray(c5)[np.ix_([1, 3], [1, 3])]
    dofs = ("Heave", "Pitch")
    out = []
    for w in RAO_OMEGA:
        env = dict(omega=w, water_depth=math.inf)
        rad = [cpt.RadiationProblem(body=body, radiating_dof=d, **env) for d in dofs]
        dif = cpt.DiffractionProblem(body=body, wave_direction=math.pi, **env)  # head seas
        res = solver.solve_all(rad + [dif], progress_bar=False)
        a = np.array([[res[j].added_mass[i] for j in range(2)] for i in dofs])
        b = np.array([[res[j].radiation_damping[i] for j in range(2)] for i in dofs])
        fk = froude_krylov_force(res[2].problem)
        f = np.array([res[2].forces[d] + fk[d] for d in dofs])
        # Capytaine's e^{-iωt} convention, pitch + bow down (rotation about +y): as the strips
        h = -(w**2) * (m + a) - 1j * w * b + c
        out.append(np.linalg.solve(h, f))
    return np.array(out)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--panel-size", type=float, default=2.0)
    ap.add_argument("--json", default=str(OUT))
    args = ap.parse_args(argv)
    c, compile_s, strip_s = strip_side()
    cap, cap_s, cap_raos = capytaine_side(args.panel_size)
    strip_raos = np.asarray(
        strip.motions(
            strip.box(L, B, T, **STRIP), np.array(RAO_OMEGA), [0.0], loading=jt.Loading(z_g=Z_G)
        ).rao
    )[:, 0][:, [1, 3]]
    raos = [
        dict(
            omega=w,
            strip_heave=abs(complex(strip_raos[i, 0])),
            panel_heave=abs(complex(cap_raos[i, 0])),
            strip_pitch=abs(complex(strip_raos[i, 1])),
            panel_pitch=abs(complex(cap_raos[i, 1])),
        )
        for i, w in enumerate(RAO_OMEGA)
    ]
    rows = []
    for i, w in enumerate(OMEGA):
        for m, (k, _) in PAIRS.items():
            a_s, b_s = float(c.added_mass[i, k, k]), float(c.damping[i, k, k])
            a_c, b_c = (float(v) for v in cap[i][m])
            rows.append(dict(omega=w, mode=m, strip_a=a_s, strip_b=b_s, panel_a=a_c, panel_b=b_c))
    result = dict(
        hull=dict(length=L, breadth=B, draft=T),
        strip=STRIP,
        z_g=Z_G,
        panel_size=args.panel_size,
        omega=OMEGA,
        rows=rows,
        head_sea_raos=raos,
        time_s=dict(strip_compile=compile_s, strip=strip_s, capytaine=cap_s),
        ratio_capytaine_over_strip=cap_s / strip_s,
        command="python benchmarks/strip_vs_capytaine.py",
    )
    path = Path(args.json)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(result, indent=1) + "\n")
    for r in rows:
        print(
            f"ω={r['omega']:.1f} {r['mode']:6s} a: strip {r['strip_a']:.4g} panel "
            f"{r['panel_a']:.4g} ({r['strip_a'] / r['panel_a'] - 1:+.1%})  b: strip "
            f"{r['strip_b']:.4g} panel {r['panel_b']:.4g}"
        )
    for r in raos:
        print(
            f"ω={r['omega']:.2f} heave strip {r['strip_heave']:.3f} panel {r['panel_heave']:.3f}"
            f"  pitch [deg/m] strip {math.degrees(r['strip_pitch']):.3f} panel "
            f"{math.degrees(r['panel_pitch']):.3f}"
        )
    print(
        f"strip {strip_s:.2f} s (+ {compile_s:.1f} s compile), Capytaine {cap_s:.1f} s: "
        f"ratio {cap_s / strip_s:.0f}"
    )


if __name__ == "__main__":
    main()
