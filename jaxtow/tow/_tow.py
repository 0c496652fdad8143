"""A tow described in one file: reading a tow file and resolving it, section by section
(`jaxtow.tow._vessel`, `_hull`, `_towline`, `_sections`), into the objects of the model
(vessel, towline, scales, drift source, tug, sea states, criteria), with every estimate and
every plausibility finding named."""

from __future__ import annotations

import copy
import dataclasses
import re
import tomllib
import warnings
from importlib import resources
from pathlib import Path

import equinox as eqx
import jax.numpy as jnp

from .. import guidelines
from .._dynamics import TowModel
from .._towline import AbstractTowline
from .._units import Scales
from .._vessel import Vessel
from ..drift import Waterline
from ..forces import CombinedForce, CurrentForce, IrregularWaveDriftForce, WindForce
from ..lines import line as catalogue_line
from ..presets import AbstractDriftSource
from ..resistance import SeaState, TowResistance, Tug, WaveDrift, tow_resistance
from ..waves import DEFAULT_OMEGA, Jonswap
from ._findings import Finding, plausibility
from ._hull import read_drift, read_waterline_spec, read_wind
from ._schema import ARRAYS, REQUIRED, SCHEMA, Problems, TowFileError, read_section, to_toml
from ._sections import StudyOptions, read_criteria, read_route, read_sea_states, read_tug
from ._towline import TowlineMake, check_geometry, read_towline
from ._vessel import read_vessel

__all__ = [
    "BUILTIN_TOWS",
    "DEPRECATED_NAMES",
    "CHANGES",
    "Tow",
    "load",
    "loads",
    "builtin_text",
    "canonical_name",
    "template",
    "show",
    "with_changes",
]

#: Built-in tow files (jaxtow/data/tows): one spelling everywhere in the command line.
BUILTIN_TOWS = {"barge1": "barge1.toml", "barge2a": "barge2a.toml", "barge2b": "barge2b.toml"}
#: Old spellings of the built-ins, accepted for one release with a deprecation message.
DEPRECATED_NAMES = {"barge_2a": "barge2a", "barge_2b": "barge2b", "barge2": "barge2a"}


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


@dataclasses.dataclass(frozen=True)
class Tow:
    """A resolved tow file. ``resolved`` is the file with every default filled in (what
    `show` prints); ``assumed`` the (key, note) pairs of every estimate the results depend
    on; ``warnings`` the values outside the physics' or the data's range; ``findings`` the
    plausibility findings (`jaxtow.tow.Finding`); ``make`` the catalogue lines of the
    towline (None where it names none); ``drift`` the one drift source every result uses
    (`jaxtow.presets.AbstractDriftSource`). Build the model objects with `model`,
    `resistance`, `sea_model`."""

    name: str
    description: str
    source: str
    resolved: dict
    scales: Scales
    vessel: Vessel | None
    towline: AbstractTowline | None
    waterline: Waterline
    drift: AbstractDriftSource
    form: str
    tug: Tug | None
    sea_states: tuple[SeaState, ...]
    route_length: float | None
    water_depth: float | None
    study: StudyOptions
    assumed: tuple
    wind_table: object
    wind_height: float
    breadth: float
    warnings: tuple[str, ...] = ()
    findings: tuple[Finding, ...] = ()
    make: TowlineMake | None = None
    criteria: guidelines.Criteria = guidelines.GUIDELINES["gl-nd-0030"]
    efficiencies: tuple[tuple[str, float], ...] = ()

    # ------------------------------------------------------------------ model objects
    @property
    def has_model(self) -> bool:
        """Whether the tow has a manoeuvring model (a vessel and a towline)."""
        return self.vessel is not None and self.towline is not None

    def _need_model(self):
        if self.vessel is None or self.towline is None:
            missing = "[vessel] derivatives (or preset)" if self.vessel is None else "[towline]"
            raise TowFileError(
                f"this tow has no manoeuvring model: stability needs {missing}",
                source=self.source,
            )

    def model(self, external=None) -> TowModel:
        """The `jaxtow.TowModel` of the tow (calm water unless ``external`` is given), with
        its scales (so ``u_tug`` can be swept)."""
        self._need_model()
        ext = {} if external is None else dict(external=external)
        return TowModel(vessel=self.vessel, towline=self.towline, scales=self.scales, **ext)

    def tug_in(self, sea: SeaState) -> Tug:
        """The tug with its efficiency in sea state ``sea`` (the sea state's where it gives
        one, else [tug] efficiency)."""
        if self.tug is None:
            raise TowFileError("this tow has no [tug]", source=self.source)
        eff = dict(self.efficiencies).get(sea.name)
        if eff is None:
            return self.tug
        return eqx.tree_at(lambda t: t.efficiency, self.tug, jnp.asarray(eff, float))

    def resistance(self) -> TowResistance:
        """The `jaxtow.resistance.TowResistance` of the tow: current from the manoeuvring
        derivatives, wind from the wind table, and the mean drift of the tow's one drift
        source at the tow's sailing form, as the stability model evaluates it."""
        self._need_model()
        waves = WaveDrift(qtf=self.drift.qtf(), form=self.form)
        return tow_resistance(
            self.vessel,
            self.scales.length,
            self.breadth,
            self.scales.draft,
            waves,
            wind_table=self.wind_table,
            wind_height=self.wind_height,
            name=self.name,
            assumed=self.assumed,
        )

    def sea_model(self, sea: SeaState, *, omega=None, form: str | None = None) -> TowModel:
        """The tow model in sea state ``sea``: the mean irregular-sea drift (JONSWAP Hs, Tp,
        γ), the wind and the current, each from its direction relative to the course, so
        that the towline tension of a straight-behind equilibrium equals the resistance
        budget's total. ``form``: the forward-speed form of the drift (default the tow
        file's; `jaxtow.drift.sailing_drift`)."""
        self._need_model()
        forces = []
        if float(sea.hs) > 0:
            forces.append(
                IrregularWaveDriftForce(
                    qtf=self.drift.qtf(),
                    spectrum=Jonswap(hs=sea.hs, tp=sea.tp, gamma=sea.gamma),
                    omega=DEFAULT_OMEGA if omega is None else omega,
                    scales=self.scales,
                    form=self.form if form is None else form,
                    angle=sea.wave_angle,
                )
            )
        res = None
        if float(sea.wind_speed) > 0:
            res = self.resistance()
            forces.append(
                WindForce(
                    load=res.wind, speed=sea.wind_speed, angle=sea.wind_angle, scales=self.scales
                )
            )
        if float(sea.current_speed) > 0:
            res = res or self.resistance()
            forces.append(
                CurrentForce(
                    load=res.hull,
                    speed=sea.current_speed,
                    angle=sea.current_angle,
                    scales=self.scales,
                )
            )
        ext = (
            None if not forces else forces[0] if len(forces) == 1 else CombinedForce(tuple(forces))
        )
        return self.model(ext)

    def show(self) -> str:
        """The resolved file as TOML, each estimate marked (`jaxtow tow show`)."""
        return show(self)


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
        m = re.search(r"line (\d+)", str(e))
        raise TowFileError(
            f"not valid TOML: {e}", source=source, line=int(m.group(1)) if m else None
        ) from None
    return _resolve(data, text, source, base)


def _check_sections(p: Problems, data: dict) -> None:
    for k in data:
        if k not in SCHEMA:
            p.error((k,), f"unknown section [{k}] (sections: {', '.join(SCHEMA)})")
    for k in REQUIRED:
        if k not in data:
            p.error((k,), f"missing section [{k}]")
    if "sea_state" in data and not isinstance(data["sea_state"], list):
        p.error(("sea_state",), "write sea states as [[sea_state]] (an array of tables)")


def _resolve(data: dict, text: str, source: str, base=None) -> Tow:
    """Check a parsed tow file and resolve it, one section at a time (each reader fills the
    section's defaults in place, so that ``resolved`` is the file as it was used)."""
    p = Problems(text, source)
    _check_sections(p, data)
    sec = {k: read_section(p, k, data.get(k, {})) for k in SCHEMA if k not in ARRAYS}
    seas_raw = [read_section(p, "sea_state", s, i) for i, s in enumerate(data.get("sea_state", []))]
    assumed: list = []
    if "name" not in sec["tow"]:
        p.error(("tow", "name"), "missing key: every tow needs a name")
    v = sec["vessel"]
    vessel = read_vessel(p, v, sec["tow"]["name"], assumed)
    L, B, T = float(v["length"]), float(v["breadth"]), float(v["draft"])
    scales = Scales(length=L, draft=T, u_tug=sec["tow"]["speed"])
    h = sec["hull"]
    waterline = read_waterline_spec(p, h, "preset" in v, base, L, B, T)
    drift = read_drift(p, h, "preset" in v, base, waterline, assumed)
    wind_table = read_wind(p, h, base, assumed)
    assumed.append(("wave_drift", f"{drift.caveat()} ({h['sailing_form']} sailing form)"))
    study = StudyOptions.from_section(sec["study"])
    towline, make, catalogue_EA = None, None, None
    if "towline" in data:
        t = sec["towline"]
        towline, make = read_towline(p, t, scales, assumed, preset="preset" in v)
        if "line" in t and ("EA_N" in t or "EA_nd" in t):
            catalogue_EA = catalogue_line(
                t["line"], t["diameter_mm"] / 1e3, grade=t.get("grade", "R3")
            ).EA
    elif vessel is not None:
        p.error(
            ("towline",),
            "missing section [towline]: a tow with a manoeuvring model needs its towline",
        )
    if towline is not None:
        check_geometry(p, sec["towline"], study, vessel, towline, L)
    tug = read_tug(p, sec["tug"], assumed, sec["criteria"].get("tug_efficiency"))
    route, water_depth = read_route(p, sec["route"])
    seas, efficiencies = read_sea_states(p, seas_raw, data.get("sea_state", []))
    crit = read_criteria(p, sec["criteria"])
    findings = plausibility(
        towline=towline,
        make=make,
        catalogue_EA=catalogue_EA,
        vessel=vessel,
        particulars=v,
        tug=tug,
        design_speed=float(sec["tow"]["speed"]),
        scales=scales,
    )
    return Tow(
        name=sec["tow"]["name"],
        description=sec["tow"]["description"],
        source=source,
        resolved=_resolved(data, sec, seas_raw),
        scales=scales,
        vessel=vessel,
        towline=towline,
        waterline=waterline,
        drift=drift,
        form=h["sailing_form"],
        tug=tug,
        sea_states=tuple(seas),
        route_length=route,
        water_depth=water_depth,
        study=study,
        assumed=tuple(assumed),
        wind_table=wind_table,
        wind_height=float(h["wind_height"]),
        breadth=B,
        warnings=tuple(p.warnings),
        findings=tuple(findings),
        make=make,
        criteria=crit,
        efficiencies=tuple(efficiencies.items()),
    )


def _resolved(data: dict, sec: dict, seas_raw: list) -> dict:
    """The file as used: the sections it has (and the required ones), defaults filled in."""
    resolved = {k: val for k, val in sec.items() if k in data or k in REQUIRED}
    if seas_raw:
        resolved["sea_state"] = seas_raw
    resolved["study"] = sec["study"]
    crit = resolved.get("criteria", sec["criteria"])
    crit.pop("tug_efficiency", None)  # the tug's efficiency is [tug] efficiency
    resolved["criteria"] = crit
    return resolved


# ---------------------------------------------------------------------- writing


def show(tow: Tow) -> str:
    """The resolved tow file as TOML: every default filled in (the [criteria] values of its
    guideline too), each estimate commented, each plausibility finding written above."""
    comments = {}
    notes = dict(tow.assumed)
    if "draft" in notes:
        comments[("vessel", "draft")] = "ESTIMATE: " + notes["draft"]
    if "EA" in notes:
        comments[("towline", "EA_N")] = "ESTIMATE: " + notes["EA"]
    if "wind_height" in notes:
        comments[("hull", "wind_height")] = "ILLUSTRATIVE: " + notes["wind_height"]
    if "wind_table" in notes:
        comments[("hull", "wind_table")] = "ILLUSTRATIVE: not measured"
    if "tug_efficiency" in notes:
        comments[("tug", "efficiency")] = "ESTIMATE: " + notes["tug_efficiency"]
    c = tow.criteria
    for k in SCHEMA["criteria"]:
        if hasattr(c, k) and c.estimate(k):
            comments[("criteria", k)] = "ESTIMATE: " + c.sources[k]
    head = [
        f"# {tow.name}: resolved from {tow.source} (every default filled in)",
        "# estimates the results depend on:",
        *(f"#   - {k}: {n}" for k, n in tow.assumed),
        *(f"# WARNING {w}" for w in tow.warnings),
        *(f"# FINDING ({f.parameter}) {f.text}" for f in tow.findings),
        "",
    ]
    return "\n".join(head) + to_toml(tow.resolved, comments)


#: `with_changes` keys: (section, key, the keys of the same quantity it replaces).
CHANGES = {
    "l0": ("towline", "l0", ("length",)),
    "length": ("towline", "length", ("l0",)),
    "xp": ("towline", "xp", ("xp_m", "bridle")),
    "EA_N": ("towline", "EA_N", ("EA_nd", "EA")),
    "EA_nd": ("towline", "EA_nd", ("EA_N", "EA")),
    "speed": ("tow", "speed", ()),
}


def with_changes(tow: Tow, **changes) -> Tow:
    """The tow with values changed in the tow file's own units and keys (``l0`` by L,
    ``length`` m, ``xp`` by L, ``EA_N`` N, ``EA_nd``, ``speed`` m/s: `CHANGES`), resolved
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
