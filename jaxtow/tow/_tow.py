"""A tow described in one file: reading, validating and resolving a tow file into the
objects of the model (vessel, towline, scales, drift source, tug, sea states)."""

from __future__ import annotations

import copy
import math
import re
import tomllib
import warnings
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .. import bem, guidelines, lines, presets, strip
from .._dynamics import TowModel
from .._simulate import initial_state
from .._towline import Bridle, CatenaryTowline, Towline
from .._units import Scales
from .._vessel import Vessel
from ..drift import METHODS
from ..drift._compare import qtf_from_method
from ..forces import CombinedForce
from ..forces._waves import IrregularWaveDriftForce
from ..forces._wind import WindForce
from ..io import read_waterline
from ..io.resistance import read_coefficient_table
from ..presets import (
    DATABASE_METHODS,
    DATABASES,
    QTF_BETA_DEG,
    QTF_OMEGA,
    STANDIN,
    barge2_waterline,
    box_waterline,
    drift_source,
)
from ..resistance import SeaState, Tug, WaveDrift, tow_resistance
from ..waves import DEFAULT_OMEGA, Jonswap, physical_tp_range
from ._schema import (
    ARRAYS,
    REQUIRED,
    SCHEMA,
    SUBTABLES,
    Invalid,
    Key,
    Problems,
    TowFileError,
    check_section,
    check_value,
    to_toml,
)

if TYPE_CHECKING:
    from .._towline import AbstractTowline
    from .._units import Scales
    from .._vessel import Vessel
    from ..drift import Waterline
    from ..resistance import Tug

__all__ = [
    "BUILTIN_TOWS",
    "DEPRECATED_NAMES",
    "Tow",
    "load",
    "loads",
    "builtin_text",
    "canonical_name",
    "template",
    "show",
]

#: Built-in tow files (jaxtow/data/tows): one spelling everywhere in the command line.
BUILTIN_TOWS = {"barge1": "barge1.toml", "barge2a": "barge2a.toml", "barge2b": "barge2b.toml"}
#: Old spellings of the built-ins, accepted for one release with a deprecation message.
DEPRECATED_NAMES = {"barge_2a": "barge2a", "barge_2b": "barge2b", "barge2": "barge2a"}

_DERIVATIVES = ("m", "Izz", "R0", "Xvv", "Xrr", "Yv", "Yr", "Yvvv", "Yrrr", "Nv", "Nr", "Nvvv")
_ADDED = ("a11", "a22", "a66")
_BRIDLE = ("x_legs", "half_spread", "apex_x")
_PAIRS = {  # the towline keys given one way or the other (exactly one of each pair)
    "length": ("l0", "length"),
    "attachment": ("xp", "xp_m"),
    "stiffness": ("EA", "EA_nd"),
}


def canonical_name(name: str) -> tuple[str, str | None]:
    """(built-in name, deprecation message or None) for a built-in tow's spelling; other
    strings (file paths) pass through."""
    if name in DEPRECATED_NAMES:
        new = DEPRECATED_NAMES[name]
        return new, f"the name {name!r} is deprecated and will be removed; use {new!r}"
    return name, None


def builtin_text(name: str) -> str:
    """The TOML text of a built-in tow file."""
    return resources.files("jaxtow").joinpath("data", "tows", BUILTIN_TOWS[name]).read_text()


def template() -> str:
    """A commented template of a tow file with every section and key (`jaxtow tow new`)."""
    return resources.files("jaxtow").joinpath("data", "tows", "template.toml").read_text()


@dataclass(frozen=True)
class Tow:
    """A resolved tow file. ``resolved`` is the file with every default filled in (what
    `show` prints); ``assumed`` the (key, note) pairs of every estimate the results depend
    on; ``warnings`` the values outside the physics' or the data's range; ``line_info``
    the catalogue lines of the towline (name, length, MBL) where it names them. Build the model
    objects with `model`, `resistance`, `sea_model`; `drift` gives the drift QTF."""

    name: str
    source: str
    resolved: dict
    scales: Scales
    vessel: Vessel | None
    towline: AbstractTowline | None
    waterline: Waterline
    drift_spec: object
    form: str
    tug: Tug | None
    sea_states: tuple
    route_length: float | None
    water_depth: float | None
    study: dict
    assumed: tuple
    wind_table: object
    wind_height: float
    warnings: tuple = ()
    line_info: list | None = None
    criteria: guidelines.Criteria = guidelines.GUIDELINES["gl-nd-0030"]
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    # ------------------------------------------------------------------ model objects
    def _need_model(self):
        if self.vessel is None or self.towline is None:
            missing = "[vessel] derivatives (or preset)" if self.vessel is None else "[towline]"
            raise TowFileError(
                f"this tow has no manoeuvring model: stability needs {missing}",
                source=self.source,
            )

    def model(self, external=None):
        """The `jaxtow.TowModel` of the tow (calm water unless ``external`` is given), with
        its scales (so ``u_tug`` can be swept)."""

        self._need_model()
        ext = {} if external is None else dict(external=external)
        return TowModel(vessel=self.vessel, towline=self.towline, scales=self.scales, **ext)

    def drift(self):
        """(QTF, description) of the tow's wave-drift source (cached)."""
        if "drift" not in self._cache:
            spec = self.drift_spec
            if isinstance(spec, dict) and "mesh" in spec:
                self._cache["drift"] = _mesh_drift(spec, self.resolved["hull"]["sailing_form"])
            elif isinstance(spec, dict) and "strip" in spec:
                self._cache["drift"] = _strip_drift(spec["strip"], self.waterline)
            elif isinstance(spec, str) and spec in METHODS:
                q = qtf_from_method(spec, self.waterline, QTF_OMEGA, _radians(QTF_BETA_DEG))
                desc = (
                    f"waterline method {spec!r} on the {self.waterline.name} waterline "
                    "(diffraction only, no motion-induced drift)"
                )
                self._cache["drift"] = (q, desc)
            else:
                self._cache["drift"] = drift_source(spec)
        return self._cache["drift"]

    def resistance(self):
        """The `jaxtow.resistance.TowResistance` of the tow (current from the manoeuvring
        derivatives, wind from the wind table, mean drift from the drift source)."""

        self._need_model()
        sc = self.scales
        if isinstance(self.drift_spec, str) and self.drift_spec in METHODS:
            waves = WaveDrift(self.waterline, method=self.drift_spec)
        else:
            waves = WaveDrift(qtf=self.drift()[0], form=self.form)
        return tow_resistance(
            self.vessel,
            sc.length,
            float(self.resolved["vessel"]["breadth"]),
            sc.draft,
            waves,
            wind_table=self.wind_table,
            wind_height=self.wind_height,
            name=self.name,
            assumed=self.assumed,
        )

    def sea_model(self, sea, *, omega=None, form: str | None = None):
        """The tow model in sea state ``sea``: mean irregular-sea drift (JONSWAP Hs, Tp, γ)
        and the wind, both from ahead of the course (the model's head-sea convention); the
        directions of ``sea`` enter the resistance budget only. ``form``: the forward-speed
        form of the drift (default the tow file's; `jaxtow.drift.sailing_drift`)."""

        self._need_model()
        forces = []
        if float(sea.hs) > 0:
            forces.append(
                IrregularWaveDriftForce(
                    qtf=self.drift()[0],
                    spectrum=Jonswap(hs=sea.hs, tp=sea.tp, gamma=sea.gamma),
                    omega=DEFAULT_OMEGA if omega is None else omega,
                    scales=self.scales,
                    form=self.form if form is None else form,
                )
            )
        if float(sea.wind_speed) > 0:
            forces.append(
                WindForce(load=self.resistance().wind, speed=sea.wind_speed, scales=self.scales)
            )
        ext = None if not forces else forces[0] if len(forces) == 1 else CombinedForce(forces)
        return self.model(ext)

    def show(self) -> str:
        """The resolved file as TOML, each estimate marked (`jaxtow tow show`)."""
        return show(self)


def _radians(x):
    return np.radians(x)


# ---------------------------------------------------------------------- reading


def load(spec) -> Tow:
    """A `Tow` from a built-in name (`BUILTIN_TOWS`; old spellings with a deprecation
    warning), a tow-file path, or an already parsed dict."""

    if isinstance(spec, dict):
        return _resolve(spec, "", "<dict>")
    spec = str(spec)
    name, msg = canonical_name(spec)
    if msg:
        warnings.warn(msg, DeprecationWarning, stacklevel=2)
    if name in BUILTIN_TOWS:
        return loads(builtin_text(name), source=f"<built-in {name}>", base=None)
    path = Path(spec)
    if not path.is_file():
        raise TowFileError(
            f"no such file, and not a built-in tow ({', '.join(BUILTIN_TOWS)})", source=spec
        )
    return loads(path.read_text(), source=str(path), base=path.parent)


def loads(text: str, source: str = "<string>", base=None) -> Tow:
    """A `Tow` from TOML text; relative file names in it are taken from ``base``."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        m = _line_of(str(e))
        raise TowFileError(f"not valid TOML: {e}", source=source, line=m) from None
    return _resolve(data, text, source, base)


def _line_of(message: str):
    m = re.search(r"line (\d+)", message)
    return int(m.group(1)) if m else None


def _check_section(p: Problems, name: str, table, index=None) -> dict:
    """A section read by its typed struct (`jaxtow.tow._schema.check_section`), with a
    suggestion for an unknown key and the schema's defaults filled in."""
    path = (name,) if index is None else (name, index)
    if not isinstance(table, dict):
        p.error(path, "expected a table")
    keys = SCHEMA[name]
    for k in table:
        if k not in keys:
            close = [c for c in keys if c.lower() == k.lower() or c.startswith(k[:3])]
            hint = f"; did you mean {close[0]!r}?" if close else ""
            p.error(path + (k,), f"unknown key{hint} (keys of [{name}]: {', '.join(keys)})")
    try:
        out = check_section(name, table)
    except Invalid as e:
        p.error(path + ((e.key,) if e.key else ()), str(e))
    for k, key in keys.items():
        if k not in out and key.default is not None:
            out[k] = list(key.default) if isinstance(key.default, list) else key.default
    return out


def _resolve(data: dict, text: str, source: str, base=None) -> Tow:
    """Check a parsed tow file and resolve it, one section at a time (each function below
    fills the section's defaults in place, so that ``resolved`` is the file as it was used)."""
    p = Problems(text, source)
    _check_sections(p, data)
    sec = {k: _check_section(p, k, data.get(k, {})) for k in SCHEMA if k not in ARRAYS}
    seas_raw = [
        _check_section(p, "sea_state", s, i) for i, s in enumerate(data.get("sea_state", []))
    ]
    assumed: list = []
    if "name" not in sec["tow"]:
        p.error(("tow", "name"), "missing key: every tow needs a name")
    v = sec["vessel"]
    vessel = _vessel(p, v, sec["tow"]["name"], assumed)
    L, B, T = float(v["length"]), float(v["breadth"]), float(v["draft"])
    scales = Scales(length=L, draft=T, u_tug=sec["tow"]["speed"])
    h = sec["hull"]
    waterline = _waterline(p, h, "preset" in v, base, L, B, T)
    drift = _drift(p, h, "preset" in v, base, T, assumed)
    form = h["sailing_form"]
    if form not in ("aranha", "linear", "thesis"):
        p.error(("hull", "sailing_form"), f"aranha, linear or thesis, got {form!r}")
    wind_table = _wind(p, h, base, assumed)
    assumed.append(("wave_drift", _describe_drift(drift, form)))
    towline, line_info = None, None
    if "towline" in data:
        towline, line_info = _towline(p, sec["towline"], "preset" in v, scales, assumed)
    elif vessel is not None:
        p.error(
            ("towline",),
            "missing section [towline]: a tow with a manoeuvring model needs its towline",
        )
    if towline is not None:
        _check_geometry(p, sec["towline"], sec["study"], vessel, towline, L)
    tug = _tug(p, sec["tug"])
    route, water_depth = _route(p, sec["route"])
    seas = _sea_states(p, seas_raw, data.get("sea_state", []))
    crit = _criteria(p, sec["criteria"])
    return Tow(
        name=sec["tow"]["name"],
        source=source,
        resolved=_resolved(data, sec, v, seas_raw),
        scales=scales,
        vessel=vessel,
        towline=towline,
        waterline=waterline,
        drift_spec=drift,
        form=form,
        tug=tug,
        sea_states=tuple(seas),
        route_length=route,
        water_depth=water_depth,
        study=sec["study"],
        assumed=tuple(assumed),
        wind_table=wind_table,
        wind_height=float(h["wind_height"]),
        warnings=tuple(p.warnings),
        line_info=line_info,
        criteria=crit,
    )


def _criteria(p: Problems, c: dict) -> guidelines.Criteria:
    """The [criteria] section: a guideline and its overridden values."""
    name = c["guideline"]
    if name not in guidelines.GUIDELINES:
        p.error(
            ("criteria", "guideline"),
            f"unknown guideline {name!r} (one of {', '.join(sorted(guidelines.GUIDELINES))})",
        )
        name = "gl-nd-0030"
    return guidelines.criteria(name, **{k: float(v) for k, v in c.items() if k != "guideline"})


def _check_sections(p: Problems, data: dict) -> None:
    for k in data:
        if k not in SCHEMA:
            p.error((k,), f"unknown section [{k}] (sections: {', '.join(SCHEMA)})")
    for k in REQUIRED:
        if k not in data:
            p.error((k,), f"missing section [{k}]")
    if "sea_state" in data and not isinstance(data["sea_state"], list):
        p.error(("sea_state",), "write sea states as [[sea_state]] (an array of tables)")


def _resolved(data: dict, sec: dict, v: dict, seas_raw: list) -> dict:
    """The file as used: the sections it has (and the required ones), defaults filled in."""
    resolved = {k: val for k, val in sec.items() if k in data or k in REQUIRED}
    resolved["vessel"] = dict(v)
    if seas_raw:
        resolved["sea_state"] = seas_raw
    resolved["study"] = sec["study"]
    return resolved


# ---------------------------------------------------------------------- [vessel]


def _vessel(p: Problems, v: dict, name: str, assumed: list) -> Vessel | None:
    """The [vessel] section: a built-in vessel, or one from derivatives and particulars (None:
    a hull without a manoeuvring model, for its drift and resistance only)."""
    if "preset" in v:
        return _preset_vessel(p, v, assumed)
    for k in ("length", "breadth", "draft"):
        if k not in v:
            p.error(
                ("vessel", k),
                "missing key: a vessel without a preset needs length, breadth and draft",
            )
    regression = v.get("regression")
    if regression is not None and regression not in presets.REGRESSIONS:
        p.error(
            ("vessel", "regression"),
            f"unknown regression {regression!r}; known: {', '.join(presets.REGRESSIONS)}",
        )
    if regression is not None and "block_coefficient" not in v:
        p.error(("vessel", "block_coefficient"), "missing key: a regression needs C_B")
    d = v.get("derivatives", {} if regression is not None else None)
    skegs = _skegs(p, v, d)
    if d is None:
        return None
    _check_derivatives(p, d)
    notes: list = []
    if "block_coefficient" in v:
        d, notes = _fill_from_particulars(v, d, regression, skegs)
    missing = [k for k in _DERIVATIVES if k not in d]
    if missing:
        p.error(("vessel", "derivatives"), f"missing derivative(s) {', '.join(missing)}")
    vals = {k: float(d[k]) for k in d}
    notes += _fill_added_masses(vals, v)
    try:
        vessel = Vessel(**vals, name=name, assumed=tuple(notes))
    except ValueError as e:
        p.error(("vessel", "derivatives"), str(e))
    assumed += notes
    return vessel


def _preset_vessel(p: Problems, v: dict, assumed: list) -> Vessel:
    if v["preset"] not in presets.VESSELS:
        p.error(
            ("vessel", "preset"),
            f"unknown preset {v['preset']!r}; built-in vessels: {', '.join(presets.VESSELS)}",
        )
    if "derivatives" in v:
        p.error(("vessel", "derivatives"), "give either preset or derivatives, not both")
    if "skegs" in v:
        p.error(
            ("vessel", "skegs"),
            "a preset's derivatives are measured with its appendages (barge_2b has skegs); "
            "skegs add to a regression's estimates only",
        )
    for k, val in (("length", presets.BARGE2_LENGTH), ("breadth", presets.BARGE2_BREADTH)):
        if k in v and v[k] != val:
            p.error(
                ("vessel", k), f"the preset's {k} is {val} m; for another hull give derivatives"
            )
    v.setdefault("length", presets.BARGE2_LENGTH)
    v.setdefault("breadth", presets.BARGE2_BREADTH)
    if "draft" not in v:
        v["draft"] = float(presets.ASSUMPTIONS["draft"]["value"])
    vessel = presets.VESSELS[v["preset"]](v["draft"])
    assumed += list(vessel.assumed)
    return vessel


def _check_derivatives(p: Problems, d) -> None:
    if not isinstance(d, dict):
        p.error(("vessel", "derivatives"), "expected a table of derivatives")
    for k, val in d.items():
        if k not in _DERIVATIVES + _ADDED:
            p.error(
                ("vessel", "derivatives", k),
                f"unknown derivative (known: {', '.join(_DERIVATIVES + _ADDED)})",
            )
        if isinstance(val, bool) or not isinstance(val, (int, float)) or not math.isfinite(val):
            p.error(("vessel", "derivatives", k), f"expected a finite number, got {val!r}")


def _skegs(p: Problems, v: dict, d: dict | None):
    """[vessel.skegs]: a `presets.Skegs` added to the regression's linear derivatives (None:
    no skegs). Refused where no regression estimates them, or where a linear derivative is
    given (a measured value already holds the hull's appendages)."""
    if "skegs" not in v:
        return None
    path = ("vessel", "skegs")
    table = v["skegs"]
    if not isinstance(table, dict):
        p.error(path, "expected a table [vessel.skegs] with span, chord (and count, area, x)")
    keys = SUBTABLES["vessel.skegs"]
    for k in table:
        if k not in keys:
            p.error(path + (k,), f"unknown key (keys of [vessel.skegs]: {', '.join(keys)})")
    try:
        out = check_section("vessel.skegs", table, keys)
    except Invalid as e:
        p.error(path + ((e.key,) if e.key else ()), str(e))
    for k in ("span", "chord"):
        if k not in out:
            p.error(path + (k,), "missing key: skegs need their span and chord")
    if "block_coefficient" not in v:
        p.error(
            path,
            "skegs add to the linear derivatives a regression estimates: give "
            "[vessel] block_coefficient (and regression), not measured Yv, Yr, Nv, Nr",
        )
    if d is None:
        p.error(
            path,
            "skegs change the manoeuvring derivatives, and this vessel has none: name a "
            "[vessel] regression or give [vessel.derivatives]",
        )
    given = [k for k in ("Yv", "Yr", "Nv", "Nr") if k in d]
    if given:
        p.error(
            ("vessel", "derivatives", given[0]),
            "a given linear derivative already holds the hull's appendages; with "
            "[vessel.skegs] leave Yv, Yr, Nv, Nr to the regression",
        )
    out.setdefault("count", keys["count"].default)
    v["skegs"] = out
    try:
        skegs = presets.Skegs(**out)
        presets.skeg_derivatives(v["length"], v["draft"], skegs)
    except ValueError as e:
        p.error(path, str(e))
    return skegs


def _fill_from_particulars(v: dict, d: dict, regression, skegs=None) -> tuple[dict, list]:
    """The derivatives not given, estimated from the particulars: every one with a
    regression named; with none named only the linear ones (Clarke), the rest must be given."""
    est, est_notes = presets.particulars_derivatives(
        v["length"],
        v["breadth"],
        v["draft"],
        v["block_coefficient"],
        regression or "clarke",
        skegs=skegs,
    )
    fill = [k for k in _DERIVATIVES + _ADDED if k not in d]
    if regression is None:
        fill = [k for k in fill if k in ("Yv", "Yr", "Nv", "Nr")]
    elif "a11" in d and "Yr" in fill and regression == "kijima":
        est["Yr"] += float(d["a11"]) - est["a11"]  # Y_r' − m_x' = πk/4
    return {**d, **{k: est[k] for k in fill}}, [(k, est_notes[k]) for k in fill]


def _fill_added_masses(vals: dict, v: dict) -> list:
    """Added masses a full table of derivatives leaves out, from the Clarke regressions."""
    if all(k in vals for k in _ADDED):
        return []
    added = presets.clarke_added_mass(vals["m"], v["length"], v["breadth"], v["draft"])
    notes = []
    for k in _ADDED:
        if k not in vals:
            vals[k] = added[k]
            note = (
                presets.ASSUMPTIONS["a11_over_m"]["note"]
                if k == "a11"
                else presets.ASSUMPTIONS["a22,a66"]["note"].replace(
                    "C_B from m' and T = 5.0 m", f"C_B from m' and T = {v['draft']} m"
                )
            )
            notes.append((k, note))
    return notes


# ---------------------------------------------------------------------- [hull]


def _waterline(p: Problems, h: dict, preset: bool, base, L: float, B: float, T: float):
    wl_spec = h.get("waterline", "barge2" if preset else "box")
    h["waterline"] = wl_spec
    if wl_spec == "box":
        return box_waterline(L, B, T)
    if wl_spec == "barge2":
        return barge2_waterline(T)
    path = _path(wl_spec, base)
    if not path.is_file():
        p.error(("hull", "waterline"), f"box, barge2 or a waterline file; no file {str(path)!r}")
    try:
        return read_waterline(path, draft=T)
    except (ValueError, OSError) as e:
        p.error(("hull", "waterline"), str(e))


def _drift(p: Problems, h: dict, preset: bool, base, T: float, assumed: list):
    """The drift source of [hull]: a mesh to solve, a drift-file table, a shipped database,
    the stand-in, a waterline method or a file (checked here, read when used)."""
    drift = h.get("drift")
    if "mesh" in h:
        if drift is not None:
            p.error(("hull", "mesh"), "give either drift or mesh, not both")
        drift = _mesh_spec(p, h["mesh"], base, T)
    if drift is None:
        drift = "barge2:near_field" if preset else "kashiwagi"
        h["drift"] = drift
        if not preset:
            assumed.append(
                (
                    "wave_drift",
                    f"no drift source given: the Kashiwagi waterline method on the {h['waterline']} waterline (estimate)",
                )
            )
    if isinstance(drift, dict) and "mesh" in drift:
        return drift
    if drift == "strip" or (isinstance(drift, dict) and "strip" in drift):
        return _strip_spec(p, h, drift, base)
    if isinstance(drift, dict):
        if "file" not in drift:
            p.error(("hull", "drift"), "a drift-file table needs file = PATH")
        path = _path(drift["file"], base)
        if not path.is_file():
            p.error(("hull", "drift"), f"no such drift file: {path}")
        return dict(drift, file=str(path))
    if isinstance(drift, str) and drift not in METHODS:
        return _named_drift(p, drift, base)
    return drift


def _strip_spec(p: Problems, h: dict, drift, base) -> dict:
    """drift = "strip" (the box or Barge 2 of the waterline) or {strip = OFFSETS_FILE}."""
    if drift == "strip":
        if h["waterline"] not in ("box", "barge2"):
            p.error(
                ("hull", "drift"),
                "drift = 'strip' needs waterline = 'box' or 'barge2' (the hull of the strips); "
                "for another hull give {strip = OFFSETS_FILE}",
            )
        return {"strip": h["waterline"]}
    path = _path(drift["strip"], base)
    if not path.is_file():
        p.error(("hull", "drift"), f"no such offsets file for the strips: {path}")
    return {"strip": str(path)}


def _named_drift(p: Problems, drift: str, base) -> str:
    hull_name, _, method = drift.rpartition(":")
    if drift == STANDIN or (hull_name in DATABASES and method in DATABASE_METHODS):
        return drift
    if drift in DATABASE_METHODS:
        p.error(
            ("hull", "drift"),
            f"name the hull too, e.g. 'barge2:{drift}' (hulls: {', '.join(DATABASES)})",
        )
    path = _path(drift, base)
    if not path.is_file():
        p.error(
            ("hull", "drift"),
            f"{drift!r} is not a shipped database (hull:method with hull in "
            f"{', '.join(DATABASES)}), {STANDIN!r}, a waterline method "
            f"({', '.join(METHODS)}) or a file",
        )
    return str(path)


def _wind(p: Problems, h: dict, base, assumed: list):
    """The wind table and windage height of [hull]."""
    if h["wind_table"] == "illustrative":
        wind_table = presets.barge2_wind_table()
        assumed.append(("wind_table", presets.ASSUMPTIONS["wind_table"]["note"]))
    else:
        try:
            wind_table = read_coefficient_table(_path(h["wind_table"], base))
        except ValueError as e:
            p.error(("hull", "wind_table"), str(e))
    if "wind_height" not in h:
        h["wind_height"] = float(presets.ASSUMPTIONS["wind_height"]["value"])
        assumed.append(("wind_height", presets.ASSUMPTIONS["wind_height"]["note"]))
    return wind_table


# ---------------------------------------------------------------------- [towline]


def _towline(p: Problems, t: dict, preset: bool, scales: Scales, assumed: list):
    """(the towline, the catalogue lines it is made of or None) of [towline]."""
    L = scales.length
    catalogue = _catalogue_line(p, t)
    _check_towline_keys(p, t, catalogue)
    l0 = t["l0"] if "l0" in t else t.get("length", 0.0) / L
    if "EA_nd" in t:
        EA_nd = t["EA_nd"]
    elif "EA" in t:
        EA_nd = float(t["EA"] / scales.force)
    else:
        EA_nd = float(catalogue.EA / scales.force) if catalogue is not None else 0.0
    xp, yp = _attachment(p, t, L)
    segs = _segments(p, t["segments"]) if "segments" in t else None
    line_info = None
    try:
        if segs is not None:
            towline = lines.composite(segs, scales=scales, xp=xp, yp=yp)
            line_info = [_line_record(lt, length) for lt, length in segs]
            assumed.append(("towline", "; ".join(f"{lt.name}: {lt.source}" for lt, _ in segs)))
        elif "weight" in t or catalogue is not None:
            weight = t["weight"] if "weight" in t or catalogue is None else catalogue.weight
            towline = CatenaryTowline(
                l0=l0, xp=xp, EA=EA_nd, w=float(weight * L / scales.force), yp=yp
            )
        else:
            towline = Towline(l0=l0, xp=xp, EA=EA_nd, yp=yp)
    except ValueError as e:
        p.error(("towline", _field_key(str(e), t)), str(e))
    if catalogue is not None:
        if "EA" in t or "EA_nd" in t:
            catalogue = catalogue.with_values(EA=float(EA_nd * scales.force))
        line_info = [_line_record(catalogue, l0 * L)]
        assumed.append(("towline", f"{catalogue.name}: {catalogue.source}"))
    if "EA" in t and preset and t["EA"] == presets.ASSUMPTIONS["EA"]["value"]:
        assumed.append(("EA", presets.ASSUMPTIONS["EA"]["note"]))
    return towline, line_info


def _check_towline_keys(p: Problems, t: dict, catalogue) -> None:
    """Exactly one key of each pair (`_PAIRS`) where the line needs it; none that a
    composite line's segments set."""
    if "segments" in t:
        for k in ("l0", "length", "EA", "EA_nd", "weight", "line", "diameter_mm", "grade"):
            if k in t:
                p.error(("towline", k), "a composite line's segments set it: drop the key")
    for name, pair in _PAIRS.items():
        given = [k for k in pair if k in t]
        optional = (
            (name == "attachment" and "bridle" in t)
            or (name == "stiffness" and (catalogue is not None or "segments" in t))
            or (name == "length" and "segments" in t)
        )
        if len(given) > 1 or (not given and not optional):
            what = "one of " + " or ".join(pair)
            p.error(
                ("towline", pair[0]),
                f"give exactly {what}" + (" (got both)" if len(given) == 2 else ""),
            )


def _check_geometry(p: Problems, t: dict, study: dict, vessel, towline, L: float) -> None:
    """What the geometry refuses before anything is computed: a towline shorter than its
    bridle's legs, and a time-domain start the towline cannot reach."""
    key = "l0" if "l0" in t else "length"
    if "bridle" in t and isinstance(t["bridle"], dict) and set(t["bridle"]) == set(_BRIDLE):
        b = {k: float(t["bridle"][k]) for k in _BRIDLE}
        leg = math.hypot(b["apex_x"] - b["x_legs"], b["half_spread"])
        if float(towline.l0) < leg:
            p.error(
                ("towline", key),
                f"the towline ({float(towline.l0) * L:.1f} m, l0' = {float(towline.l0):.3g}) is "
                f"shorter than the bridle's legs ({leg * L:.1f} m): lengthen it",
            )
    if vessel is None or not study["time_domain"]:
        return
    try:
        initial_state(
            TowModel(vessel=vessel, towline=towline),
            psi0=math.radians(study["psi0_deg"]),
            y0=study["y0"],
        )
    except ValueError:
        reach = float(towline.length_at_tension(vessel.R0))
        p.error(
            ("study", "y0"),
            f"the time-domain start y0' = {study['y0']:g} (sway offset by L, with psi0 = "
            f"{study['psi0_deg']:g} deg) is not reachable with the towline ({reach:.3g} L "
            f"stretched, {reach * L:.1f} m): give a smaller [study] y0 or a longer towline",
        )


def _attachment(p: Problems, t: dict, L: float) -> tuple[float, float]:
    """(x_p', y_p') of the towline's attachment point: given, or a bridle's apex."""
    if "bridle" not in t:
        return (t["xp"] if "xp" in t else t["xp_m"] / L), t["yp"]
    b = t["bridle"]
    if not isinstance(b, dict) or set(b) != set(_BRIDLE):
        p.error(("towline", "bridle"), f"expected {{{', '.join(k + ' = ...' for k in _BRIDLE)}}}")
    if "xp" in t or "xp_m" in t:
        p.error(("towline", "bridle"), "a bridle sets the attachment point: drop xp")
    try:
        apex = Bridle.symmetric(*(float(b[k]) for k in _BRIDLE)).apex
    except ValueError as e:
        p.error(("towline", "bridle"), str(e))
    return float(apex[0]), float(apex[1])


# ---------------------------------------------------------------------- [tug], [route]


def _tug(p: Problems, g: dict) -> Tug | None:
    """The tug of [tug]: a quadratic pull curve or a pull table (None: no tug given)."""
    if not any(k in g for k in ("bollard_pull_t", "free_speed", "speeds", "pulls_t")):
        return None
    tonne = 9.80665e3
    eff = dict(efficiency=g["efficiency"], resistance_coefficient=g["resistance_coefficient"])
    try:
        if "speeds" in g or "pulls_t" in g:
            for k in ("speeds", "pulls_t"):
                if k not in g:
                    p.error(("tug", k), "a pull table needs both speeds and pulls_t")
            if len(g["speeds"]) != len(g["pulls_t"]):
                p.error(("tug", "pulls_t"), "needs as many values as speeds")
            return Tug.from_table(g["speeds"], np.asarray(g["pulls_t"]) * tonne, **eff)
        for k in ("bollard_pull_t", "free_speed"):
            if k not in g:
                p.error(
                    ("tug", k),
                    "missing key: give bollard_pull_t and free_speed, or speeds and pulls_t",
                )
        return Tug(bollard_pull=g["bollard_pull_t"] * tonne, free_speed=g["free_speed"], **eff)
    except ValueError as e:
        p.error(("tug",), str(e))


def _route(p: Problems, r: dict) -> tuple[float | None, float | None]:
    """(route length [m], water depth [m]) of [route]."""
    if "length_nm" in r and "length_m" in r:
        p.error(("route", "length_m"), "give length_nm or length_m, not both")
    route = r["length_nm"] * 1852.0 if "length_nm" in r else r.get("length_m")
    return route, r.get("water_depth")


# ---------------------------------------------------------------------- [[sea_state]]


def _sea_states(p: Problems, seas_raw: list, given: list) -> list:
    seas = [_sea_state(p, i, s, given[i]) for i, s in enumerate(seas_raw)]
    names = [s.name for s in seas]
    if len(set(names)) != len(names):
        i = next(i for i, n in enumerate(names) if names.index(n) != i)
        p.error(("sea_state", i, "name"), f"sea-state names must differ; {names[i]!r} is repeated")
    return seas


def _sea_state(p: Problems, i: int, s: dict, given: dict) -> SeaState:
    """Sea state ``i`` (``s`` checked, ``given`` as written): a built-in one with overrides,
    or Hs and Tp with wind and current; a Tp outside the physical range is a warning."""
    if "builtin" in s:
        if s["builtin"] not in presets.SEA_STATES:
            p.error(
                ("sea_state", i, "builtin"),
                f"unknown sea state {s['builtin']!r}; built-in: {', '.join(presets.SEA_STATES)}",
            )
        for k, val in presets.SEA_STATES[s["builtin"]].items():
            if k not in given:
                s[k] = float(val)
        s.setdefault("name", s["builtin"])
    for k in ("hs", "tp"):
        if k not in s:
            p.error(
                ("sea_state", i, k), "missing key: every sea state needs hs and tp (or a builtin)"
            )
    s.setdefault("name", f"sea state {i + 1}")
    if s["hs"] > 0:
        lo, hi = (float(x) for x in physical_tp_range(s["hs"]))
        if not lo <= s["tp"] <= hi:
            p.warn(
                ("sea_state", i, "tp"),
                f"Tp = {s['tp']:g} s is outside the physical range {lo:.2f}-{hi:.2f} s for "
                f"Hs = {s['hs']:g} m (thesis eq. 3.5): such a sea is steeper or flatter than "
                "wind seas are",
            )
    kw = {k: s[k] for k in ("hs", "tp", "gamma", "wind_speed", "current_speed")}
    for k in ("wave_angle", "wind_angle", "current_angle"):
        kw[k] = math.radians(s[f"{k}_deg"])
    try:
        return SeaState(**kw, name=s["name"])
    except ValueError as e:
        p.error(("sea_state", i), str(e))


_SEGMENT_KEYS = {"line", "diameter_mm", "length", "grade"}


def _catalogue_line(p: Problems, t: dict):
    """The `jaxtow.lines.LineType` named by [towline] line and diameter_mm (None if none)."""
    if "line" not in t:
        for k in ("diameter_mm", "grade"):
            if k in t:
                p.error(("towline", k), "needs line = ... (a catalogue line)")
        return None

    if "diameter_mm" not in t:
        p.error(("towline", "diameter_mm"), "missing key: a catalogue line needs its diameter")
    try:
        return lines.line(t["line"], t["diameter_mm"] / 1e3, grade=t.get("grade", "R3"))
    except ValueError as e:
        key = "grade" if "grade" in str(e) else "diameter_mm" if "diameter" in str(e) else "line"
        p.error(("towline", key), str(e).replace(" m for", " for").replace("give metres", "mm?"))


def _segments(p: Problems, segs: list) -> list:
    """[(LineType, length [m]), ...] of [towline] segments (each checked, named by index)."""

    out = []
    for i, seg in enumerate(segs):
        where = ("towline", "segments")
        unknown = set(seg) - _SEGMENT_KEYS
        if unknown:
            p.error(
                where,
                f"segment {i + 1}: unknown key(s) {sorted(unknown)} (known: "
                f"{sorted(_SEGMENT_KEYS)})",
            )
        missing = {"line", "diameter_mm", "length"} - set(seg)
        if missing:
            p.error(where, f"segment {i + 1}: missing key(s) {sorted(missing)}")
        num = [seg["diameter_mm"], seg["length"]]
        if not all(
            isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) and x > 0
            for x in num
        ):
            p.error(where, f"segment {i + 1}: diameter_mm and length must be numbers > 0")
        try:
            lt = lines.line(seg["line"], seg["diameter_mm"] / 1e3, grade=seg.get("grade", "R3"))
        except ValueError as e:
            p.error(where, f"segment {i + 1}: {e}")
        out.append((lt, float(seg["length"])))
    if len(out) < 2:
        p.error(("towline", "segments"), "a composite line needs at least two segments")
    return out


def _line_record(lt, length: float) -> dict:
    return dict(
        name=lt.name,
        length_m=float(length),
        mbl_kN=lt.mbl / 1e3,
        EA_N=lt.EA,
        weight_N_per_m=lt.weight,
        source=lt.source,
    )


_MESH_KEYS = {"file", "method", "omega", "beta_deg", "cog_z", "symmetric"}


def _mesh_spec(p: Problems, mesh, base, draft) -> dict:
    """The resolved [hull] mesh table (checked; solved lazily by `Tow.drift`)."""
    m = {"file": mesh} if isinstance(mesh, str) else dict(mesh)
    extra = set(m) - _MESH_KEYS
    if extra or "file" not in m:
        p.error(
            ("hull", "mesh"),
            f"expected a path or {{{', '.join(sorted(_MESH_KEYS))}}}; got {sorted(m)}",
        )
    path = _path(m["file"], base)
    if not path.is_file():
        p.error(("hull", "mesh"), f"no mesh file {str(path)!r}")
    if m.get("method", "near_field") not in ("near_field", "far_field"):
        p.error(("hull", "mesh"), f"method near_field or far_field, got {m['method']!r}")

    for k, default in (("omega", [0.05, 2.5, 61]), ("beta_deg", [0.0, 180.0, 25])):
        try:
            m[k] = check_value(Key("grid", k), m.get(k, default))
        except Invalid as e:
            p.error(("hull", "mesh"), f"{k}: {e}")
    cache = path.parent / ".jaxtow_bem" / path.stem
    return dict(
        mesh=str(path),
        method=m.get("method", "near_field"),
        omega=m["omega"],
        beta_deg=m["beta_deg"],
        cog_z=m.get("cog_z"),
        symmetric=bool(m.get("symmetric", True)),
        cache=str(cache),
    )


def _mesh_drift(spec: dict, form: str):
    """(QTF, description) of a mesh by a Capytaine panel solve (cached per frequency)."""

    try:
        bem.require_capytaine()
    except ImportError as e:
        raise TowFileError(f"[hull] mesh needs the panel-method extra: {e}") from None
    mesh = bem.read_mesh(spec["mesh"])
    (w0, w1, nw), (b0, b1, nb) = spec["omega"], spec["beta_deg"]
    omega = np.linspace(float(w0), float(w1), int(nw))
    beta = np.radians(np.linspace(float(b0), float(b1), int(nb)))
    ds = bem.bem_drift(
        mesh, omega, beta, cog_z=spec["cog_z"], cache_dir=spec["cache"], progress=True
    )
    q = bem.qtf_from_bem(ds, spec["method"], symmetric=spec["symmetric"])
    desc = (
        f"panel QTF of mesh {spec['mesh']} ({spec['method'].replace('_', ' ')}, jaxtow bem, "
        f"{len(mesh.faces)} hull panels; {form} sailing form)"
    )
    return q, desc


def _strip_drift(hull_spec: str, wl):
    """(QTF, description) of strip theory (`jaxtow.strip.drift_qtf`) for the box or Barge 2
    of the waterline, or an offsets file, with the panel pipeline's CoG estimate."""
    T = float(wl.draft)
    if hull_spec == "box":
        pts = np.asarray(wl.points)
        hull = strip.box(float(np.ptp(pts[:, 0])), float(np.ptp(pts[:, 1])), T)
    elif hull_spec == "barge2":
        hull = presets.barge2_hull(T)
    else:
        try:
            hull = strip.offsets_file(hull_spec)
        except ValueError as e:
            raise TowFileError(f"[hull] drift: {e}") from None
    z_g = float(presets.ASSUMPTIONS["cog_z"]["value"]) - T
    q = strip.drift_qtf(hull, wl, QTF_OMEGA, _radians(QTF_BETA_DEG), z_g=z_g)
    desc = (
        f"strip theory of the {hull.name} hull ({hull.x.shape[0]} sections): Gerritsma-"
        f"Beukelman added resistance plus the R-function short-wave part on the {wl.name} "
        f"waterline; CoG {z_g:g} m above the waterline (estimate); zero-speed table"
    )
    return q, desc


def _path(name, base) -> Path:
    path = Path(name)
    return path if path.is_absolute() or base is None else Path(base) / path


def _field_key(message: str, t: dict) -> str:
    for k in ("l0", "xp", "yp", "EA"):
        if f"'{k}'" in message:
            return {
                "l0": "l0" if "l0" in t else "length",
                "xp": "xp" if "xp" in t else "xp_m",
                "EA": "EA" if "EA" in t else "EA_nd",
            }.get(k, k)
    return "l0"


def _describe_drift(drift, form) -> str:
    if isinstance(drift, str) and drift in METHODS:
        return f"waterline method {drift!r} (misses the motion-induced drift where L/lambda < 1)"
    if isinstance(drift, dict) and "mesh" in drift:
        return (
            f"panel solve of mesh {drift['mesh']} ({drift['method']}; CoG height, radii of "
            "gyration and roll damping: the documented estimates of jaxtow.presets.ASSUMPTIONS "
            "unless cog_z is given)"
        )
    if isinstance(drift, dict) and "strip" in drift:
        return (
            f"strip theory of the {drift['strip']} hull at zero speed (Gerritsma-Beukelman plus "
            "the R-function short-wave part; no lateral motion-induced drift; on a barge it "
            "over-predicts the panel method's surge drift in waves longer than the hull, see "
            "docs/strip.md; CoG height, radii of gyration and roll damping: the documented "
            f"estimates; {form} sailing form)"
        )
    what = drift if isinstance(drift, str) else f"file {drift['file']}"
    return f"drift source {what} ({form} sailing form)"


def show(tow: Tow) -> str:
    """The resolved tow file as TOML: every default filled in, each estimate commented."""
    comments = {}
    notes = dict(tow.assumed)
    if "draft" in notes:
        comments[("vessel", "draft")] = "ESTIMATE: " + notes["draft"]
    if "EA" in notes:
        comments[("towline", "EA")] = "ESTIMATE: " + notes["EA"]
    if "wind_height" in notes:
        comments[("hull", "wind_height")] = "ILLUSTRATIVE: " + notes["wind_height"]
    if "wind_table" in notes:
        comments[("hull", "wind_table")] = "ILLUSTRATIVE: not measured"
    head = [
        f"# {tow.name}: resolved from {tow.source} (every default filled in)",
        "# estimates the results depend on:",
        *(f"#   - {k}: {n}" for k, n in tow.assumed),
        *(f"# WARNING {w}" for w in tow.warnings),
        "",
    ]
    return "\n".join(head) + to_toml(tow.resolved, comments)


#: `with_changes` keys: (section, key, the keys of the same quantity it replaces).
CHANGES = {
    "l0": ("towline", "l0", ("length",)),
    "length": ("towline", "length", ("l0",)),
    "xp": ("towline", "xp", ("xp_m", "bridle")),
    "EA": ("towline", "EA", ("EA_nd",)),
    "EA_nd": ("towline", "EA_nd", ("EA",)),
    "speed": ("tow", "speed", ()),
}


def with_changes(tow: Tow, **changes) -> Tow:
    """The tow with values changed in the tow file's own units and keys (``l0`` by L,
    ``length`` m, ``xp`` by L, ``EA`` N, ``EA_nd``, ``speed`` m/s: `CHANGES`), resolved
    again from its file, so that every check of a tow file applies to the changed one (the
    command line's overrides). The source names the changes."""
    unknown = set(changes) - set(CHANGES)
    if unknown:
        raise ValueError(f"unknown changes {sorted(unknown)} (one of {', '.join(CHANGES)})")
    data = copy.deepcopy(tow.resolved)
    for name, value in changes.items():
        section, key, replaces = CHANGES[name]
        table = data.setdefault(section, {})
        for k in replaces:
            table.pop(k, None)
        table[key] = float(value)
    said = ", ".join(f"{k} = {v:g}" for k, v in changes.items())
    base = None if tow.source.startswith("<") else Path(tow.source).parent
    return loads(to_toml(data), source=f"{tow.source} with {said}", base=base)
