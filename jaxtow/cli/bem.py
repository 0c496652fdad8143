"""``jaxtow bem CONFIG``: panel-method (Capytaine) drift databases for Barge 1 / Barge 2 or a
user hull (thesis sections 2.3.1, 4, 5, appendix B), from a small TOML config.

Writes to ``--out``: ``bem.nc`` (RAOs, hydrodynamic coefficients, far-/near-field drift,
near-field parts I-IV, sectional moments), ``qtf_far_field.nc`` and ``qtf_near_field.nc``
(jaxtow QTF databases with the mesh, solver and versions in their attributes, for
``jaxtow resistance`` / ``jaxtow report waves --qtf`` / `jaxtow.io.load_qtf`), figures of the
RAOs (B.2, B.3), the QTFs (4.3c, 4.4c, 4.5a, B.4) and the near-field parts (2.11), and
``summary.json``. ``--convergence 2,1.5,1`` runs the mesh-convergence study (B.1) instead.
"""

from __future__ import annotations

import json
import math
import sys
import tomllib
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import numpy as np

import jaxtow as jt

from ._common import positive_float, positive_int
from ._config import config_dispatch, config_text, read_config as _read_config
from .tow import load_tow

BUILTIN = {"barge1": "bem_barge1.toml", "barge2": "bem_barge2.toml"}
_KEYS = {
    "hull": {"kind", "length", "breadth", "draft", "panel_size", "path", "grading"},
    "mass": {"cog_z", "roll_damping", "radii"},
    "waves": {"omega", "beta_deg", "water_depth"},
}


def read_config(config) -> dict:
    """The parsed config: a built-in name (barge1, barge2), a TOML path, or a dict."""
    return _read_config(config, BUILTIN)


def _number(value, where: str) -> float:
    """A config value as a number; an error naming the key otherwise."""
    if isinstance(value, bool):
        raise ValueError(f"config {where}: expected a number, got {value!r}")
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ValueError(f"config {where}: expected a number, got {value!r}") from None


def _config_grid(spec, name):
    if not (isinstance(spec, list) and len(spec) == 3):
        raise ValueError(f"config [waves] {name}: expected [start, stop, count], got {spec!r}")
    lo, hi, n = (_number(x, f"[waves] {name}") for x in spec)
    if n != int(n) or n < 1:
        raise ValueError(
            f"config [waves] {name}: count must be a whole number >= 1, got {spec[2]!r}"
        )
    return np.linspace(lo, hi, int(n))


def build(cfg: dict, panel_size: float | None = None):
    """(mesh builder panel_size -> HullMesh, default panel size, omega, beta [rad], bem_drift keywords)."""

    for sec, allowed in _KEYS.items():
        extra = set(cfg.get(sec, {})) - allowed
        if extra:
            raise ValueError(
                f"config [{sec}]: unknown key(s) {sorted(extra)}; allowed: {sorted(allowed)}"
            )
    extra = set(cfg) - set(_KEYS)
    if extra:
        raise ValueError(f"config: unknown section(s) {sorted(extra)}; allowed: {sorted(_KEYS)}")
    h, m, w = cfg.get("hull", {}), cfg.get("mass", {}), cfg.get("waves", {})
    kind = h.get("kind", "box")
    size = (
        float(panel_size)
        if panel_size is not None
        else _number(h.get("panel_size", 1.0), "[hull] panel_size")
    )
    grading = _number(h.get("grading", 0.0), "[hull] grading")
    if kind == "box":

        def builder(p):
            return jt.bem.raked_barge_mesh(
                _number(h.get("length", 76.2), "[hull] length"),
                _number(h.get("breadth", 24.4), "[hull] breadth"),
                _number(h.get("draft", 5.0), "[hull] draft"),
                0.0,
                panel_size=p,
                grading=grading,
                name="barge1_box",
            )
    elif kind == "barge2":

        def builder(p):
            return jt.bem.barge2_mesh(h.get("draft"), panel_size=p, grading=grading)
    elif kind == "file":
        if "path" not in h:
            raise ValueError("config [hull] kind = 'file' needs path = 'mesh file'")

        def builder(p):
            return jt.bem.read_mesh(h["path"], panel_size=p)
    else:
        raise ValueError(f"config [hull] kind: 'box', 'barge2' or 'file', got {kind!r}")
    omega = _config_grid(w.get("omega", [0.05, 2.5, 61]), "omega")
    beta = np.radians(_config_grid(w.get("beta_deg", [0, 180, 25]), "beta_deg"))
    depth = w.get("water_depth", "inf")
    depth = (
        math.inf
        if str(depth).lower() in ("inf", "infinity")
        else _number(depth, "[waves] water_depth")
    )
    kw = dict(water_depth=depth)
    return builder, size, omega, beta, kw, _loading(m)


def _loading(mass: dict):
    """The loading condition of a mesh from the config's [mass] (``cog_z`` above the keel,
    ``radii``, ``roll_damping``; the documented estimates for what it leaves out)."""
    given = {k: mass[k] for k in ("radii", "roll_damping") if k in mass}

    def of(mesh):
        draft = -float(mesh.vertices[:, 2].min())
        if "cog_z" in mass:
            return jt.Loading.above_keel(float(mass["cog_z"]), draft, **given)
        return jt.Loading.estimate(draft, **given)

    return of


def cmd_bem(args):
    try:
        jt.bem.require_capytaine()
    except ImportError as e:
        raise SystemExit(f"jaxtow bem: {e}") from None
    try:
        builder, size, omega, beta, kw, loading = build(read_config(args.config), args.panel_size)
        if args.n_omega:
            omega = np.linspace(omega[0], omega[-1], args.n_omega)
    except (ValueError, KeyError, OSError) as e:
        raise SystemExit(f"jaxtow bem: {e}") from None
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    cache = Path(args.cache) if args.cache else out / "cache"
    if args.convergence:
        sizes = [float(s) for s in args.convergence.split(",")]
        kw["loading"] = loading(builder(sizes[0]))
        _convergence(args, builder, sizes, omega, beta, cache, kw, out)
        return
    mesh = builder(size)
    kw["loading"] = loading(mesh)
    print(
        f"{mesh.name}: {mesh.n_panels} hull panels + {len(mesh.lid_faces)} lid panels, {omega.size} frequencies "
        f"x {beta.size} headings"
    )
    ds = jt.bem.bem_drift(mesh, omega, beta, cache_dir=cache, progress=not args.quiet, **kw)
    jt.io.save_netcdf(ds, out / "bem.nc")
    bad = ds.omega.values[~ds.resolved.values]
    if bad.size:
        print(
            f"warning: {bad.size} frequencies from {bad.min():.2f} rad/s have fewer than "
            f"{jt.bem.solve.MIN_PANELS_PER_WAVELENGTH:g} panels per wavelength (dataset variable 'resolved'); "
            "use a smaller --panel-size"
        )
    sym = bool(np.isclose(float(beta[0]), 0.0))
    for method in ("far_field", "near_field"):
        q = jt.bem.qtf_from_bem(ds, method, symmetric=sym)
        jt.io.save_qtf(q, out / f"qtf_{method}.nc", attrs=jt.bem.qtf_attrs(ds, method))
    summary = jt.bem.summary.bem_summary(ds, mesh)
    jt.io.write_file(out / "summary.json", json.dumps(summary, indent=2))
    _figures(ds, beta, out)
    keys = ("short_wave_surge_head_seas", "near_vs_far_fx", "near_vs_far_fy")
    print(json.dumps({k: summary[k] for k in keys}, indent=1))
    print(f"wrote bem.nc, qtf_far_field.nc, qtf_near_field.nc, figures and summary.json to {out}")


def _convergence(args, builder, sizes, omega, beta, cache, kw, out: Path) -> None:
    """``--convergence``: the drift at several panel sizes (thesis fig. B.1)."""
    runs, summary = jt.bem.mesh_convergence(
        builder, sizes, omega, beta, cache_dir=cache, progress=not args.quiet, **kw
    )
    jt.io.save_netcdf(summary, out / "convergence.nc")
    jt.plotting.save(
        jt.plotting.bem.plot_mesh_convergence(summary, runs),
        out / "fig_B1_convergence.png",
        dpi=120,
    )
    print(
        summary.near_vs_far.to_dataframe().unstack("zone").to_string()
        if hasattr(summary, "to_dataframe")
        else summary
    )
    print(f"wrote convergence.nc and fig_B1_convergence.png to {out}")


def _figures(ds, beta, out: Path) -> None:
    """RAOs, QTFs and near-field parts at up to three headings of the solve."""
    bds = [float(np.degrees(b)) for b in beta[:: max(1, beta.size // 3)]][:3]
    for bd in sorted(set([bds[0], 15.0 if np.any(np.isclose(np.degrees(beta), 15)) else bds[-1]])):
        jt.plotting.save(jt.plotting.bem.plot_rao(ds, bd), out / f"fig_rao_beta{bd:g}.png", dpi=110)
    jt.plotting.save(jt.plotting.bem.plot_bem_qtf(ds, bds), out / "fig_qtf.png", dpi=110)
    jt.plotting.save(
        jt.plotting.bem.plot_nearfield_parts(ds, bds[min(1, len(bds) - 1)]),
        out / "fig_nearfield_parts.png",
        dpi=110,
    )


def add_parser(sub):
    r = sub.add_parser(
        "bem", help="panel-method drift database with Capytaine (needs: pip install 'jaxtow[bem]')"
    )
    r.add_argument(
        "config",
        help="TOML panel config, a tow file with a [hull] mesh, or a built-in tow's: "
        "barge1, barge2a, barge2b (print with --show-config)",
    )
    r.add_argument("--out", default="bem_out", help="output folder (default bem_out)")
    r.add_argument(
        "--panel-size", type=positive_float, default=None, help="override [hull] panel_size [m]"
    )
    r.add_argument(
        "--n-omega", type=positive_int, default=None, help="override the number of frequencies"
    )
    r.add_argument("--cache", default=None, help="per-frequency cache folder (default OUT/cache)")
    r.add_argument(
        "--convergence", default=None, help="mesh study instead: comma-separated panel sizes [m]"
    )
    r.add_argument("--quiet", action="store_true", help="no progress bar")
    r.add_argument("--show-config", action="store_true", help="print the config and exit")
    r.add_argument(
        "--force",
        action="store_true",
        help="recompute even where OUT already holds the finished outputs of the same request",
    )
    r.set_defaults(func=_dispatch, fingerprint=fingerprint)


#: The built-in tows' panel configs (one spelling of the built-ins everywhere).
TOW_CONFIGS = {"barge1": "barge1", "barge2a": "barge2", "barge2b": "barge2"}


def fingerprint(args) -> str | None:
    """A digest of everything that decides the outputs of ``jaxtow bem``: the config's text
    (and the mesh file it names), the panel size, frequency count and mesh study asked for,
    the versions of jaxtow and Capytaine and the source of jaxtow's panel code. Where a
    finished run into the same folder recorded the same digest and its outputs are all
    there, the command has nothing to do (`jaxtow.cli._manifest.up_to_date`). None (always
    run) for a tow file, a config that cannot be read, or ``--show-config``."""

    spec = TOW_CONFIGS.get(args.config, args.config)
    if args.show_config or (spec not in BUILTIN and not Path(str(spec)).is_file()):
        return None
    try:
        text = config_text(spec, BUILTIN)
        cfg = tomllib.loads(text)
    except (ValueError, OSError, tomllib.TOMLDecodeError):
        return None
    if "vessel" in cfg:  # a tow file: its mesh and estimates resolve through load_tow
        return None
    digest = jt.io.Fingerprint()

    def add(label, data: bytes):
        digest.labelled(label, data)

    add("config", text.encode())
    mesh = cfg.get("hull", {}).get("path") if cfg.get("hull", {}).get("kind") == "file" else None
    if mesh is not None:
        try:
            add("mesh", Path(mesh).read_bytes())
        except OSError:
            return None
    add("options", repr((args.panel_size, args.n_omega, args.convergence)).encode())
    for pkg in ("jaxtow", "capytaine"):
        try:
            add(pkg, version(pkg).encode())
        except PackageNotFoundError:
            add(pkg, b"")
    here = Path(__file__).resolve()
    for src in sorted((here.parent.parent / "bem").glob("*.py")) + [here]:
        add(src.name, src.read_bytes())
    return digest.hexdigest()


def _dispatch(args):
    if args.config == "barge2":
        print(
            "jaxtow bem: warning: the name 'barge2' is deprecated and will be removed; use "
            "'barge2a' or 'barge2b' (the same hull)",
            file=sys.stderr,
        )
    args.config = TOW_CONFIGS.get(args.config, args.config)
    tow_cfg = _tow_file_config(args.config)
    if tow_cfg is not None:
        if args.show_config:
            print(json.dumps(tow_cfg, indent=1))
            return
        args.config = tow_cfg
    config_dispatch("bem", BUILTIN, cmd_bem)(args)


def _tow_file_config(spec):
    """The panel config of a tow file whose [hull] has a mesh (None for anything else: a
    built-in name or a panel config)."""

    path = Path(str(spec))
    if str(spec) in BUILTIN or not path.is_file():
        return None
    try:
        data = tomllib.loads(path.read_text())
    except (tomllib.TOMLDecodeError, OSError):
        return None
    if "vessel" not in data:  # a panel config
        return None

    tow = load_tow(spec, "bem")
    mesh = tow.drift
    if not isinstance(mesh, jt.bem.MeshDriftSource):
        raise SystemExit(
            f"jaxtow bem: error: tow file {spec} has no [hull] mesh to solve (its drift comes "
            f"from {mesh.describe()})"
        )
    mass = {} if mesh.cog_z is None else {"cog_z": mesh.cog_z}
    return {
        "hull": {"kind": "file", "path": mesh.mesh},
        "mass": mass,
        "waves": {"omega": list(mesh.omega), "beta_deg": list(mesh.beta_deg)},
    }
