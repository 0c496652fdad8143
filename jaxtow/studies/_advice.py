"""A way forward for what fails, each suggestion re-run and re-checked:

* **yaw** (the tow does not follow the tug): for each towline or tow parameter the smallest
  change that makes the straight-behind equilibrium stable (`jaxtow.design.stable_value`: a
  scan and Newton's method with the project's own derivatives), and **skegs**: the smallest
  span of twin stern skegs that makes the hull course stable (`jaxtow.presets.skeg_derivatives`
  on the hull's linear derivatives); each re-checked with the full equilibrium search and
  eigenvalues;
* **seabed** (the catenary touches the bottom): the longest towline that clears it at the
  calm-water tension, re-checked by the catenary and the stability at that length (a lighter
  line clears it too; a heavier one sags more);
* **pull** (the tug cannot hold the tow): the bollard pull that holds it in the weather
  criterion and every sea state, re-checked against the pull checks and the MBL it then needs.

Every value is given in the tow file's units with the line that makes it."""

from __future__ import annotations

import math

import equinox as eqx
import jax.numpy as jnp
import numpy as np

from .. import design, guidelines, presets
from .._dynamics import typed_like
from .._equilibrium import equilibria, straight_behind
from .._parameters import get_parameter, with_parameters
from .._roots import bisect, bisect_fixed
from .._stability import STABLE
from .._towline import CatenaryTowline, CompositeTowline
from .._units import KNOT, TONNE_FORCE
from ._conditions import equilibria_and_stability
from ._records import AdviceRow, StudySummary

__all__ = ["ADVICE_RANGES", "yaw_advice", "skeg_advice", "seabed_advice", "tug_advice", "advice"]

#: The range searched for each parameter, relative to its present value (l0', EA', U_tug),
#: or absolute (x_p' from the CoG to one ship length ahead of it: a bridle apex can lie
#: ahead of the bow).
ADVICE_RANGES = {
    "l0": ("relative", 0.25, 4.0),
    "xp": ("absolute", 0.0, 1.0),
    "u_tug": ("relative", 0.25, 2.0),
    "EA": ("relative", 0.1, 10.0),
}
_WORDS = {
    "l0": "towline length",
    "xp": "attachment point (bridle apex) ahead of the CoG",
    "u_tug": "tow speed",
    "EA": "towline stiffness (line size)",
}
#: The largest skeg span searched, by the draft.
SKEG_SPAN_MAX = 2.0


def _in_units(name: str, value: float, scales) -> str:
    L = scales.length
    if name == "l0":
        return f"{value * L:.1f} m (l0' = {value:.3g})"
    if name == "xp":
        return f"{value * L:.1f} m (x_p' = {value:.3g})"
    if name == "u_tug":
        return f"{value:.2f} m/s ({value / KNOT:.1f} kn)"
    return f"{value * float(scales.force):.3g} N (EA' = {value:.3g})"


def _tow_file(name: str, value: float, scales) -> str:
    L = scales.length
    return {
        "l0": f"[towline] length = {value * L:.1f}",
        "xp": f"[towline] xp = {value:.3g}",
        "u_tug": f"[tow] speed = {value:.2f}",
        "EA": f"[towline] EA_N = {value * float(scales.force):.3g}",
    }[name]


def _follows(model) -> bool:
    """The full check at a suggested value: a straight-behind equilibrium that is stable."""
    eqs, st, _, _ = equilibria_and_stability(model)
    st = st.stability
    ok = np.asarray(eqs.valid)
    return bool(np.any(straight_behind(np.asarray(eqs.psi), ok) & ok & (st == STABLE)))


def yaw_advice(model, condition: str) -> list[AdviceRow]:
    """For each parameter of `ADVICE_RANGES` the model has as one number: the value nearest
    the present one that makes the straight-behind equilibrium stable (margin
    `jaxtow.design.ADVICE_MARGIN`), with the change in the tow file's units and ``verified``
    (the full equilibrium search at it finds the tow following the tug); ``value`` None
    when no value in the range does."""
    scales = model.reference_scales
    rate = float(scales.u_tug) / scales.length
    out = []
    # a composite line's EA is per segment: no one number to change
    names = tuple(n for n in ADVICE_RANGES if np.ndim(get_parameter(model, n)) == 0)
    for name in names:
        kind, a, b = ADVICE_RANGES[name]
        p = float(get_parameter(model, name))
        lo, hi = (a * p, b * p) if kind == "relative" else (a, b)
        found = design.stable_value(model, name, lo, hi, among=names)
        row = dict(
            condition=condition,
            kind="change",
            parameter=name,
            what=_WORDS[name],
            present=p,
            present_text=_in_units(name, p, scales),
            searched_text=f"{_in_units(name, lo, scales)} to {_in_units(name, hi, scales)}",
        )
        if found is not None:
            changed = with_parameters(model, **{name: found.value})
            row.update(
                value=found.value,
                value_text=_in_units(name, found.value, scales),
                tow_file=_tow_file(name, found.value, scales),
                new_max_real=found.abscissa * rate,
                verified=_follows(changed),
            )
        out.append(AdviceRow(**row))
    return sorted(
        out,
        key=lambda r: (
            math.inf if r.value is None else abs(r.value - r.present) / max(abs(r.present), 1e-9)
        ),
    )


def _skegs_of(tow):
    """(count, chord, span) of the skegs already fitted ([vessel.skegs]), else twin skegs of
    a tenth of the length's chord and no span."""
    given = tow.resolved.get("vessel", {}).get("skegs")
    if isinstance(given, dict):
        return int(given.get("count", 2)), float(given["chord"]), float(given["span"])
    return 2, round(0.1 * tow.scales.length, 1), 0.0


def _with_skegs(vessel, L, T, count, chord, span, base_span):
    """``vessel`` with the skegs' derivatives of ``span`` in place of those of ``base_span``."""
    add = presets.skeg_derivatives(L, T, presets.Skegs(count, span, chord))
    old = (
        presets.skeg_derivatives(L, T, presets.Skegs(count, base_span, chord))
        if base_span
        else None
    )
    names = ("Yv", "Yr", "Nv", "Nr")
    present = tuple(getattr(vessel, k) for k in names)
    new = tuple(
        jnp.asarray(p + getattr(add, k) - (getattr(old, k) if old else 0.0), float)
        for p, k in zip(present, names)
    )
    # typed as the present values (weakly, as a tow file's are): the equilibria and
    # stability programs of the calm-water model then serve every span
    return eqx.tree_at(lambda x: (x.Yv, x.Yr, x.Nv, x.Nr), vessel, typed_like(present, new))


def _smallest_span(c_of, follows, lo, hi) -> float:
    """The smallest span [m, to the centimetre] whose hull is course stable (``c_of`` > 0:
    the first decimetre, then the centimetre), and, where the tow does not follow the tug at
    it, the smallest at which it does (``follows``, by halving)."""
    coarse = np.arange(max(math.floor(lo * 10.0), 1), math.ceil(hi * 10.0) + 1) / 10.0
    k = int(np.argmax([c_of(x) > 0 for x in coarse]))
    start = round(coarse[k - 1] * 100) if k > 0 else max(round(lo * 100), 1)
    fine = np.arange(start, round(coarse[k] * 100) + 1) / 100.0
    span = float(fine[int(np.argmax([c_of(x) > 0 for x in fine]))])
    if not follows(span) and follows(hi):
        steps = math.ceil(math.log2((hi - span) / 0.01))
        span = math.ceil(bisect_fixed(follows, span, hi, steps)[1] * 100.0) / 100.0
    return span


def skeg_advice(tow, model, condition: str) -> AdviceRow | None:
    """The smallest span of twin stern skegs (the chord of skegs already fitted, else a
    tenth of the length) that makes the hull course stable (stability coefficient c > 0)
    with the skegs' derivatives of `jaxtow.presets.skeg_derivatives` added to the vessel's
    linear ones, and, where the tow does not follow the tug at it, the smallest that makes
    it follow; re-checked with the full equilibrium search. None where the hull is course
    stable already."""
    v, L, T = model.vessel, tow.scales.length, tow.scales.draft
    c0 = float(v.stability_coefficient())
    if c0 > 0:
        return None
    count, chord, base_span = _skegs_of(tow)

    def vessel_with(span):
        return _with_skegs(v, L, T, count, chord, span, base_span)

    def follows(span):
        return _follows(eqx.tree_at(lambda m: m.vessel, model, vessel_with(span)))

    lo, hi = max(base_span, 0.01 * T), SKEG_SPAN_MAX * T
    row = dict(
        condition=condition,
        kind="skegs",
        parameter="skegs.span",
        what=f"{count} stern skeg(s) of chord {chord:g} m: their span below the hull",
        present=base_span,
        present_text=(f"{base_span:g} m" if base_span else "no skegs") + f" (c = {c0:+.4f})",
        searched_text=f"{lo:.2f} to {hi:.1f} m",
    )
    if float(vessel_with(hi).stability_coefficient()) <= 0:
        return AdviceRow(**row, note="no span up to twice the draft makes the hull course stable")
    span = _smallest_span(lambda x: float(vessel_with(x).stability_coefficient()), follows, lo, hi)
    new = vessel_with(span)
    preset = "preset" in tow.resolved.get("vessel", {})
    note = (
        "the preset's derivatives hold its appendages: the estimate adds the skegs to the "
        "measured values (Barge 2b is the measured barge with skegs)"
        if preset
        else "skegs as lifting surfaces (docs/estimates.md)"
    )
    return AdviceRow(
        **row,
        value=span,
        value_text=f"{span:.2f} m (c = {float(new.stability_coefficient()):+.4f})",
        tow_file=f"[vessel.skegs] count = {count}, span = {span:.2f}, chord = {chord:g}",
        verified=follows(span),
        note=note,
    )


def seabed_advice(tow, model, s: StudySummary) -> AdviceRow | None:
    """The longest towline whose calm-water catenary clears the seabed by the criterion's
    clearance (the horizontal tension held at the calm straight-behind value, R0'), re-checked
    by the catenary of the full equilibrium and the stability at that length."""
    line = model.towline
    cat = s.towline.catenary if s.towline is not None else None
    if (
        cat is None
        or tow.water_depth is None
        or not isinstance(line, (CatenaryTowline, CompositeTowline))
    ):
        return None
    need = tow.water_depth - tow.criteria.seabed_clearance
    if cat.sag_m <= need:
        return None
    L = tow.scales.length
    T = float(model.vessel.R0)

    def sag(l0):
        m = with_parameters(model, l0=l0).towline
        assert isinstance(m, (CatenaryTowline, CompositeTowline))
        return m.sag(m.length_at_tension(T)) * L

    l00 = float(line.l0)
    lo = 0.05 * l00
    row = dict(
        condition="calm water",
        kind="seabed",
        parameter="l0",
        what="towline length (clear of the seabed)",
        present=l00,
        present_text=_in_units("l0", l00, model.reference_scales),
        searched_text=f"{lo * L:.0f} to {l00 * L:.0f} m",
    )
    note = "a lighter line clears it too; a heavier one sags more"
    if float(sag(lo)) > need:
        return AdviceRow(**row, note=note)
    root, _ = bisect(lambda x, _: need - sag(x), jnp.asarray(lo), jnp.asarray(l00), atol=1e-4 * l00)
    # whole metres, rounded down: the advice clears the seabed rather than touching it
    l0 = math.floor(float(root) * L) / L
    changed = with_parameters(model, l0=l0)
    eqs = equilibria(changed)
    k = int(np.argmin(np.where(np.asarray(eqs.valid), np.abs(np.asarray(eqs.psi)), np.inf)))
    new_line = changed.towline
    assert isinstance(new_line, (CatenaryTowline, CompositeTowline))
    new_sag = float(new_line.sag(eqs.state[k, 3])) * L
    return AdviceRow(
        **row,
        value=l0,
        value_text=f"{l0 * L:.0f} m (sag {new_sag:.1f} m in {tow.water_depth:g} m of water)",
        tow_file=f"[towline] length = {l0 * L:.0f}",
        verified=bool(new_sag <= need),
        note=note
        + (
            "; at this length the tow still follows the tug in calm water"
            if _follows(changed)
            else "; at this length the tow fishtails in calm water: see the yaw advice"
        ),
    )


def tug_advice(tow, s: StudySummary) -> AdviceRow | None:
    """The rated bollard pull [t, to the tonne above] that holds the tow in the weather
    criterion and in every sea state, where the tug's does not; re-checked: every pull check
    passes with it, and the note says what MBL the guideline then asks of the towline."""
    if tow.tug is None or s.assessment is None:
        return None
    pulls = [
        c
        for c in s.assessment.checks
        if c.key == "bollard_pull_criterion" or c.key.startswith("pull:")
    ]
    failing = [c for c in pulls if c.verdict == "fail" and c.limit is not None]
    if not failing:
        return None
    need = max(c.limit for c in pulls if c.limit is not None)
    bp = float(math.ceil(need))
    present = float(tow.tug.bollard_pull) / TONNE_FORCE
    mbl_need = guidelines.mbl_factor(bp, tow.criteria) * bp
    note = f"the guideline then asks a towline MBL of {mbl_need:.0f} t"
    if tow.make is not None:
        has = tow.make.main.mbl / TONNE_FORCE
        note += f" (the {tow.make.main.name} has {has:.0f} t)"
    return AdviceRow(
        condition=", ".join(c.condition for c in failing),
        kind="tug",
        parameter="bollard_pull_t",
        what="tug bollard pull",
        present=present,
        present_text=f"{present:.1f} t",
        searched_text=f"the required pull of every pull check ({need:.1f} t)",
        value=bp,
        value_text=f"{bp:.0f} t",
        tow_file=f"[tug] bollard_pull_t = {bp:.0f}",
        verified=all(bp >= (c.limit or 0.0) for c in pulls),
        note=note,
    )


def advice(tow, s: StudySummary) -> list[AdviceRow]:
    """The way forward of a study: the yaw changes (calm water first: a tow that fishtails in
    calm water needs that change; else each sea state whose yaw criterion fails at the
    design speed) with skegs, then the seabed and the tug (module docstring)."""
    out: list[AdviceRow] = []
    a = s.assessment
    failing = (
        []
        if a is None
        else [c for c in a.checks if c.key.startswith("yaw:") and c.verdict == "fail"]
    )
    calm = next((c for c in failing if c.key == "yaw:calm"), None)
    if calm is not None:
        model = tow.model()
        out += yaw_advice(model, "calm water")
        sk = skeg_advice(tow, model, "calm water")
        if sk is not None:
            out.insert(0, sk)
    else:
        for sea in tow.sea_states:
            if any(c.key == f"yaw:sea:{sea.name}" for c in failing):
                out += yaw_advice(tow.sea_model(sea), f"sea state {sea.name}")
    if tow.has_model:
        sb = seabed_advice(tow, tow.model(), s)
        if sb is not None:
            out.append(sb)
    tg = tug_advice(tow, s)
    if tg is not None:
        out.append(tg)
    return out
