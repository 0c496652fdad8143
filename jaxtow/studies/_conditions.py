"""The equilibria and stability of a tow in one condition (calm water, a sea state at the
design speed or at its operating speed) as a typed `Condition`: every equilibrium, its
validity in plain words, the verdict, and the verdict again under the bounds that still hold
where the forward-speed drift theory is outside its validity."""

from __future__ import annotations

import equinox as eqx
import jax
import msgspec
import numpy as np

from .._dynamics import all_valid, at_tug_speed, validity
from .._equilibrium import padded_equilibria, straight_behind
from .._program_cache import persistent
from .._stability import MARGINAL, STABILITY_LABELS, STABLE, stability
from ._records import Bounds, Condition, EquilibriumRow

__all__ = [
    "YAW_VERDICTS",
    "VALIDITY_WORDS",
    "SPEED_FLAGS",
    "BOUND_FORMS",
    "yaw_verdict",
    "condition",
    "with_bounds",
    "sea_conditions",
]

#: Plain-words verdicts of a set of equilibria (`yaw_verdict`).
YAW_VERDICTS = {
    "follows": "follows the tug: the straight-behind equilibrium is stable",
    "sheers": "sheers to one side: only off-axis equilibria are stable",
    "fishtails": "fishtails: no equilibrium is stable (a limit cycle or divergence)",
    "marginal": "marginal: the best equilibrium is at the stability boundary (|max Re λ| "
    "within the stability tolerance)",
    "invalid": "no equilibrium found (the towline is slack at every heading)",
}
#: The validity flags in plain words (the report never shows a flag's name).
VALIDITY_WORDS = {
    "line_taut": "the towline goes slack",
    "moving_ahead": "the barge turns stern first (outside the manoeuvring model, whose "
    "derivatives are for ahead motion)",
    "froude_ok": "the tow is too fast for the drift theory (Froude number 0.15 or more; it "
    "is for slow ships)",
    "no_separation": "the tow is faster than the waves' orbital velocity (U >= omega_p Hs/2), "
    "where the forward-speed drift theory's unseparated flow does not hold",
    "tau_ok": "tau = omega U / g exceeds 1/4: Aranha's forward-speed correction is a "
    "small-tau theory",
    "encounter_positive": "the tow overtakes some of the waves (encounter frequency <= 0)",
    "heading_in_table": "the wave heading lies outside the drift table",
    "yaw_rate_damping": "the drift table has no sectional moments, so the yaw-rate drift "
    "damping is left out",
}
#: The validity flags of the forward-speed drift theory: outside them, the verdict is also
#: given under the bounds that still hold (`BOUND_FORMS`).
SPEED_FLAGS = ("no_separation", "froude_ok", "tau_ok", "encounter_positive")
#: The drift forms the verdict is repeated with where the forward-speed theory is outside its
#: validity: the zero-speed drift (no speed correction) and the thesis's form (which counts
#: the encounter-frequency shift twice: the largest speed effect of the three).
BOUND_FORMS = {"stationary": "zero-speed drift", "thesis": "the thesis's form"}


def yaw_verdict(psi, max_real, found, stab_codes) -> str:
    """The key of `YAW_VERDICTS` for equilibria at headings ``psi`` [rad] with ``max_real``,
    found by the solver where ``found``, and `jaxtow.classify` codes ``stab_codes`` (−1
    stable, 0 marginal, 1 unstable)."""
    psi, ok, codes = np.asarray(psi), np.asarray(found, bool), np.asarray(stab_codes)
    stable = ok & (codes == STABLE)
    if not ok.any():
        return "invalid"
    if (stable & straight_behind(psi, ok)).any():
        return "follows"
    if stable.any():
        return "sheers"
    if (ok & (codes == MARGINAL)).any():
        return "marginal"
    return "fishtails"


@persistent
@eqx.filter_jit
def stability_and_validity(model, states):
    """Stability and the validity flags of ``states`` as one compiled program: run eagerly,
    their hundreds of operations are dispatched one by one on every run, cached or not. The
    model's parameters were checked by `equilibria` before, so the program holds no run-time
    check (a host callback, which would keep it out of the persistent compilation cache)."""
    st = stability(model, states, throw=False)
    flags = jax.vmap(lambda y: validity(model, y, throw=False))(states)
    return st, flags, jax.vmap(all_valid)(flags)


def equilibria_and_stability(model):
    """(equilibria, their stability, validity flags, all valid) of ``model``, the found
    roots only (NumPy arrays). The stability program runs on every slot of the fixed-size
    set (`jaxtow.padded_equilibria`): one shape, one program, whatever the number of roots.
    The model's parameters are checked first (a clear error names a bad one)."""
    fixed = padded_equilibria(model)
    st, flags, ok = jax.device_get(stability_and_validity(model, fixed.state))
    keep = np.asarray(fixed.found)
    return (
        fixed.select(keep),
        jax.tree.map(lambda a: np.asarray(a)[keep], st),
        {k: np.asarray(v)[keep] for k, v in flags.items()},
        np.asarray(ok)[keep],
    )


def condition(model, name: str, kind: str, sea=None) -> Condition:
    """The `Condition` of ``model``: every equilibrium, its stability and validity, and the
    verdict."""
    eqs, st, flags, ok = equilibria_and_stability(model)
    sc = model.reference_scales
    force, rate = float(sc.force), float(sc.u_tug) / sc.length
    found = np.asarray(eqs.valid)
    straight = straight_behind(np.asarray(eqs.psi), found)
    rows: list[EquilibriumRow] = []
    outside_all: set[str] = set()
    flags = {k: np.asarray(v) for k, v in flags.items() if np.asarray(v).dtype == bool}
    for i in range(len(eqs)):
        outside = sorted(k for k, v in flags.items() if not v[i])
        outside_all |= set(outside)
        rows.append(
            EquilibriumRow(
                psi_deg=float(np.degrees(eqs.psi[i])),
                gamma_deg=float(np.degrees(eqs.gamma[i])),
                tension=float(eqs.tension[i]) * force,
                tension_nd=float(eqs.tension[i]),
                max_real=float(st.max_real[i]) * rate,
                max_real_nd=float(st.max_real[i]),
                stability=STABILITY_LABELS[int(st.stability[i])],
                found=bool(found[i]),
                valid=bool(found[i]) and bool(ok[i]),
                outside=outside,
                straight=bool(straight[i]),
            )
        )
    key = yaw_verdict(eqs.psi, st.max_real, found, np.asarray(st.stability))
    outside: list[str] = sorted(outside_all)
    text = YAW_VERDICTS[key]
    words = [VALIDITY_WORDS.get(k, k) for k in outside]
    if outside and key != "invalid":
        text += "; outside the model's validity: " + "; ".join(words)
    return Condition(
        name=name,
        kind=kind,
        sea_state=None if sea is None else sea.name,
        speed=float(sc.u_tug),
        force_scale=force,
        time_scale=sc.length / float(sc.u_tug),
        hs=0.0 if sea is None else float(sea.hs),
        tp=0.0 if sea is None else float(sea.tp),
        wind_speed=0.0 if sea is None else float(sea.wind_speed),
        current_speed=0.0 if sea is None else float(sea.current_speed),
        equilibria=rows,
        verdict=key,
        verdict_text=text,
        outside_validity=outside,
        outside_text=words,
    )


def with_bounds(tow, sea, rec: Condition, speed: float | None = None) -> Condition:
    """``rec`` with its ``bounds`` where a forward-speed validity flag fails: the verdict
    under the zero-speed drift and the thesis's form, and whether either differs."""
    if not set(rec.outside_validity) & set(SPEED_FLAGS):
        return rec
    verdicts = {}
    for form in BOUND_FORMS:
        if form == tow.form:
            continue
        model = tow.sea_model(sea, form=form)
        if speed is not None:
            model = at_tug_speed(model, speed)
        verdicts[form] = condition(model, rec.name, rec.kind, sea).verdict
    bounds = Bounds(verdicts=verdicts, changes=any(v != rec.verdict for v in verdicts.values()))
    words = ", ".join(f"{BOUND_FORMS[f]}: {v}" for f, v in verdicts.items())
    text = (
        rec.verdict_text
        + f". Under the bounds that still hold ({words}) the verdict "
        + ("changes: it rests on the forward-speed theory" if bounds.changes else "is the same")
    )
    return msgspec.structs.replace(rec, bounds=bounds, verdict_text=text)


def sea_conditions(tow, sea, operating_speed: float | None) -> list[Condition]:
    """Sea state ``sea`` at the design speed and, where it differs, at its operating speed
    (a tow that follows the tug at one speed may not at the other)."""
    notes = []
    angles = (float(sea.wave_angle), float(sea.wind_angle), float(sea.current_angle))
    if any(a != 0.0 for a in angles):
        notes.append(
            "waves, wind and current from their own directions (the straight-behind "
            "equilibrium may lie a little off ψ = 0)"
        )
    out = []
    rec = condition(tow.sea_model(sea), f"sea state {sea.name}", "sea state", sea)
    out.append(msgspec.structs.replace(with_bounds(tow, sea, rec), notes=notes))
    design = float(tow.scales.u_tug)
    if operating_speed is not None and abs(operating_speed - design) > 1e-3:
        model = at_tug_speed(tow.sea_model(sea), operating_speed)
        name = f"sea state {sea.name} at {operating_speed:.2f} m/s"
        rec = condition(model, name, "operating speed", sea)
        rec = with_bounds(tow, sea, rec, operating_speed)
        out.append(msgspec.structs.replace(rec, notes=notes))
    return out
