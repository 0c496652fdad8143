"""Towline catalogue: steel wire rope, chain and fibre rope from their nominal diameter, and
composite lines in series.

A `LineType` holds what a towline's make and diameter give: mass and submerged weight per
metre, axial stiffness EA and minimum breaking load (MBL), with its source. `LineType.towline`
makes the tow model's line (an elastic catenary, or the straight elastic line), `composite`
a line of several segments in series (`jaxtow.CompositeTowline`).

The properties are the published d² (and d³) laws that the classification rules and the
line-type tools of the field use, in SI units with d the nominal diameter in metres:

* **Six-strand wire rope** (IWRC: independent wire rope core; FC: fibre core): mass,
  EA and MBL from the OrcaFlex line-type wizard (Orcina, *OrcaFlex help: Line type wizard,
  wire rope*): IWRC 3989.7 d² kg/m, EA 4.04e10 d² N, MBL 633.358e6 d² N; FC 3610.9 d² kg/m,
  3.67e10 d² N, 584.175e6 d² N. Submerged weight with the displaced volume of the steel
  (IWRC, 7850 kg/m³) or of steel and core (FC, effective 6810 kg/m³).
* **Sheathed spiral-strand wire** (mooring wire): NREL MoorPy's wire-rope coefficients
  (Hall et al., MoorPy, 2021–): 5293 d² kg/m, EA 97.1e9 d² N, MBL 1022e6 d² N, effective
  density 4875.5 kg/m³ with the sheath (a steel fill of about 0.86 of the nominal circle,
  that of spiral strand; six-strand rope is near 0.65).
* **Chain** (studless, studlink): mass 19 900 d² (studless) and 21 900 d² (studlink)
  kg/m and EA 0.854e11 d² and 1.01e11 d² N (OrcaFlex line-type wizard, chain); MBL by
  grade from IACS UR W22 / DNV-OS-E302: c d²(44 − 80 d) MN·10³ with c = 0.0211 (ORQ),
  0.0223 (R3), 0.0249 (R3S), 0.0274 (R4), 0.0304 (R4S), 0.0320 (R5) (d in mm there:
  c d_mm² (44 − 0.08 d_mm) kN). Submerged weight 1 − ρ_w/7850 of the weight in air.
* **Fibre rope** (nylon, polyester): mass, MBL and the quasi-static stiffness EA = k·MBL
  from NREL's MoorPy line property coefficients (Hall et al., MoorPy, 2021–; nylon
  585.15 d² kg/m, MBL 230.29e6 d³ + 207.0e6 d² N, k = 5; polyester 678.75 d² kg/m, MBL
  308.2e6 d² N, k = 14); specific gravity 1.14 (nylon), 1.38 (polyester). These are
  linear (secant) stiffnesses: a fibre line's load–extension curve stiffens with load, and
  `fit_power_law` fits the Bernitsas–Kekridis law T = S_b ε^q (`jaxtow.PowerLawTowline`)
  to a maker's load–extension points.

These are catalogue-level values for planning: a specific rope's certificate (its EA and
MBL) replaces them (`LineType` takes any values).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from ._rules import ParameterError
from ._towline import CatenaryTowline, CompositeTowline, Towline
from ._units import RHO_SEA, G

__all__ = [
    "LineType",
    "LINES",
    "CHAIN_GRADES",
    "wire_rope",
    "chain",
    "fibre_rope",
    "line",
    "composite",
    "fit_power_law",
]

_STEEL = 7850.0  # kg/m³
_WIZARD = "OrcaFlex line-type wizard (Orcina)"

#: Chain grades and their MBL factor c in MBL = c d²(44 − 0.08 d) kN (d in mm), IACS UR W22 /
#: DNV-OS-E302.
CHAIN_GRADES = {
    "ORQ": 0.0211,
    "R3": 0.0223,
    "R3S": 0.0249,
    "R4": 0.0274,
    "R4S": 0.0304,
    "R5": 0.0320,
}

_WIRE = {  # core: (mass kg/m per d², EA N per d², MBL N per d², effective density kg/m³)
    "IWRC": (3989.7, 4.04e10, 633.358e6, _STEEL),
    "FC": (3610.9, 3.67e10, 584.175e6, 6810.0),
    "spiral": (5293.0, 97.1e9, 1022e6, 4875.5),
}
_MOORPY = "NREL MoorPy line property coefficients"
_CHAIN = {"studless": (19.9e3, 0.854e11), "studlink": (21.9e3, 1.01e11)}
_FIBRE = {  # mass per d², (MBL per d², per d³), EA / MBL, specific gravity
    "nylon": (585.15, (207.0e6, 230.29e6), 5.0, 1.14),
    "polyester": (678.75, (308.2e6, 0.0), 14.0, 1.38),
}
#: The catalogue's line names (the tow file's ``line`` key) and what each is.
LINES = {
    "wire": "six-strand steel wire rope, independent wire rope core (IWRC)",
    "wire-fc": "six-strand steel wire rope, fibre core",
    "wire-spiral": "sheathed spiral-strand steel wire (mooring wire)",
    "chain": "studless chain",
    "chain-studlink": "studlink chain",
    "nylon": "nylon fibre rope",
    "polyester": "polyester fibre rope",
}
#: The diameter range [m] each kind's laws are published for (outside: a ValueError).
_RANGE = {"wire": (0.01, 0.16), "chain": (0.02, 0.2), "fibre": (0.02, 0.3)}


@dataclass(frozen=True)
class LineType:
    """One line: ``name``, ``kind`` (wire | chain | fibre), nominal ``diameter`` [m],
    ``mass`` in air [kg/m], submerged ``weight`` [N/m], axial stiffness ``EA`` [N],
    minimum breaking load ``mbl`` [N], and the ``source`` of the values."""

    name: str
    kind: str
    diameter: float
    mass: float
    weight: float
    EA: float
    mbl: float
    source: str

    def __post_init__(self):
        for f in ("diameter", "mass", "EA", "mbl"):
            v = getattr(self, f)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ValueError(f"LineType {f} must be > 0 and finite, got {v!r}")
        if not (math.isfinite(self.weight) and self.weight >= 0):
            raise ValueError(
                f"LineType weight must be >= 0 and finite (a buoyant line is not modelled), "
                f"got {self.weight!r}"
            )

    def towline(self, length: float, *, scales, xp: float, yp: float = 0.0, catenary=True):
        """The tow model's line of unstretched ``length`` [m] on the tow of ``scales``:
        an elastic catenary (`jaxtow.CatenaryTowline`) with this line's weight, or with
        ``catenary=False`` the straight elastic line (`jaxtow.Towline`) of the same EA."""

        if catenary:
            return CatenaryTowline.from_si(
                length, self.weight, self.EA, scales=scales, xp=xp, yp=yp
            )
        return Towline(l0=length / scales.length, xp=xp, EA=self.EA / scales.force, yp=yp)

    def with_values(self, **values) -> LineType:
        """The same line with values from a certificate (e.g. ``EA=``, ``mbl=``)."""
        return replace(self, source=self.source + "; " + ", ".join(values) + " given", **values)


def _diameter(kind: str, d) -> float:
    lo, hi = _RANGE[kind]
    if isinstance(d, bool) or not isinstance(d, (int, float)) or not math.isfinite(d):
        raise ParameterError("diameter", f"diameter must be a finite number in metres, got {d!r}")
    if not lo <= d <= hi:
        raise ParameterError(
            "diameter",
            f"diameter must lie in [{lo}, {hi}] m for {kind} (the published laws' range), "
            f"got {d} m" + (" (a diameter in mm? give metres)" if d > 1 else ""),
        )
    return float(d)


def wire_rope(diameter: float, core: str = "IWRC") -> LineType:
    """Steel wire of nominal ``diameter`` [m]: six-strand rope with ``core`` IWRC or FC, or
    ``core="spiral"``, sheathed spiral strand."""
    if core not in _WIRE:
        raise ParameterError("core", f"core must be one of {sorted(_WIRE)}, got {core!r}")
    d = _diameter("wire", diameter)
    m, ea, mbl, rho = _WIRE[core]
    mass = m * d**2
    spiral = core == "spiral"
    return LineType(
        name=f"{d * 1e3:g} mm "
        + ("sheathed spiral-strand wire" if spiral else f"six-strand wire rope ({core})"),
        kind="wire",
        diameter=d,
        mass=mass,
        weight=mass * G * (1.0 - RHO_SEA / rho),
        EA=ea * d**2,
        mbl=mbl * d**2,
        source=f"{_MOORPY} (wire rope)" if spiral else _WIZARD,
    )


def chain(diameter: float, grade: str = "R3", kind: str = "studless") -> LineType:
    """Chain of nominal (bar) ``diameter`` [m], ``grade`` (`CHAIN_GRADES`), ``kind``
    studless or studlink."""
    if grade not in CHAIN_GRADES:
        raise ParameterError("grade", f"grade must be one of {list(CHAIN_GRADES)}, got {grade!r}")
    if kind not in _CHAIN:
        raise ParameterError("kind", f"kind must be one of {sorted(_CHAIN)}, got {kind!r}")
    d = _diameter("chain", diameter)
    m, ea = _CHAIN[kind]
    mass = m * d**2
    dmm = d * 1e3
    return LineType(
        name=f"{dmm:g} mm {grade} {kind} chain",
        kind="chain",
        diameter=d,
        mass=mass,
        weight=mass * G * (1.0 - RHO_SEA / _STEEL),
        EA=ea * d**2,
        mbl=CHAIN_GRADES[grade] * dmm**2 * (44.0 - 0.08 * dmm) * 1e3,
        source=f"{_WIZARD} (mass, EA); IACS UR W22 / DNV-OS-E302 (MBL)",
    )


def fibre_rope(diameter: float, material: str = "polyester") -> LineType:
    """Nylon or polyester rope of nominal ``diameter`` [m] (linear secant EA; see
    `fit_power_law` for the load-dependent law)."""
    if material not in _FIBRE:
        raise ParameterError(
            "material", f"material must be one of {sorted(_FIBRE)}, got {material!r}"
        )
    d = _diameter("fibre", diameter)
    m, (b2, b3), k, sg = _FIBRE[material]
    mass = m * d**2
    mbl = b2 * d**2 + b3 * d**3
    return LineType(
        name=f"{d * 1e3:g} mm {material} rope",
        kind="fibre",
        diameter=d,
        mass=mass,
        weight=mass * G * (1.0 - RHO_SEA / (1000.0 * sg)),
        EA=k * mbl,
        mbl=mbl,
        source=f"NREL MoorPy line property coefficients (quasi-static EA = {k:g} MBL)",
    )


def line(name: str, diameter: float, *, grade: str = "R3") -> LineType:
    """A catalogue line by its name in `LINES` (``grade`` for chain)."""
    if name == "wire":
        return wire_rope(diameter, "IWRC")
    if name == "wire-fc":
        return wire_rope(diameter, "FC")
    if name == "wire-spiral":
        return wire_rope(diameter, "spiral")
    if name in ("chain", "chain-studlink"):
        return chain(diameter, grade, "studless" if name == "chain" else "studlink")
    if name in _FIBRE:
        return fibre_rope(diameter, name)
    raise ParameterError("line", f"line must be one of {list(LINES)}, got {name!r}")


def composite(segments, *, scales, xp: float, yp: float = 0.0):
    """A line of ``segments`` [(LineType, length [m]), ...] in series, from the hawser to
    the tug (`jaxtow.CompositeTowline`)."""

    segments = list(segments)
    if len(segments) < 2:
        raise ValueError("segments: a composite line needs at least two (LineType, length)")
    for i, (lt, length) in enumerate(segments):
        if not isinstance(lt, LineType):
            raise ValueError(f"segments[{i}]: expected (LineType, length), got {lt!r}")
        if not (isinstance(length, (int, float)) and math.isfinite(length) and length > 0):
            raise ValueError(f"segments[{i}]: length must be > 0 and finite, got {length!r}")
    return CompositeTowline.from_si(
        [s[1] for s in segments],
        [s[0].weight for s in segments],
        [s[0].EA for s in segments],
        scales=scales,
        xp=xp,
        yp=yp,
    )


def fit_power_law(strain, tension) -> tuple[float, float]:
    """(S_b, q) of T = S_b ε^q (Bernitsas & Kekridis; `jaxtow.PowerLawTowline`) fitted by
    least squares in log–log to load–extension points (``strain`` ε > 0, ``tension`` > 0
    in any unit: S_b comes in the same unit)."""
    e, t = np.asarray(strain, float), np.asarray(tension, float)
    if e.shape != t.shape or e.ndim != 1 or e.size < 2:
        raise ValueError("strain and tension must be 1-D arrays of one length (>= 2 points)")
    if not (np.all(np.isfinite(e)) and np.all(e > 0)):
        raise ValueError("strain must be > 0 and finite at every point")
    if not (np.all(np.isfinite(t)) and np.all(t > 0)):
        raise ValueError("tension must be > 0 and finite at every point")
    q, log_s = np.polyfit(np.log(e), np.log(t), 1)
    return float(np.exp(log_s)), float(q)
