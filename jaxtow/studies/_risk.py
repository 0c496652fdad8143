"""The irregular-sea risk step of a tow study: where the linear verdict cannot decide (a yaw
criterion NOT DETERMINED, or on request with ``[study] risk = "always"``), the Monte Carlo
of `jaxtow.risk` within the study's time budget (``[study] risk_budget_s``): the probability
of fishtailing with its interval, the towline's largest tension against its MBL, the
probability against Hs, and the design changes tried on the same random numbers (a shorter
and a longer towline, the hawser point forward and aft), which the advice reports.

The budget is shared equally by the sea states run; within one, half goes to the base runs,
a fifth to the probability at half the sea state's Hs, the rest to the design changes,
which replay the base runs' first random numbers. Each batch stops after the chunk that
reaches its share (at least one chunk of four runs each).
"""

from __future__ import annotations

import dataclasses
import math
import time

import msgspec
import numpy as np

from .. import design, risk
from .._parameters import get_parameter, with_parameters
from ..resistance import SeaState
from ._conditions import VALIDITY_WORDS
from ._records import (
    AdviceRow,
    CheckRow,
    Probability,
    RiskDesignRow,
    RiskHsPoint,
    RiskRecord,
    StudySummary,
)

__all__ = ["risk_seas", "risk_step", "risk_record", "with_risk", "risk_advice", "RISK_SETTINGS"]

#: The Monte Carlo's settings in a study: chunks of 4 runs (the budget's granularity).
RISK_SETTINGS = risk.RiskSettings(chunk_size=4)
#: Shares of one sea state's budget: base runs, probability at a lower Hs, design changes.
SHARES = (0.5, 0.2, 0.3)
#: The lower Hs of the probability curve, as a fraction of the sea state's.
HS_FRACTION = 0.5


def risk_seas(tow, s: StudySummary) -> list[SeaState]:
    """The sea states the study runs the Monte Carlo for ([study] risk): auto: those whose
    yaw criterion (at the design or the operating speed) is not determined; always: every
    sea state with waves; never: none."""
    mode = tow.study.risk
    seas = [sea for sea in tow.sea_states if float(sea.hs) > 0]
    if mode == "never" or not tow.has_model:
        return []
    if mode == "always":
        return seas
    undecided = set()
    if s.assessment is not None:
        for c in s.assessment.checks:
            if c.key.startswith(("yaw:sea:", "yaw:operating:")) and c.verdict == "not determined":
                undecided.add(c.key.split(":", 2)[2])
    return [sea for sea in seas if sea.name in undecided]


def _p(value, interval) -> Probability:
    return Probability(value=float(value), low=float(interval[0]), high=float(interval[1]))


def risk_record(tow, r: risk.RiskResult, hs_curve, design, seconds: float) -> RiskRecord:
    """The record of one sea state's Monte Carlo."""
    s, d = r.settings, r.described
    exposure = None
    if tow.route_length is not None and d.get("speed"):
        exposure = tow.route_length / float(d["speed"]) / 3600.0
    outside = [VALIDITY_WORDS.get(k, k) for k, v in r.validity.items() if v is False]
    return RiskRecord(
        sea_state=d.get("sea_state", ""),
        hs=float(d.get("hs", 0.0)),
        tp=float(d.get("tp", 0.0)),
        runs=r.n,
        failed_runs=r.failed_runs,
        duration_h=s.duration / 3600.0,
        record_h=r.record_hours,
        stopped_by_budget=d.get("stopped_by_budget", ""),
        yaw_threshold_deg=s.yaw_threshold,
        fishtail=_p(r.fishtail_probability, r.confidence_interval),
        fishtail_5deg=_p(*r.probability_at(5.0)),
        fishtail_20deg=_p(*r.probability_at(20.0)),
        exposure_h=exposure,
        fishtail_exposure=None if exposure is None else _p(*r.probability_in(exposure)),
        static_tension=r.static_tension,
        mpm_tension=r.mpm_tension if r.n >= 2 else float(np.max(r.max_tension)),
        largest_tension=float(np.max(r.max_tension[r.completed])) if r.n else math.nan,
        mbl=r.mbl,
        exceed_mbl=None if r.mbl is None else _p(*r.exceedance(r.mbl)),
        design_load=r.design_load,
        exceed_design_load=None if r.design_load is None else _p(*r.exceedance(r.design_load)),
        slack=_p(*r.slack_probability),
        outside_validity=outside,
        hs_curve=hs_curve,
        design=design,
        settings=dict(
            n_components=s.n_components,
            nodes=s.nodes,
            n_gusts=s.n_gusts,
            omega_range=d.get("omega_range"),
            rtol=s.rtol,
            seed=s.seed,
            transient_s=s.transient,
            initial_yaw_deg=s.initial_yaw,
            start=d.get("start", ""),
            length=float(tow.scales.length),
        ),
        seconds=seconds,
    )


def _candidates(tow, sea) -> list[tuple[str, float, str]]:
    """The design changes tried: the towline length by a quarter and the hawser point by
    0.1 L, each in the direction that lowers the linear margin's max Re λ of the sea state's
    straight-behind equilibrium (`jaxtow.design.spectral_abscissa`, by central differences;
    inside the rules), with its text in metres."""
    model = tow.sea_model(sea)
    L = tow.scales.length
    l0, xp = float(get_parameter(model, "l0")), float(get_parameter(model, "xp"))

    def slope(name: str, x: float, h: float) -> float:  # central difference: the catenary's
        # solve has loops that reverse mode cannot cross
        up = design.spectral_abscissa(with_parameters(model, **{name: x + h}))
        down = design.spectral_abscissa(with_parameters(model, **{name: x - h}))
        return float(up - down)

    dl0, dxp = slope("l0", l0, 0.01 * l0), slope("xp", xp, 0.01)
    out = [("l0", l0 * (0.75 if dl0 > 0 else 1.33))]
    x_new = xp - 0.1 if dxp > 0 else xp + 0.1
    if 0.0 <= x_new <= 1.0:
        out.append(("xp", x_new))
    return [
        (p, v, f"{p} {'length' if p == 'l0' else 'hawser point'} {v * L:.0f} m") for p, v in out
    ]


def _run_sea(tow, sea, budget: float, settings, duration: float):
    """One sea state: the base runs, the probability at half its Hs, the design changes."""
    kw = dict(duration=duration, settings=settings)
    base = risk.irregular_sea(
        tow, sea, n_runs=int(tow.study.risk_runs), budget_s=SHARES[0] * budget, **kw
    )
    n = max(base.n, 2)
    low_sea = dataclasses.replace(sea, hs=sea.hs * HS_FRACTION)
    low = risk.irregular_sea(tow, low_sea, n_runs=n, budget_s=SHARES[1] * budget, **kw)
    curve = [
        RiskHsPoint(
            hs=float(x.described["hs"]),
            runs=x.n,
            fishtail=_p(x.fishtail_probability, x.confidence_interval),
        )
        for x in (low, base)
    ]
    design_rows = []
    cands = _candidates(tow, sea)
    present = tow.sea_model(sea)
    for name, value, text in cands:
        r = risk.irregular_sea(
            tow,
            sea,
            n_runs=n,
            parameters={name: value},
            budget_s=SHARES[2] * budget / len(cands),
            **kw,
        )
        d = risk.difference(base, r, {name: value})
        k = min(base.n, r.n)
        design_rows.append(
            RiskDesignRow(
                parameter=name,
                present=float(get_parameter(present, name)),
                value=value,
                text=text,
                runs=k,
                base=float(np.mean(base.fishtails[:k])),
                changed=float(np.mean(r.fishtails[:k])),
                difference=_p(d.difference, d.interval),
                p_value=d.p_value,
            )
        )
    return base, [low], curve, design_rows


def risk_step(tow, s: StudySummary, *, budget_s: float | None = None) -> tuple[list, dict]:
    """The Monte Carlo of every sea state `risk_seas` picks, within the budget. Returns the
    records and, for the figures, {sea state: (result, the results at lower Hs)}."""
    seas = risk_seas(tow, s)
    if not seas:
        return [], {}
    opts = tow.study
    budget = float(opts.risk_budget_s if budget_s is None else budget_s) / len(seas)
    duration = float(opts.risk_hours) * 3600.0
    records, figures = [], {}
    for sea in seas:
        t0 = time.perf_counter()
        base, lower, curve, design_rows = _run_sea(tow, sea, budget, RISK_SETTINGS, duration)
        records.append(risk_record(tow, base, curve, design_rows, time.perf_counter() - t0))
        figures[sea.name] = (base, lower)
    return records, figures


def with_risk(checks: list[CheckRow], records: list[RiskRecord]) -> list[CheckRow]:
    """The yaw rows of the sea states run, their reason completed with the Monte Carlo's
    probability (the verdict stays: the linear criterion is what the guideline asks)."""
    by_sea = {r.sea_state: r for r in records}
    out = []
    for c in checks:
        sea = c.key.split(":", 2)[2] if c.key.startswith(("yaw:sea:", "yaw:operating:")) else None
        r = by_sea.get(sea) if sea is not None else None
        if r is not None and c.verdict == "not determined":
            p = r.fishtail
            c = msgspec.structs.replace(
                c,
                reason=c.reason
                + f". The irregular-sea Monte Carlo at the design speed ({r.runs} runs of "
                f"{r.duration_h:g} h): P(fishtail) = {100 * p.value:.0f} % "
                f"({100 * p.low:.0f}-{100 * p.high:.0f} %)",
            )
        out.append(c)
    return out


def risk_advice(records: list[RiskRecord]) -> list[AdviceRow]:
    """The design changes of the Monte Carlo as advice rows: for each sea state run, the
    change that lowers the fishtail probability most (verified where its paired interval
    lies below zero)."""
    out = []
    for r in records:
        if not r.design:
            continue
        best = min(r.design, key=lambda d: d.difference.value)
        if best.difference.value >= 0:
            continue
        d = best.difference
        out.append(
            AdviceRow(
                condition=f"sea state {r.sea_state} (irregular-sea risk)",
                kind="risk",
                parameter=best.parameter,
                what="towline length" if best.parameter == "l0" else "hawser point",
                present=best.present,
                present_text=f"P(fishtail) = {100 * best.base:.0f} % over {best.runs} runs",
                searched_text="the towline length by a quarter and the hawser point by 0.1 L, "
                "each the way the linear margin improves",
                value=best.value,
                value_text=f"{best.text}: P(fishtail) = {100 * best.changed:.0f} % "
                f"(change {100 * d.value:+.0f} %, {100 * d.low:+.0f} to {100 * d.high:+.0f} %; "
                f"McNemar p = {best.p_value:.2g})",
                tow_file=_tow_file(best, r),
                verified=bool(d.high < 0 and best.p_value < 0.05),
                note="the same random numbers for both (common random numbers); confirmed only "
                "where McNemar's exact test gives p < 0.05",
            )
        )
    return out


def _tow_file(row: RiskDesignRow, r: RiskRecord) -> str:
    L = float(r.settings.get("length", 0.0)) or None
    if L is None:
        return ""
    key = "length" if row.parameter == "l0" else "xp_m"
    return f"[towline] {key} = {row.value * L:.0f}"
