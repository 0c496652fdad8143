"""The tow file's schema: every section and key with its type, units, rule and default, the
typed structs that read each section (msgspec, made from the schema), the errors that name
the key and its line, and the writer of the resolved file (tomli-w).

The schema is data (`SCHEMA`): the reader, the template and the documentation
(docs/towfile.md) all follow it, so a key is declared in one place.
"""

from __future__ import annotations

import math
import re
import warnings
from dataclasses import dataclass, field
from typing import Annotated, Any, NoReturn

import msgspec
import tomli_w
from msgspec import UNSET, Meta, UnsetType

from ..drift import FORMS as SAILING_FORMS
from ..guidelines import GUIDELINES
from ..lines import CHAIN_GRADES, LINES
from ..presets import REGRESSIONS, SEA_STATES, VESSELS

__all__ = [
    "TowFileError",
    "TowFileWarning",
    "Key",
    "SCHEMA",
    "SUBTABLES",
    "ARRAYS",
    "locate",
    "to_toml",
]


#: When a study runs the irregular-sea Monte Carlo ([study] risk).
RISK_MODES = ("auto", "always", "never")
#: The enums of the schema (a str key's choices), read from the library's own lists.
PRESETS = tuple(VESSELS)
FORMS = tuple(f for f in SAILING_FORMS if f != "stationary")  # the zero-speed bound only
LINE_NAMES = tuple(LINES)
GRADES = tuple(CHAIN_GRADES)
SEA_STATE_NAMES = tuple(SEA_STATES)
GUIDELINE_NAMES = tuple(GUIDELINES)


class TowFileError(ValueError):
    """A tow file that cannot be used: the message names the file, the line and the key."""

    def __init__(self, message: str, *, source: str = "", line: int | None = None, key: str = ""):
        self.source, self.line, self.key = source, line, key
        where = f"tow file {source}" if source else "tow file"
        if line is not None:
            where += f", line {line}"
        if key:
            where += f", key {key}"
        super().__init__(f"{where}: {message}")


class TowFileWarning(UserWarning):
    """A tow-file value that is usable but outside what the physics or the data cover."""


@dataclass(frozen=True)
class Key:
    """One key of a section: ``kind`` float | int | str | bool | floats (a list of numbers) |
    grid ([lo, hi, n]) | table (an inline table or a string) | tables (a list of inline
    tables); ``rule`` positive | nonnegative | finite | unit (0 < x ≤ 1) | None; ``choices``
    the values a str key may take (an enum: refused otherwise, with the list); ``units`` and
    ``doc`` for the template and the docs; ``default`` (None: no default); ``deprecated``
    the key that replaces it (a warning when given)."""

    kind: str
    doc: str
    units: str = "-"
    rule: str | None = None
    default: object = None
    choices: tuple = ()
    deprecated: str | None = None


def _keys(**kw) -> dict:
    return kw


#: The sections and their keys. ``sea_state`` is an array of tables ([[sea_state]]).
SCHEMA: dict[str, dict[str, Key]] = {
    "tow": _keys(
        name=Key("str", "a short name for outputs and the report"),
        description=Key("str", "one line on the tow for the report", default=""),
        speed=Key(
            "float",
            "design tow speed U_tug: the scale of the non-dimensional model",
            "m/s",
            "positive",
            2.0,
        ),
    ),
    "vessel": _keys(
        preset=Key("str", "a built-in manoeuvring model: barge_2a | barge_2b", choices=PRESETS),
        length=Key("float", "length L (the model's length scale)", "m", "positive"),
        breadth=Key("float", "breadth B", "m", "positive"),
        draft=Key("float", "draft T (default for a preset: the documented 5.0 m)", "m", "positive"),
        block_coefficient=Key(
            "float",
            "C_B: estimates the linear derivatives Yv, Yr, Nv, Nr that [vessel.derivatives] "
            "leaves out (the regression's; no appendages: add skegs with [vessel.skegs])",
            "-",
            "unit",
        ),
        regression=Key(
            "str",
            "clarke | kijima: the linear regression for the derivatives left out; given "
            "without [vessel.derivatives], every parameter is estimated from L, B, T and C_B "
            "(jaxtow.presets.particulars_derivatives)",
            choices=REGRESSIONS,
        ),
        skegs=Key(
            "table",
            "skegs added to the regression's linear derivatives (a vessel with "
            "block_coefficient): the keys of [vessel.skegs] below",
        ),
        derivatives=Key(
            "table",
            "non-dimensional mass and manoeuvring derivatives (Hong et al. convention, "
            "thesis Table 3.7): m, Izz, R0, Xvv, Xrr, Yv, Yr, Yvvv, Yrrr, Nv, Nr, Nvvv; "
            "optional a11, a22, a66 (default: 5 % of m' and Clarke et al. 1983)",
        ),
    ),
    "hull": _keys(
        waterline=Key(
            "str",
            "waterline for the waterline drift methods: box (L x B rectangle) | barge2 "
            "(the raked Barge 2) | a half-waterline file (jaxtow.io.read_waterline)",
        ),
        drift=Key(
            "table",
            "wave-drift source: a shipped panel database (barge1:far_field, "
            "barge2:near_field, ...), standin, a waterline method (kashiwagi, faltinsen, "
            "...) on the waterline, strip (strip theory of the box or barge2 waterline's "
            "hull; {strip = OFFSETS_FILE} for another), or a drift file as a path or {file = PATH, ulen = ..., "
            "rho = ..., g = ..., reference_point = ..., symmetry = ..., moment_set = ...}",
        ),
        mesh=Key(
            "table",
            "a hull mesh for a panel solve instead of drift (Capytaine, the bem extra): a "
            "path, or {file = PATH, method = near_field | far_field, omega = [lo, hi, n], "
            "beta_deg = [0, 180, n], cog_z = ..., symmetric = true}; solved once per "
            "frequency and cached beside the tow file",
        ),
        sailing_form=Key(
            "str",
            "forward-speed form of the drift: aranha | linear | thesis",
            default="aranha",
            choices=FORMS,
        ),
        wind_table=Key(
            "str",
            "wind coefficients: 'illustrative' (the ILLUSTRATIVE Barge 2 table) or a CSV "
            "file with columns angle_deg, cx, cy, cn from 0 to 180 deg",
            default="illustrative",
        ),
        wind_height=Key("float", "windage height above the waterline", "m", "positive"),
    ),
    "towline": _keys(
        l0=Key("float", "unstretched towline length l0' (by L)", "L", "positive"),
        length=Key("float", "unstretched towline length (instead of l0)", "m", "positive"),
        xp=Key("float", "attachment point x_p' ahead of the CoG (by L)", "L", "finite"),
        xp_m=Key("float", "attachment point ahead of the CoG (instead of xp)", "m", "finite"),
        yp=Key("float", "attachment point y_p' to port (by L)", "L", "finite", 0.0),
        EA_N=Key("float", "axial stiffness EA in newtons", "N", "positive"),
        EA_nd=Key(
            "float", "axial stiffness EA' = EA / (½ρTLU²) (instead of EA_N)", "-", "positive"
        ),
        EA=Key(
            "float",
            "deprecated spelling of EA_N (newtons): EA alone is ambiguous beside the "
            "model's non-dimensional EA'",
            "N",
            "positive",
            deprecated="EA_N",
        ),
        line=Key(
            "str",
            "a catalogue line (jaxtow.lines): wire | wire-fc | wire-spiral | chain | chain-studlink | nylon "
            "| polyester; its EA, weight and MBL come from diameter_mm (EA_N or weight given "
            "here replace the catalogue's)",
            choices=LINE_NAMES,
        ),
        diameter_mm=Key("float", "nominal diameter of the catalogue line", "mm", "positive"),
        grade=Key(
            "str", "chain grade: ORQ | R3 | R3S | R4 | R4S | R5 (default R3)", choices=GRADES
        ),
        segments=Key(
            "tables",
            "a composite line in series, from the hawser to the tug: [{line, diameter_mm, "
            "length, grade}, ...] (the keys of [towline.segments] below; instead of line, "
            "l0/length and EA_N)",
        ),
        weight=Key(
            "float",
            "submerged weight per unit length: the line is an elastic catenary "
            "(jaxtow.CatenaryTowline) instead of a straight elastic line",
            "N/m",
            "nonnegative",
        ),
        bridle=Key(
            "table",
            "a symmetric bridle {x_legs, half_spread, apex_x, line, diameter_mm, grade} (the "
            "keys of [towline.bridle] below): legs from (x_legs, ±half_spread) to the apex, "
            "which is then the attachment point",
        ),
    ),
    "tug": _keys(
        bollard_pull_t=Key("float", "bollard pull", "t", "positive"),
        free_speed=Key("float", "speed where the pull vanishes", "m/s", "positive"),
        efficiency=Key(
            "float",
            "offshore towing efficiency: the share of the rated pull the tug gives in the "
            "sea states and the weather criterion (default: the documented estimate 0.75)",
            "-",
            "unit",
        ),
        resistance_coefficient=Key(
            "float",
            "the tug's own resistance c U² (0: the pull curve is net)",
            "N s²/m²",
            "nonnegative",
            0.0,
        ),
        speeds=Key("floats", "a pull table: speeds from 0 (instead of the quadratic curve)", "m/s"),
        pulls_t=Key("floats", "a pull table: pulls at those speeds", "t"),
    ),
    "route": _keys(
        length_nm=Key("float", "route length", "nm", "positive"),
        length_m=Key("float", "route length (instead of length_nm)", "m", "positive"),
        water_depth=Key(
            "float",
            "least water depth on the route (the towline's seabed clearance)",
            "m",
            "positive",
        ),
    ),
    "sea_state": _keys(
        builtin=Key(
            "str",
            "a thesis sea state: survival | sailing (other keys override it)",
            choices=SEA_STATE_NAMES,
        ),
        name=Key("str", "name in tables and the report"),
        hs=Key("float", "significant wave height (0: calm water)", "m", "nonnegative"),
        tp=Key("float", "JONSWAP peak period", "s", "positive"),
        gamma=Key("float", "JONSWAP peak enhancement", "-", "positive", 3.3),
        wind_speed=Key("float", "wind speed", "m/s", "nonnegative", 0.0),
        current_speed=Key("float", "current speed", "m/s", "nonnegative", 0.0),
        wave_angle_deg=Key(
            "float", "waves from, relative to the course (0: head)", "deg", "finite", 0.0
        ),
        wind_angle_deg=Key("float", "wind from, relative to the course", "deg", "finite", 0.0),
        current_angle_deg=Key(
            "float", "current from, relative to the course", "deg", "finite", 0.0
        ),
        tug_efficiency=Key(
            "float",
            "the tug's efficiency in this sea state (default [tug] efficiency)",
            "-",
            "unit",
        ),
    ),
    "criteria": _keys(
        guideline=Key(
            "str",
            "the towing guideline the assessment checks: gl-nd-0030 | dnv-st-n001 "
            "(docs/guidelines.md); the keys below override its values",
            default="gl-nd-0030",
            choices=GUIDELINE_NAMES,
        ),
        wind_speed=Key("float", "weather criterion: wind speed", "m/s", "nonnegative"),
        hs=Key("float", "weather criterion: significant wave height", "m", "nonnegative"),
        current_speed=Key("float", "weather criterion: current speed", "m/s", "nonnegative"),
        tug_efficiency=Key(
            "float",
            "deprecated: the tug's efficiency is [tug] efficiency, one value for the sea "
            "states and the weather criterion; given here it must equal that one",
            "-",
            "unit",
            deprecated="tug.efficiency",
        ),
        length_factor=Key(
            "float", "minimum towline length = length_factor x BP/MBL", "m", "positive"
        ),
        connection_ratio=Key(
            "float", "MBL of connecting parts / towline MBL (estimate 1.0)", "-", "positive"
        ),
        seabed_clearance=Key(
            "float", "least clearance of the towline above the seabed", "m", "nonnegative"
        ),
    ),
    "study": _keys(
        map_xp=Key(
            "grid",
            "x_p' grid of the stability map [lo, hi, n] (default: the design x_p' ± 0.3 L "
            "within 0 to 1 L, 25 points)",
            "L",
        ),
        map_l0=Key(
            "grid",
            "l0' grid of the stability map [lo, hi, n] (default: a third to three times the "
            "design l0', 25 points)",
            "L",
        ),
        time_domain=Key("bool", "run the time-domain check", default=True),
        t1=Key("float", "time-domain run length (by L/U_tug)", "-", "positive", 400.0),
        psi0_deg=Key("float", "initial heading of the disturbed start", "deg", "finite", 0.0),
        y0=Key("float", "initial sway offset of the CoG (by L)", "L", "finite", 0.3),
        sea_states=Key("bool", "equilibria and stability in each sea state", default=True),
        speeds=Key(
            "grid", "tow speeds of the resistance table [lo, hi, n]", "m/s", default=[0.0, 3.5, 15]
        ),
        risk=Key(
            "str",
            "the irregular-sea Monte Carlo (jaxtow.risk): auto (for each sea state whose yaw "
            "criterion is not determined) | always (every sea state) | never",
            default="auto",
            choices=RISK_MODES,
        ),
        risk_budget_s=Key(
            "float",
            "wall-time budget of the Monte Carlo, all sea states and its design comparisons "
            "together (runs stop after the chunk that reaches it)",
            "s",
            "positive",
            300.0,
        ),
        risk_runs=Key("int", "most runs per sea state", "-", "positive", 256),
        risk_hours=Key("float", "duration of each run (the exposure)", "h", "positive", 3.0),
    ),
}

#: Sub-tables with keys of their own: [vessel.skegs] (`jaxtow.presets.Skegs`), a bridle, the
#: segments of a composite line, a hull mesh and a drift file's reading options.
SUBTABLES: dict[str, dict[str, Key]] = {
    "vessel.skegs": _keys(
        count=Key("int", "how many identical skegs (2: twin skegs)", "-", "positive", 2),
        span=Key(
            "float",
            "greatest depth of one skeg below the hull bottom it hangs from",
            "m",
            "positive",
        ),
        chord=Key("float", "length of one skeg along the hull", "m", "positive"),
        area=Key(
            "float",
            "lateral area of one skeg (default span x chord; a skeg filling a raked stern: "
            "span x chord / 2)",
            "m2",
            "positive",
        ),
        x=Key(
            "float",
            "where the skeg's force acts, from midships, + forward (default: the middle of "
            "a skeg ending at the stern, -L/2 + chord/2)",
            "m",
            "finite",
        ),
    ),
    "towline.bridle": _keys(
        x_legs=Key("float", "where the legs meet the hull, ahead of the CoG", "L", "finite"),
        half_spread=Key("float", "half the distance between the legs' ends", "L", "positive"),
        apex_x=Key("float", "the apex (the attachment point) ahead of the CoG", "L", "finite"),
        line=Key("str", "the legs' catalogue line (their MBL is checked)", choices=LINE_NAMES),
        diameter_mm=Key("float", "the legs' nominal diameter", "mm", "positive"),
        grade=Key("str", "chain grade of the legs", choices=GRADES),
    ),
    "towline.segments": _keys(
        line=Key("str", "the segment's catalogue line", choices=LINE_NAMES),
        diameter_mm=Key("float", "its nominal diameter", "mm", "positive"),
        length=Key("float", "its length", "m", "positive"),
        grade=Key("str", "chain grade", choices=GRADES),
    ),
    "hull.mesh": _keys(
        file=Key("str", "the mesh file (formats Capytaine reads)"),
        method=Key(
            "str",
            "near_field | far_field",
            default="near_field",
            choices=("near_field", "far_field"),
        ),
        omega=Key("grid", "frequencies [lo, hi, n]", "rad/s", default=[0.05, 2.5, 61]),
        beta_deg=Key("grid", "headings [0, 180, n]", "deg", default=[0.0, 180.0, 25]),
        cog_z=Key(
            "float",
            "the CoG above the keel (default the documented estimate, 10 m)",
            "m",
            "nonnegative",
        ),
        symmetric=Key("bool", "the hull is port-starboard symmetric", default=True),
    ),
    "hull.drift": _keys(
        file=Key("str", "a drift file (jaxtow, Capytaine, WAMIT .8/.9)"),
        strip=Key("str", "an offsets file: strip theory of that hull"),
        ulen=Key("float", "WAMIT's length scale ULEN", "m", "positive"),
        rho=Key("float", "the file's water density", "kg/m3", "positive"),
        g=Key("float", "the file's gravity", "m/s2", "positive"),
        reference_point=Key("floats", "the file's moment reference point (x, y)", "m"),
        symmetry=Key("str", "how to complete the headings: auto | none | ..."),
        symmetry_tol=Key("float", "the symmetry check's tolerance", "-", "positive"),
        moment_set=Key("int", "WAMIT's moment set I", "-", "positive"),
    ),
}

#: Sections that are arrays of tables.
ARRAYS = frozenset({"sea_state"})
#: Sections a tow file must have.
REQUIRED = ("tow", "vessel")


class Invalid(ValueError):
    """A value of the wrong kind or outside its rule (the message says which; ``key`` names
    the key where a section was checked)."""

    def __init__(self, message: str, key: str | None = None):
        super().__init__(message)
        self.key = key


#: Each kind's type (msgspec converts and checks it) and each rule's constraint.
_RULES = {
    None: Meta(),
    "finite": Meta(),
    "positive": Meta(gt=0),
    "nonnegative": Meta(ge=0),
    "unit": Meta(gt=0, le=1),
}
_GRID = tuple[float, float, Annotated[int, Meta(ge=1)]]


def _type(key: Key):
    kinds = {
        "float": Annotated[float, _RULES[key.rule]],
        "int": Annotated[int, _RULES[key.rule]],
        "str": str,
        "bool": bool,
        "floats": list[float],
        "grid": _GRID,
        "table": str | dict[str, Any],
        "tables": Annotated[list[dict[str, Any]], Meta(min_length=1)],
    }
    return kinds[key.kind]


def section_struct(name: str, keys: dict[str, Key]) -> type[msgspec.Struct]:
    """The typed struct of one section: every key optional (a missing key is UNSET), unknown
    keys refused."""
    fields = [(k, _type(key) | UnsetType, UNSET) for k, key in keys.items()]
    return msgspec.defstruct(f"{name}_section", fields, kw_only=True, forbid_unknown_fields=True)


def _reason(error: msgspec.ValidationError, value) -> str:
    """msgspec's sentence without its path, with the value where it does not name it."""
    text = str(error).split(" - at `", 1)[0]
    return f"{text} ({value!r})" if " got " in text else f"{text}, got {value!r}"


def _checked(key: str, kind: str, value, choices: tuple = ()):
    """Rules msgspec does not state: finite numbers, a grid's hi > lo, an enum's values."""
    if choices and value not in choices:
        raise Invalid(f"must be one of {', '.join(map(str, choices))}, got {value!r}")
    if kind in ("float", "int") and not math.isfinite(value):
        raise Invalid(f"must be finite, got {value!r}")
    if kind == "floats" and not all(math.isfinite(x) for x in value):
        raise Invalid(f"must be finite numbers, got {value!r}")
    if kind == "grid":
        lo, hi, n = value
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise Invalid(f"must be finite, got {list(value)!r}")
        if n > 1 and not hi > lo:
            raise Invalid(f"needs hi > lo, got [{lo:g}, {hi:g}]")
        return [float(lo), float(hi), int(n)]
    return value


def check_section(name: str, table: dict, keys: dict[str, Key] | None = None) -> dict:
    """The keys of ``table`` (a section's known keys) converted by the section's typed struct
    and checked by their rules: {key: value} of the keys given; `Invalid` with the key
    otherwise (``Invalid.key``)."""
    keys = SCHEMA[name] if keys is None else keys
    struct = _STRUCTS.get(name) if keys is SCHEMA.get(name) else _struct(name, keys)
    try:
        obj = msgspec.convert(table, struct, strict=True)
    except msgspec.ValidationError as e:
        m = re.search(r" - at `\$\.(\w+)", str(e))
        k = m.group(1) if m else None
        raise Invalid(_reason(e, table.get(k) if k else table), key=k) from None
    out = {}
    for k in keys:
        v = getattr(obj, k)
        if v is UNSET:
            continue
        try:
            out[k] = _checked(k, keys[k].kind, v, keys[k].choices)
        except Invalid as e:
            raise Invalid(str(e), key=k) from None
    return out


def check_value(key: Key, value):
    """One value converted to ``key``'s kind and checked by its rule; `Invalid` otherwise."""
    return check_section("value", {"value": value}, {"value": key})["value"]


_HEADER = re.compile(r"^\s*(\[\[?)\s*([A-Za-z0-9_.\-]+)\s*\]\]?")
_KEYLINE = re.compile(r"^\s*([A-Za-z0-9_\-]+)\s*=")


def locate(text: str, path: tuple) -> int | None:
    """The 1-based line of ``path`` in the TOML ``text``: (section,), (section, key),
    (section, index, key) for an array of tables, or a dotted sub-table (vessel,
    derivatives, key). None where it is not written (a missing key)."""
    if not text:
        return None
    want = [p for p in path if not isinstance(p, int)]
    index = next((p for p in path if isinstance(p, int)), None)
    counts: dict[str, int] = {}
    current: tuple = ()
    section_line = None
    for n, line in enumerate(text.splitlines(), 1):
        stripped = line.split("#", 1)[0]
        h = _HEADER.match(stripped)
        if h:
            name = h.group(2)
            if h.group(1) == "[[":
                counts[name] = counts.get(name, -1) + 1
                current = (name, counts[name])
            else:
                current = (name,)
            names = tuple(name.split("."))
            same_index = index is None or (len(current) > 1 and current[1] == index)
            if names == tuple(want) and same_index:
                return n
            if names == tuple(want[: len(names)]) and same_index:
                section_line = n
            continue
        sec = current[0].split(".") if current else []
        idx = current[1] if len(current) > 1 else None
        if index is not None and idx != index:
            continue
        rest = want[len(sec) :]
        if sec != want[: len(sec)] or not rest:
            continue
        k = _KEYLINE.match(stripped)
        if k and k.group(1) == rest[0]:
            if len(rest) == 1:
                return n
            # a key inside an inline table on this line
            if re.search(rf"[{{,]\s*{re.escape(rest[1])}\s*=", stripped):
                return n
            return n
    return section_line


def _plain(v):
    """``v`` without None values (TOML has no null), tuples as lists."""
    if isinstance(v, dict):
        return {k: _plain(x) for k, x in v.items() if x is not None}
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    return v


def to_toml(data: dict, comments: dict | None = None) -> str:
    """TOML text of a resolved tow file (written by tomli-w), with ``comments[(section,
    key)]`` (or ``comments[(section, index, key)]`` in an array of tables) after the values."""
    comments = comments or {}
    out = []
    section, index, counts = None, None, {}
    for line in tomli_w.dumps(_plain(data)).splitlines():
        h = _HEADER.match(line)
        if h:
            section = h.group(2)
            if h.group(1) == "[[":
                counts[section] = index = counts.get(section, -1) + 1
            else:
                index = None
        k = None if h else _KEYLINE.match(line)
        if k and section is not None:
            note = comments.get((section, index, k.group(1))) or comments.get((section, k.group(1)))
            if note:
                line = f"{line:<40} # {note}"
        out.append(line)
    return "\n".join(out) + "\n"


@dataclass
class Problems:
    """Collects the first error (raised) with its key and line."""

    text: str
    source: str
    warnings: list = field(default_factory=list)

    def error(self, path: tuple, message: str) -> NoReturn:
        key = ".".join(str(p) if not isinstance(p, int) else f"[{p + 1}]" for p in path)
        key = key.replace(".[", "[")
        raise TowFileError(message, source=self.source, line=locate(self.text, path), key=key)

    def warn(self, path: tuple, message: str):
        key = ".".join(str(p) if not isinstance(p, int) else f"[{p + 1}]" for p in path)
        key = key.replace(".[", "[")
        line = locate(self.text, path)
        where = f"tow file {self.source}" + (f", line {line}" if line else "") + f", key {key}"
        msg = f"{where}: {message}"
        self.warnings.append(msg)
        warnings.warn(msg, TowFileWarning, stacklevel=4)


def read_section(p: Problems, name: str, table, index=None) -> dict:
    """A section read by its typed struct (`check_section`), with a suggestion for an unknown
    key, the schema's defaults filled in and a warning for a deprecated key."""
    path = (name,) if index is None else (name, index)
    return _read(p, path, table, name, SCHEMA[name])


def read_subtable(p: Problems, path: tuple, table, name: str, label: str = "") -> dict:
    """A sub-table (`SUBTABLES`: [vessel.skegs], a bridle, a segment, a mesh, a drift file's
    options) read as `read_section` reads a section; ``path`` locates it for the errors,
    ``label`` starts their message (which of a list of tables)."""
    return _read(p, path, table, name, SUBTABLES[name], label)


def _read(p: Problems, path: tuple, table, name: str, keys: dict, label: str = "") -> dict:
    said = f"{label}: " if label else ""
    if not isinstance(table, dict):
        p.error(path, f"{said}expected a table [{name}]")
    for k in table:
        if k not in keys:
            close = [c for c in keys if c.lower() == k.lower() or c.startswith(k[:3])]
            hint = f"; did you mean {close[0]!r}?" if close else ""
            p.error(path + (k,), f"{said}unknown key{hint} (keys of [{name}]: {', '.join(keys)})")
    try:
        out = check_section(name, table, keys)
    except Invalid as e:
        p.error(path + ((e.key,) if e.key else ()), f"{said}{e}")
    for k, key in keys.items():
        if key.deprecated and k in out:
            p.warn(path + (k,), f"deprecated, use {key.deprecated}: {key.doc}")
        if k not in out and key.default is not None:
            out[k] = list(key.default) if isinstance(key.default, list) else key.default
    return out


def schema_markdown() -> str:
    """The key tables of docs/towfile.md, made from `SCHEMA` (a test keeps the page equal)."""
    out = []
    for sec, keys in {**SCHEMA, **SUBTABLES}.items():
        head = f"[[{sec}]]" if sec in ARRAYS else f"[{sec}]"
        out += [
            f"### `{head}`",
            "",
            "| key | units | default | meaning |",
            "| --- | --- | --- | --- |",
        ]
        for k, key in keys.items():
            d = key.default
            if d is None:
                dflt = "—"
            elif isinstance(d, bool):
                dflt = f"`{str(d).lower()}`"
            elif d == "":
                dflt = '`""`'
            else:
                dflt = f"`{d}`"
            doc = key.doc.replace("|", chr(92) + "|")
            out.append(f"| `{k}` | {key.units} | {dflt} | {doc} |")
        out.append("")
    return "\n".join(out)


#: The typed struct of each section (made from `SCHEMA`, so a key is still declared once).
_STRUCTS = {name: section_struct(name, keys) for name, keys in SCHEMA.items()}
_SUBSTRUCTS = {
    name: section_struct(name.replace(".", "_"), keys) for name, keys in SUBTABLES.items()
}


def _struct(name: str, keys: dict):
    if keys is SUBTABLES.get(name):
        return _SUBSTRUCTS[name]
    return section_struct(name.replace(".", "_"), keys)
