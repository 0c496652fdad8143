"""Advice for a failing yaw criterion: for each towline or tow parameter, the smallest change
that makes the tow follow the tug (`jaxtow.design.stable_value`: a scan and Newton's method
with the project's own derivatives), in the tow file's units, re-checked with the full
equilibrium search and eigenvalues at the suggested value."""

from __future__ import annotations

import math

import numpy as np

from .. import design
from .._equilibrium import equilibria
from .._parameters import get_parameter, with_parameters
from .._stability import STABLE, stability

__all__ = ["ADVICE_RANGES", "yaw_advice"]

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


def _in_units(name: str, value: float, scales) -> str:
    L = scales.length
    if name == "l0":
        return f"{value * L:.1f} m (l0' = {value:.3g})"
    if name == "xp":
        return f"{value * L:.1f} m (x_p' = {value:.3g})"
    if name == "u_tug":
        return f"{value:.2f} m/s ({value / 0.514444:.1f} kn)"
    return f"{value * float(scales.force):.3g} N (EA' = {value:.3g})"


def _follows(model) -> bool:
    """The full check at a suggested value: a straight-behind equilibrium that is stable."""
    eqs = equilibria(model)
    st = np.asarray(stability(model, eqs.state).stability)
    straight = np.abs(np.degrees(np.asarray(eqs.psi))) < 1.0
    return bool(np.any(straight & np.asarray(eqs.valid) & (st == STABLE)))


def yaw_advice(model, condition: str) -> list[dict]:
    """For each parameter of `ADVICE_RANGES` the model has as one number: the value nearest
    the present one that makes the straight-behind equilibrium stable (margin
    `jaxtow.design.ADVICE_MARGIN`), with the change in the tow file's units and
    ``verified`` (the full equilibrium search at it finds the tow following the tug); or
    ``value`` None when no value in the range does."""
    scales = model.reference_scales
    out = []
    for name, (kind, a, b) in ADVICE_RANGES.items():
        present = np.asarray(get_parameter(model, name))
        if present.ndim != 0:  # a composite line's EA: per segment, no one number to change
            continue
        p = float(present)
        lo, hi = (a * p, b * p) if kind == "relative" else (a, b)
        found = design.stable_value(model, name, lo, hi)
        rec = dict(
            condition=condition,
            parameter=name,
            what=_WORDS[name],
            present=p,
            present_text=_in_units(name, p, scales),
            searched=[lo, hi],
            searched_text=f"{_in_units(name, lo, scales)} to {_in_units(name, hi, scales)}",
            value=None,
        )
        if found is not None:
            changed = with_parameters(model, **{name: found["value"]})
            rec.update(
                value=found["value"],
                value_text=_in_units(name, found["value"], scales),
                change=found["value"] - p,
                new_max_real=found["abscissa"] * float(scales.u_tug) / scales.length,
                verified=_follows(changed),
            )
        out.append(rec)
    out.sort(
        key=lambda r: (
            math.inf if r["value"] is None else abs(r["change"]) / max(abs(r["present"]), 1e-9)
        )
    )
    return out
