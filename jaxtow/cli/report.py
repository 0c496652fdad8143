"""``jaxtow report waves --out DIR``: towing stability in waves and tow resistance (thesis
chapters 6.2-6.3 and 7): stability and equilibrium maps, time-domain runs (with the slowly
varying drift), ``claims.json`` / ``claims.md`` checking every thesis claim under each drift
source (the shipped panel near field, its far field, the stand-in) and each sailing-drift
form, and the attribution of every claim of the primary source and form that does not
reproduce (`jaxtow.studies.WaveStudy`, `jaxtow.studies.attribute`)."""

from __future__ import annotations

import json
from pathlib import Path, Path as _P

import jaxtow as jt

from ._common import positive_float, positive_int


def _figures(study, out: Path) -> None:
    """Figures and NetCDF datasets of the primary study (drift source and form)."""
    for v in ("2a", "2b"):
        for tag, maps in (
            ("map_l0_omega", study.maps_l0_omega),
            ("equilibria_zeta_omega", study.equilibria_zeta_omega),
            ("map_l0_tp", study.maps_l0_tp),
            ("map_utug_omega", study.maps_utug_omega),
        ):
            jt.io.save_dataset(maps[v], out / f"barge_{v}_{tag}.nc")
    for tag, ds in study.maps_xp.items():
        jt.io.save_dataset(ds, out / f"barge_2a_equilibria_xp_{tag}.nc")
    for stem, ax in jt.plotting.waves_report.wave_study_figures(study).items():
        jt.plotting.save(ax, out / f"{stem}.png")


def _panel_variants(folder):
    """{(estimate, end): QTF, ("base",): QTF} from a folder of ``jaxtow bem`` runs named
    base, cogz_lo, cogz_hi, radii_lo, radii_hi, zeta_lo, zeta_hi (near field)."""

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
            out[key] = jt.io.load_qtf(f)
    return out if ("base",) in out else None


def file_options(pairs) -> dict:
    """``--qtf-option KEY=VALUE`` pairs as reader options (numbers, ``x,y`` pairs, words)."""

    out: dict = {}
    for pair in pairs:
        key, eq, value = pair.partition("=")
        if not eq or key not in jt.presets.FILE_OPTIONS:
            raise SystemExit(
                f"jaxtow report: --qtf-option {pair!r}: expected KEY=VALUE with KEY in {jt.presets.FILE_OPTIONS}"
            )
        parts = value.split(",")
        try:
            nums = [float(v) for v in parts]
            out[key] = nums if len(nums) > 1 else (int(nums[0]) if key == "moment_set" else nums[0])
        except ValueError:
            out[key] = value
    return out


def plan(args):
    """(primary source, sources, forms) of a report: the primary source and form first, then
    the others of ``--sources`` / ``--forms`` (default: all of `jt.reports.SOURCES`, aranha and thesis)."""
    primary = args.qtf or "near_field"
    opts = getattr(args, "qtf_option", None) or []
    if opts:
        if not _P(primary).exists():
            raise SystemExit(
                f"jaxtow report: --qtf-option applies to a drift file; --qtf {primary!r} is none"
            )
        primary = dict(file=primary, **file_options(opts))
    srcs = args.sources.split(",") if args.sources else jt.reports.SOURCES
    fms = args.forms.split(",") if args.forms else ("aranha", "thesis")
    sources = [primary] + [s for s in srcs if s and s != primary]
    forms = [args.form] + [f for f in fms if f and f != args.form]
    return primary, sources, forms


def cmd_report(args):
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    primary, sources, forms = plan(args)

    def keep(message: str, claims: list) -> None:
        print(message, flush=True)
        # the full report runs for hours on 2 cores: a run stopped on the way keeps the
        # claims it has (overwritten at the end)
        jt.io.write_file(out / "claims.partial.json", json.dumps(claims, indent=2, default=float))

    report = jt.studies.wave_report(
        primary,
        sources,
        forms,
        progress=not args.quiet,
        attribution=args.attribution,
        attribution_n=args.attribution_n,
        panel_variants=_panel_variants(args.panel_variants) if args.panel_variants else None,
        slow_drift_hours=args.slow_drift_hours,
        on_progress=keep,
        zeta_a=args.zeta_a,
        hs=args.hs,
        n=args.n,
        n_grid=args.n_grid,
        t1=args.t1,
        wind=args.wind,
    )
    summary, claims = report.summary, report.claims
    _figures(report.primary, out)
    if report.slow_drift:
        jt.plotting.save(
            jt.plotting.waves_report.plot_runs(
                {k: (v[0], v[1]) for k, v in report.slow_drift.items()},
                title=f"Barge 2a, l0' = 2.5, Hs = {args.hs} m, Tp = 7 s: mean vs slowly varying drift",
            ),
            out / "barge_2a_slow_drift.png",
        )
    jt.io.write_file(out / "claims.json", json.dumps(claims, indent=2, default=float))
    (out / "claims.partial.json").unlink(missing_ok=True)
    jt.io.write_file(out / "summary.json", json.dumps(summary, indent=2, default=float))
    jt.io.write_file(out / "claims.md", jt.reports.claims_markdown(claims, summary["sources"]))
    print(jt.reports.claims_table(claims))
    print(f"primary drift forces: {report.primary.source} ({args.form})")
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
    _source_options(r)
    _attribution_options(r)
    _study_options(r)
    r.add_argument("--quiet", action="store_true", help="no progress bars")
    r.set_defaults(func=cmd_report)


def _source_options(r) -> None:
    """The drift sources and forms of the report."""
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
        "--form",
        choices=("aranha", "linear", "thesis"),
        default="aranha",
        help="forward-speed form of the drift (jaxtow.drift.sailing_drift): Aranha's finite "
        "form (default), its linearisation, or the thesis's reading (counts the "
        "encounter-frequency shift twice)",
    )


def _attribution_options(r) -> None:
    r.add_argument(
        "--no-attribution",
        dest="attribution",
        action="store_false",
        help="skip the attribution of the claims that do not reproduce",
    )
    r.add_argument(
        "--attribution-n",
        type=positive_int,
        default=None,
        help="map points per axis of the attribution re-runs (default n // 2, at least 9)",
    )
    r.add_argument(
        "--panel-variants",
        default=None,
        help="folder of jaxtow bem runs of the panel-only estimates (base, cogz_lo, cogz_hi, "
        "radii_lo, radii_hi, zeta_lo, zeta_hi) for the attribution",
    )


def _study_options(r) -> None:
    """The sea, the grids and the runs of the study."""
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
        type=positive_int,
        default=41,
        help="points per map axis (41: the six source/form studies took 88 min on 2 loaded "
        "cores and the whole report about 2 h; --sources/--forms to run fewer)",
    )
    r.add_argument(
        "--n-grid",
        type=positive_int,
        default=401,
        help="heading-scan points over ±90 deg of the equilibrium search",
    )
    r.add_argument("--t1", type=positive_float, default=400.0, help="time-domain run length [L/U]")
    r.add_argument(
        "--wind",
        type=float,
        default=10.0,
        help="head-wind speed of the wind run [m/s] (thesis: 10)",
    )
