"""The [vessel] section of a tow file: a built-in manoeuvring model, or one from derivatives
and particulars (with skegs), every estimate listed."""

from __future__ import annotations

import math

from .. import presets
from .._vessel import Vessel
from ._schema import SUBTABLES, Problems, read_subtable

__all__ = ["read_vessel", "DERIVATIVES", "ADDED_MASSES"]

#: The non-dimensional derivatives a vessel needs (Hong et al. convention, thesis Table 3.7).
DERIVATIVES = ("m", "Izz", "R0", "Xvv", "Xrr", "Yv", "Yr", "Yvvv", "Yrrr", "Nv", "Nr", "Nvvv")
#: The added masses a vessel may give (estimated when left out).
ADDED_MASSES = ("a11", "a22", "a66")


def read_vessel(p: Problems, v: dict, name: str, assumed: list) -> Vessel | None:
    """The [vessel] section: a built-in vessel, or one from derivatives and particulars (None:
    a hull without a manoeuvring model, for its drift and resistance only). Fills the
    section's defaults in place and appends every estimate to ``assumed``."""
    if "preset" in v:
        return _preset_vessel(p, v, assumed)
    for k in ("length", "breadth", "draft"):
        if k not in v:
            p.error(
                ("vessel", k),
                "missing key: a vessel without a preset needs length, breadth and draft",
            )
    regression = v.get("regression")
    if regression is not None and "block_coefficient" not in v:
        p.error(("vessel", "block_coefficient"), "missing key: a regression needs C_B")
    d = v.get("derivatives", {} if regression is not None else None)
    skegs = _skegs(p, v, d)
    if d is None:
        return None
    _check_derivatives(p, d)
    notes: list = []
    if "block_coefficient" in v:
        d, notes = _fill_from_particulars(v, d, regression, skegs)
    missing = [k for k in DERIVATIVES if k not in d]
    if missing:
        p.error(("vessel", "derivatives"), f"missing derivative(s) {', '.join(missing)}")
    vals = {k: float(d[k]) for k in d}
    notes += _fill_added_masses(vals, v)
    try:
        vessel = Vessel(**vals, name=name, assumed=tuple(notes))
    except ValueError as e:
        key = getattr(e, "parameter", None)
        p.error(("vessel", "derivatives") + ((key,) if key in vals else ()), str(e))
    assumed += notes
    return vessel


def _preset_vessel(p: Problems, v: dict, assumed: list) -> Vessel:
    if "derivatives" in v:
        p.error(("vessel", "derivatives"), "give either preset or derivatives, not both")
    if "skegs" in v:
        p.error(
            ("vessel", "skegs"),
            "a preset's derivatives are measured with its appendages (barge_2b has skegs); "
            "skegs add to a regression's estimates only",
        )
    for k, val in (("length", presets.BARGE2_LENGTH), ("breadth", presets.BARGE2_BREADTH)):
        if k in v and v[k] != val:
            p.error(
                ("vessel", k), f"the preset's {k} is {val} m; for another hull give derivatives"
            )
    v.setdefault("length", presets.BARGE2_LENGTH)
    v.setdefault("breadth", presets.BARGE2_BREADTH)
    if "draft" not in v:
        v["draft"] = float(presets.ASSUMPTIONS["draft"]["value"])
    vessel = presets.VESSELS[v["preset"]](v["draft"])
    assumed += list(vessel.assumed)
    return vessel


def _check_derivatives(p: Problems, d) -> None:
    if not isinstance(d, dict):
        p.error(("vessel", "derivatives"), "expected a table of derivatives")
    for k, val in d.items():
        if k not in DERIVATIVES + ADDED_MASSES:
            p.error(
                ("vessel", "derivatives", k),
                f"unknown derivative (known: {', '.join(DERIVATIVES + ADDED_MASSES)})",
            )
        if isinstance(val, bool) or not isinstance(val, (int, float)) or not math.isfinite(val):
            p.error(("vessel", "derivatives", k), f"expected a finite number, got {val!r}")


def _skegs(p: Problems, v: dict, d: dict | None):
    """[vessel.skegs]: a `presets.Skegs` added to the regression's linear derivatives (None:
    no skegs). Refused where no regression estimates them, or where a linear derivative is
    given (a measured value already holds the hull's appendages)."""
    if "skegs" not in v:
        return None
    path = ("vessel", "skegs")
    out = read_subtable(p, path, v["skegs"], "vessel.skegs")
    for k in ("span", "chord"):
        if k not in out:
            p.error(path + (k,), "missing key: skegs need their span and chord")
    if "block_coefficient" not in v:
        p.error(
            path,
            "skegs add to the linear derivatives a regression estimates: give "
            "[vessel] block_coefficient (and regression), not measured Yv, Yr, Nv, Nr",
        )
    if d is None:
        p.error(
            path,
            "skegs change the manoeuvring derivatives, and this vessel has none: name a "
            "[vessel] regression or give [vessel.derivatives]",
        )
    given = [k for k in ("Yv", "Yr", "Nv", "Nr") if k in d]
    if given:
        p.error(
            ("vessel", "derivatives", given[0]),
            "a given linear derivative already holds the hull's appendages; with "
            "[vessel.skegs] leave Yv, Yr, Nv, Nr to the regression",
        )
    out.setdefault("count", SUBTABLES["vessel.skegs"]["count"].default)
    v["skegs"] = out
    try:
        skegs = presets.Skegs(**out)
        presets.skeg_derivatives(v["length"], v["draft"], skegs)
    except ValueError as e:
        key = getattr(e, "parameter", None)
        p.error(path + ((key,) if key in out else ()), str(e))
    return skegs


def _fill_from_particulars(v: dict, d: dict, regression, skegs=None) -> tuple[dict, list]:
    """The derivatives not given, estimated from the particulars: every one with a
    regression named; with none named only the linear ones (Clarke), the rest must be given."""
    est, est_notes = presets.particulars_derivatives(
        v["length"],
        v["breadth"],
        v["draft"],
        v["block_coefficient"],
        regression or "clarke",
        skegs=skegs,
    )
    fill = [k for k in DERIVATIVES + ADDED_MASSES if k not in d]
    if regression is None:
        fill = [k for k in fill if k in ("Yv", "Yr", "Nv", "Nr")]
    elif "a11" in d and "Yr" in fill and regression == "kijima":
        est["Yr"] += float(d["a11"]) - est["a11"]  # Y_r' − m_x' = πk/4
    return {**d, **{k: est[k] for k in fill}}, [(k, est_notes[k]) for k in fill]


def _fill_added_masses(vals: dict, v: dict) -> list:
    """Added masses a full table of derivatives leaves out, from the Clarke regressions."""
    if all(k in vals for k in ADDED_MASSES):
        return []
    added = presets.clarke_added_mass(vals["m"], v["length"], v["breadth"], v["draft"])
    notes = []
    for k in ADDED_MASSES:
        if k not in vals:
            vals[k] = getattr(added, k)
            note = (
                presets.ASSUMPTIONS["a11_over_m"]["note"]
                if k == "a11"
                else presets.ASSUMPTIONS["a22,a66"]["note"].replace(
                    "C_B from m' and T = 5.0 m", f"C_B from m' and T = {v['draft']} m"
                )
            )
            notes.append((k, note))
    return notes
