"""The [tug], [route], [[sea_state]], [criteria] and [study] sections of a tow file."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .. import guidelines, presets
from .._units import NAUTICAL_MILE, TONNE_FORCE
from ..resistance import SeaState, Tug
from ..waves import physical_tp_range
from ._schema import SCHEMA, Problems

__all__ = ["StudyOptions", "read_tug", "read_route", "read_sea_states", "read_criteria"]


@dataclasses.dataclass(frozen=True)
class StudyOptions:
    """What `jaxtow study` runs ([study]): the stability map's grids ``map_xp``, ``map_l0``
    ([lo, hi, n], by L; None: centred on the design point), the time-domain check
    (``time_domain``, its length ``t1`` by L/U and its start ``psi0_deg``, ``y0``), the
    stability in each sea state (``sea_states``), the resistance table's ``speeds``
    [lo, hi, n] m/s, and the irregular-sea Monte Carlo (``risk``: auto | always | never,
    its wall-time budget ``risk_budget_s``, at most ``risk_runs`` runs of ``risk_hours``
    per sea state)."""

    map_xp: tuple | None = None
    map_l0: tuple | None = None
    time_domain: bool = True
    t1: float = 400.0
    psi0_deg: float = 0.0
    y0: float = 0.3
    sea_states: bool = True
    speeds: tuple = (0.0, 3.5, 15)
    risk: str = "auto"
    risk_budget_s: float = 300.0
    risk_runs: int = 256
    risk_hours: float = 3.0

    @classmethod
    def from_section(cls, s: dict) -> StudyOptions:
        kw = {f.name: s[f.name] for f in dataclasses.fields(cls) if f.name in s}
        for k in ("map_xp", "map_l0", "speeds"):
            if kw.get(k) is not None:
                kw[k] = tuple(kw[k])
        return cls(**kw)


def read_tug(p: Problems, g: dict, assumed: list, criteria_efficiency: float | None):
    """The tug of [tug]: a quadratic pull curve or a pull table (None: no tug given). Its
    efficiency is the one value of the sea states and the weather criterion: [tug]
    efficiency; the deprecated [criteria] tug_efficiency must equal it (loading refuses
    otherwise) and stands for it when [tug] leaves it out; without either, the documented
    estimate."""
    given = g.get("efficiency")
    if given is not None and criteria_efficiency is not None and given != criteria_efficiency:
        p.error(
            ("criteria", "tug_efficiency"),
            f"[criteria] tug_efficiency = {criteria_efficiency:g} differs from [tug] "
            f"efficiency = {given:g}: the tug has one efficiency, for the sea states and the "
            "weather criterion alike; give it once, in [tug]",
        )
    if not any(k in g for k in ("bollard_pull_t", "free_speed", "speeds", "pulls_t")):
        return None
    if given is None:
        given = criteria_efficiency
    if given is None:
        given = float(presets.ASSUMPTIONS["tug_efficiency"]["value"])
        assumed.append(("tug_efficiency", presets.ASSUMPTIONS["tug_efficiency"]["note"]))
    g["efficiency"] = given
    eff = dict(efficiency=given, resistance_coefficient=g["resistance_coefficient"])
    try:
        if "speeds" in g or "pulls_t" in g:
            for k in ("speeds", "pulls_t"):
                if k not in g:
                    p.error(("tug", k), "a pull table needs both speeds and pulls_t")
            if len(g["speeds"]) != len(g["pulls_t"]):
                p.error(("tug", "pulls_t"), "needs as many values as speeds")
            return Tug.from_table(g["speeds"], np.asarray(g["pulls_t"]) * TONNE_FORCE, **eff)
        for k in ("bollard_pull_t", "free_speed"):
            if k not in g:
                p.error(
                    ("tug", k),
                    "missing key: give bollard_pull_t and free_speed, or speeds and pulls_t",
                )
        return Tug(
            bollard_pull=g["bollard_pull_t"] * TONNE_FORCE, free_speed=g["free_speed"], **eff
        )
    except ValueError as e:
        key = {"bollard_pull": "bollard_pull_t", "pulls": "pulls_t"}.get(
            getattr(e, "parameter", ""), getattr(e, "parameter", None)
        )
        p.error(("tug",) + ((key,) if key else ()), str(e))


def read_route(p: Problems, r: dict) -> tuple[float | None, float | None]:
    """(route length [m], water depth [m]) of [route]."""
    if "length_nm" in r and "length_m" in r:
        p.error(("route", "length_m"), "give length_nm or length_m, not both")
    route = r["length_nm"] * NAUTICAL_MILE if "length_nm" in r else r.get("length_m")
    return route, r.get("water_depth")


def read_sea_states(p: Problems, seas_raw: list, given: list) -> tuple[list, dict]:
    """(the sea states, {name: the tug's efficiency in it} where a sea state gives one)."""
    seas = [_sea_state(p, i, s, given[i]) for i, s in enumerate(seas_raw)]
    names = [s.name for s in seas]
    if len(set(names)) != len(names):
        i = next(i for i, n in enumerate(names) if names.index(n) != i)
        p.error(("sea_state", i, "name"), f"sea-state names must differ; {names[i]!r} is repeated")
    eff = {
        s.name: float(r["tug_efficiency"])
        for s, r in zip(seas, seas_raw)
        if r.get("tug_efficiency") is not None
    }
    return seas, eff


def _sea_state(p: Problems, i: int, s: dict, given: dict) -> SeaState:
    """Sea state ``i`` (``s`` checked, ``given`` as written): a built-in one with overrides,
    or Hs and Tp with wind and current; a Tp outside the physical range is a warning."""
    if "builtin" in s:
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
        key = getattr(e, "parameter", None)
        p.error(("sea_state", i) + ((key,) if key in s else ()), str(e))


def read_criteria(p: Problems, c: dict) -> guidelines.Criteria:
    """The [criteria] section: a guideline and the values that differ from its own (the
    efficiency is the tug's, `read_tug`); the section is filled in place with the
    guideline's values, so that the resolved file names every limit it was checked
    against."""
    base = guidelines.GUIDELINES[c["guideline"]]
    keys = [k for k in c if k not in ("guideline", "tug_efficiency")]
    out = guidelines.criteria(
        c["guideline"], **{k: float(c[k]) for k in keys if float(c[k]) != getattr(base, k)}
    )
    for k in SCHEMA["criteria"]:
        if k not in ("guideline", "tug_efficiency") and hasattr(out, k):
            c.setdefault(k, getattr(out, k))
    return out
