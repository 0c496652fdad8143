"""Journée's (1992, Delft report 909) four Wigley models in regular head waves at Fn 0.2, 0.3
and 0.4 by strip theory: heave and pitch RAOs and the added resistance by Gerritsma-Beukelman
and by the strips' far field (Maruo), in the report's normalisation. Writes
``benchmarks/data/strip/wigley.json``; the test suite recomputes rows of it.

The report's measured values are not in this repository (its data files are not reachable
from here), so the table holds the two methods side by side, and docs/strip.md says what is
and is not compared. With ``--capytaine`` the zero-speed heave and pitch coefficients of
model I are compared with the panel method on a mesh of the same analytic hull.

    python benchmarks/strip_wigley.py [--capytaine] [--json PATH]
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np

import jaxtow as jt
import jaxtow.strip as strip

OUT = Path(__file__).parent / "data" / "strip" / "wigley.json"
#: the models (report §2): L = 3 m, T = 0.1875 m, k_yy = 0.25 L, fresh water
L, T, K_YY, RHO, G = 3.0, 0.1875, 0.75, 1000.0, 9.81
MODELS = {"I": (0.3, 1.0), "II": (0.6, 1.0), "III": (0.3, 0.0), "IV": (0.6, 0.0)}
FROUDE = [0.2, 0.3, 0.4]
LAMBDA_OVER_L = [0.5, 0.6, 0.75, 0.9, 1.0, 1.1, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0]
#: the centre of gravity is put on the waterline (the report's KG is not used: in head seas
#: it enters only the pitch restoring through ρg∇ BG, a few per cent of ρg I_L here)
Z_G = 0.0


def model_rows(name):
    breadth, alpha = MODELS[name]
    hull = strip.wigley(L, breadth, T, alpha=alpha)
    lam = np.array(LAMBDA_OVER_L) * L
    k = 2 * np.pi / lam
    omega = np.sqrt(k * G)
    radii = (0.35 * breadth, K_YY, K_YY)
    opts = dict(loading=jt.Loading(z_g=Z_G, radii=radii), water=jt.Water(rho=RHO, g=G))
    rows = []
    for fn in FROUDE:
        u = fn * np.sqrt(G * L)
        gb = strip.added_resistance(hull, omega, [0.0], u, **opts)
        far = strip.added_resistance(hull, omega, [0.0], u, method=strip.FarField(), **opts)
        rao = np.asarray(gb.motions.rao)[:, 0]
        scale = RHO * G * breadth**2 / L  # R_aw'' = R / (ρ g ζa² B²/L)
        for i, lo in enumerate(LAMBDA_OVER_L):
            rows.append(
                dict(
                    model=name,
                    froude=fn,
                    lambda_over_l=lo,
                    omega=float(omega[i]),
                    omega_e=float(np.asarray(gb.motions.omega_e)[i, 0]),
                    heave=float(abs(rao[i, 1])),
                    pitch=float(abs(rao[i, 3]) / k[i]),  # θa / (k ζa)
                    raw_gerritsma_beukelman=float(np.asarray(gb.resistance)[i, 0] / scale),
                    raw_maruo=float(np.asarray(far.resistance)[i, 0] / scale),
                    valid=bool(np.asarray(far.valid)[i, 0]),
                )
            )
    return rows


#: frequencies of the zero-speed coefficient comparison with the panel method [rad/s]
PANEL_OMEGA = [3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 10.0]


def wigley_mesh(breadth, alpha, nx=60, nz=12):
    """A Capytaine mesh of Journée's Wigley form (`jaxtow.strip.wigley`'s formula): quads
    between nx + 1 stations and nz + 1 cosine-spaced depths on both sides."""
    import capytaine as cpt

    x = np.linspace(-L / 2, L / 2, nx + 1)
    z = -T * 0.5 * (1.0 - np.cos(np.linspace(0.0, np.pi, nz + 1)))
    xi2, ze2 = (2 * x / L)[:, None] ** 2, (z / T)[None, :] ** 2
    eta = (1 - ze2) * (1 - xi2) * (1 + 0.2 * xi2) + alpha * ze2 * (1 - ze2**4) * (1 - xi2) ** 4
    half = 0.5 * breadth * eta
    verts = [
        (x[i], s * half[i, j], z[j])
        for s in (1.0, -1.0)
        for i in range(nx + 1)
        for j in range(nz + 1)
    ]
    faces = []
    for side in (0, 1):
        idx = lambda i, j: (side * (nx + 1) + i) * (nz + 1) + j  # noqa: E731
        for i in range(nx):
            for j in range(nz):
                quad = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1))
                faces.append(quad if side == 0 else quad[::-1])
    return cpt.Mesh(np.array(verts), np.array(faces)).merged()


def panel_rows():
    """Zero-speed heave and pitch added mass and damping of model I: strips against
    Capytaine on `wigley_mesh` (60 × 12 panels a side)."""
    import capytaine as cpt

    breadth, alpha = MODELS["I"]
    dofs = cpt.rigid_body_dofs(rotation_center=(0, 0, 0))
    body = cpt.FloatingBody(mesh=wigley_mesh(breadth, alpha), dofs=dofs).immersed_part()
    body = body.with_only_dofs(["Heave", "Pitch"])
    problems = [
        cpt.RadiationProblem(body=body, radiating_dof=d, omega=w, rho=RHO, g=G)
        for w in PANEL_OMEGA
        for d in ("Heave", "Pitch")
    ]
    ds = cpt.assemble_dataset(cpt.BEMSolver().solve_all(problems), hydrostatics=False)
    hull = strip.wigley(L, breadth, T, alpha=alpha)
    c = strip.hull_coefficients(hull, np.array(PANEL_OMEGA), water=jt.Water(rho=RHO, g=G))
    rows = []
    for i, w in enumerate(PANEL_OMEGA):
        for name, dof, j in (("33", "Heave", 1), ("55", "Pitch", 3)):
            sel = dict(omega=w, radiating_dof=dof, influenced_dof=dof)
            rows.append(
                dict(
                    omega=w,
                    omega_nd=w * np.sqrt(L / G),
                    coefficient=name,
                    strip_added_mass=float(np.asarray(c.added_mass)[i, j, j]),
                    panel_added_mass=float(ds.added_mass.sel(**sel)),
                    strip_damping=float(np.asarray(c.damping)[i, j, j]),
                    panel_damping=float(ds.radiation_damping.sel(**sel)),
                )
            )
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--capytaine", action="store_true", help="compare with the panel method")
    ap.add_argument("--json", default=str(OUT))
    args = ap.parse_args(argv)
    t0 = time.perf_counter()
    rows = [r for name in MODELS for r in model_rows(name)]
    result = dict(
        models={n: dict(breadth=b, alpha=a) for n, (b, a) in MODELS.items()},
        length=L,
        draft=T,
        k_yy=K_YY,
        rho=RHO,
        g=G,
        z_g=Z_G,
        rows=rows,
        command="python benchmarks/strip_wigley.py --capytaine",
    )
    if args.capytaine:
        result["panel"] = panel_rows()
        for r in result["panel"]:
            print(
                f"ω√(L/g) {r['omega_nd']:5.2f} A{r['coefficient']} strip "
                f"{r['strip_added_mass']:8.2f} panel {r['panel_added_mass']:8.2f}   "
                f"B{r['coefficient']} strip {r['strip_damping']:8.2f} panel {r['panel_damping']:8.2f}"
            )
    path = Path(args.json)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(result, indent=1) + "\n")
    print(f"{'model':5} {'Fn':>4} {'λ/L':>5} {'heave':>6} {'pitch':>6} {'GB':>7} {'Maruo':>7}")
    for r in rows:
        print(
            f"{r['model']:5} {r['froude']:4.1f} {r['lambda_over_l']:5.2f} {r['heave']:6.3f} "
            f"{r['pitch']:6.3f} {r['raw_gerritsma_beukelman']:7.2f} {r['raw_maruo']:7.2f}"
            + ("" if r["valid"] else "  (invalid)")
        )
    print(f"{len(rows)} rows in {time.perf_counter() - t0:.0f} s")


if __name__ == "__main__":
    main()
