"""Mesh convergence of the panel-method drift of Barge 1 and near-field vs far-field agreement
(thesis appendix B.1, fig. B.1; issue: FF ≈ NF on a converged mesh, error per zone).

    python benchmarks/bem_convergence.py [--sizes 2 1.5 1] [--out bench_out/bem] [--n-omega 12]

Needs the extra (pip install 'jaxtow[bem]'). Barge 1 (76.2 × 24.4 × 5 m box, CoG 10 m above
the keel), headings 0, 15 (the thesis's ψ = 15°) and 90 deg, frequencies 0.3-2.1 rad/s. Writes
convergence.nc, convergence.json and fig_B1_convergence.png, and prints the relative MSE
(E = Σ(F − F_ref)² / Σ F_ref²) per zone: each mesh's near field against its own far field,
and each mesh against the finest mesh's far field. Wall time on 2 cores: about 10 min with
1 m as the finest size (roughly 30 s per frequency at 1 m).
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

import numpy as np


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=float, nargs="+", default=[2.0, 1.5, 1.0])
    ap.add_argument("--n-omega", type=int, default=12)
    ap.add_argument("--out", default="bench_out/bem")
    ap.add_argument("--cache", default=None, help="cache directory (default OUT/cache)")
    args = ap.parse_args(argv)

    from jaxtow import bem
    from jaxtow.plotting.bem import plot_mesh_convergence

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    omega = np.linspace(0.3, 2.1, args.n_omega)
    beta = np.radians([0.0, 15.0, 90.0])
    t0 = time.perf_counter()
    runs, summary = bem.mesh_convergence(
        lambda p: bem.box_barge_mesh(panel_size=p),
        args.sizes,
        omega,
        beta,
        cache_dir=args.cache or out / "cache",
        progress=True,
    )
    wall = time.perf_counter() - t0
    summary.to_netcdf(out / "convergence.nc")
    rep = {
        "wall_s": wall,
        "omega": omega.tolist(),
        "beta_deg": [0, 15, 90],
        "panel_size": [],
        "n_panels": [],
    }
    for p in summary.panel_size.values:
        rep["panel_size"].append(float(p))
        rep["n_panels"].append(int(summary.n_panels.sel(panel_size=p)))
        for c in ("fx", "fy"):
            nv = summary.near_vs_far.sel(panel_size=p, component=c)
            rep.setdefault(f"near_vs_far_{c}", []).append(
                {z: float(nv.sel(zone=z)) for z in summary.zone.values}
            )
    (out / "convergence.json").write_text(json.dumps(rep, indent=1))
    plot_mesh_convergence(summary, runs).savefig(out / "fig_B1_convergence.png", dpi=120)
    print(f"wall {wall:.0f} s")
    for c in ("fx", "fy"):
        print(f"near field vs far field, {c} (relative MSE per zone):")
        for p, row in zip(rep["panel_size"], rep[f"near_vs_far_{c}"]):
            print(f"  {p:5.2f} m: " + "  ".join(f"{z} {v:.2e}" for z, v in row.items()))
    return rep


if __name__ == "__main__":
    main()
