"""``jaxtow map``: any sweep over named parameters, to NetCDF and a figure."""

from __future__ import annotations

import shutil
from pathlib import Path

import jaxtow as jt

from ._common import grid_option, model_options, parse_sets, positive_int, tow_model, tow_option


def cmd_map(args):
    if not args.param:
        raise SystemExit("error: give at least one --param NAME LO HI N")
    model, tow_name = tow_model(args, overrides=parse_sets(args.set))
    grid = {}
    for name, lo, hi, n in args.param:
        grid[name] = grid_option((lo, hi, n), f"param {name}")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    stem = tow_name + "_" + "_".join(grid)
    # finished chunks are kept here while the sweep runs: an interrupted map resumes
    checkpoint = out / f".{stem}.chunks"

    def run():
        return jt.sweep(
            model,
            grid,
            method=args.method,
            progress=not args.quiet,
            chunk_size=args.chunk_size,
            max_roots=args.max_roots,
            eigenvalues=args.eigenvalues,
            checkpoint=checkpoint,
        )

    try:
        try:
            ds = run()
        except ValueError as e:
            if "chunks of another sweep" not in str(e):
                raise
            shutil.rmtree(checkpoint)  # left by an interrupted run of another map: start anew
            ds = run()
    except ValueError as e:
        raise SystemExit(f"error: {e}") from None
    jt.io.save_dataset(ds, out / f"{stem}.nc")
    shutil.rmtree(checkpoint, ignore_errors=True)
    names = list(grid)
    if len(names) == 1:
        jt.plotting.save(
            jt.plotting.plot_equilibria_vs(ds, names[0]), out / f"{stem}_equilibria.png"
        )
        jt.plotting.save(jt.plotting.plot_max_real_vs(ds, names[0]), out / f"{stem}_max_real.png")
    elif len(names) == 2:
        jt.plotting.save(
            jt.plotting.plot_stability_map(ds, names[0], names[1]), out / f"{stem}_map.png"
        )
    n_unstable = int(((ds["stability"] == 1) & ds["valid"]).sum())
    print(f"{ds.sizes}: {n_unstable} unstable equilibria; wrote {out / (stem + '.nc')}")


def add_parser(sub):
    m = sub.add_parser("map", help="sweep any parameters; NetCDF + figure")
    tow_option(m)
    m.add_argument(
        "--param",
        nargs=4,
        action="append",
        metavar=("NAME", "LO", "HI", "N"),
        help="swept parameter and its grid, e.g. --param l0 0.2 2.5 100 (repeatable)",
    )
    m.add_argument(
        "--eigenvalues",
        action="store_true",
        help="store every eigenvalue (eig_real, eig_imag; LAPACK) besides max Re λ "
        "(default: max Re λ alone, by the faster pure-JAX spectral abscissa)",
    )
    m.add_argument(
        "--method",
        choices=("numerical", "analytic"),
        default="numerical",
        help="equilibrium solver (analytic: calm water, elastic line only)",
    )
    m.add_argument("--max-roots", type=positive_int, default=4, help="equilibrium slots per point")
    m.add_argument("--out", default="results", help="output folder")
    m.add_argument(
        "--chunk-size", type=positive_int, default=16384, help="points per vmapped chunk"
    )
    m.add_argument("--quiet", action="store_true", help="no progress bar")
    model_options(m)
    m.set_defaults(func=cmd_map)
