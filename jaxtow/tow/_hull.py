"""The [hull] section of a tow file: the waterline, the drift source (resolved once into one
`jaxtow.presets.AbstractDriftSource`), the forward-speed form and the wind table."""

from __future__ import annotations

from pathlib import Path

from .. import presets, strip
from .._body import Loading
from ..bem import MeshDriftSource
from ..drift import WATERLINE_METHODS
from ..io import read_coefficient_table, read_offsets, read_waterline
from ..presets import (
    DATABASE_METHODS,
    DATABASES,
    STANDIN,
    AbstractDriftSource,
    StripSource,
    WaterlineSource,
    barge2_waterline,
    box_waterline,
    drift_source,
)
from ._schema import Problems, read_subtable

__all__ = ["read_waterline_spec", "read_drift", "read_wind", "resolve_path"]


def resolve_path(name, base) -> Path:
    """A file named in a tow file: as given if absolute, else beside the tow file."""
    path = Path(name)
    return path if path.is_absolute() or base is None else Path(base) / path


def read_waterline_spec(p: Problems, h: dict, preset: bool, base, L: float, B: float, T: float):
    """The hull's waterline (for the waterline drift methods and the strips' short-wave part)."""
    wl_spec = h.get("waterline", "barge2" if preset else "box")
    h["waterline"] = wl_spec
    if wl_spec == "box":
        return box_waterline(L, B, T)
    if wl_spec == "barge2":
        return barge2_waterline(T)
    path = resolve_path(wl_spec, base)
    if not path.is_file():
        p.error(("hull", "waterline"), f"box, barge2 or a waterline file; no file {str(path)!r}")
    try:
        return read_waterline(path, draft=T)
    except (ValueError, OSError) as e:
        p.error(("hull", "waterline"), str(e))


def read_drift(p: Problems, h: dict, preset: bool, base, waterline, assumed: list):
    """The drift source of [hull] (checked here; computed on first use): a mesh to solve, a
    drift-file table, a shipped database, the stand-in, a waterline method, strip theory or
    a file. Fills [hull] drift's default in place."""
    drift = h.get("drift")
    if "mesh" in h:
        if drift is not None:
            p.error(("hull", "mesh"), "give either drift or mesh, not both")
        return _mesh(p, h["mesh"], base)
    if drift is None:
        drift = "barge2:near_field" if preset else "kashiwagi"
        h["drift"] = drift
        if not preset:
            assumed.append(
                (
                    "wave_drift",
                    f"no drift source given: the Kashiwagi waterline method on the "
                    f"{h['waterline']} waterline (estimate)",
                )
            )
    if drift == "strip" or (isinstance(drift, dict) and "strip" in drift):
        return _strip(p, h, drift, base, waterline)
    if isinstance(drift, dict):
        opts = read_subtable(p, ("hull", "drift"), drift, "hull.drift")
        if "file" not in opts:
            p.error(("hull", "drift"), "a drift-file table needs file = PATH")
        path = resolve_path(opts["file"], base)
        if not path.is_file():
            p.error(("hull", "drift"), f"no such drift file: {path}")
        return _source(p, dict(opts, file=str(path)))
    if drift in WATERLINE_METHODS:
        return WaterlineSource(drift, waterline)
    hull_name, _, method = drift.rpartition(":")
    if drift == STANDIN or (hull_name in DATABASES and method in DATABASE_METHODS):
        return _source(p, drift)
    if drift in DATABASE_METHODS:
        p.error(
            ("hull", "drift"),
            f"name the hull too, e.g. 'barge2:{drift}' (hulls: {', '.join(DATABASES)})",
        )
    path = resolve_path(drift, base)
    if not path.is_file():
        p.error(
            ("hull", "drift"),
            f"{drift!r} is not a shipped database (hull:method with hull in "
            f"{', '.join(DATABASES)}), {STANDIN!r}, a waterline method "
            f"({', '.join(WATERLINE_METHODS)}), strip or a file",
        )
    return _source(p, str(path))


def _source(p: Problems, spec) -> AbstractDriftSource:
    try:
        return drift_source(spec)
    except ValueError as e:
        p.error(("hull", "drift"), str(e))


def _mesh(p: Problems, mesh, base) -> MeshDriftSource:
    """The resolved [hull] mesh table (checked; solved on first use, cached beside the file)."""
    m = read_subtable(
        p, ("hull", "mesh"), {"file": mesh} if isinstance(mesh, str) else mesh, "hull.mesh"
    )
    if "file" not in m:
        p.error(("hull", "mesh"), "a mesh table needs file = PATH")
    path = resolve_path(m["file"], base)
    if not path.is_file():
        p.error(("hull", "mesh"), f"no mesh file {str(path)!r}")
    return MeshDriftSource(
        mesh=str(path),
        method=m["method"],
        omega=tuple(m["omega"]),
        beta_deg=tuple(m["beta_deg"]),
        cog_z=m.get("cog_z"),
        symmetric=bool(m["symmetric"]),
        cache=str(path.parent / ".jaxtow_bem" / path.stem),
    )


def _strip(p: Problems, h: dict, drift, base, waterline) -> StripSource:
    """drift = "strip" (the box or Barge 2 of the waterline) or {strip = OFFSETS_FILE}."""
    T = float(waterline.draft)
    if drift == "strip":
        name = h["waterline"]
        if name == "box":
            hull = strip.box(float(waterline.length), float(waterline.breadth), T)
        elif name == "barge2":
            hull = presets.barge2_hull(T)
        else:
            p.error(
                ("hull", "drift"),
                "drift = 'strip' needs waterline = 'box' or 'barge2' (the hull of the strips); "
                "for another hull give {strip = OFFSETS_FILE}",
            )
        return StripSource(hull, waterline, name, loading=Loading.estimate(T))
    extra = set(drift) - {"strip"}
    if extra:
        p.error(
            ("hull", "drift"), f"{{strip = OFFSETS_FILE}} takes no other keys, got {sorted(extra)}"
        )
    path = resolve_path(drift["strip"], base)
    if not path.is_file():
        p.error(("hull", "drift"), f"no such offsets file for the strips: {path}")
    try:
        hull = read_offsets(path)
    except ValueError as e:
        p.error(("hull", "drift"), str(e))
    return StripSource(hull, waterline, str(path), loading=Loading.estimate(T))


def read_wind(p: Problems, h: dict, base, assumed: list):
    """The wind table and windage height of [hull] (defaults filled in place)."""
    if h["wind_table"] == "illustrative":
        wind_table = presets.barge2_wind_table()
        assumed.append(("wind_table", presets.ASSUMPTIONS["wind_table"]["note"]))
    else:
        try:
            wind_table = read_coefficient_table(resolve_path(h["wind_table"], base))
        except (ValueError, OSError) as e:
            p.error(("hull", "wind_table"), str(e))
    if "wind_height" not in h:
        h["wind_height"] = float(presets.ASSUMPTIONS["wind_height"]["value"])
        assumed.append(("wind_height", presets.ASSUMPTIONS["wind_height"]["note"]))
    return wind_table
