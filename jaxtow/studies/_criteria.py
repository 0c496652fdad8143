"""The guideline assessment of a study (`jaxtow.guidelines`): one pass/fail table whose
every number is one the report shows (the worst case over the sea state's physical Tp range,
the weakest line segment, the straight-behind equilibrium), and the findings a planner must
read (seabed contact, validity, warnings). Numbers only; the report and the console print it."""

from __future__ import annotations

import math

import numpy as np

from .. import guidelines, resistance
from ..guidelines import TONNE, Check
from ..resistance import SeaState
from ._resistance import worst_over_tp

__all__ = ["assessment"]


def _straight_max_real(record: dict) -> float:
    """max Re λ' of the straight-behind equilibrium of an equilibria record (NaN if none; its
    validity flags are reported beside it, not used to drop it)."""
    rows = [e for e in record["equilibria"] if abs(e["psi_deg"]) < 1.0]
    return min((e["max_real"] for e in rows), default=math.nan)


def weather_pull(tow, c: guidelines.Criteria, n_tp: int = 41) -> tuple[float, float]:
    """(towing force [N], worst Tp [s]) to hold the tow at zero speed in the weather
    criterion, the worst over the physical Tp range of its Hs (thesis eq. 3.5)."""
    tr = tow.resistance()
    sea = SeaState(
        name="criterion",
        hs=c.hs,
        tp=10.0,  # the worst over the physical range replaces it where Hs > 0
        wind_speed=c.wind_speed,
        current_speed=c.current_speed,
    )
    if c.hs <= 0:
        return float(resistance.required_pull(tr, sea).towing_force), math.nan
    return worst_over_tp(tr, sea, n_tp=n_tp)


def _pull_checks(tow, s: dict, c: guidelines.Criteria) -> tuple[list, list]:
    """The weather criterion and each sea state: the tug's bollard pull against the pull
    the report's resistance table requires (its worst over Tp); the operating speeds."""
    checks, speeds = [], []
    bp_t = float(tow.tug.bollard_pull) / TONNE
    force, tp = weather_pull(tow, c)
    need = force / c.tug_efficiency / TONNE
    chk = guidelines.check_bollard_pull(need, bp_t, c)
    detail = (
        f"wind {c.wind_speed:g} m/s, Hs {c.hs:g} m"
        + (f" (worst Tp {tp:.1f} s)" if math.isfinite(tp) else "")
        + f", current {c.current_speed:g} m/s; efficiency {c.tug_efficiency:g}"
    )
    checks.append(dict(chk.record(), detail=detail, key="bollard_pull_criterion"))
    for r in s.get("resistance", []):
        worst = max(r["required_bollard_pull"], r.get("worst_required_bollard_pull", 0.0))
        at = r.get("worst_tp") if worst > r["required_bollard_pull"] else r["tp"]
        chk = Check(
            f"bollard pull, sea state {r['sea_state']} (hold the tow, worst over Tp)",
            bp_t,
            worst / TONNE,
            "min",
            "t",
            "the tow's resistance budget at zero speed with the [tug] efficiency",
        )
        checks.append(
            dict(chk.record(), detail=f"worst at Tp {at:.1f} s", key=f"pull_{r['sea_state']}")
        )
        ok = r["status"] == "successful"
        speeds.append(
            dict(
                sea_state=r["sea_state"],
                status=r["status"],
                speed=r["operating_speed"] if "operating_speed" in r else None,
                transit_time_h=r.get("transit_time_h") if ok else None,
                message=r["message"],
            )
        )
    return checks, speeds


def _line_checks(tow, s: dict, c: guidelines.Criteria) -> list:
    """Towline MBL and length against the bollard pull; connecting parts against the line;
    the catenary against the water depth."""
    out = []
    line = s.get("towline", {})
    strength = line.get("strength")
    if strength and tow.tug is not None:
        bp = float(tow.tug.bollard_pull)
        segs = strength["segments"]
        main = max(segs, key=lambda x: x["length_m"])
        mbl = main["mbl_kN"] * 1e3
        out.append(dict(guidelines.check_mbl(mbl / TONNE, bp / TONNE, c).record(), key="mbl"))
        length = sum(x["length_m"] for x in segs)
        out.append(dict(guidelines.check_towline_length(length, bp, mbl, c).record(), key="length"))
        parts = [x for x in segs if x is not main]
        if parts:
            weakest = min(parts, key=lambda x: x["mbl_kN"])
            chk = guidelines.check_connections(weakest["mbl_kN"] * 1e3 / TONNE, mbl / TONNE, c)
            out.append(dict(chk.record(), detail=weakest["name"], key="connections"))
    cat = line.get("catenary")
    if cat and "water_depth" in cat:
        chk = guidelines.check_seabed_clearance(cat["sag_m"], cat["water_depth"], c)
        out.append(dict(chk.record(), key="seabed"))
    return out


def yaw_conditions(s: dict) -> list:
    """(name, equilibria record) of every condition the study judged: calm water, each sea
    state at the design speed and, where it differs, at its operating speed."""
    out = [("calm water", s["calm"])] if "calm" in s else []
    for k, v in s.get("sea_states", {}).items():
        out.append((f"sea state {k}", v))
        if "at_operating_speed" in v:
            u = v["at_operating_speed"]["speed"]
            out.append((f"sea state {k} at {u:.2f} m/s", v["at_operating_speed"]))
    return out


def _yaw_checks(s: dict) -> list:
    out = []
    for name, rec in yaw_conditions(s):
        rate = rec.get("speed", s["design_speed"]) / s["length"]  # λ = λ' U/L [1/s]
        chk = guidelines.check_yaw(_straight_max_real(rec) * rate, name)
        detail = rec["verdict_text"]
        out.append(dict(chk.record(), detail=detail, key=f"yaw_{name}"))
    return out


def _findings(tow, s: dict, checks: list) -> list:
    """What a planner must read beside the table, most serious first."""
    out = []
    for ch in checks:
        if ch["key"] == "seabed" and not ch["passed"]:
            out.append(
                f"the towline touches the seabed: catenary sag exceeds the water depth by "
                f"{-ch['value']:.1f} m"
            )
    for sp in s.get("speeds", []):
        if sp["speed"] is None:
            out.append(
                f"sea state {sp['sea_state']}: the tug cannot hold the tow ({sp['message']})"
            )
    for name, rec in yaw_conditions(s):
        if rec.get("outside_validity"):
            b = rec.get("bounds")
            held = (
                "; under the bounds that still hold (zero-speed drift, the thesis's form) the "
                + ("verdict CHANGES" if b["changes"] else "verdict is the same")
                if b
                else "; see the validity section for what still holds"
            )
            out.append(
                f"{name}: outside the model's validity ({', '.join(rec['outside_validity'])})"
                + held
            )
    for ch in checks:
        if ch["estimate"] and not ch["passed"]:
            out.append(f"'{ch['criterion']}' fails against a documented estimate: {ch['source']}")
    out += [str(w) for w in tow.warnings]
    return out


def assessment(tow, s: dict) -> dict:
    """The guideline table (``checks``: `Check` records with a ``key``), the operating
    ``speeds`` (None where the tug cannot hold the tow: never an operating speed), the
    ``findings`` and ``all_passed``, from a study summary ``s`` and the tow."""
    c = tow.criteria
    checks, speeds = ([], [])
    if tow.tug is not None and s.get("resistance") is not None:
        checks, speeds = _pull_checks(tow, s, c)
    checks += _line_checks(tow, s, c)
    checks += _yaw_checks(s)
    for ch in checks:  # JSON: no NaN (a missing equilibrium fails its criterion)
        for k in ("value", "limit", "margin"):
            if not np.isfinite(ch[k]):
                ch[k] = None
        ch["passed"] = bool(ch["passed"]) and ch["value"] is not None
    out = dict(guideline=c.name, checks=checks, speeds=speeds)
    out["findings"] = _findings(tow, dict(s, speeds=speeds), checks)
    out["all_passed"] = all(ch["passed"] for ch in checks) and all(
        sp["speed"] is not None for sp in speeds
    )
    return out
