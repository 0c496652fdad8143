"""A vessel from its particulars (L, B, T, C_B): the published linear regressions of Clarke,
Gedling & Hine (1983) and Kijima et al. (1990), the Clarke added masses, the borrowed
nonlinear terms of Barge 2a, and the radii of gyration of the documented estimate."""

from __future__ import annotations

import math

from .._vessel import Vessel
from ._values import _TABLE_3_7, ASSUMPTIONS


def block_coefficient_from_mass(m_nd: float, length: float, breadth: float) -> float:
    """C_B from m' = m / (½ρTL²) = 2 C_B B / L (independent of the draft)."""
    return m_nd * length / (2.0 * breadth)


def clarke_added_mass(
    m_nd: float, length: float, breadth: float, draft: float, a11_fraction: float | None = None
) -> dict:
    """Added masses (a11', a22', a66') in the ½ρTL² / ½ρTL⁴ scales.

    a22', a66' from Clarke, Gedling & Hine (1983) (see module docstring), a11' as a
    fraction of m' (default `ASSUMPTIONS['a11_over_m']`).
    """
    if a11_fraction is None:
        a11_fraction = float(ASSUMPTIONS["a11_over_m"]["value"])
    cb = block_coefficient_from_mass(m_nd, length, breadth)
    t_l, b_t, b_l = draft / length, breadth / draft, breadth / length
    yvdot = math.pi * t_l**2 * (1.0 + 0.16 * cb * b_t - 5.1 * b_l**2)  # by ½ρL³
    nrdot = math.pi * t_l**2 * (1.0 / 12.0 + 0.017 * cb * b_t - 0.33 * b_l)  # by ½ρL⁵
    return dict(a11=a11_fraction * m_nd, a22=yvdot / t_l, a66=nrdot / t_l)


#: Validity of the Clarke, Gedling & Hine (1983) regressions as commonly quoted: the model
#: tests covered ships and barges of L/B 3.9-9.0 (flagged, not refused, outside it).
CLARKE_LB_RANGE = (3.0, 9.0)


def clarke_linear_derivatives(
    length: float, breadth: float, draft: float, block_coefficient: float
) -> dict:
    """Linear sway and yaw derivatives from Clarke, Gedling & Hine (1983), "The application
    of manoeuvring criteria in hull design using linear theory", Trans. RINA 125, 45-68
    (regressions of rotating-arm and PMM tests), with S = π(T/L)²:

    −Y_v' = S (1 + 0.40 C_B B/T),        −Y_r' = S (−1/2 + 2.2 B/L − 0.080 B/T),
    −N_v' = S (1/2 + 2.4 T/L),           −N_r' = S (1/4 + 0.039 B/T − 0.56 B/L),

    on ½ρL²U (Y_v), ½ρL³U (Y_r, N_v), ½ρL⁴U (N_r), converted here to the Hong et al. scales
    of `jaxtow.Vessel` (½ρTLU etc.: multiply by L/T). Returns the four derivatives and
    ``lb_in_range`` (L/B inside `CLARKE_LB_RANGE`). The regressions are for ship forms: a
    barge's skegs, rake and square bilges are outside what they describe (docs/estimates.md
    compares them with Barge 2a/2b's measured values)."""
    L, B, T, cb = (float(x) for x in (length, breadth, draft, block_coefficient))
    S = math.pi * (T / L) ** 2
    to_hong = L / T
    return dict(
        Yv=-S * (1.0 + 0.40 * cb * B / T) * to_hong,
        Yr=-S * (-0.5 + 2.2 * B / L - 0.080 * B / T) * to_hong,
        Nv=-S * (0.5 + 2.4 * T / L) * to_hong,
        Nr=-S * (0.25 + 0.039 * B / T - 0.56 * B / L) * to_hong,
        lb_in_range=CLARKE_LB_RANGE[0] <= L / B <= CLARKE_LB_RANGE[1],
    )


def kijima_linear_derivatives(
    length: float, breadth: float, draft: float, block_coefficient: float, a11: float = 0.0
) -> dict:
    """Linear sway and yaw derivatives from Kijima, Katsuno, Nakiri & Furukawa (1990), "On
    the manoeuvring performance of a ship with the parameter of loading condition", J. Soc.
    Naval Arch. Japan 168, 141-148 (even keel), with k = 2T/L:

    Y_v' = −(πk/2 + 1.4 C_B B/L),   Y_r' − m_x' = πk/4,   N_v' = −k,   N_r' = −0.54 k + k²,

    on ½ρLTU (Y_v), ½ρL²TU (Y_r, N_v), ½ρL³TU (N_r): the Hong et al. scales of
    `jaxtow.Vessel`. Their MMG form carries −(m + m_x) u r on the left, as jaxtow's model
    does, so Y_r' here is πk/4 + a11' (``a11``: the surge added mass a11'). The regression
    was fitted to merchant-ship models without appendages (its database's range is not
    reproduced here): a barge, and a skeg above all, is outside it."""
    L, B, T, cb = (float(x) for x in (length, breadth, draft, block_coefficient))
    k = 2.0 * T / L
    return dict(
        Yv=-(0.5 * math.pi * k + 1.4 * cb * B / L),
        Yr=0.25 * math.pi * k + float(a11),
        Nv=-k,
        Nr=-0.54 * k + k**2,
    )


#: The linear regressions a vessel from particulars can use (the tow file's
#: ``[vessel] regression``).
REGRESSIONS = ("clarke", "kijima")

#: The terms no regression here gives, borrowed from the thesis's Barge 2a (Table 3.7): a
#: raked barge without skegs, L/B = 3.1, C_B = 0.93 (`particulars_derivatives`).
_BORROWED = ("R0", "Xvv", "Xrr", "Yvvv", "Yrrr", "Nvvv")


def particulars_derivatives(
    length: float,
    breadth: float,
    draft: float,
    block_coefficient: float,
    regression: str = "clarke",
) -> tuple[dict, dict]:
    """Every `jaxtow.Vessel` parameter of a hull known by its particulars, and a note on
    each estimate: (values, notes).

    * m' = 2 C_B B/L (the displacement ρ C_B L B T on ½ρTL²: exact for the given C_B);
    * Izz' = m' (k_zz/L)² with k_zz from `ASSUMPTIONS['radii_of_gyration']`;
    * the linear Y_v', Y_r', N_v', N_r' from ``regression`` (`clarke_linear_derivatives` or
      `kijima_linear_derivatives`);
    * a11', a22', a66' from `clarke_added_mass`;
    * R0', X_vv', X_rr', Y_vvv', Y_rrr', N_vvv' borrowed from Barge 2a (thesis Table 3.7):
      the only barge whose nonlinear terms are published here. A cross-flow drag estimate
      was considered and rejected (docs/estimates.md: for Barge 2 it makes Y_vvv' three
      to five times the measured value). Good for raked barges without skegs of similar
      proportions; anything else needs measured or CFD terms.
    """
    if regression not in REGRESSIONS:
        raise ValueError(f"regression must be one of {REGRESSIONS}, got {regression!r}")
    L, B, T, cb = (float(x) for x in (length, breadth, draft, block_coefficient))
    for name, v in (("length", L), ("breadth", B), ("draft", T)):
        if not (math.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be > 0 and finite, got {v!r}")
    if not 0.3 <= cb <= 1.0:
        raise ValueError(f"block_coefficient must lie in [0.3, 1.0], got {cb!r}")
    m = 2.0 * cb * B / L
    kzz = ASSUMPTIONS["radii_of_gyration"]["value"][2]
    vals = dict(m=m, Izz=m * kzz**2)
    notes = dict(
        m=f"m' = 2 C_B B/L with C_B = {cb:g}",
        Izz=f"Izz' = m' (k_zz/L)^2, k_zz = {kzz:g} L: {ASSUMPTIONS['radii_of_gyration']['note']}",
    )
    added = clarke_added_mass(m, L, B, T)
    vals.update(added)
    for k in ("a11", "a22", "a66"):
        notes[k] = (
            ASSUMPTIONS["a11_over_m"]["note"]
            if k == "a11"
            else f"Clarke, Gedling & Hine (1983) added-mass regression with C_B = {cb:g}, T = {T:g} m"
        )
    if regression == "clarke":
        lin = clarke_linear_derivatives(L, B, T, cb)
        where = "" if lin.pop("lb_in_range") else "; L/B OUTSIDE the regression's range"
        src = "Clarke, Gedling & Hine (1983)"
    else:
        lin = kijima_linear_derivatives(L, B, T, cb, a11=added["a11"])
        where = ""
        src = "Kijima, Katsuno, Nakiri & Furukawa (1990)"
    vals.update(lin)
    for k in lin:
        notes[k] = (
            f"{src} linear regression with C_B = {cb:g} (no appendages: skegs are not "
            f"seen){where}; estimate"
        )
    for k in _BORROWED:
        vals[k] = _TABLE_3_7["2a"][k]
        notes[k] = (
            "borrowed from Barge 2a (thesis Table 3.7: a raked barge without skegs, L/B 3.1, "
            "C_B 0.93); estimate"
        )
    return vals, notes


def vessel_from_particulars(
    length: float,
    breadth: float,
    draft: float,
    block_coefficient: float,
    regression: str = "clarke",
    name: str = "vessel from particulars",
) -> Vessel:
    """A `jaxtow.Vessel` with every parameter from `particulars_derivatives`; its
    ``assumed`` lists each estimate. Use it with `Scales(length, draft, u_tug)`."""
    vals, notes = particulars_derivatives(length, breadth, draft, block_coefficient, regression)
    return Vessel(**vals, name=name, assumed=tuple(notes.items()))


def radii_of_gyration(length: float, breadth: float) -> tuple[float, float, float]:
    """(k_xx, k_yy, k_zz) [m] from `ASSUMPTIONS['radii_of_gyration']` (Journee's approximations)."""
    fx, fy, fz = ASSUMPTIONS["radii_of_gyration"]["value"]
    return fx * breadth, fy * length, fz * length
