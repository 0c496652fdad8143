"""``jaxtow calm``: the calm-water towing-stability study (thesis section 6.1)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import jaxtow as jt

from ..io._atomic import write_file
from ._common import (
    grid_option,
    model_options,
    parse_sets,
    positive_int,
    run_time_domain,
    time_domain_options,
    tow_model,
    tow_names,
    tow_option,
)


def cmd_calm(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sets = parse_sets(args.set)
    summary = {}
    opts = dict(method="numerical", progress=not args.quiet, chunk_size=args.chunk_size)
    for name in tow_names(args, "calm"):
        model, vname = tow_model(args, name, sets, "calm")
        c = float(model.vessel.stability_coefficient())
        ds_xp = jt.sweep(model, {"xp": grid_option(args.xp_grid, "xp-grid")}, **opts)
        ds_l0 = jt.sweep(model, {"l0": grid_option(args.l0_grid, "l0-grid")}, **opts)
        ds_map = jt.sweep(
            model,
            {"xp": grid_option(args.map_xp, "map-xp"), "l0": grid_option(args.map_l0, "map-l0")},
            **opts,
        )
        for tag, ds in (
            ("equilibria_vs_xp", ds_xp),
            ("max_real_vs_l0", ds_l0),
            ("map_xp_l0", ds_map),
        ):
            jt.io.save_dataset(ds, out / f"{vname}_{tag}.nc")
        jt.plotting.save(
            jt.plotting.plot_equilibria_vs(
                ds_xp,
                "xp",
                title=f"{model.vessel.name}: equilibria (fig. 6.3), l0'={float(model.towline.l0):g}",
            ),
            out / f"{vname}_equilibria_vs_xp.png",
        )
        jt.plotting.save(
            jt.plotting.plot_max_real_vs(
                ds_l0,
                "l0",
                title=f"{model.vessel.name}: max Re(lambda), xp'={float(model.towline.xp):g} (fig. 6.4)",
            ),
            out / f"{vname}_max_real_vs_l0.png",
        )
        jt.plotting.save(
            jt.plotting.plot_stability_map(ds_map, "xp", "l0"), out / f"{vname}_map_xp_l0.png"
        )
        # Summary numbers at the configured (xp, l0).
        eqs = jt.equilibria(model)
        st = jt.stability(model, eqs.state)
        straight = (
            ds_l0["max_real"].where(ds_l0["valid"] & (ds_l0["branch"] == 0)).max("equilibrium")
        )
        summary[vname] = dict(
            stability_coefficient_c=c,
            course_stable=c > 0,
            xp=float(model.towline.xp),
            l0=float(model.towline.l0),
            EA=float(model.towline.EA),  # pyright: ignore[reportAttributeAccessIssue]
            equilibria_psi_deg=[float(np.degrees(p)) for p in eqs.psi],
            equilibria_max_real=[float(v) for v in st.max_real],
            equilibria_stability=[jt.STABILITY_LABELS[int(s)] for s in st.stability],
            straight_behind_max_real_range_over_l0=[float(straight.min()), float(straight.max())],
            assumed_values=dict(model.assumed),
        )
        if not args.no_time_domain:
            summary[vname]["time_domain"] = run_time_domain(model, vname, args, out)
    write_file(out / "summary.json", json.dumps(summary, indent=2, default=float))
    for vname, s in summary.items():
        print(
            f"{vname}: c = {s['stability_coefficient_c']:+.4f} ({'course stable' if s['course_stable'] else 'course unstable'})"
        )
        for p, mr, lab in zip(
            s["equilibria_psi_deg"], s["equilibria_max_real"], s["equilibria_stability"]
        ):
            print(f"   psi = {p:+8.3f} deg   max Re(lambda) = {mr:+.5f}   {lab}")
        lo, hi = s["straight_behind_max_real_range_over_l0"]
        print(f"   straight behind, max Re(lambda) over l0' grid: [{lo:+.4f}, {hi:+.4f}]")
    print("note: draft, added masses and EA' are documented estimates (jaxtow.presets.ASSUMPTIONS)")
    print(f"wrote figures, NetCDF datasets and summary.json to {out}")


def add_parser(sub):
    c = sub.add_parser("calm", help="reproduce the without-waves stability study (thesis 6.1)")
    c.add_argument("--out", default="results", help="output folder (default: results)")
    tow_option(c, multiple=True, default=("barge2a", "barge2b"))
    c.add_argument(
        "--xp-grid",
        nargs=3,
        default=(0.0, 0.6, 121),
        metavar=("LO", "HI", "N"),
        help="x_p' grid for the equilibria figure (default 0 0.6 121)",
    )
    c.add_argument(
        "--l0-grid",
        nargs=3,
        default=(0.2, 2.5, 116),
        metavar=("LO", "HI", "N"),
        help="l0' grid for the max Re(lambda) figure (default 0.2 2.5 116)",
    )
    c.add_argument("--map-xp", nargs=3, default=(0.0, 0.6, 61), metavar=("LO", "HI", "N"))
    c.add_argument("--map-l0", nargs=3, default=(0.2, 2.5, 47), metavar=("LO", "HI", "N"))
    c.add_argument(
        "--chunk-size", type=positive_int, default=16384, help="points per vmapped chunk"
    )
    c.add_argument("--quiet", action="store_true", help="no progress bar")
    c.add_argument(
        "--no-time-domain",
        action="store_true",
        help="skip the runs from the thesis's initial condition (figs 6.5-6.7)",
    )
    time_domain_options(c)
    model_options(c)
    c.set_defaults(func=cmd_calm)
