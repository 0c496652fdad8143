"""``jaxtow report waves --out DIR``: towing stability in waves (thesis chapters 6.2-6.3, 7.2.2):
stability and equilibrium maps, time-domain runs and ``claims.json`` checking the thesis's
claims, each with its numbers and reproduced yes/no."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from .. import reports as W


def _map(model, grid, progress, n_grid):
    from .._sweep import sweep

    return sweep(
        model,
        grid,
        n_grid=n_grid,
        max_roots=4,
        routh_hurwitz=False,
        progress=progress,
        specialise=True,
    )


def _straight(ds, field="max_real"):
    from ..study import nearest_straight

    return nearest_straight({k: ds[k].values for k in ("valid", "psi", field)}, field)


def _invalid(ds):
    """Where the equilibrium nearest straight behind is outside the physics' validity."""
    return _straight(ds, "physics_valid") == 0.0


def _validity_share(ds) -> dict:
    """Share of the map points (with a straight-behind equilibrium) that meet each flag."""
    out = {}
    for k in ds.data_vars:
        if (k.startswith("validity_") and ds[k].dtype == bool) or k == "physics_valid":
            v = _straight(ds, k)
            has = np.isfinite(v)
            out[k.removeprefix("validity_")] = float(np.mean(v[has] == 1.0)) if has.any() else None
    return out


def cmd_report(args):

    from .. import presets
    from .._metrics import fishtail_metrics
    from .._simulate import initial_state, simulate
    from ..io import save_dataset
    from ..plotting.calm import save
    from ..plotting.waves_report import (
        plot_count_map,
        plot_heading_map,
        plot_max_real_map,
        plot_runs,
        plot_with_without,
    )
    from ..study import (
        APPROXIMATE_QTF,
        approximate_qtf,
        barge2_irregular_model,
        barge2_wave_model,
        valid_count,
    )
    from ..waves import physical_tp_range

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    progress = not args.quiet
    if args.qtf:
        from .resistance import _qtf

        qtf, source = _qtf(args.qtf), f"QTF file {args.qtf}"
    else:
        qtf, source = approximate_qtf(), APPROXIMATE_QTF

    za, n, form = args.zeta_a, args.n, args.form
    l0 = np.linspace(0.3, 3.0, n)
    omega = np.linspace(0.3, 2.0, n)
    claims: list = []
    summary: dict = dict(
        drift_source=source,
        zeta_a=za,
        u_tug=presets.U_TUG_DEFAULT,
        xp=0.5,
        sailing_form=form,
        assumptions={k: v["note"] for k, v in presets.ASSUMPTIONS.items()},
    )
    attrs = dict(drift_source=source, sailing_form=form)
    validity = summary.setdefault("validity_share", {})

    # --- (l0', omega) stability maps, with the calm reference (figs 6.17-6.19) -------------
    maps, calm = {}, {}
    for v in ("2a", "2b"):
        m = barge2_wave_model(v, omega=1.0, zeta_a=za, qtf=qtf, form=form)
        ds = _map(m, {"l0": l0, "external.omega": omega}, progress, args.n_grid).assign_attrs(attrs)
        save_dataset(ds, out / f"barge_{v}_map_l0_omega.nc")
        maps[v] = _straight(ds)
        validity[f"barge_{v}_map_l0_omega"] = _validity_share(ds)
        cds = _map(m.__class__(vessel=m.vessel, towline=m.towline), {"l0": l0}, False, args.n_grid)
        calm[v] = _straight(cds)
        save(
            plot_max_real_map(
                l0,
                omega,
                maps[v],
                title=f"Barge {v}: max Re lambda, straight behind, "
                f"zeta_a = {za} m (figs 6.17-6.19)",
                note=source,
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_map_l0_omega.png",
        )
    for v in ("2a", "2b"):
        picks = {
            f"omega = {omega[k]:.2f} rad/s": maps[v][:, k]
            for k in sorted({int(np.argmin(np.abs(omega - w))) for w in (0.5, 0.8, 1.0, 1.5)})
        }
        save(
            plot_with_without(
                l0,
                calm[v],
                picks,
                title=f"Barge {v}: with and without waves, zeta_a = {za} m (figs 6.27-6.28)",
                note=source,
            ),
            out / f"barge_{v}_with_without_waves.png",
        )
    claims.append(
        W.low_frequency_waves_keep_calm_verdict(maps["2a"], calm["2a"], omega, source=source)
    )
    claims.append(W.moderate_waves_stabilise_2a(maps["2a"], omega, source=source))
    claims.append(W.barge_2b_stays_stable(maps["2b"], calm["2b"], source=source))

    # --- equilibria over (zeta_a, omega) (figs 6.13-6.16, position count) ---------------------
    zs = np.linspace(0.05, 2.5, max(n // 2, 6))
    extra = {}
    for v in ("2a", "2b"):
        m = barge2_wave_model(v, omega=1.0, zeta_a=za, qtf=qtf, form=form)
        ds = _map(
            m, {"external.zeta_a": zs, "external.omega": omega}, progress, args.n_grid
        ).assign_attrs(attrs)
        save_dataset(ds, out / f"barge_{v}_equilibria_zeta_omega.nc")
        cnt = valid_count({k: ds[k].values for k in ("valid",)})
        c0 = int(
            valid_count(
                {
                    "valid": _map(
                        m.__class__(vessel=m.vessel, towline=m.towline),
                        {"l0": [2.5]},
                        False,
                        args.n_grid,
                    )["valid"].values
                }
            )[0]
        )
        extra[v] = dict(
            calm_count=c0, max_count_below_0_8=int(cnt[zs < 0.8].max()), max_count=int(cnt.max())
        )
        save(
            plot_count_map(
                zs,
                omega,
                cnt,
                title=f"Barge {v}: number of equilibria, l0' = 2.5 (calm: {c0})",
                note=source,
            ),
            out / f"barge_{v}_equilibria_zeta_omega.png",
        )
        save(
            plot_heading_map(
                zs,
                omega,
                _straight(ds, "psi"),
                "zeta_a [m]",
                title=f"Barge {v}: heading of the equilibrium nearest straight behind",
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_heading_zeta_omega.png",
        )
    claims.append(W.small_waves_add_no_equilibria(extra, source=source))

    # --- tug speed: (U_tug, omega) maps of heading and max Re lambda at l0' = 2.5 -----------
    speeds = np.linspace(1.0, 3.0, max(n // 2, 6))
    for v in ("2a", "2b"):
        m = barge2_wave_model(v, l0=2.5, omega=1.0, zeta_a=za, qtf=qtf, form=form)
        ds = _map(m, {"u_tug": speeds, "external.omega": omega}, progress, args.n_grid)
        ds = ds.assign_attrs(attrs)
        save_dataset(ds, out / f"barge_{v}_map_utug_omega.nc")
        validity[f"barge_{v}_map_utug_omega"] = _validity_share(ds)
        save(
            plot_max_real_map(
                speeds,
                omega,
                _straight(ds),
                xlabel="U_tug [m/s]",
                title=f"Barge {v}: max Re lambda over tug speed, l0' = 2.5, zeta_a = {za} m",
                note=source,
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_map_utug_omega.png",
        )
        save(
            plot_heading_map(
                speeds,
                omega,
                _straight(ds, "psi"),
                "U_tug [m/s]",
                title=f"Barge {v}: heading nearest straight behind over tug speed",
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_heading_utug_omega.png",
        )

    # --- heading over (xp', omega) (fig. 6.13) ------------------------------------------------
    xps = np.linspace(0.05, 1.0, n)
    ds = _map(
        barge2_wave_model("2a", omega=1.0, zeta_a=za, qtf=qtf, form=form),
        {"xp": xps, "external.omega": omega},
        progress,
        args.n_grid,
    ).assign_attrs(attrs)
    save_dataset(ds, out / "barge_2a_equilibria_xp_omega.nc")
    save(
        plot_heading_map(
            xps,
            omega,
            _straight(ds, "psi"),
            "x_p' [-]",
            title=f"Barge 2a: heading nearest straight behind, zeta_a = {za} m (fig. 6.13)",
        ),
        out / "barge_2a_heading_xp_omega.png",
    )

    # --- irregular seas: (l0', Tp) over the physical range (fig. 6.26) -----------------------
    lo, hi = (float(t) for t in physical_tp_range(args.hs))
    tps = np.linspace(lo, hi, max(n // 2, 6))
    irr = {}
    for v in ("2a", "2b"):
        m = barge2_irregular_model(v, hs=args.hs, tp=0.5 * (lo + hi), qtf=qtf, form=form)
        ds = _map(m, {"l0": l0, "external.spectrum.tp": tps}, progress, args.n_grid).assign_attrs(
            attrs
        )
        save_dataset(ds, out / f"barge_{v}_map_l0_tp.nc")
        irr[v] = _straight(ds)
        validity[f"barge_{v}_map_l0_tp"] = _validity_share(ds)
        save(
            plot_max_real_map(
                l0,
                tps,
                irr[v],
                ylabel="Tp [s]",
                title=f"Barge {v}: max Re lambda, Hs = {args.hs} m (fig. 6.26)",
                note=source,
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_map_l0_tp.png",
        )
    ds = _map(
        barge2_irregular_model("2a", hs=args.hs, tp=0.5 * (lo + hi), qtf=qtf, form=form),
        {"xp": xps, "external.spectrum.tp": tps},
        progress,
        args.n_grid,
    ).assign_attrs(attrs)
    save_dataset(ds, out / "barge_2a_equilibria_xp_tp.nc")
    save(
        plot_heading_map(
            xps,
            tps,
            _straight(ds, "psi"),
            "x_p' [-]",
            ylabel="Tp [s]",
            title=f"Barge 2a: heading nearest straight behind, Hs = {args.hs} m (fig. 6.23)",
        ),
        out / "barge_2a_heading_xp_tp.png",
    )
    claims.append(W.irregular_sea_keeps_2a_stable(irr["2a"], args.hs, (lo, hi), source=source))

    # --- time domain: path widths (figs 6.20-6.22, 7.5) and linear agreement ------------------
    runs, widths = {}, {}
    for tag, w in (("calm", None), ("omega_1.0", 1.0), ("omega_1.5", 1.5)):
        m = barge2_wave_model(
            "2a", l0=2.5, omega=w or 1.0, zeta_a=za if w else 0.0, qtf=qtf, form=form
        )
        sim = simulate(m, initial_state(m, psi0=0.2, y0=0.1), t1=args.t1, n_save=2001)
        met = fishtail_metrics(m, sim)
        runs[tag], widths[tag] = (m, sim), float(met["path_width"])
    from ..forces._wind import WindForce
    from ..presets import barge2_resistance

    extra_runs = {
        f"irregular Hs = {args.hs} m, Tp = 7 s": barge2_irregular_model(
            "2a", l0=2.5, hs=args.hs, tp=7.0, qtf=qtf, form=form
        ),
        f"wind {args.wind:g} m/s (ILLUSTRATIVE table)": barge2_wave_model(
            "2a",
            l0=2.5,
            zeta_a=0.0,
            qtf=qtf,
            wind=WindForce(
                load=barge2_resistance().wind, speed=args.wind, scales=presets.barge2_scales()
            ),
        ),
    }
    for tag, m in extra_runs.items():
        sim = simulate(m, initial_state(m, psi0=0.2, y0=0.1), t1=args.t1, n_save=2001)
        runs[tag], widths[tag] = (m, sim), float(fishtail_metrics(m, sim)["path_width"])
    save(
        plot_runs(runs, title=f"Barge 2a, l0' = 2.5, zeta_a = {za} m (figs 6.20-6.22, 7.5)"),
        out / "barge_2a_time_domain.png",
    )
    wind_tag = f"wind {args.wind:g} m/s (ILLUSTRATIVE table)"
    claims.append(W.waves_reduce_path_width(widths, source=source))
    claims.append(W.path_widths_match_thesis(widths, source=source))
    claims.append(W.head_wind_reduces_path_width(widths, wind_tag, args.wind, source=source))
    agree = _linear_agreement(maps, l0, omega, za, qtf, args)
    claims.append(W.time_domain_agrees_with_linear(agree, source=source))

    summary["claims"] = claims
    (out / "claims.json").write_text(json.dumps(claims, indent=2, default=float))
    (out / "summary.json").write_text(json.dumps(summary, indent=2, default=float))
    for c in claims:
        print(f"[{'yes' if c['reproduced'] else 'NO '}] {c['claim']}")
    print(f"drift forces: {source}")
    print(f"wrote figures, NetCDF datasets, claims.json and summary.json to {out}")


def _linear_agreement(maps, l0, omega, za, qtf, args, margin: float = 0.02, per_side: int = 4):
    """Simulate map points with |max Re λ| > margin (both signs) from a small disturbance of
    the straight-behind equilibrium; stable ⇔ the run converges."""

    from .._equilibrium import equilibria
    from .._metrics import fishtail_metrics
    from .._parameters import with_parameters
    from .._simulate import simulate
    from ..study import barge2_wave_model

    rng = np.random.default_rng(1)
    picks = []
    for sign in (-1, 1):
        ii, jj = np.nonzero(sign * maps["2a"] > margin)
        if ii.size:
            k = rng.choice(ii.size, size=min(per_side, ii.size), replace=False)
            picks += [(int(ii[q]), int(jj[q]), sign) for q in k]
    base = barge2_wave_model("2a", omega=1.0, zeta_a=za, qtf=qtf, form=args.form)
    rows, ok = [], 0
    for i, j, sign in picks:
        m = with_parameters(base, l0=float(l0[i]), **{"external.omega": float(omega[j])})
        e = equilibria(m)
        y = e.state[int(np.argmin(np.abs(np.asarray(e.psi))))]
        sim = simulate(m, y.at[5].add(math.radians(2.0)), t1=args.t1, n_save=1001)
        out = fishtail_metrics(m, sim)["outcome"]
        agrees = (out == "converged") == (sign < 0)
        ok += agrees
        rows.append(
            dict(
                l0=float(l0[i]),
                omega=float(omega[j]),
                max_real=float(maps["2a"][i, j]),
                outcome=out,
                agrees=bool(agrees),
            )
        )
    return dict(runs=len(rows), agree=ok, margin=margin, points=rows)


def add_parser(sub):
    r = sub.add_parser(
        "report", help="reproduce a thesis chapter into a folder (figures, NetCDF, claims.json)"
    )
    r.add_argument(
        "chapter",
        choices=("waves",),
        help="waves: towing stability in waves (thesis 6.2-6.3, 7.2.2)",
    )
    r.add_argument("--out", default="results/waves", help="output folder")
    r.add_argument(
        "--qtf",
        default=None,
        help="panel-method QTF file (.nc/.csv jaxtow, .8/.9 WAMIT); default: the "
        "documented Kashiwagi-waterline stand-in",
    )
    r.add_argument(
        "--zeta-a", type=float, default=1.25, help="regular-wave amplitude [m] (thesis: 1.25)"
    )
    r.add_argument(
        "--hs", type=float, default=2.4, help="Hs of the irregular sea [m] (thesis: 2.4)"
    )
    r.add_argument(
        "--n", type=int, default=41, help="points per map axis (41: a few minutes on 2 cores)"
    )
    r.add_argument(
        "--n-grid",
        type=int,
        default=401,
        help="heading-scan points over ±90 deg of the equilibrium search",
    )
    r.add_argument("--t1", type=float, default=400.0, help="time-domain run length [L/U]")
    r.add_argument(
        "--wind",
        type=float,
        default=10.0,
        help="head-wind speed of the wind run [m/s] (thesis: 10)",
    )
    r.add_argument(
        "--form",
        choices=("aranha", "linear", "thesis"),
        default="aranha",
        help="forward-speed form of the drift (jaxtow.drift.sailing_drift): Aranha's finite "
        "form (default), its linearisation, or the thesis's reading (counts the "
        "encounter-frequency shift twice)",
    )
    r.add_argument("--quiet", action="store_true", help="no progress bars")
    r.set_defaults(func=cmd_report)
