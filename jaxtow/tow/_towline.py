"""The [towline] section of a tow file: the line (straight elastic, catenary or composite), its
attachment point or bridle, and its make (the catalogue lines of the main towline, the
segments and the bridle legs, whose breaking loads the guideline checks read)."""

from __future__ import annotations

import dataclasses
import math

from .. import lines, presets
from .._dynamics import TowModel
from .._simulate import initial_state
from .._towline import Bridle, CatenaryTowline, Towline
from .._units import Scales
from ._schema import Problems, read_subtable

__all__ = ["LineSegment", "TowlineMake", "read_towline", "check_geometry", "bridle_leg_length"]

#: The towline keys given one way or the other (exactly one of each pair where needed).
PAIRS = {
    "length": ("l0", "length"),
    "attachment": ("xp", "xp_m"),
    "stiffness": ("EA_N", "EA_nd"),
}
_BRIDLE = ("x_legs", "half_spread", "apex_x")


@dataclasses.dataclass(frozen=True)
class LineSegment:
    """One piece of a towline's make: the catalogue ``name``, its ``role`` ("towline": the
    main line; "segment": a pennant or other piece in series; "bridle leg"), its ``length``
    [m], minimum breaking load ``mbl`` [N], axial stiffness ``EA`` [N], submerged ``weight``
    [N/m] and the ``source`` of the values."""

    name: str
    role: str
    length: float
    mbl: float
    EA: float
    weight: float
    source: str

    @classmethod
    def of(cls, lt: lines.LineType, role: str, length: float) -> LineSegment:
        return cls(lt.name, role, float(length), lt.mbl, lt.EA, lt.weight, lt.source)


@dataclasses.dataclass(frozen=True)
class TowlineMake:
    """The catalogue lines a towline is made of: ``segments`` in series (the longest is the
    main towline) and the ``bridle_leg`` (None without a bridle, or a bridle whose make is
    not given: then ``bridle`` is True)."""

    segments: tuple[LineSegment, ...]
    bridle_leg: LineSegment | None = None
    bridle: bool = False

    @property
    def main(self) -> LineSegment:
        return max(self.segments, key=lambda s: s.length)

    @property
    def connections(self) -> tuple[LineSegment, ...]:
        """The connecting parts: every piece but the main towline, the bridle legs too."""
        main = self.main
        parts = [s for s in self.segments if s is not main]
        return tuple(parts + ([self.bridle_leg] if self.bridle_leg is not None else []))

    @property
    def weakest(self) -> LineSegment:
        """The weakest piece carrying the whole tension (the segments in series; a bridle's
        legs share it)."""
        return min(self.segments, key=lambda s: s.mbl)

    @property
    def length(self) -> float:
        """The towline's length [m] (the segments in series, without the bridle)."""
        return sum(s.length for s in self.segments)


def bridle_leg_length(b: dict) -> float:
    """One leg of a symmetric bridle, by L (the table of [towline] bridle)."""
    return math.hypot(float(b["apex_x"]) - float(b["x_legs"]), float(b["half_spread"]))


def _catalogue_line(p: Problems, t: dict, where: tuple = ("towline",)):
    """The `jaxtow.lines.LineType` named by line and diameter_mm of a table (None if none)."""
    if "line" not in t:
        for k in ("diameter_mm", "grade"):
            if k in t:
                p.error(where + (k,), "needs line = ... (a catalogue line)")
        return None
    if "diameter_mm" not in t:
        p.error(where + ("diameter_mm",), "missing key: a catalogue line needs its diameter")
    try:
        return lines.line(t["line"], t["diameter_mm"] / 1e3, grade=t.get("grade", "R3"))
    except ValueError as e:
        key = {"diameter": "diameter_mm"}.get(getattr(e, "parameter", ""), "line")
        key = "grade" if getattr(e, "parameter", "") == "grade" else key
        p.error(where + (key,), str(e).replace(" m for", " for").replace("give metres", "mm?"))


def _segments(p: Problems, segs: list) -> list:
    """[(LineType, length [m]), ...] of [towline] segments (each checked, named by index)."""
    if len(segs) < 2:
        p.error(
            ("towline", "segments"),
            "a composite line needs at least two segments; for one line give line, "
            "diameter_mm and length (or l0) instead",
        )
    out = []
    where = ("towline", "segments")
    for i, seg in enumerate(segs):
        label = f"segment {i + 1}"
        s = read_subtable(p, where, seg, "towline.segments", label)
        missing = {"line", "diameter_mm", "length"} - set(s)
        if missing:
            p.error(where, f"{label}: missing key(s) {sorted(missing)}")
        try:
            lt = lines.line(s["line"], s["diameter_mm"] / 1e3, grade=s.get("grade", "R3"))
        except ValueError as e:
            p.error(where, f"{label}: {e}")
        out.append((lt, float(s["length"])))
    return out


def _check_keys(p: Problems, t: dict, catalogue) -> None:
    """Exactly one key of each pair (`PAIRS`) where the line needs it; none that a composite
    line's segments set."""
    if "segments" in t:
        for k in ("l0", "length", "EA_N", "EA_nd", "weight", "line", "diameter_mm", "grade"):
            if k in t:
                p.error(("towline", k), "a composite line's segments set it: drop the key")
    for name, pair in PAIRS.items():
        given = [k for k in pair if k in t]
        optional = (
            (name == "attachment" and "bridle" in t)
            or (name == "stiffness" and (catalogue is not None or "segments" in t))
            or (name == "length" and "segments" in t)
        )
        if len(given) > 1 or (not given and not optional):
            p.error(
                ("towline", pair[0]),
                f"give exactly one of {' or '.join(pair)}"
                + (" (got both)" if len(given) == 2 else ""),
            )


def _attachment(p: Problems, t: dict, L: float) -> tuple[float, float, dict | None]:
    """(x_p', y_p', the bridle table or None) of the towline's attachment point: given, or a
    bridle's apex."""
    if "bridle" not in t:
        return (t["xp"] if "xp" in t else t["xp_m"] / L), t["yp"], None
    b = read_subtable(p, ("towline", "bridle"), t["bridle"], "towline.bridle")
    missing = [k for k in _BRIDLE if k not in b]
    if missing:
        p.error(("towline", "bridle"), f"missing key(s) {', '.join(missing)} of the bridle")
    if "xp" in t or "xp_m" in t:
        p.error(("towline", "bridle"), "a bridle sets the attachment point: drop xp")
    try:
        apex = Bridle.symmetric(*(float(b[k]) for k in _BRIDLE)).apex
    except ValueError as e:
        p.error(("towline", "bridle"), str(e))
    t["bridle"] = b
    return float(apex[0]), float(apex[1]), b


def read_towline(p: Problems, t: dict, scales: Scales, assumed: list, preset: bool = False):
    """(the towline, its `TowlineMake` or None) of [towline]; ``t`` is the checked section,
    updated in place to the keys used."""
    L = scales.length
    if "EA" in t:
        if "EA_N" in t:
            p.error(("towline", "EA"), "give EA_N only (EA is its deprecated spelling)")
        t["EA_N"] = t.pop("EA")  # its deprecation is warned by the schema
    catalogue = _catalogue_line(p, t)
    _check_keys(p, t, catalogue)
    segs = _segments(p, t["segments"]) if "segments" in t else None
    l0 = t["l0"] if "l0" in t else t.get("length", 0.0) / L
    if "EA_nd" in t:
        EA_nd = t["EA_nd"]
    elif "EA_N" in t:
        EA_nd = float(t["EA_N"] / scales.force)
    else:
        EA_nd = float(catalogue.EA / scales.force) if catalogue is not None else 0.0
    xp, yp, bridle = _attachment(p, t, L)
    make = None
    try:
        if segs is not None:
            towline = lines.composite(segs, scales=scales, xp=xp, yp=yp)
            make = [LineSegment.of(lt, "segment", length) for lt, length in segs]
            assumed.append(("towline", "; ".join(f"{lt.name}: {lt.source}" for lt, _ in segs)))
        elif "weight" in t or catalogue is not None:
            weight = t["weight"] if "weight" in t or catalogue is None else catalogue.weight
            towline = CatenaryTowline(
                l0=l0, xp=xp, EA=EA_nd, w=float(weight * L / scales.force), yp=yp
            )
        else:
            towline = Towline(l0=l0, xp=xp, EA=EA_nd, yp=yp)
    except ValueError as e:
        p.error(("towline", _key_of(getattr(e, "parameter", "l0"), t)), str(e))
    if catalogue is not None:
        if "EA_N" in t or "EA_nd" in t:
            catalogue = catalogue.with_values(EA=float(EA_nd * scales.force))
        make = [LineSegment.of(catalogue, "towline", l0 * L)]
        assumed.append(("towline", f"{catalogue.name}: {catalogue.source}"))
    if preset and t.get("EA_N") == presets.ASSUMPTIONS["EA"]["value"]:
        assumed.append(("EA", presets.ASSUMPTIONS["EA"]["note"]))
    if make is not None:
        main = max(make, key=lambda s: s.length)
        make = [dataclasses.replace(s, role="towline") if s is main else s for s in make]
    leg = None
    if bridle is not None and "line" in bridle:
        lt = _catalogue_line(p, bridle, ("towline", "bridle"))
        leg = LineSegment.of(lt, "bridle leg", bridle_leg_length(bridle) * L)
    out = None if make is None else TowlineMake(tuple(make), leg, bridle is not None)
    return towline, out


def _key_of(field: str, t: dict) -> str:
    """The tow-file key of a towline field (its spelling in the file)."""
    return {
        "l0": "l0" if "l0" in t else "length",
        "xp": "xp" if "xp" in t else "xp_m",
        "EA": "EA_nd" if "EA_nd" in t else "EA_N",
        "yp": "yp",
        "w": "weight",
    }.get(field, "l0")


def check_geometry(p: Problems, t: dict, study, vessel, towline, L: float) -> None:
    """What the geometry refuses before anything is computed: a towline shorter than its
    bridle's legs, and a time-domain start the towline cannot reach."""
    key = "l0" if "l0" in t else "length"
    if isinstance(t.get("bridle"), dict):
        leg = bridle_leg_length(t["bridle"])
        if float(towline.l0) < leg:
            p.error(
                ("towline", key),
                f"the towline ({float(towline.l0) * L:.1f} m, l0' = {float(towline.l0):.3g}) is "
                f"shorter than the bridle's legs ({leg * L:.1f} m): lengthen it",
            )
    if vessel is None or not study.time_domain:
        return
    try:
        initial_state(
            TowModel(vessel=vessel, towline=towline),
            psi0=math.radians(study.psi0_deg),
            y0=study.y0,
        )
    except ValueError:
        reach = float(towline.length_at_tension(vessel.R0))
        p.error(
            ("study", "y0"),
            f"the time-domain start y0' = {study.y0:g} (sway offset by L, with psi0 = "
            f"{study.psi0_deg:g} deg) is not reachable with the towline ({reach:.3g} L "
            f"stretched, {reach * L:.1f} m): give a smaller [study] y0 or a longer towline",
        )
