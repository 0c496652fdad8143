"""``jaxtow resistance CONFIG``: tow resistance budget, required pull and operating speed
(thesis sections 7.1-7.2, figs 2.1, 7.2-7.4) from a small TOML config."""

from __future__ import annotations

import json
import math
import sys
import tomllib
from pathlib import Path

import msgspec
import numpy as np

import jaxtow as jt

from ._config import config_dispatch, read_config as _read_config
from .tow import load_tow

NM = 1852.0  # m
TONNE_FORCE = 9.80665e3  # N
BUILTIN = {"barge2": "resistance_barge2.toml"}
_TOW_KEYS = {"vessel", "wave_drift", "sailing_form", "wind_table", "wind_height", "heading_deg"}
_TUG_KEYS = {
    "bollard_pull_t",
    "free_speed",
    "efficiency",
    "resistance_coefficient",
    "speeds",
    "pulls_t",
}
_SEA_KEYS = {
    "name",
    "hs",
    "tp",
    "gamma",
    "wind_speed",
    "current_speed",
    "wave_angle_deg",
    "wind_angle_deg",
    "current_angle_deg",
}


def read_config(config) -> dict:
    """The parsed config: a built-in name (barge2), a TOML path, or a dict."""
    return _read_config(config, BUILTIN)


def _unknown(section: str, got: dict, allowed: set):
    extra = set(got) - allowed
    if extra:
        raise ValueError(
            f"config [{section}]: unknown key(s) {sorted(extra)}; allowed: {sorted(allowed)}"
        )


def build(cfg: dict):
    """(tow, tug, sea states, heading [rad], route length [m] or None) from a parsed config."""

    for key in ("tow", "tug", "sea_state"):
        if key not in cfg:
            raise ValueError(
                f"config: missing section [{key}]"
                if key != "sea_state"
                else "config: needs at least one [[sea_state]]"
            )
    unknown = set(cfg) - {"tow", "tug", "sea_state", "route"}
    if unknown:
        raise ValueError(
            f"config: unknown section(s) {sorted(unknown)}; known: tow, tug, sea_state, route"
        )
    tow_c, tug_c = cfg["tow"], cfg["tug"]
    _unknown("tow", tow_c, _TOW_KEYS)
    _unknown("tug", tug_c, _TUG_KEYS)
    vessel = tow_c.get("vessel", "barge_2a")
    if vessel not in ("barge_2a", "barge_2b"):
        raise ValueError(
            f"config [tow] vessel: built-in vessels are 'barge_2a' and 'barge_2b', got {vessel!r}"
        )
    source = jt.presets.drift_source(tow_c.get("wave_drift", "near_field"))
    kw = dict(wind_height=tow_c.get("wind_height"))
    kw["qtf"], kw["drift_source"] = source.qtf(), source.describe()
    kw["form"] = tow_c.get("sailing_form", "aranha")
    if "wind_table" in tow_c:
        kw["wind_table"] = jt.io.read_coefficient_table(tow_c["wind_table"])
    tow = jt.presets.barge2_resistance(vessel.split("_")[1], **kw)
    eff = dict(
        efficiency=tug_c.get("efficiency", 1.0),
        resistance_coefficient=tug_c.get("resistance_coefficient", 0.0),
    )
    if "speeds" in tug_c or "pulls_t" in tug_c:
        tug = jt.resistance.Tug.from_table(
            tug_c["speeds"], np.asarray(tug_c["pulls_t"], float) * TONNE_FORCE, **eff
        )
    else:
        if "bollard_pull_t" not in tug_c or "free_speed" not in tug_c:
            raise ValueError(
                "config [tug]: give bollard_pull_t and free_speed, or speeds and pulls_t"
            )
        tug = jt.resistance.Tug(
            bollard_pull=float(tug_c["bollard_pull_t"]) * TONNE_FORCE,
            free_speed=tug_c["free_speed"],
            **eff,
        )
    seas = []
    for i, s in enumerate(cfg["sea_state"]):
        _unknown(f"sea_state {i + 1}", s, _SEA_KEYS)
        kw = {k: s[k] for k in ("hs", "tp", "gamma", "wind_speed", "current_speed") if k in s}
        for k in ("wave_angle", "wind_angle", "current_angle"):
            if f"{k}_deg" in s:
                kw[k] = math.radians(s[f"{k}_deg"])
        if "hs" not in kw or "tp" not in kw:
            raise ValueError(f"config [[sea_state]] {i + 1}: hs and tp are required")
        seas.append(jt.resistance.SeaState(**kw, name=s.get("name", f"sea state {i + 1}")))
    route = cfg.get("route", {})
    _unknown("route", route, {"length_nm", "length_m"})
    length = route["length_nm"] * NM if "length_nm" in route else route.get("length_m")
    if length is not None and not (math.isfinite(length) and length > 0):
        raise ValueError(f"config [route]: the route length must be > 0, got {length!r} m")
    return tow, tug, seas, math.radians(tow_c.get("heading_deg", 0.0)), length


def format_table(rows: list, tug, route_length) -> str:
    """The readable table of `jaxtow resistance`."""
    head = (
        f"tug: bollard pull {float(tug.bollard_pull) / TONNE_FORCE:.1f} t, efficiency {float(tug.efficiency):g}, "
        f"top speed {float(tug.max_speed):g} m/s"
        + (f"; route {route_length / NM:g} nm" if route_length else "")
    )

    cols, body = jt.studies.resistance_table(rows)
    table = [list(cols), *body]
    notes = [f"! {r.sea_state}: {r.message}" for r in rows if r.message]
    width = [max(len(row[j]) for row in table) for j in range(len(cols))]
    lines = [head, ""]
    for k, row in enumerate(table):
        lines.append(
            "  ".join(c.rjust(w) if j else c.ljust(w) for j, (c, w) in enumerate(zip(row, width)))
        )
        if k == 0:
            lines.append("-" * len(lines[-1]))
    lines += [
        "",
        "hold: towing force to hold the tow at zero speed at the given Tp; req. BP: the tug's rated "
        "bollard pull for it (/ efficiency); worst: over the physical Tp range (eq. 3.5)",
    ] + notes
    return "\n".join(lines)


def inputs(spec):
    """(tow, tug, sea states, heading, route) from a tow file or built-in tow (barge2a,
    barge2b), or from an old resistance config (the built-in ``barge2`` or a file with
    [tow] vessel = ...), which is deprecated."""

    spec = str(spec)
    old = spec in BUILTIN
    if not old and jt.tow.canonical_name(spec)[0] not in jt.tow.BUILTIN_TOWS:
        try:
            cfg = tomllib.loads(Path(spec).read_text()) if Path(spec).is_file() else {}
        except (tomllib.TOMLDecodeError, OSError):
            cfg = {}
        old = "vessel" not in cfg and "vessel" in cfg.get("tow", {})
    if old:
        print(
            "jaxtow resistance: warning: resistance configs are deprecated and will be "
            "removed; use a tow file (jaxtow tow new) or a built-in tow (barge2a)"
            + (" — the built-in 'barge2' is now 'barge2a'" if spec in BUILTIN else ""),
            file=sys.stderr,
        )
        try:
            return build(read_config(spec))
        except (ValueError, KeyError, OSError) as e:
            raise SystemExit(f"jaxtow resistance: {e}") from None
    tow = load_tow(spec, "resistance")
    if tow.tug is None or tow.vessel is None:
        raise SystemExit(
            f"jaxtow resistance: error: tow {tow.name!r} needs a manoeuvring model ([vessel]) "
            "and a [tug]"
        )
    if not tow.sea_states:
        raise SystemExit(f"jaxtow resistance: error: tow {tow.name!r} has no [[sea_state]]")
    return tow.resistance(), tow.tug, list(tow.sea_states), 0.0, tow.route_length


def cmd_resistance(args):
    tow, tug, seas, heading, route = inputs(args.config)
    study = jt.studies.resistance_study(tow, tug, seas, heading, route)
    print(format_table(study.rows, tug, route))
    notes = [f"  - {k}: {n}" for k, n in tow.assumed]
    print("\nresults depend on these estimates / ILLUSTRATIVE inputs:\n" + "\n".join(notes))
    if not args.out:
        return
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for sea in seas:
        tag = sea.name.replace(" ", "_")
        jt.io.save_dataset(study.budgets[sea.name], out / f"resistance_{tag}.nc")
    for stem, ax in jt.plotting.resistance.resistance_figures(study).items():
        jt.plotting.save(ax, out / f"{stem}.png")
    summary = dict(
        tow=tow.name,
        assumed=dict(tow.assumed),
        tug=dict(
            bollard_pull=float(tug.bollard_pull),
            free_speed=float(tug.max_speed),
            efficiency=float(tug.efficiency),
        ),
        route_length_m=route,
        sea_states=[msgspec.to_builtins(r) for r in study.rows],
    )
    jt.io.write_file(out / "summary.json", json.dumps(summary, indent=2, default=float))
    print(f"wrote figures, NetCDF datasets and summary.json to {out}")


def add_parser(sub):
    r = sub.add_parser(
        "resistance", help="tow resistance, required pull and operating speed (thesis 7.1-7.2)"
    )
    r.add_argument(
        "config",
        help="tow file or built-in tow (barge2a, barge2b); an old resistance config "
        f"(built-in: {', '.join(BUILTIN)}) is still read, deprecated",
    )
    r.add_argument(
        "--out", default=None, help="also write datasets, figures and summary.json to this folder"
    )
    r.add_argument(
        "--show-config",
        action="store_true",
        help="print the config (e.g. the built-in one) and exit",
    )
    r.set_defaults(func=_dispatch)


def _dispatch(args):
    if args.show_config and jt.tow.canonical_name(str(args.config))[0] in jt.tow.BUILTIN_TOWS:
        print(load_tow(args.config, "resistance").show())
        return
    config_dispatch("resistance", BUILTIN, cmd_resistance)(args)
