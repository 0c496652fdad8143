"""``jaxtow report waves --out DIR``: towing stability in waves and tow resistance (thesis
chapters 6.2-6.3 and 7): stability and equilibrium maps, time-domain runs (with the slowly
varying drift), ``claims.json`` / ``claims.md`` checking every thesis claim under each drift
source (the shipped panel near field, its far field, the stand-in) and each sailing-drift
form, and the attribution of every claim of the primary source and form that does not
reproduce (`jaxtow.studies.WaveStudy`, `jaxtow.studies.attribute`)."""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np

from ..io._atomic import write_file


def _straight(ds, field="max_real"):
    from .. import studies as W

    return W.straight(ds, field)


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


#: The drift sources of the claims table, and their short names.
SOURCES = ("near_field", "far_field", "standin")
SOURCE_NAMES = {
    "near_field": "panel near field",
    "far_field": "panel far field",
    "standin": "stand-in",
}


def _figures(study, out: Path, summary: dict, progress: bool) -> None:
    """Figures and NetCDF datasets of the primary study (drift source and form)."""
    from ..io import save_dataset
    from ..plotting.calm import save
    from ..plotting.waves_report import (
        plot_count_map,
        plot_heading_map,
        plot_max_real_map,
        plot_runs,
        plot_with_without,
    )
    from ..studies import valid_count

    src, za, ax = study.source, study.zeta_a, study.axes
    l0, omega, tps = ax["l0"], ax["omega"], ax["tp"]
    validity = summary.setdefault("validity_share", {})
    for v in ("2a", "2b"):
        ds = study.maps_l0_omega[v]
        save_dataset(ds, out / f"barge_{v}_map_l0_omega.nc")
        validity[f"barge_{v}_map_l0_omega"] = _validity_share(ds)
        save(
            plot_max_real_map(
                l0,
                omega,
                _straight(ds),
                title=f"Barge {v}: max Re lambda, straight behind, zeta_a = {za} m (figs 6.17-6.19)",
                note=src,
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_map_l0_omega.png",
        )
        mp = _straight(ds)
        picks = {
            f"omega = {omega[k]:.2f} rad/s": mp[:, k]
            for k in sorted({int(np.argmin(np.abs(omega - w))) for w in (0.5, 0.8, 1.0, 1.5)})
        }
        save(
            plot_with_without(
                l0,
                study.calm[v],
                picks,
                title=f"Barge {v}: with and without waves, zeta_a = {za} m (figs 6.27-6.28)",
                note=src,
            ),
            out / f"barge_{v}_with_without_waves.png",
        )
        ds = study.equilibria_zeta_omega[v]
        save_dataset(ds, out / f"barge_{v}_equilibria_zeta_omega.nc")
        save(
            plot_count_map(
                study.zeta_grid,
                omega,
                valid_count({"valid": ds["valid"].values}),
                title=f"Barge {v}: number of equilibria, l0' = 2.5 (calm: {study.calm_counts[v]})",
                note=src,
            ),
            out / f"barge_{v}_equilibria_zeta_omega.png",
        )
        save(
            plot_heading_map(
                study.zeta_grid,
                omega,
                _straight(ds, "psi"),
                "zeta_a [m]",
                title=f"Barge {v}: heading of the equilibrium nearest straight behind",
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_heading_zeta_omega.png",
        )
        ds = study.maps_l0_tp[v]
        save_dataset(ds, out / f"barge_{v}_map_l0_tp.nc")
        validity[f"barge_{v}_map_l0_tp"] = _validity_share(ds)
        save(
            plot_max_real_map(
                l0,
                tps,
                _straight(ds),
                ylabel="Tp [s]",
                title=f"Barge {v}: max Re lambda, Hs = {study.hs} m (fig. 6.26)",
                note=src,
                invalid=_invalid(ds),
            ),
            out / f"barge_{v}_map_l0_tp.png",
        )
        # tug speed: (U_tug, omega) maps of max Re lambda and heading at l0' = 2.5
        speeds = np.linspace(1.0, 3.0, max(study.n // 2, 6))
        ds = study._map(study.wave_model(v, l0=2.5), {"u_tug": speeds, "external.omega": omega})
        save_dataset(ds, out / f"barge_{v}_map_utug_omega.nc")
        validity[f"barge_{v}_map_utug_omega"] = _validity_share(ds)
        save(
            plot_max_real_map(
                speeds,
                omega,
                _straight(ds),
                xlabel="U_tug [m/s]",
                title=f"Barge {v}: max Re lambda over tug speed, l0' = 2.5, zeta_a = {za} m",
                note=src,
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
    # heading over (xp', omega) and (xp', Tp) (figs 6.13, 6.23)
    xps = np.linspace(0.05, 1.0, study.n)
    for tag, model, grid, ylab, fig in (
        (
            "omega",
            study.wave_model("2a"),
            {"xp": xps, "external.omega": omega},
            "omega [rad/s]",
            "6.13",
        ),
        (
            "tp",
            study.irregular_model("2a"),
            {"xp": xps, "external.spectrum.tp": tps},
            "Tp [s]",
            "6.23",
        ),
    ):
        ds = study._map(model, grid)
        save_dataset(ds, out / f"barge_2a_equilibria_xp_{tag}.nc")
        save(
            plot_heading_map(
                xps,
                grid[list(grid)[1]],
                _straight(ds, "psi"),
                "x_p' [-]",
                ylabel=ylab,
                title=f"Barge 2a: heading nearest straight behind (fig. {fig})",
                invalid=_invalid(ds),
            ),
            out / f"barge_2a_heading_xp_{tag}.png",
        )
    runs = {k: (m, sim) for k, (m, sim, _) in study.runs.items()}
    save(
        plot_runs(runs, title=f"Barge 2a, l0' = 2.5, zeta_a = {za} m (figs 6.20-6.22, 7.5)"),
        out / "barge_2a_time_domain.png",
    )


def _panel_variants(folder):
    """{(estimate, end): QTF, ("base",): QTF} from a folder of ``jaxtow bem`` runs named
    base, cogz_lo, cogz_hi, radii_lo, radii_hi, zeta_lo, zeta_hi (near field)."""
    from ..io import load_qtf

    names = {
        "base": ("base",),
        "cogz_lo": ("cog_z", "low"),
        "cogz_hi": ("cog_z", "high"),
        "radii_lo": ("radii_of_gyration", "low"),
        "radii_hi": ("radii_of_gyration", "high"),
        "zeta_lo": ("roll_damping", "low"),
        "zeta_hi": ("roll_damping", "high"),
    }
    out = {}
    for d, key in names.items():
        f = Path(folder) / d / "qtf_near_field.nc"
        if f.exists():
            out[key] = load_qtf(f)
    return out if ("base",) in out else None


def claims_table(claims: list) -> str:
    """The readable claims table: one row per claim, one column per (source, form)."""
    cols = sorted(
        {(c["source_key"], c["sailing_form"]) for c in claims},
        key=lambda k: (SOURCES.index(k[0]) if k[0] in SOURCES else 9, k[1]),
    )
    ids = list(dict.fromkeys(c["id"] for c in claims))
    by = {(c["id"], c["source_key"], c["sailing_form"]): c for c in claims}
    text = {c["id"]: c["claim"] for c in claims}
    head = "| claim | " + " | ".join(f"{SOURCE_NAMES.get(s, s)}, {f}" for s, f in cols) + " |"
    lines = [head, "|---" * (len(cols) + 1) + "|"]
    for i in ids:
        cells = []
        for s, f in cols:
            c = by.get((i, s, f))
            cells.append("-" if c is None else ("yes" if c["reproduced"] else "NO"))
        lines.append(f"| {text[i]} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def _brief(measured, limit: int = 4) -> str:
    """A few of a claim's measured numbers, for a table cell."""
    items = []

    def walk(prefix, v):
        if isinstance(v, dict):
            for k, x in v.items():
                walk(f"{prefix}{k}" if not prefix else f"{prefix}.{k}", x)
        elif isinstance(v, bool):
            items.append(f"{prefix} {'yes' if v else 'no'}")
        elif isinstance(v, (int, float)):
            items.append(f"{prefix} {float(v):.3g}")
        elif (
            isinstance(v, (list, tuple))
            and v
            and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v)
        ):
            items.append(f"{prefix} " + "/".join(f"{float(x):.3g}" for x in v))

    walk("", measured)
    return "; ".join(items[:limit]) + (" …" if len(items) > limit else "")


def attribution_text(claims: list) -> str:
    """The attribution of each claim that carries one (`jaxtow.studies.attribute`), as
    markdown: the claim re-run at both ends of each estimate's plausible range, the panel
    variants, the gradient at the deciding point and what flips it."""
    out = []
    for c in claims:
        a = c.get("attribution")
        if not a:
            continue
        yes = "reproduced" if a["reproduced_at_attribution_grid"] else "not reproduced"
        out += [
            f"### {c['id']}",
            "",
            f"{c['claim']}. At the attribution grid ({a['grid_points_per_axis']} points per "
            f"axis) the claim is {yes}.",
            "",
            "| estimate | low end of the range | high end of the range |",
            "|---|---|---|",
        ]
        rows = dict(a["estimates"])
        pan = a.get("panel_estimates", {})
        rows.update(
            {f"{k} (panel variant)": v for k, v in pan.items() if k != "base_at_variant_mesh"}
        )
        for name, ends in rows.items():
            if not isinstance(ends, dict):
                out.append(f"| {name} | {ends} | |")
                continue
            cells = []
            for end in ("low", "high"):
                r = ends.get(end)
                if not isinstance(r, dict):
                    cells.append(str(r))
                    continue
                verdict = "reproduced" if r["reproduced"] else "not reproduced"
                cells.append(f"{r['value']}: {verdict} ({_brief(r['measured'], 2)})")
            out.append(f"| {name} | " + " | ".join(cells) + " |")
        if "base_at_variant_mesh" in pan:
            base = "reproduced" if pan["base_at_variant_mesh"] else "not reproduced"
            out += ["", f"Base database at the panel variants' mesh: {base}."]
        g = a.get("gradient")
        if isinstance(g, dict):
            parts = [
                f"{k} {v['relative_change_to_flip'] * 100:+.0f} %"
                for k, v in g["parameters"].items()
            ]
            out += [
                "",
                f"Deciding point {g['point']}: max Re λ {g['max_real']:.4g}; the linear change "
                f"of each estimate that would make it {g['wanted']}: " + ", ".join(parts) + ".",
            ]
        elif g:
            out += ["", f"Gradient: {g}."]
        flips = a.get("flipped_by") or []
        out += [
            "",
            "Flipped by: " + (", ".join(flips) if flips else "none of the estimates") + ".",
            "",
        ]
    return "\n".join(out)


def claims_markdown(claims: list, sources: dict) -> str:
    """``claims.md``: the claims table, the drift sources ({key: description}) and, where
    claims carry one, the readable attribution."""
    attributed = any(c.get("attribution") for c in claims)
    return (
        "# Thesis claims by drift source and sailing-drift form\n\n"
        + claims_table(claims)
        + "\nDrift sources:\n\n"
        + "".join(f"* {SOURCE_NAMES.get(k, k)}: {v}\n" for k, v in sources.items())
        + (
            "\n## Attribution of the claims that do not reproduce (primary source and form)\n\n"
            + attribution_text(claims)
            + "\nThe numbers behind each row are in claims.json, key 'attribution'.\n"
            if attributed
            else ""
        )
    )


def file_options(pairs) -> dict:
    """``--qtf-option KEY=VALUE`` pairs as reader options (numbers, ``x,y`` pairs, words)."""
    from ..presets import FILE_OPTIONS

    out: dict = {}
    for pair in pairs:
        key, eq, value = pair.partition("=")
        if not eq or key not in FILE_OPTIONS:
            raise SystemExit(
                f"jaxtow report: --qtf-option {pair!r}: expected KEY=VALUE with KEY in {FILE_OPTIONS}"
            )
        parts = value.split(",")
        try:
            nums = [float(v) for v in parts]
            out[key] = nums if len(nums) > 1 else (int(nums[0]) if key == "moment_set" else nums[0])
        except ValueError:
            out[key] = value
    return out


def _key(spec) -> str:
    """The claims-table key of a drift source spec (a drift-file mapping: its file)."""
    return spec if isinstance(spec, str) else str(spec["file"])


def plan(args):
    """(primary source, sources, forms) of a report: the primary source and form first, then
    the others of ``--sources`` / ``--forms`` (default: all of `SOURCES`, aranha and thesis)."""
    primary = args.qtf or "near_field"
    opts = getattr(args, "qtf_option", None) or []
    if opts:
        from pathlib import Path as _P

        if not _P(primary).exists():
            raise SystemExit(
                f"jaxtow report: --qtf-option applies to a drift file; --qtf {primary!r} is none"
            )
        primary = dict(file=primary, **file_options(opts))
    srcs = args.sources.split(",") if args.sources else SOURCES
    fms = args.forms.split(",") if args.forms else ("aranha", "thesis")
    sources = [primary] + [s for s in srcs if s and s != primary]
    forms = [args.form] + [f for f in fms if f and f != args.form]
    return primary, sources, forms


def cmd_report(args):
    from .. import presets, studies as W
    from ..presets import drift_source

    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    progress = not args.quiet
    primary, sources, forms = plan(args)
    common = dict(
        zeta_a=args.zeta_a, hs=args.hs, n=args.n, n_grid=args.n_grid, t1=args.t1, wind=args.wind
    )
    base = W.WaveStudy(qtf=primary, form=args.form, progress=progress, **common)
    summary: dict = dict(
        drift_source=base.source,
        zeta_a=args.zeta_a,
        u_tug=presets.U_TUG_DEFAULT,
        xp=0.5,
        sailing_form=args.form,
        sources={_key(s): drift_source(s)[1] for s in sources},
        forms=forms,
        assumptions={k: v["note"] for k, v in presets.ASSUMPTIONS.items()},
        plausible_ranges={k: v["note"] for k, v in presets.PLAUSIBLE_RANGES.items()},
    )
    claims: list = []
    t0 = time.perf_counter()
    for s in sources:
        for f in forms:
            st = (
                base
                if (s, f) == (primary, args.form)
                else base.variant(qtf=s, form=f, progress=False)
            )
            for c in st.claims():
                c["source_key"] = _key(s)
                claims.append(c)
            if (s, f) == (primary, args.form):
                _figures(st, out, summary, progress)
            print(
                f"claims computed: {SOURCE_NAMES.get(_key(s), _key(s))}, {f} ({time.perf_counter() - t0:.0f} s)",
                flush=True,
            )
            # kept as each study finishes: the full report runs for hours on 2 cores, and a
            # run stopped on the way keeps the claims it has (overwritten at the end)
            write_file(out / "claims.partial.json", json.dumps(claims, indent=2, default=float))
    # attribution of every claim of the primary study that does not reproduce
    variants = _panel_variants(args.panel_variants) if args.panel_variants else None
    if args.attribution:
        for c in claims:
            if (c["source_key"], c["sailing_form"]) == (_key(primary), args.form) and not c[
                "reproduced"
            ]:
                a = W.attribute(base, c["id"], n=args.attribution_n, panel_variants=variants)
                c["attribution"] = a
                print(
                    f"attributed: {c['id']}: flipped by {a['flipped_by'] or 'none of the estimates'}",
                    flush=True,
                )
                write_file(out / "claims.partial.json", json.dumps(claims, indent=2, default=float))
    # slowly varying drift in the time domain
    if args.slow_drift_hours > 0:
        from ..plotting.calm import save
        from ..plotting.waves_report import plot_runs

        sd = W.slow_drift_runs(base, hours=args.slow_drift_hours)
        summary["slow_drift"] = {k: v[3] for k, v in sd.items()}
        save(
            plot_runs(
                {k: (v[0], v[1]) for k, v in sd.items()},
                title=f"Barge 2a, l0' = 2.5, Hs = {args.hs} m, Tp = 7 s: mean vs slowly varying drift",
            ),
            out / "barge_2a_slow_drift.png",
        )
    summary["claims"] = claims
    write_file(out / "claims.json", json.dumps(claims, indent=2, default=float))
    (out / "claims.partial.json").unlink(missing_ok=True)
    write_file(out / "summary.json", json.dumps(summary, indent=2, default=float))
    table = claims_table(claims)
    write_file(out / "claims.md", claims_markdown(claims, summary["sources"]))
    print(table)
    print(f"primary drift forces: {base.source} ({args.form})")
    print(f"wrote figures, NetCDF datasets, claims.json, claims.md and summary.json to {out}")


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
        help="primary drift source: near_field (default: the shipped Barge 2 panel database), "
        "far_field, standin (the Kashiwagi-waterline stand-in) or a drift file (.nc/.csv jaxtow, "
        "a Capytaine drift .nc, .8/.9 WAMIT; half tables of symmetric hulls are completed, the "
        "yaw moment is moved to the CoG of the WAMIT listing next to the file)",
    )
    r.add_argument(
        "--qtf-option",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="reader option of a --qtf file (repeatable): ulen, rho, g, symmetry=auto|none, "
        "symmetry_tol, reference_point=cog|origin|X,Y, moment_set=6|-6",
    )
    r.add_argument(
        "--sources",
        default=None,
        help="comma-separated drift sources of the claims table (default near_field,far_field,standin)",
    )
    r.add_argument(
        "--forms",
        default=None,
        help="comma-separated sailing-drift forms of the claims table (default aranha,thesis)",
    )
    r.add_argument(
        "--no-attribution",
        dest="attribution",
        action="store_false",
        help="skip the attribution of the claims that do not reproduce",
    )
    r.add_argument(
        "--attribution-n",
        type=int,
        default=None,
        help="map points per axis of the attribution re-runs (default n // 2, at least 9)",
    )
    r.add_argument(
        "--panel-variants",
        default=None,
        help="folder of jaxtow bem runs of the panel-only estimates (base, cogz_lo, cogz_hi, "
        "radii_lo, radii_hi, zeta_lo, zeta_hi) for the attribution",
    )
    r.add_argument(
        "--slow-drift-hours",
        type=float,
        default=3.0,
        help="record length of the slowly varying drift runs [h] (0: skip)",
    )
    r.add_argument(
        "--zeta-a", type=float, default=1.25, help="regular-wave amplitude [m] (thesis: 1.25)"
    )
    r.add_argument(
        "--hs", type=float, default=2.4, help="Hs of the irregular sea [m] (thesis: 2.4)"
    )
    r.add_argument(
        "--n",
        type=int,
        default=41,
        help="points per map axis (41: the six source/form studies took 88 min on 2 loaded "
        "cores and the whole report about 2 h; --sources/--forms to run fewer)",
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
