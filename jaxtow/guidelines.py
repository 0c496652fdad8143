"""Towing-guideline criteria as pure functions of the tow's numbers: the weather criterion
and the required bollard pull, the towline's breaking load against the bollard pull, the
minimum towline length, the catenary against the water depth, the connecting parts against
the line, and the yaw behaviour. Each returns a `Check`: the value, the limit, pass/fail,
the margin and the source of the limit.

The values and their sources are in one place, `Criteria` (docs/guidelines.md has the
table). Where this project could not read a value in the published text, the value is a
documented estimate, says so in its ``source`` and is overridable in the tow file's
``[criteria]`` section; results that depend on it say so (`Check.estimate`).
"""

from __future__ import annotations

import dataclasses
import math

__all__ = [
    "Check",
    "Criteria",
    "GUIDELINES",
    "criteria",
    "mbl_factor",
    "minimum_towline_length",
    "check_bollard_pull",
    "check_mbl",
    "check_towline_length",
    "check_seabed_clearance",
    "check_connections",
    "check_yaw",
]


@dataclasses.dataclass(frozen=True)
class Criteria:
    """The limits of a guideline (SI unless named otherwise) and where each comes from.

    ``wind_speed`` [m/s], ``hs`` [m], ``current_speed`` [m/s]: the weather criterion the
    tug must hold the tow in (acting together, from ahead, zero speed over ground; the tug's
    efficiency is the tow's, one value: `check_bollard_pull`); ``mbl_breaks`` [t], ``mbl_factors``: the MBL/BP law of `mbl_factor`;
    ``length_factor`` [m]: the minimum towline length is ``length_factor``·BP/MBL;
    ``connection_ratio``: the MBL of bridles, pennants and shackles relative to the
    towline's; ``seabed_clearance`` [m]: the least clearance of the catenary above the
    seabed; ``sources``: field → the clause, or "estimate: ..." where no text was read."""

    name: str
    wind_speed: float = 20.0
    hs: float = 5.0
    current_speed: float = 0.5
    mbl_breaks: tuple = (40.0, 90.0)
    mbl_factors: tuple = (3.0, 2.0)
    length_factor: float = 1800.0
    connection_ratio: float = 1.0
    seabed_clearance: float = 0.0
    sources: dict = dataclasses.field(default_factory=dict)

    def estimate(self, field: str) -> bool:
        """True if ``field`` is a documented estimate, not a value read in the text."""
        return self.sources.get(field, "").startswith("estimate")

    def replace(self, **changes) -> Criteria:
        """A copy with ``changes`` (a tow file's ``[criteria]`` overrides); a changed value's
        source becomes "set in the tow file"."""
        unknown = set(changes) - {f.name for f in dataclasses.fields(self)} - {"name"}
        if unknown:
            raise ValueError(f"unknown criteria {sorted(unknown)}")
        sources = dict(self.sources, **{k: "set in the tow file" for k in changes})
        return dataclasses.replace(self, **changes, sources=sources)


_WEATHER = (
    "the unrestricted-towage weather criterion the guidelines are cited for (wind 20 m/s, "
    "Hs 5 m, current 0.5 m/s acting together; the text itself was not available to this "
    "project: docs/guidelines.md)"
)
_SHARED = {
    "wind_speed": _WEATHER,
    "hs": _WEATHER,
    "current_speed": _WEATHER,
    "mbl_breaks": "main towline MBL for unrestricted towages as the guideline is cited for: "
    "3.0 BP up to 40 t, (3.8 - BP/50) BP from 40 to 90 t, 2.0 BP above 90 t",
    "mbl_factors": "as mbl_breaks",
    "length_factor": "minimum main towline length 1800 BP/MBL metres, as the guideline is "
    "cited for",
    "connection_ratio": "estimate: connecting parts (bridle legs, pennant, shackles) not "
    "weaker than the towline; check the edition in use for its own ratio",
    "seabed_clearance": "the static catenary must clear the seabed (a physical limit; set a "
    "margin in [criteria] seabed_clearance)",
}

#: The guidelines a tow file can name in ``[criteria] guideline``.
GUIDELINES = {
    "gl-nd-0030": Criteria(
        name="GL Noble Denton 0030/ND, Guidelines for marine transportations",
        sources=dict(_SHARED),
    ),
    "dnv-st-n001": Criteria(
        name="DNV-ST-N001, Marine operations and marine warranty (towing)",
        sources=dict(_SHARED),
    ),
}


def criteria(guideline: str = "gl-nd-0030", **overrides) -> Criteria:
    """The `Criteria` of ``guideline`` (a key of `GUIDELINES`) with ``overrides``."""
    if guideline not in GUIDELINES:
        raise ValueError(
            f"parameter 'guideline' must be one of {sorted(GUIDELINES)}, got {guideline!r}"
        )
    base = GUIDELINES[guideline]
    return base.replace(**overrides) if overrides else base


@dataclasses.dataclass(frozen=True)
class Check:
    """One criterion: ``value`` against ``limit`` (``passed`` when value is on the right
    side: ``value >= limit`` for ``kind='min'``, ``<=`` for ``'max'``), the ``margin``
    (value − limit for 'min', limit − value for 'max'; negative when failing), ``units``,
    ``source`` and ``estimate`` (the limit is a documented estimate)."""

    criterion: str
    value: float
    limit: float
    kind: str
    units: str
    source: str
    estimate: bool = False

    @property
    def passed(self) -> bool:
        return bool(self.margin >= 0)

    @property
    def margin(self) -> float:
        return self.value - self.limit if self.kind == "min" else self.limit - self.value

    def record(self) -> dict:
        """JSON-ready: every field, ``passed`` and ``margin``."""
        return dict(dataclasses.asdict(self), passed=self.passed, margin=self.margin)


def _positive(name: str, x: float) -> float:
    x = float(x)
    if not (math.isfinite(x) and x > 0):
        raise ValueError(f"parameter {name!r} must be > 0 and finite, got {x!r}")
    return x


def mbl_factor(bollard_pull_t: float, c: Criteria | None = None) -> float:
    """The required MBL/BP of the main towline at a bollard pull [t]: ``mbl_factors[0]`` up
    to ``mbl_breaks[0]``, ``mbl_factors[1]`` above ``mbl_breaks[1]``, linear in between
    (with the defaults 3.0, then 3.8 − BP/50, then 2.0: continuous at 40 and 90 t)."""
    c = c or GUIDELINES["gl-nd-0030"]
    bp = _positive("bollard_pull_t", bollard_pull_t)
    (b0, b1), (f0, f1) = c.mbl_breaks, c.mbl_factors
    if bp <= b0:
        return f0
    if bp >= b1:
        return f1
    return f0 + (f1 - f0) * (bp - b0) / (b1 - b0)


def minimum_towline_length(bollard_pull: float, mbl: float, c: Criteria | None = None) -> float:
    """``length_factor``·BP/MBL [m] (both forces in the same units)."""
    c = c or GUIDELINES["gl-nd-0030"]
    return c.length_factor * _positive("bollard_pull", bollard_pull) / _positive("mbl", mbl)


def check_bollard_pull(
    required_t: float, available_t: float, c: Criteria, *, efficiency_source: str = ""
) -> Check:
    """The tug's rated continuous bollard pull [t] against the pull required to hold the tow
    in the weather criterion [t] (towing force / tug efficiency); ``efficiency_source`` says
    where the efficiency came from ("estimate: ..." when it is the documented estimate)."""
    return Check(
        "bollard pull (hold the tow in the weather criterion)",
        float(available_t),
        float(required_t),
        "min",
        "t",
        efficiency_source or c.sources.get("hs", ""),
        efficiency_source.startswith("estimate"),
    )


def check_mbl(mbl_t: float, bollard_pull_t: float, c: Criteria) -> Check:
    """The weakest towline segment's MBL [t] against the factor times the bollard pull."""
    need = mbl_factor(bollard_pull_t, c) * float(bollard_pull_t)
    return Check(
        f"towline MBL (>= {mbl_factor(bollard_pull_t, c):.2f} x bollard pull)",
        float(mbl_t),
        need,
        "min",
        "t",
        c.sources.get("mbl_breaks", ""),
        c.estimate("mbl_breaks"),
    )


def check_towline_length(length_m: float, bollard_pull: float, mbl: float, c: Criteria) -> Check:
    """The towline's length [m] against `minimum_towline_length`."""
    return Check(
        "towline length",
        float(length_m),
        minimum_towline_length(bollard_pull, mbl, c),
        "min",
        "m",
        c.sources.get("length_factor", ""),
        c.estimate("length_factor"),
    )


def check_seabed_clearance(sag_m: float, water_depth_m: float, c: Criteria) -> Check:
    """The catenary's clearance above the seabed (depth − sag) [m] against the least
    allowed."""
    return Check(
        "towline clear of the seabed (water depth - catenary sag)",
        float(water_depth_m) - float(sag_m),
        c.seabed_clearance,
        "min",
        "m",
        c.sources.get("seabed_clearance", ""),
        c.estimate("seabed_clearance"),
    )


def check_connections(weakest_connection_t: float, towline_mbl_t: float, c: Criteria) -> Check:
    """The weakest connecting part's MBL [t] against ``connection_ratio`` times the
    towline's."""
    return Check(
        "connecting parts (bridle, pennant, shackles) against the towline",
        float(weakest_connection_t),
        c.connection_ratio * float(towline_mbl_t),
        "min",
        "t",
        c.sources.get("connection_ratio", ""),
        c.estimate("connection_ratio"),
    )


def check_yaw(max_real: float, condition: str) -> Check:
    """Yaw behaviour: the largest real part of the eigenvalues of the straight-behind
    equilibrium [1/s] against 0: the tow follows the tug when it is negative (a
    disturbance decays, halving in ln 2/|max Re λ| seconds)."""
    return Check(
        f"follows the tug, {condition} (max Re lambda, straight behind)",
        float(max_real),
        0.0,
        "max",
        "1/s",
        "directional stability on the towline: every equilibrium's eigenvalues (docs/model.md "
        "section 5); the guidelines ask for a tow that follows the tug",
    )
