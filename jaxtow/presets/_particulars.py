"""A vessel from its particulars (L, B, T, C_B): the published linear regressions of Clarke,
Gedling & Hine (1983) and Kijima et al. (1990), the Clarke added masses, the borrowed
nonlinear terms of Barge 2a, the radii of gyration of the documented estimate, and skegs as
low-aspect-ratio lifting surfaces (`skeg_derivatives`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .._values import ASSUMPTIONS, TABLE_3_7
from .._vessel import Vessel


def block_coefficient_from_mass(m_nd: float, length: float, breadth: float) -> float:
    """C_B from m' = m / (½ρTL²) = 2 C_B B / L (independent of the draft)."""
    return m_nd * length / (2.0 * breadth)


@dataclass(frozen=True)
class AddedMasses:
    """Added masses a11', a22' (by ½ρTL²) and a66' (by ½ρTL⁴) of `jaxtow.Vessel`."""

    a11: float
    a22: float
    a66: float

    def as_parameters(self) -> dict:
        """{name: value}, to build a `jaxtow.Vessel` with."""
        return dict(a11=self.a11, a22=self.a22, a66=self.a66)


@dataclass(frozen=True)
class LinearDerivatives:
    """The linear sway and yaw derivatives Y_v', Y_r', N_v', N_r' of a regression, in the
    Hong et al. scales of `jaxtow.Vessel`; ``lb_in_range``: L/B inside the regression's
    range (None where the regression states none)."""

    Yv: float
    Yr: float
    Nv: float
    Nr: float
    lb_in_range: bool | None = None

    def as_parameters(self) -> dict:
        """{name: value} of the four derivatives."""
        return dict(Yv=self.Yv, Yr=self.Yr, Nv=self.Nv, Nr=self.Nr)


def clarke_added_mass(
    m_nd: float, length: float, breadth: float, draft: float, a11_fraction: float | None = None
) -> AddedMasses:
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
    return AddedMasses(a11=a11_fraction * m_nd, a22=yvdot / t_l, a66=nrdot / t_l)


#: Validity of the Clarke, Gedling & Hine (1983) regressions as commonly quoted: the model
#: tests covered ships and barges of L/B 3.9-9.0 (flagged, not refused, outside it).
CLARKE_LB_RANGE = (3.0, 9.0)


def clarke_linear_derivatives(
    length: float, breadth: float, draft: float, block_coefficient: float
) -> LinearDerivatives:
    """Linear sway and yaw derivatives from Clarke, Gedling & Hine (1983), "The application
    of manoeuvring criteria in hull design using linear theory", Trans. RINA 125, 45-68
    (regressions of rotating-arm and PMM tests), with S = π(T/L)²:

    −Y_v' = S (1 + 0.40 C_B B/T),        −Y_r' = S (−1/2 + 2.2 B/L − 0.080 B/T),
    −N_v' = S (1/2 + 2.4 T/L),           −N_r' = S (1/4 + 0.039 B/T − 0.56 B/L),

    on ½ρL²U (Y_v), ½ρL³U (Y_r, N_v), ½ρL⁴U (N_r), converted here to the Hong et al. scales
    of `jaxtow.Vessel` (½ρTLU etc.: multiply by L/T). Returns the four derivatives with
    ``lb_in_range`` (L/B inside `CLARKE_LB_RANGE`). The regressions are for ship forms: a
    barge's skegs, rake and square bilges are outside what they describe (docs/estimates.md
    compares them with Barge 2a/2b's measured values)."""
    L, B, T, cb = (float(x) for x in (length, breadth, draft, block_coefficient))
    S = math.pi * (T / L) ** 2
    to_hong = L / T
    return LinearDerivatives(
        Yv=-S * (1.0 + 0.40 * cb * B / T) * to_hong,
        Yr=-S * (-0.5 + 2.2 * B / L - 0.080 * B / T) * to_hong,
        Nv=-S * (0.5 + 2.4 * T / L) * to_hong,
        Nr=-S * (0.25 + 0.039 * B / T - 0.56 * B / L) * to_hong,
        lb_in_range=CLARKE_LB_RANGE[0] <= L / B <= CLARKE_LB_RANGE[1],
    )


def kijima_linear_derivatives(
    length: float, breadth: float, draft: float, block_coefficient: float, a11: float = 0.0
) -> LinearDerivatives:
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
    return LinearDerivatives(
        Yv=-(0.5 * math.pi * k + 1.4 * cb * B / L),
        Yr=0.25 * math.pi * k + float(a11),
        Nv=-k,
        Nr=-0.54 * k + k**2,
    )


def helmbold_lift_slope(aspect_ratio: float) -> float:
    """dC_L/dα [1/rad] of a thin unswept wing of (effective) aspect ratio Λ, Helmbold's
    equation (1942), 2πΛ / (2 + √(Λ² + 4)): it tends to Jones's slender-wing value πΛ/2 as
    Λ → 0 (a barge skeg's range) and to the 2-D 2π as Λ → ∞."""
    a = float(aspect_ratio)
    if not (math.isfinite(a) and a > 0):
        raise ValueError(f"aspect_ratio must be > 0 and finite, got {aspect_ratio!r}")
    return 2.0 * math.pi * a / (2.0 + math.sqrt(a * a + 4.0))


@dataclass(frozen=True)
class Skegs:
    """Identical skegs under the stern, each a thin plate in the hull's centre-plane
    direction (the tow file's ``[vessel.skegs]``), in metres:

    * ``count``: how many (1 centre skeg, 2 twin skegs, ...);
    * ``span``: the greatest depth of one skeg, from the hull bottom it hangs from down to its
      lower edge;
    * ``chord``: its length along the hull;
    * ``area``: its lateral area (None: span × chord, a rectangle; a skeg filling a
      raked stern is a triangle, ½ span × chord);
    * ``x``: where its force acts, from midships, + forward (None: the middle of a skeg
      whose aft end is at the stern, −L/2 + chord/2).

    Twin skegs are counted each on its own: the formulation neglects their interference
    (in Inoue, Kijima & Doi's tests the lateral force grew as twin skegs were set further
    apart)."""

    count: int = 2
    span: float = 0.0
    chord: float = 0.0
    area: float | None = None
    x: float | None = None

    def __post_init__(self):
        if isinstance(self.count, bool) or int(self.count) != self.count or self.count < 1:
            raise ValueError(f"skegs count must be a whole number >= 1, got {self.count!r}")
        for name in ("span", "chord") + (("area",) if self.area is not None else ()):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise ValueError(f"skegs {name} must be > 0 and finite [m], got {v!r}")
        if self.x is not None and not math.isfinite(self.x):
            raise ValueError(f"skegs x must be finite [m], got {self.x!r}")

    @property
    def lateral_area(self) -> float:
        """The lateral area of one skeg [m²]."""
        return float(self.area) if self.area is not None else self.span * self.chord

    @property
    def aspect_ratio(self) -> float:
        """The effective aspect ratio 2 span²/area: the hull bottom the skeg hangs from acts as
        a reflection plane, doubling the geometric span²/area (Journée & Massie, Offshore
        Hydromechanics, on rudders under a hull)."""
        return 2.0 * self.span**2 / self.lateral_area


@dataclass(frozen=True)
class SkegDerivatives:
    """What skegs add to Y_v', Y_r', N_v', N_r' (`skeg_derivatives`), with the ``lift_slope``
    [1/rad] at the effective ``aspect_ratio`` and the centre of pressure ``x`` [m]."""

    Yv: float
    Yr: float
    Nv: float
    Nr: float
    lift_slope: float
    aspect_ratio: float
    x: float


def skeg_derivatives(length: float, draft: float, skegs: Skegs) -> SkegDerivatives:
    """The skegs' contribution to Y_v', Y_r', N_v', N_r' in the Hong et al. scales of
    `jaxtow.Vessel` (½ρLTU, ½ρL²TU, ½ρL³TU), from quasi-steady lifting-surface theory:

    each skeg sees the local drift angle of its centre of pressure, −(v + r x)/U, and gives
    the side force ½ρ A U² C_Lα (its lift, `helmbold_lift_slope` of the effective aspect
    ratio `Skegs.aspect_ratio`), so with k = n A C_Lα / (L T) and ξ = x/L:

    ΔY_v' = −k,  ΔY_r' = ΔN_v' = −k ξ,  ΔN_r' = −k ξ².

    A stern skeg (ξ < 0) adds sway damping, a stabilising N_v' and yaw damping, as model
    tests of barges with skegs show. The formulation leaves out the skeg's interaction with
    the hull (the cross-flow a skeg stops at the stern bilge, the hull's wake and the
    straightening of the flow): docs/estimates.md compares it with Barge 2a/2b."""
    L, T = float(length), float(draft)
    x = float(skegs.x) if skegs.x is not None else -0.5 * L + 0.5 * skegs.chord
    if not -0.5 * L <= x <= 0.5 * L:
        raise ValueError(f"skegs x must lie along the hull, within ±L/2 = ±{L / 2:g} m; got {x:g}")
    lam = skegs.aspect_ratio
    cla = helmbold_lift_slope(lam)
    k = skegs.count * skegs.lateral_area * cla / (L * T)
    xi = x / L
    return SkegDerivatives(
        Yv=-k, Yr=-k * xi, Nv=-k * xi, Nr=-k * xi * xi, lift_slope=cla, aspect_ratio=lam, x=x
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
    skegs: Skegs | None = None,
) -> tuple[dict, dict]:
    """Every `jaxtow.Vessel` parameter of a hull known by its particulars, and a note on
    each estimate: (values, notes).

    * m' = 2 C_B B/L (the displacement ρ C_B L B T on ½ρTL²: exact for the given C_B);
    * Izz' = m' (k_zz/L)² with k_zz from `ASSUMPTIONS['radii_of_gyration']`;
    * the linear Y_v', Y_r', N_v', N_r' from ``regression`` (`clarke_linear_derivatives` or
      `kijima_linear_derivatives`);
    * with ``skegs``, their `skeg_derivatives` added to the four linear derivatives;
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
    vals.update(added.as_parameters())
    for k in ("a11", "a22", "a66"):
        notes[k] = (
            ASSUMPTIONS["a11_over_m"]["note"]
            if k == "a11"
            else f"Clarke, Gedling & Hine (1983) added-mass regression with C_B = {cb:g}, T = {T:g} m"
        )
    if regression == "clarke":
        reg = clarke_linear_derivatives(L, B, T, cb)
        where = "" if reg.lb_in_range else "; L/B OUTSIDE the regression's range"
        src = "Clarke, Gedling & Hine (1983)"
    else:
        reg = kijima_linear_derivatives(L, B, T, cb, a11=added.a11)
        where = ""
        src = "Kijima, Katsuno, Nakiri & Furukawa (1990)"
    lin = reg.as_parameters()
    vals.update(lin)
    for k in lin:
        notes[k] = (
            f"{src} linear regression with C_B = {cb:g} (no appendages: skegs are not "
            f"seen){where}; estimate"
        )
    if skegs is not None:
        add = skeg_derivatives(L, T, skegs)
        for k in lin:
            vals[k] += getattr(add, k)
            notes[k] = (
                f"{src} linear regression with C_B = {cb:g}{where}, plus {skegs.count} "
                f"skeg(s) as lifting surfaces ({k}' {getattr(add, k):+.4f}: Helmbold lift "
                f"slope {add.lift_slope:.3f}/rad at effective aspect ratio "
                f"{add.aspect_ratio:.2f}, acting at x = {add.x:g} m); estimate"
            )
    for k in _BORROWED:
        vals[k] = TABLE_3_7["2a"][k]
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
    skegs: Skegs | None = None,
) -> Vessel:
    """A `jaxtow.Vessel` with every parameter from `particulars_derivatives`; its
    ``assumed`` lists each estimate. Use it with `Scales(length, draft, u_tug)`."""
    vals, notes = particulars_derivatives(
        length, breadth, draft, block_coefficient, regression, skegs=skegs
    )
    return Vessel(**vals, name=name, assumed=tuple(notes.items()))
