"""Plausibility of a tow file at load: values that are valid one by one but do not fit
together (a stiffness a thousand times off its line's catalogue value, a static stretch no
line bears, a mass that no hull of those particulars has, a design speed the tug cannot make)
become named findings, not silent acceptance. Each says what was found, in plain words, and
the key it concerns."""

from __future__ import annotations

import dataclasses

from .. import lines

__all__ = ["Finding", "plausibility", "breaking_strain"]

#: A stiffness given for a catalogue line this far from the catalogue's (either way) is a
#: finding: certificates differ from the catalogue's d² laws by tens of per cent, not by
#: factors of three (a factor of 1000 is a kN/N slip).
EA_RATIO = 3.0
#: The block coefficients a displacement hull can have (a box is 1; a fine ship 0.5).
CB_RANGE = (0.35, 1.0)
#: How far the C_B of a given mass may lie from the given block coefficient.
CB_TOLERANCE = 0.1


@dataclasses.dataclass(frozen=True)
class Finding:
    """A finding at load: its ``key`` (what kind), the ``text`` in plain words, and the
    tow-file ``parameter`` it concerns ("section.key", or "")."""

    key: str
    text: str
    parameter: str = ""


def breaking_strain(lt: lines.LineType) -> float:
    """The strain at which a line of this make breaks, MBL/EA (its elastic stretch at the
    minimum breaking load)."""
    return lt.mbl / lt.EA


def _largest_breaking_strain() -> float:
    """The largest breaking strain of the catalogue's makes (nylon's), at a usual size."""
    out = 0.0
    for name in lines.LINES:
        try:
            out = max(out, breaking_strain(lines.line(name, 0.064)))
        except ValueError:
            continue
    return out


def plausibility(*, towline, make, catalogue_EA, vessel, particulars, tug, design_speed, scales):
    """The findings of a resolved tow (`Finding` list): ``catalogue_EA`` [N] is the catalogue
    stiffness of a named line whose EA was given (None otherwise); ``particulars`` the
    [vessel] section (length, breadth, block_coefficient)."""
    force = float(scales.force)
    EA_nd = float(getattr(towline, "series_EA", getattr(towline, "EA", 0.0))) if towline else 0.0
    out = []
    if catalogue_EA is not None and EA_nd > 0:
        out += _ea_findings(EA_nd, force, catalogue_EA)
    if vessel is not None and towline is not None and EA_nd > 0:
        out += _stretch_findings(float(vessel.R0) / EA_nd, make, catalogue_EA)
    if vessel is not None:
        out += _mass_findings(float(vessel.m), particulars)
    if tug is not None and design_speed >= float(tug.max_speed):
        out.append(
            Finding(
                "tug_speed",
                f"the design tow speed {design_speed:g} m/s is at or above the tug's free "
                f"speed {float(tug.max_speed):g} m/s, where its pull vanishes: the tug cannot "
                "tow at it",
                "tow.speed",
            )
        )
    return out


def _ea_findings(EA_nd: float, force: float, catalogue_EA: float) -> list:
    given = EA_nd * force
    ratio = given / catalogue_EA
    if 1 / EA_RATIO <= ratio <= EA_RATIO:
        return []
    slip = ""
    for factor, words in ((1e-3, "kN typed where N are expected"), (1e3, "N typed where kN")):
        if abs(ratio / factor - 1) < 0.2:
            slip = f": a unit slip ({words})?"
    text = (
        f"the towline's EA given ({given:.3g} N, EA' = {EA_nd:.3g}) is {ratio:.3g} times the "
        f"catalogue value of its make ({catalogue_EA:.3g} N){slip}"
    )
    return [Finding("EA_catalogue", text, "towline.EA_N")]


def _stretch_findings(strain: float, make, catalogue_EA) -> list:
    """The static stretch under the calm straight-behind tension T' = R0' against what the
    line's make (or, without one, any catalogue line) bears before it breaks."""
    if make is None:
        limit = _largest_breaking_strain()
    else:  # each piece's catalogue make (a given EA is what is being checked)
        main = make.main
        limit = min(
            s.mbl / (catalogue_EA if s is main and catalogue_EA is not None else s.EA)
            for s in make.segments
        )
    if strain <= limit:
        return []
    which = "its make" if make is not None else "any catalogue line (nylon's)"
    text = (
        f"the towline would stretch {100 * strain:.1f} % under the calm-water tow force at the "
        f"design speed (R0' / EA'), more than {which} bears before it breaks "
        f"({100 * limit:.1f} %): check EA and its units"
    )
    return [Finding("static_stretch", text, "towline.EA_N")]


def _mass_findings(m: float, particulars: dict) -> list:
    L, B = float(particulars["length"]), float(particulars["breadth"])
    cb = m * L / (2.0 * B)  # m' = m / (½ρTL²) = 2 C_B B / L
    out = []
    lo, hi = CB_RANGE
    if not lo <= cb <= hi:
        text = (
            f"the vessel's mass m' = {m:.4g} means a block coefficient of {cb:.3f} for "
            f"L = {L:g} m, B = {B:g} m (m' = 2 C_B B/L), outside {lo}-{hi}: check m' (it is "
            "by ½ρTL², not the displacement)"
        )
        out.append(Finding("block_coefficient", text, "vessel.derivatives.m"))
    given = particulars.get("block_coefficient")
    if given is not None and abs(cb - given) > CB_TOLERANCE:
        text = (
            f"the vessel's mass m' = {m:.4g} means C_B = {cb:.3f}, not the {given:g} given: "
            "the mass, the draft or C_B is off"
        )
        out.append(Finding("block_coefficient", text, "vessel.block_coefficient"))
    return out
