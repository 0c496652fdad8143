"""Built-in vessels and the values the thesis text does not give.

Barge 2 of the thesis (Hong et al. / Nam et al. raked barge, L = 76.2 m, B = 24.4 m) in two
versions (thesis Table 3.7): **2a** without skegs (course unstable) and **2b** with skegs
(course stable). The manoeuvring derivatives, mass and yaw inertia are the published values.

The thesis text lacks the draft, the added masses and the towline stiffness. They are set
here, in this one place, as documented estimates (`ASSUMPTIONS`); every model built from
these presets carries the list in ``Vessel.assumed`` and every dataset in its attributes.

* Draft T = 5.0 m: a loaded 250 ft × 80 ft (76.2 m × 24.4 m) deck barge, the class of the
  Maritime Swift barge that Barge 2 is based on (thesis section 3.5), has a moulded depth of
  about 6 m and a loaded draft of 4-5 m; 5.0 m is also the box draft used for Barge 1
  panel computations (docs/bem.md). In the non-dimensional equations T only enters through
  EA' (and later the wave-drift normalisation). Consistency check: m' = 2 C_B B/L gives
  C_B = 0.928 from m' = 0.5943 independently of T, a plausible block coefficient for a
  raked barge.
* Added masses a22', a66' from the empirical regressions of Clarke, Gedling & Hine (1983),
  "The application of manoeuvring criteria in hull design using linear theory", Trans.
  RINA 125: −Y_v̇ / (½ρL³) = π(T/L)² [1 + 0.16 C_B B/T − 5.1 (B/L)²] and
  −N_ṙ / (½ρL⁵) = π(T/L)² [1/12 + 0.017 C_B B/T − 0.33 B/L], converted to the ½ρTL² and
  ½ρTL⁴ scales used here (multiply by L/T).
* a11' = 0.05 m': the usual first estimate of surge added mass for full hull forms
  (about 5 % of displacement mass; e.g. Brix, *Manoeuvring Technical Manual*, 1993).
* Towline EA = 2.6e8 N: a 76 mm six-strand steel wire rope with IWRC (metallic area about
  0.58·πd²/4 = 2.63e-3 m², rope modulus about 1.0e11 Pa), a usual main towline for a tow
  of this size. EA' = EA / (½ρTLU_tug²), i.e. about 333 at U_tug = 2 m/s. The elastic
  catenary of a long wire makes the effective stiffness lower; users model that by lowering
  EA'.
* Bow and stern rake of Barge 2 (for the waterline methods and hull meshes): the text
  describes a raked barge without dimensions. jaxtow takes a plan-rectangular waterline
  76.2 m × 24.4 m with a straight rake at each end that runs from the waterline down to the
  keel over a horizontal distance a. Its volume loss is a·B·T, so C_B = 1 − a/L; matching
  C_B = 0.928 from the published m' gives a = 5.49 m, a rake at 42.3° to the horizontal,
  i.e. a waterline flare η = 47.7° at the bow and stern faces (`barge2_rake`).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from ._towline import Towline
from ._units import RHO_SEA, Scales
from ._vessel import Vessel

if TYPE_CHECKING:  # the resistance and drift modules import these presets lazily
    from .drift import QTF
    from .resistance import CoefficientTable, SeaState, TowResistance, Tug

__all__ = [
    "BARGE2_LENGTH",
    "BARGE2_BREADTH",
    "U_TUG_DEFAULT",
    "ASSUMPTIONS",
    "PLAUSIBLE_RANGES",
    "BARGE2_WIND_TABLE",
    "SEA_STATES",
    "ILLUSTRATIVE_TUG",
    "barge2_scales",
    "block_coefficient_from_mass",
    "clarke_added_mass",
    "clarke_linear_derivatives",
    "kijima_linear_derivatives",
    "particulars_derivatives",
    "vessel_from_particulars",
    "REGRESSIONS",
    "CLARKE_LB_RANGE",
    "radii_of_gyration",
    "barge2_rake",
    "barge_2a",
    "barge_2b",
    "VESSELS",
    "steel_wire_EA_nd",
    "default_towline",
    "barge2_wind_table",
    "barge2_resistance",
    "resistance_model",
    "sea_state",
    "illustrative_tug",
]

#: Main particulars of Barge 2 (thesis section 3.5; L and B from the text).
BARGE2_LENGTH = 76.2  # m
BARGE2_BREADTH = 24.4  # m
#: Tug speed used throughout thesis chapter 6.
U_TUG_DEFAULT = 2.0  # m/s

#: The documented estimates for values the thesis text lacks (see module docstring).
ASSUMPTIONS = {
    "draft": dict(
        value=5.0,
        units="m",
        note="loaded draft of a 76.2 m x 24.4 m deck barge; estimate, not from the thesis",
    ),
    "a11_over_m": dict(
        value=0.05, units="-", note="surge added mass 5 % of mass (Brix 1993); estimate"
    ),
    "a22,a66": dict(
        value=None,
        units="-",
        note="Clarke, Gedling & Hine (1983) regressions with C_B from m' and T = 5.0 m; estimate",
    ),
    "EA": dict(
        value=2.6e8,
        units="N",
        note="76 mm 6-strand IWRC steel wire, EA = 1.0e11 Pa x 2.63e-3 m^2; estimate",
    ),
    "rake": dict(
        value=None,
        units="m",
        note="Barge 2 bow/stern rake from waterline to keel over a = (1 - C_B) L = 5.49 m "
        "(C_B = 0.928 from m'); geometry estimate, not from the thesis",
    ),
    "wind_table": dict(
        value=None,
        units="-",
        note="ILLUSTRATIVE Barge 2 wind coefficients (BARGE2_WIND_TABLE): OCIMF-form curve "
        "shapes with values chosen by jaxtow; not measured, not the thesis's "
        "(unpublished) Smit Barge 2 table",
    ),
    "cog_z": dict(
        value=10.0,
        units="m",
        note="height of the CoG above the keel for the panel computations (thesis Table B.3, "
        "Barge 1; the thesis's choice after its CoG study, appendix B.3)",
    ),
    "radii_of_gyration": dict(
        value=(0.35, 0.25, 0.25),
        units="B, L, L",
        note="k_xx = 0.35 B, k_yy = k_zz = 0.25 L: the middle of Journee's ranges "
        "(0.30-0.40 B, 0.22-0.28 L; Journee & Massie, Offshore Hydromechanics, "
        "2001), which thesis Table B.1 quotes (the table itself is lost); estimate",
    ),
    "roll_damping": dict(
        value=0.05,
        units="of critical",
        note="linearised viscous roll damping for the panel-method RAOs (potential flow "
        "alone gives an unbounded roll resonance); 5 % of critical, a usual value "
        "for a barge without bilge keels; estimate",
    ),
    "wind_height": dict(
        value=10.0,
        units="m",
        note="ILLUSTRATIVE above-water height of Barge 2 with deck cargo (about 1.1 m "
        "freeboard + 9 m cargo); the thesis's 'arbitrary deck load' is not given",
    ),
}

#: Plausible ranges of the documented estimates, for the attribution of claims
#: (`jaxtow.reports.attribute`): absolute ends for draft, CoG height, radii of gyration and
#: roll damping; factors on the estimate for a11', a22', a66' and EA'.
PLAUSIBLE_RANGES = {
    "draft": dict(
        low=4.0,
        high=5.5,
        units="m",
        note="loaded draft of a 250 ft deck barge: 4-5 m, 5.5 m deep-loaded",
    ),
    "a11": dict(
        low=0.4,
        high=2.0,
        units="x estimate",
        note="surge added mass 2-10 % of the mass (Brix 1993)",
    ),
    "a22": dict(
        low=0.7,
        high=1.3,
        units="x estimate",
        note="scatter of the Clarke, Gedling & Hine (1983) regression, about +-30 % for a barge",
    ),
    "a66": dict(
        low=0.7,
        high=1.3,
        units="x estimate",
        note="scatter of the Clarke, Gedling & Hine (1983) regression, about +-30 % for a barge",
    ),
    "EA": dict(
        low=0.5,
        high=1.5,
        units="x estimate",
        note="rope modulus 0.8-1.2e11 Pa and 64-88 mm wires; the catenary of a long line "
        "softens it further (low end)",
    ),
    "cog_z": dict(
        low=8.0,
        high=13.1,
        units="m",
        note="above the keel: a light deck cargo (8 m) to the highest CoG the IMO 2008 IS Code "
        "allows at the 5 m draft (GM_T >= 0.15 m; KM = 13.26 m). The 13.8 m the thesis's "
        "chapter 7 quotes gives GM_T = -0.54 m here: it capsizes",
    ),
    "radii_of_gyration": dict(
        low=(0.30, 0.22, 0.22),
        high=(0.40, 0.28, 0.28),
        units="B, L, L",
        note="the ends of Journee's ranges",
    ),
    "roll_damping": dict(
        low=0.02,
        high=0.10,
        units="of critical",
        note="bare barge (2 %) to bilge keels or skegs (10 %)",
    ),
}

#: ILLUSTRATIVE wind-load coefficients of Barge 2 with box-shaped deck cargo (OCIMF form,
#: eqs 2.25-2.27, on B·H, L·H, L²·H), against the relative wind angle it comes from (deg,
#: 0 = head wind, counter-clockwise; port-starboard symmetric). The curve shapes follow the
#: published OCIMF / Blendermann (1994) pattern for box-like superstructures (C_x ≈ −0.8 head
#: wind, +0.7 stern wind; C_y ≈ −0.9 beam wind; a small C_n turning the bow away from the
#: wind). The numbers are jaxtow's choice, NOT measured and NOT the thesis's table (its
#: Smit Barge 2 coefficients are unpublished). Replace them with model-test data.
BARGE2_WIND_TABLE = dict(
    angle_deg=[0, 15, 30, 45, 60, 75, 90, 105, 120, 135, 150, 165, 180],
    cx=[-0.80, -0.78, -0.70, -0.57, -0.40, -0.20, 0.00, 0.18, 0.35, 0.50, 0.61, 0.68, 0.70],
    cy=[0.0, -0.25, -0.48, -0.68, -0.82, -0.90, -0.92, -0.90, -0.82, -0.68, -0.48, -0.25, 0.0],
    cn=[0.0, -0.04, -0.07, -0.08, -0.07, -0.04, 0.0, 0.04, 0.07, 0.08, 0.07, 0.04, 0.0],
)

#: Thesis sea states (section 3.1, Table A.1): 1 = survival/stationary, 2 = sailing. Table
#: A.1's period T is taken as the JONSWAP peak period; the current is zero (a current is a
#: change of the relative speed).
SEA_STATES = {
    "survival": dict(hs=5.0, tp=10.5, wind_speed=20.0, current_speed=0.0),
    "sailing": dict(hs=2.4, tp=8.2, wind_speed=10.0, current_speed=0.0),
}

#: ILLUSTRATIVE ocean tug for the Barge 2 examples (quadratic pull curve): 40 t bollard
#: pull, pull vanishing at 7 m/s (13.6 kn), offshore towing efficiency 0.75 (the usual
#: industry factor). Not from the thesis (its tug is not specified).
ILLUSTRATIVE_TUG = dict(
    bollard_pull=40.0 * 9.80665e3, free_speed=7.0, efficiency=0.75, resistance_coefficient=0.0
)

# Published values, thesis Table 3.7 (Hong et al. [37], Nam et al. [51]).
_TABLE_3_7 = {
    "2a": dict(
        m=0.5943,
        Izz=0.0494,
        R0=0.0697,
        Xvv=-0.1999,
        Xrr=0.1288,
        Yv=-0.4003,
        Yr=0.0161,
        Yvvv=-1.2109,
        Yrrr=0.9199,
        Nv=-0.1692,
        Nr=-0.0639,
        Nvvv=0.1184,
    ),
    "2b": dict(
        m=0.5943,
        Izz=0.0494,
        R0=0.0747,
        Xvv=-0.3889,
        Xrr=-0.0924,
        Yv=-0.5998,
        Yr=0.0875,
        Yvvv=-0.3269,
        Yrrr=0.0,
        Nv=-0.0624,
        Nr=-0.1004,
        Nvvv=-0.4149,
    ),
}


def barge2_scales(u_tug: float = U_TUG_DEFAULT, draft: float | None = None) -> Scales:
    """Reference scales of Barge 2 (draft defaults to the documented estimate)."""
    d = ASSUMPTIONS["draft"]["value"] if draft is None else draft
    return Scales(length=BARGE2_LENGTH, draft=d, u_tug=u_tug)


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


def barge2_rake(draft: float | None = None) -> dict:
    """Rake geometry of Barge 2 (see the module docstring): horizontal extent ``a`` [m] of
    each end rake below the waterline, its angle to the horizontal and the waterline flare
    η (angle of the raked face from the vertical) [rad]."""
    T = ASSUMPTIONS["draft"]["value"] if draft is None else float(draft)
    cb = block_coefficient_from_mass(_TABLE_3_7["2a"]["m"], BARGE2_LENGTH, BARGE2_BREADTH)
    a = (1.0 - cb) * BARGE2_LENGTH
    angle = math.atan2(T, a)
    return dict(extent=a, angle=angle, flare=0.5 * math.pi - angle, draft=T, block_coefficient=cb)


def _barge2(version: str, draft: float | None) -> Vessel:
    table = _TABLE_3_7[version]
    d = ASSUMPTIONS["draft"]["value"] if draft is None else draft
    added = clarke_added_mass(table["m"], BARGE2_LENGTH, BARGE2_BREADTH, d)
    assumed = (
        ("draft", f"T = {d} m: {ASSUMPTIONS['draft']['note']}"),
        ("a11", ASSUMPTIONS["a11_over_m"]["note"]),
        ("a22", ASSUMPTIONS["a22,a66"]["note"]),
        ("a66", ASSUMPTIONS["a22,a66"]["note"]),
    )
    skeg = "without skegs, course unstable" if version == "2a" else "with skegs, course stable"
    return Vessel(**table, **added, name=f"barge_{version} ({skeg})", assumed=assumed)


def barge_2a(draft: float | None = None) -> Vessel:
    """Barge 2a, without skegs (course unstable, c = −0.0723), thesis Table 3.7."""
    return _barge2("2a", draft)


def barge_2b(draft: float | None = None) -> Vessel:
    """Barge 2b, with skegs (course stable, c = 0.0286), thesis Table 3.7."""
    return _barge2("2b", draft)


VESSELS = {"barge_2a": barge_2a, "barge_2b": barge_2b}


def steel_wire_EA_nd(
    u_tug: float = U_TUG_DEFAULT, draft: float | None = None, EA: float | None = None
) -> float:
    """EA' = EA / (½ρTLU²) of the documented steel wire towline on Barge 2."""
    EA = ASSUMPTIONS["EA"]["value"] if EA is None else EA
    return float(EA / barge2_scales(u_tug, draft).force)


def default_towline(
    l0: float = 2.5, xp: float = 0.5, u_tug: float = U_TUG_DEFAULT, draft: float | None = None
) -> Towline:
    """Elastic steel towline for Barge 2 with the documented EA (estimate)."""
    return Towline(l0=l0, xp=xp, EA=steel_wire_EA_nd(u_tug, draft))


# --------------------------------------------------------------- Barge 2 resistance, sea states, tug


def barge2_wind_table() -> CoefficientTable:
    """The ILLUSTRATIVE Barge 2 wind table (`BARGE2_WIND_TABLE`)."""
    from .resistance import CoefficientTable

    t = BARGE2_WIND_TABLE
    return CoefficientTable.symmetric(
        t["angle_deg"],
        t["cx"],
        t["cy"],
        t["cn"],
        label="ILLUSTRATIVE Barge 2 wind table (jaxtow.BARGE2_WIND_TABLE)",
        illustrative=True,
    )


def barge2_resistance(
    version: str = "2a",
    *,
    method: str = "kashiwagi",
    wind_table: CoefficientTable | None = None,
    wind_height: float | None = None,
    qtf: QTF | None = None,
    draft: float | None = None,
    omega=None,
    form: str = "aranha",
    drift_source: str | None = None,
) -> TowResistance:
    """Barge 2 (thesis section 7.1-7.2): current/calm-water load from the manoeuvring
    derivatives of version ``2a`` or ``2b`` (fig. 7.1b), wind from ``wind_table`` (default
    the ILLUSTRATIVE table) on H = ``wind_height`` (default the ILLUSTRATIVE 10 m), mean
    wave drift from the Barge 2 waterline by ``method`` or from a panel ``qtf`` (with the
    forward-speed ``form`` of `jaxtow.drift.sailing_drift`; ``drift_source`` names it). The
    returned ``assumed`` lists every estimate the numbers depend on, and the drift source."""
    from .drift import barge2_waterline
    from .resistance import WaveDrift

    if version not in ("2a", "2b"):
        raise ValueError(f"parameter 'version' must be '2a' or '2b', got {version!r}")
    vessel = VESSELS[f"barge_{version}"](draft)
    T = ASSUMPTIONS["draft"]["value"] if draft is None else float(draft)
    H = ASSUMPTIONS["wind_height"]["value"] if wind_height is None else float(wind_height)
    table = barge2_wind_table() if wind_table is None else wind_table
    waves = (
        WaveDrift(qtf=qtf, omega=omega, form=form)
        if qtf is not None
        else WaveDrift(barge2_waterline(draft), method=method, omega=omega)
    )
    assumed = [("draft", f"T = {T} m: {ASSUMPTIONS['draft']['note']}")]
    if table.illustrative:
        assumed.append(("wind_table", ASSUMPTIONS["wind_table"]["note"]))
    if wind_height is None:
        assumed.append(("wind_height", ASSUMPTIONS["wind_height"]["note"]))
    if qtf is None:
        assumed.append(
            (
                "wave_drift",
                f"waterline method {method!r} on the estimated Barge 2 rake "
                f"({ASSUMPTIONS['rake']['note']}); misses the motion-induced "
                "drift in the motion zone (L/lambda < 1)",
            )
        )
    else:
        assumed.append(("wave_drift", f"{drift_source or 'user QTF'} ({form} sailing form)"))
    return resistance_model(
        vessel,
        BARGE2_LENGTH,
        BARGE2_BREADTH,
        T,
        waves,
        wind_table=table,
        wind_height=H,
        name=f"barge_{version}",
        assumed=tuple(assumed),
    )


def resistance_model(
    vessel: Vessel,
    length: float,
    breadth: float,
    draft: float,
    waves,
    *,
    wind_table: CoefficientTable,
    wind_height: float,
    name: str = "tow",
    assumed: tuple = (),
) -> TowResistance:
    """The `jaxtow.resistance.TowResistance` of any vessel: the current/calm-water load from
    its manoeuvring derivatives (fig. 7.1b) on L, B, T [m], the OCIMF wind load of
    ``wind_table`` on the windage height [m], and ``waves`` (a `WaveDrift`)."""
    from .resistance import RHO_AIR, ManoeuvringCoefficients, OCIMFLoad, TowResistance

    L, B = float(length), float(breadth)
    hull = OCIMFLoad(ManoeuvringCoefficients(vessel, L, B), RHO_SEA, L, B, float(draft))
    wind = OCIMFLoad(wind_table, RHO_AIR, L, B, float(wind_height))
    return TowResistance(hull=hull, wind=wind, waves=waves, name=name, assumed=tuple(assumed))


def sea_state(name: str, **overrides) -> SeaState:
    """Thesis sea state ``'survival'`` (1: Hs = 5 m, U_wind = 20 m/s) or ``'sailing'`` (2:
    Hs = 2.4 m, U_wind = 10 m/s), `SEA_STATES`, with any field overridden."""
    from .resistance import SeaState

    if name not in SEA_STATES:
        raise ValueError(
            f"parameter 'name': unknown sea state {name!r}; choose from {sorted(SEA_STATES)}"
        )
    return SeaState(**{**SEA_STATES[name], **overrides}, name=name)


def illustrative_tug(**overrides) -> Tug:
    """The ILLUSTRATIVE 40 t tug of the examples (`ILLUSTRATIVE_TUG`)."""
    from .resistance import Tug

    return Tug(**{**ILLUSTRATIVE_TUG, **overrides})
