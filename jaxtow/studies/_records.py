"""The typed records of a tow study, end to end: the study builds them, the report, the figures,
the command line and the JSON writer read them by attribute (a type checker follows every
field from the study to the page). Frozen `msgspec.Struct`s: ``msgspec.json`` writes them
as they are (`to_json`), NaN as null, and the step store keeps them as pickles.

SI units unless a name says otherwise; non-dimensional values (by the tow's scales:
½ρTLU² forces, L/U times) carry a ``_nd`` suffix or say so.
"""

from __future__ import annotations

import math

import msgspec

__all__ = [
    "Record",
    "EquilibriumRow",
    "Bounds",
    "Condition",
    "MeanDriftRow",
    "DriftRecord",
    "ResistanceRow",
    "TugRecord",
    "LineSegmentRow",
    "StrengthRecord",
    "CatenaryRecord",
    "TowlineRecord",
    "MapRecord",
    "TimeDomainRecord",
    "CheckRow",
    "OperatingRow",
    "Assessment",
    "AdviceRow",
    "FindingRow",
    "Incomplete",
    "Probability",
    "RiskHsPoint",
    "RiskDesignRow",
    "RiskRecord",
    "StudySummary",
    "to_json",
    "VERDICTS",
    "CHECK_VERDICTS",
]

#: The overall verdict of a study.
VERDICTS = ("acceptable", "not acceptable", "not determined")
#: The verdict of one criterion.
CHECK_VERDICTS = ("pass", "fail", "not determined", "not checked")


class Record(msgspec.Struct, frozen=True, kw_only=True):
    """Base of the study's records."""


class EquilibriumRow(Record, frozen=True, kw_only=True):
    """One equilibrium: heading ``psi_deg`` and towline angle ``gamma_deg`` [deg], towline
    tension ``tension`` [N] (``tension_nd`` by ½ρTLU²), the largest real part of its
    eigenvalues ``max_real`` [1/s] (``max_real_nd`` by U/L), its ``stability`` (stable,
    marginal, unstable), whether the solver found it (``found``) and whether it is inside
    every validity limit (``valid``), the limits it breaks (``outside``: flag names; the
    plain words are `Condition.outside_text`), and whether it is straight behind
    (``straight``: `jaxtow.straight_behind`)."""

    psi_deg: float
    gamma_deg: float
    tension: float
    tension_nd: float
    max_real: float
    max_real_nd: float
    stability: str
    found: bool
    valid: bool
    outside: list[str]
    straight: bool


class Bounds(Record, frozen=True, kw_only=True):
    """The verdict repeated under the bounds that still hold where the forward-speed drift
    theory is outside its validity: drift form → verdict key, and whether any differs."""

    verdicts: dict[str, str]
    changes: bool


class Condition(Record, frozen=True, kw_only=True):
    """The equilibria and stability of the tow in one condition: its ``name`` ("calm water",
    "sea state survival", "sea state survival at 2.34 m/s"), ``kind`` (calm, sea state,
    operating speed), the ``sea_state`` it belongs to, the tow ``speed`` [m/s], the scales
    of its non-dimensional numbers, the sea (Hs, Tp, wind, current), the ``equilibria``,
    the ``verdict`` (a key of `jaxtow.studies.YAW_VERDICTS`) and its ``verdict_text``, the
    validity limits any equilibrium breaks (``outside_validity``, with ``outside_text`` in
    plain words), the ``bounds`` where the forward-speed theory is outside its validity,
    and ``notes``."""

    name: str
    kind: str
    sea_state: str | None
    speed: float
    force_scale: float
    time_scale: float
    hs: float
    tp: float
    wind_speed: float
    current_speed: float
    equilibria: list[EquilibriumRow]
    verdict: str
    verdict_text: str
    outside_validity: list[str]
    outside_text: list[str]
    bounds: Bounds | None = None
    notes: list[str] = []

    @property
    def straight(self) -> EquilibriumRow | None:
        """The straight-behind equilibrium (None if the solver found none)."""
        rows = [e for e in self.equilibria if e.straight and e.found]
        return min(rows, key=lambda e: abs(e.psi_deg), default=None)


class MeanDriftRow(Record, frozen=True, kw_only=True):
    """The mean surge drift [N] of the hull in one sea state, at rest and at the design
    speed (negative: pushing the tow astern)."""

    sea_state: str
    hs: float
    tp: float
    fx_stationary: float
    fx_design_speed: float


class DriftRecord(Record, frozen=True, kw_only=True):
    """The hull's wave drift: its ``source`` (the one drift source every result uses), the
    head-sea surge at the highest frequency against the short-wave wall limit ½ρgB, and the
    mean drift in each sea state."""

    source: str
    wall_limit_ratio: float
    mean_drift: list[MeanDriftRow]


class ResistanceRow(Record, frozen=True, kw_only=True):
    """One sea state's resistance: the sea, the tug's ``efficiency`` in it, the components at
    zero speed (``hold``, [N] by `jaxtow.resistance.COMPONENTS`) and their sum
    ``hold_towing_force``, the ``required_bollard_pull`` [N] (and its worst over the
    physical Tp range, with that Tp), the operating point's ``status`` and ``message``;
    where the tug holds the tow: the ``operating_speed`` [m/s], its Froude number, the tug's
    ``available_pull`` there [N] (η P(U) less its own resistance: what it gives the
    towline), the components there, the overtaken share of the sea's energy and the
    transit time."""

    sea_state: str
    hs: float
    tp: float
    wind_speed: float
    current_speed: float
    efficiency: float
    hold: dict[str, float]
    hold_towing_force: float
    required_bollard_pull: float
    physical_tp_range: list[float] | None = None
    worst_tp: float | None = None
    worst_required_bollard_pull: float | None = None
    status: str = "successful"
    message: str = ""
    operating_speed: float | None = None
    froude: float | None = None
    available_pull: float | None = None
    operating_resistance: dict[str, float] | None = None
    overtaken_energy: float | None = None
    transit_time_h: float | None = None

    @property
    def required(self) -> float:
        """The required bollard pull [N], the worst over Tp where the sea has waves."""
        return max(self.required_bollard_pull, self.worst_required_bollard_pull or 0.0)

    @property
    def required_tp(self) -> float:
        """The Tp [s] the required bollard pull is the worst at."""
        worst = self.worst_required_bollard_pull or 0.0
        return self.worst_tp if worst > self.required_bollard_pull and self.worst_tp else self.tp


class TugRecord(Record, frozen=True, kw_only=True):
    """The tug: rated ``bollard_pull`` [N], ``free_speed`` [m/s], its ``efficiency`` and
    the sea states that give their own (``efficiencies``)."""

    bollard_pull: float
    free_speed: float
    efficiency: float
    efficiencies: dict[str, float] = {}
    efficiency_estimate: bool = False


class LineSegmentRow(Record, frozen=True, kw_only=True):
    """One piece of the towline's make (`jaxtow.tow.LineSegment`)."""

    name: str
    role: str
    length: float
    mbl: float
    EA: float
    weight: float
    source: str


class StrengthRecord(Record, frozen=True, kw_only=True):
    """The towline's make and its loads: the pieces, the weakest in series and its ``mbl``
    [N]; the largest mean end tension over calm water and every sea state [N] (where the
    study got that far) with the condition it is in, its share of the MBL, and MBL / BP."""

    segments: list[LineSegmentRow]
    weakest: str
    mbl: float
    max_end_tension: float | None = None
    max_tension_condition: str | None = None
    utilisation: float | None = None
    mbl_over_bollard_pull: float | None = None


class CatenaryRecord(Record, frozen=True, kw_only=True):
    """The catenary of a line with weight at the calm-water equilibrium nearest straight
    behind: span, horizontal and end tension [N], sag [m], effective and elastic stiffness
    (non-dimensional), and against the water depth its seabed clearance."""

    span_m: float
    horizontal_tension: float
    end_tension: float
    sag_m: float
    effective_stiffness_nd: float
    elastic_stiffness_nd: float
    water_depth: float | None = None
    seabed_clearance_m: float | None = None


class TowlineRecord(Record, frozen=True, kw_only=True):
    """The towline: unstretched length ``length_m`` [m] (``l0`` by L), attachment ``xp``,
    ``yp`` by L (to port), ``EA`` [N] (``EA_nd``), and its catenary and strength."""

    l0: float
    length_m: float
    xp: float
    yp: float
    EA: float
    EA_nd: float
    catenary: CatenaryRecord | None = None
    strength: StrengthRecord | None = None


class MapRecord(Record, frozen=True, kw_only=True):
    """The calm-water stability map around the design point: its grids [lo, hi, n] by L,
    the ``design_xp``, ``design_l0`` (by L), the tow's length [m] for the dimensional axes,
    and the share of the map where the straight-behind equilibrium is stable."""

    xp: list[float]
    l0: list[float]
    design_xp: float
    design_l0: float
    length: float
    straight_stable_share: float


class TimeDomainRecord(Record, frozen=True, kw_only=True):
    """The calm-water run from a disturbed start (heading ``psi0_deg``, sway ``y0`` by L, for
    ``t1`` by L/U) and its fishtailing metrics (`jaxtow.FishtailMetrics`), with the
    run's validity flags."""

    psi0_deg: float
    y0: float
    t1: float
    outcome: str
    path_width: float | None
    yaw_range: list[float] | None
    slewing_period: float | None
    ended_early: bool
    validity: dict[str, bool]


class CheckRow(Record, frozen=True, kw_only=True):
    """One criterion of the guideline: ``key`` (stable, for scripts), the ``criterion`` in
    words and its ``condition``, ``value`` against ``limit`` (``kind`` min: value ≥ limit;
    max: value ≤ limit) in ``units``, the ``margin``, the ``verdict`` (`CHECK_VERDICTS`:
    pass, fail, not determined where the result rests on a theory outside its validity and
    a bound that still holds gives the other answer, not checked where an input it needs is
    missing), ``reason`` (why not determined or not checked, in plain words), ``detail``
    (the basis), the ``source`` of the limit and whether it is an ``estimate``. Yaw rows
    give ``time_s``: the time a disturbance takes to halve (stable) or double (unstable)."""

    key: str
    criterion: str
    condition: str
    kind: str
    units: str
    verdict: str
    value: float | None = None
    limit: float | None = None
    margin: float | None = None
    reason: str = ""
    detail: str = ""
    source: str = ""
    estimate: bool = False
    time_s: float | None = None

    @property
    def passed(self) -> bool:
        return self.verdict == "pass"


class OperatingRow(Record, frozen=True, kw_only=True):
    """One sea state's operating point: the ``speed`` [m/s] (None when the tug cannot hold
    the tow), the pull the tug gives the towline there ``available_pull`` [N], and the
    towline tension of the stability model at that speed ``towline_tension`` [N]: the same
    number, since the resistance budget and the model evaluate one drift source (and the
    same wind and current) at the same speed."""

    sea_state: str
    speed: float | None
    available_pull: float | None
    towline_tension: float | None
    status: str
    message: str
    transit_time_h: float | None = None


class FindingRow(Record, frozen=True, kw_only=True):
    """A plausibility finding of the tow file (`jaxtow.tow.Finding`)."""

    key: str
    text: str
    parameter: str = ""


class Assessment(Record, frozen=True, kw_only=True):
    """The decision: ``verdict`` (`VERDICTS`) and the one sentence of why (``reason``), the
    ``guideline`` and its ``checks``, the ``operating`` point of each sea state, and the
    ``findings`` a planner must read (plain sentences, the most serious first)."""

    verdict: str
    reason: str
    guideline: str
    checks: list[CheckRow]
    operating: list[OperatingRow]
    findings: list[str]

    @property
    def all_passed(self) -> bool:
        return self.verdict == "acceptable"

    def counts(self) -> dict[str, int]:
        """How many checks have each verdict."""
        return {v: sum(c.verdict == v for c in self.checks) for v in CHECK_VERDICTS}


class AdviceRow(Record, frozen=True, kw_only=True):
    """One way forward: for ``condition``, change ``what`` (``kind``: a tow parameter, skegs,
    the line for the seabed, a larger tug) from ``present_text`` to ``value_text`` (None
    where no value in ``searched_text`` does it), with the tow-file line that makes it
    (``tow_file``), the re-checked result (``new_max_real`` [1/s] where it is a yaw
    change) and ``verified`` (the full check at the suggested value passes)."""

    condition: str
    kind: str
    parameter: str
    what: str
    present: float
    present_text: str
    searched_text: str
    value: float | None = None
    value_text: str | None = None
    tow_file: str | None = None
    new_max_real: float | None = None
    verified: bool | None = None
    note: str = ""


class Probability(Record, frozen=True, kw_only=True):
    """A probability from a batch of runs and its 95 % Wilson interval (``low``, ``high``)."""

    value: float
    low: float
    high: float


class RiskHsPoint(Record, frozen=True, kw_only=True):
    """The fishtail probability at another significant wave height ``hs`` [m] (the sea
    state's Tp, γ, wind and current), from ``runs`` runs."""

    hs: float
    runs: int
    fishtail: Probability


class RiskDesignRow(Record, frozen=True, kw_only=True):
    """One design change tried on the same random numbers as the base runs: ``parameter``
    from ``present`` to ``value`` (by L), its text in metres, the probabilities of the base
    and the changed tow over the ``runs`` they share, the ``difference`` (changed − base)
    with its paired 95 % interval, and McNemar's exact ``p_value`` (below 0.05: the change
    is real)."""

    parameter: str
    present: float
    value: float
    text: str
    runs: int
    base: float
    changed: float
    difference: Probability
    p_value: float


class RiskRecord(Record, frozen=True, kw_only=True):
    """The irregular-sea Monte Carlo of one sea state (`jaxtow.risk.irregular_sea`) at the
    design speed: ``runs`` of ``duration_h`` hours (``failed_runs`` that did not reach the
    end; ``stopped_by_budget`` where the time budget ended the batch), the ``fishtail``
    probability in a run (yaw amplitude above ``yaw_threshold_deg``) and at 5° and 20°, the
    probability over the route's ``exposure_h`` where it has one, the towline's static
    tension, the most probable maximum tension in 3 h (``mpm_tension``) and the largest of
    all runs [N], the probabilities of exceeding the MBL and the guideline's design load
    MBL/f(BP) [N], of a slack event, the validity of the drift at the static equilibrium in
    words, the probability against Hs, the design changes tried, the settings used and the
    wall time."""

    sea_state: str
    hs: float
    tp: float
    runs: int
    failed_runs: int
    duration_h: float
    record_h: float
    stopped_by_budget: str = ""
    yaw_threshold_deg: float
    fishtail: Probability
    fishtail_5deg: Probability
    fishtail_20deg: Probability
    exposure_h: float | None = None
    fishtail_exposure: Probability | None = None
    static_tension: float
    mpm_tension: float
    largest_tension: float
    mbl: float | None = None
    exceed_mbl: Probability | None = None
    design_load: float | None = None
    exceed_design_load: Probability | None = None
    slack: Probability
    outside_validity: list[str] = []
    hs_curve: list[RiskHsPoint] = []
    design: list[RiskDesignRow] = []
    settings: dict[str, object] = {}
    seconds: float = 0.0


class Incomplete(Record, frozen=True, kw_only=True):
    """Where a study stopped: the ``step`` running, what went wrong (``error``), and whether
    it was a Ctrl-C."""

    step: str
    error: str
    interrupted: bool


class StudySummary(Record, frozen=True, kw_only=True):
    """Everything a tow study found, typed: the tow and its scales, the drift, the
    resistance and operating points, the ``conditions`` (calm water, each sea state at the
    design speed and at its operating speed), the map, the time-domain check, the
    ``assessment`` (the decision) and the ``advice``; what was ``skipped`` and why, the
    estimates (``assumed``), ``warnings`` and ``plausibility`` findings of the tow file,
    the step times, and ``incomplete`` where the study stopped early."""

    tow: str
    description: str
    source: str
    design_speed: float
    length: float
    breadth: float
    draft: float
    force_scale: float
    time_scale: float
    sailing_form: str
    drift_source: str
    assumed: list[list[str]]
    warnings: list[str]
    plausibility: list[FindingRow]
    skipped: dict[str, str] = {}
    drift: DriftRecord | None = None
    stability_coefficient_c: float | None = None
    towline: TowlineRecord | None = None
    tug: TugRecord | None = None
    route_length_m: float | None = None
    components: list[str] = []
    resistance: list[ResistanceRow] = []
    conditions: list[Condition] = []
    map: MapRecord | None = None
    time_domain: TimeDomainRecord | None = None
    assessment: Assessment | None = None
    advice: list[AdviceRow] = []
    risk: list[RiskRecord] = []
    incomplete: Incomplete | None = None
    step_times_s: dict[str, float] = {}
    figure_errors: dict[str, str] = {}

    @property
    def calm(self) -> Condition | None:
        return next((c for c in self.conditions if c.kind == "calm"), None)

    def sea(self, name: str, kind: str = "sea state") -> Condition | None:
        """The condition of sea state ``name`` (``kind`` "sea state" at the design speed,
        "operating speed" at its operating speed)."""
        return next((c for c in self.conditions if c.sea_state == name and c.kind == kind), None)


def _enc_hook(obj):
    if hasattr(obj, "item"):  # NumPy and JAX scalars
        return obj.item()
    raise NotImplementedError(f"no JSON for {type(obj).__name__}")


def _finite(x):
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def to_json(record: Record, *, indent: int = 2) -> str:
    """The record as readable JSON (msgspec; NaN and ±inf as null)."""
    raw = msgspec.json.encode(record, enc_hook=_enc_hook)
    return msgspec.json.format(raw, indent=indent).decode()
