"""``jaxtow drift``: the waterline drift-method comparison of thesis chapters 4-5."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from ..io._atomic import write_file
from ._common import _tow_option, positive_int

SWAY_METHODS = ("faltinsen", "liu", "fujii_takahashi", "kuroda", "kashiwagi")


def _waterline(args):
    """The waterline of ``--waterline FILE`` or of the tow (``--tow``; ``--draft`` overrides
    its draft)."""
    import jaxtow as jt

    from ._common import _tow_names
    from .tow import load_tow

    if args.waterline:
        return jt.io.read_waterline(args.waterline, draft=args.draft or 5.0)
    name = _tow_names(args, "drift")[0]
    tow = load_tow(name, "drift")
    if args.draft is None:
        return tow.waterline
    spec = tow.resolved["hull"]["waterline"]
    if spec == "box":
        return jt.presets.box_waterline(
            tow.scales.length, tow.resolved["vessel"]["breadth"], args.draft
        )
    if spec == "barge2":
        return jt.presets.barge2_waterline(draft=args.draft)
    return jt.io.read_waterline(spec, draft=args.draft)


def _zone_mse(ds, component, base):
    import jaxtow as jt

    b = ds[component].sel({"method": base}).values
    return {
        m: jt.drift.relative_mse_by_zone(
            ds[component].sel({"method": m}).values, b, ds.omega.values, float(ds.attrs["length"])
        )
        for m in ds.method.values
        if m != base
    }


def cmd_drift(args):
    import jax
    import jax.numpy as jnp

    import jaxtow as jt

    from .._units import RHO_SEA, G
    from ..io import drift_methods_dataset, save_dataset
    from ..plotting.calm import save
    from ..plotting.drift import plot_drift_methods, plot_irregular_methods

    if args.base not in jt.drift.METHODS:
        raise SystemExit(
            f"error: --base {args.base!r} is not a drift method; choose from {sorted(jt.drift.METHODS)}"
        )
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    wl = _waterline(args)
    L, B = float(wl.length), float(wl.breadth)
    omega = jnp.linspace(0.2, args.omega_max, args.n_omega)
    b_sway = math.radians(args.sway_heading)
    opts = {"faltinsen": {"speed_factor": (2.0, 2.0)}}
    summary = dict(
        waterline=wl.name,
        length=L,
        breadth=B,
        draft=float(wl.draft),
        block_coefficient=float(wl.block_coefficient),
        base=args.base,
        assumptions="Barge 2 rake and drafts: jaxtow.presets.ASSUMPTIONS; garbled formulas: "
        "see jaxtow.drift.METHODS docstrings",
    )

    # stationary, regular waves (figs 4.3, 4.4)
    est0 = jt.drift.compare_methods(wl, omega, 0.0, options=opts)
    ds0 = drift_methods_dataset(est0, omega, beta=0.0, waterline=wl, base=args.base)
    est_s = jt.drift.compare_methods(wl, omega, b_sway, methods=SWAY_METHODS, options=opts)
    ds_s = drift_methods_dataset(est_s, omega, beta=b_sway, waterline=wl, base=args.base)
    save_dataset(ds0, out / "stationary_head_seas.nc")
    save_dataset(ds_s, out / "stationary_oblique.nc")
    save(
        plot_drift_methods(ds0, "fx", title=f"{wl.name}: stationary surge, beta = 0 (fig. 4.3)"),
        out / "fig4_3_stationary_surge.png",
    )
    save(
        plot_drift_methods(
            ds_s,
            "fy",
            title=f"{wl.name}: stationary sway, beta = {args.sway_heading:g} deg (fig. 4.4)",
        ),
        out / "fig4_4_stationary_sway.png",
    )
    summary["regular_relative_mse_by_zone"] = dict(
        surge=_zone_mse(ds0, "fx", args.base), sway=_zone_mse(ds_s, "fy", args.base)
    )

    # stationary, irregular seas over Tp (figs 4.5, 4.6): survival sea state Hs = 5 m
    hs = args.hs
    tp = jnp.linspace(4.0, 16.0, 61)
    tp_lo, tp_hi = (float(t) for t in jt.waves.physical_tp_range(hs))
    irr = {}
    for name in jt.drift.METHODS:
        f = jax.jit(
            jax.vmap(
                lambda t, b, n=name: jt.drift.irregular_drift(n, wl, hs, t, b, **opts.get(n, {})),
                in_axes=(0, None),
            )
        )
        irr[name] = (np.asarray(f(tp, 0.0)), np.asarray(f(tp, b_sway)))
    norm_x = RHO_SEA * G * B * hs**2 / 8
    norm_y = RHO_SEA * G * L * hs**2 / 8
    save(
        plot_irregular_methods(
            np.asarray(tp),
            {k: v[0] for k, v in irr.items()},
            hs,
            0,
            norm_x,
            (tp_lo, tp_hi),
            title=f"{wl.name}: stationary surge in JONSWAP, Hs = {hs} m, beta = 0 (fig. 4.5)",
            ylabel="Fx / (rho g B Hs^2/8)",
        ),
        out / "fig4_5_irregular_surge.png",
    )
    save(
        plot_irregular_methods(
            np.asarray(tp),
            {k: irr[k][1] for k in SWAY_METHODS},
            hs,
            1,
            norm_y,
            (tp_lo, tp_hi),
            title=f"{wl.name}: stationary sway in JONSWAP, Hs = {hs} m (fig. 4.6)",
            ylabel="Fy / (rho g L Hs^2/8)",
        ),
        out / "fig4_6_irregular_sway.png",
    )
    phys = (np.asarray(tp) >= tp_lo) & (np.asarray(tp) <= tp_hi)
    base_irr = irr[args.base]
    summary["irregular_relative_mse_physical_tp"] = {
        m: dict(
            surge=jt.drift.relative_mse(v[0][:, 0], base_irr[0][:, 0], phys),
            sway=(
                jt.drift.relative_mse(v[1][:, 1], base_irr[1][:, 1], phys)
                if m in SWAY_METHODS
                else None
            ),
        )
        for m, v in irr.items()
        if m != args.base
    }
    summary["physical_tp_range"] = [tp_lo, tp_hi]

    # sailing (figs 5.6, 5.7): surge speeds in head seas, sway speeds at the oblique heading
    import matplotlib.pyplot as plt

    sail = dict(opts)
    sail["faltinsen_thesis"] = {"speed_factor": (4.0, 2.0)}
    for tag, comp, beta, speeds, fig in (
        ("surge", "fx", 0.0, args.speeds, "fig5_6_sailing_surge.png"),
        ("sway", "fy", b_sway, args.speeds, "fig5_7_sailing_sway.png"),
    ):
        fig_, axes = plt.subplots(2, 3, figsize=(13, 7), sharex=True)
        for ax, name in zip(axes.ravel(), ["faltinsen", "faltinsen_thesis", *SWAY_METHODS[1:]]):
            fn = jt.drift.METHODS["faltinsen" if name == "faltinsen_thesis" else name]
            dss = []
            for s in speeds:
                uv = (s, 0.0) if tag == "surge" else (0.0, s)
                e = fn(wl, omega, beta, *uv, **sail.get(name, {}))
                dss.append(
                    drift_methods_dataset(
                        {name: e}, omega, beta=beta, u=uv[0], v=uv[1], waterline=wl
                    )
                )
            plot_drift_methods(
                dss,
                comp,
                ax=ax,
                labels=[f"{'u' if tag == 'surge' else 'v'} = {s:g} m/s" for s in speeds],
                title=name,
            )
        fig_.suptitle(
            f"{wl.name}: sailing {tag}, beta = {math.degrees(beta):g} deg (figs 5.6/5.7)",
            fontsize=10,
        )
        save(axes[0, 0], out / fig)

    write_file(out / "summary.json", json.dumps(summary, indent=2, default=float))
    print(
        f"{wl.name}: L = {L:g} m, B = {B:g} m, T = {float(wl.draft):g} m, C_B = {float(wl.block_coefficient):.3f}"
    )
    print(f"relative MSE against {args.base!r} (regular waves, surge beta = 0) per zone:")
    print(f"  {'method':18s} {'motion':>10s} {'transition':>11s} {'reflection':>11s}")
    for m, z in summary["regular_relative_mse_by_zone"]["surge"].items():
        cells = [
            f"{z[k]:10.3g}" if z[k] is not None else f"{'-':>10s}"
            for k in ("motion", "transition", "reflection")
        ]
        print(f"  {m:18s} {cells[0]} {cells[1]:>11s} {cells[2]:>11s}")
    print(f"wrote figures, NetCDF datasets and summary.json to {out}")


def add_parser(sub):
    d = sub.add_parser("drift", help="compare the waterline drift methods (thesis chapters 4-5)")
    _tow_option(d, default=("barge1",))
    d.add_argument(
        "--waterline", help="half-waterline text file instead (see jaxtow.io.read_waterline)"
    )
    d.add_argument(
        "--draft",
        type=float,
        default=None,
        help="draft [m] (default: the documented 5.0 m estimate)",
    )
    d.add_argument(
        "--base", default="faltinsen", help="base method for the relative MSE (default faltinsen)"
    )
    d.add_argument(
        "--sway-heading", type=float, default=-15.0, help="heading for the sway figures [deg]"
    )
    d.add_argument(
        "--hs", type=float, default=5.0, help="Hs of the irregular comparison [m] (default 5)"
    )
    d.add_argument(
        "--speeds", type=float, nargs="+", default=[0.0, 1.0, 2.0, 3.0], help="speeds [m/s]"
    )
    d.add_argument(
        "--omega-max", type=float, default=2.1, help="highest wave frequency [rad/s] (default 2.1)"
    )
    d.add_argument(
        "--n-omega",
        type=positive_int,
        default=191,
        help="frequencies from 0.2 rad/s to --omega-max",
    )
    d.add_argument("--out", default="results/drift", help="output folder")
    d.set_defaults(func=cmd_drift)
