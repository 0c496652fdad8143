"""``jaxtow calm``: the calm-water towing-stability study (thesis section 6.1)."""

from __future__ import annotations

import json
from pathlib import Path

import msgspec

import jaxtow as jt

from ._common import (
    grid_option,
    model_options,
    parse_sets,
    positive_int,
    time_domain_options,
    time_domain_settings,
    tow_model,
    tow_names,
    tow_option,
    write_time_domain,
)


def cmd_calm(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sets = parse_sets(args.set)
    models = {}
    for name in tow_names(args, "calm"):
        model, vname = tow_model(args, name, sets, "calm")
        models[vname] = model
    td = None if args.no_time_domain else time_domain_settings(args)
    try:
        study = jt.studies.calm_study(
            models,
            xp_grid=grid_option(args.xp_grid, "xp-grid"),
            l0_grid=grid_option(args.l0_grid, "l0-grid"),
            map_xp=grid_option(args.map_xp, "map-xp"),
            map_l0=grid_option(args.map_l0, "map-l0"),
            chunk_size=args.chunk_size,
            progress=not args.quiet,
            time_domain=td,
        )
    except ValueError as e:
        raise SystemExit(f"jaxtow calm: error: {e}") from None
    for vname, model in models.items():
        ds = study.datasets[vname]
        for tag, d in ds.items():
            jt.io.save_dataset(d, out / f"{vname}_{tag}.nc")
        line = model.towline
        jt.plotting.save(
            jt.plotting.plot_equilibria_vs(
                ds["equilibria_vs_xp"],
                "xp",
                title=f"{model.vessel.name}: equilibria (fig. 6.3), l0'={float(line.l0):g}",
            ),
            out / f"{vname}_equilibria_vs_xp.png",
        )
        jt.plotting.save(
            jt.plotting.plot_max_real_vs(
                ds["max_real_vs_l0"],
                "l0",
                title=f"{model.vessel.name}: max Re(lambda), xp'={float(line.xp):g} (fig. 6.4)",
            ),
            out / f"{vname}_max_real_vs_l0.png",
        )
        jt.plotting.save(
            jt.plotting.plot_stability_map(ds["map_xp_l0"], "xp", "l0"),
            out / f"{vname}_map_xp_l0.png",
        )
        if vname in study.runs:
            write_time_domain(model, vname, study.runs[vname], args, out)
    records = {k: msgspec.to_builtins(r) for k, r in study.records.items()}
    jt.io.write_file(out / "summary.json", json.dumps(records, indent=2))
    for vname, r in study.records.items():
        print(
            f"{vname}: c = {r.stability_coefficient_c:+.4f} ({'course stable' if r.course_stable else 'course unstable'})"
        )
        for e in r.design.equilibria:
            print(
                f"   psi = {e.psi_deg:+8.3f} deg   max Re(lambda) = {e.max_real_nd:+.5f}   {e.stability}"
            )
        lo, hi = r.straight_max_real_range_over_l0
        print(f"   straight behind, max Re(lambda) over l0' grid: [{lo:+.4f}, {hi:+.4f}]")
    print("note: draft, added masses and EA' are documented estimates (jaxtow.ASSUMPTIONS)")
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
