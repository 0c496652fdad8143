"""The built-in Barge 1 and Barge 2 of the thesis: vessels, waterlines, towline, resistance
model, sea states and tug, built from the values of `jaxtow._values`."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .._towline import Towline
from .._units import TONNE_FORCE, Scales
from .._values import (
    ASSUMPTIONS,
    BARGE2_BREADTH,
    BARGE2_LENGTH,
    BARGE2_WIND_TABLE,
    ILLUSTRATIVE_TUG,
    SEA_STATES,
    TABLE_3_7,
    U_TUG_DEFAULT,
)
from .._vessel import Vessel
from ..drift import QTF
from ..drift._waterline import Waterline, mirror_half, waterline
from ..resistance import CoefficientTable, SeaState, TowResistance, Tug, WaveDrift, tow_resistance
from ..strip import raked_box
from ._particulars import block_coefficient_from_mass, clarke_added_mass


def barge2_scales(u_tug: float = U_TUG_DEFAULT, draft: float | None = None) -> Scales:
    """Reference scales of Barge 2 (draft defaults to the documented estimate)."""
    d = ASSUMPTIONS["draft"]["value"] if draft is None else draft
    return Scales(length=BARGE2_LENGTH, draft=d, u_tug=u_tug)


@dataclass(frozen=True)
class Rake:
    """The rake of Barge 2's ends: the horizontal ``extent`` a [m] of each end rake below
    the waterline, its ``angle`` to the horizontal and the waterline ``flare`` η (the raked
    face's angle from the vertical) [rad], at ``draft`` [m], with the hull's
    ``block_coefficient``."""

    extent: float
    angle: float
    flare: float
    draft: float
    block_coefficient: float


def barge2_rake(draft: float | None = None) -> Rake:
    """Rake geometry of Barge 2 (see the module docstring), a `Rake`."""
    T = ASSUMPTIONS["draft"]["value"] if draft is None else float(draft)
    cb = block_coefficient_from_mass(TABLE_3_7["2a"]["m"], BARGE2_LENGTH, BARGE2_BREADTH)
    a = (1.0 - cb) * BARGE2_LENGTH
    angle = math.atan2(T, a)
    return Rake(extent=a, angle=angle, flare=0.5 * math.pi - angle, draft=T, block_coefficient=cb)


def box_waterline(
    length: float = 76.2, breadth: float = 24.4, draft: float | None = None
) -> Waterline:
    """Rectangular wall-sided waterline (Barge 1: L = 76.2 m, B = 24.4 m), centred on
    midships. The draft defaults to the documented Barge 2 estimate (5.0 m,
    `jaxtow.ASSUMPTIONS`); the thesis text does not give Barge 1's."""
    T = ASSUMPTIONS["draft"]["value"] if draft is None else draft
    a, b = 0.5 * length, 0.5 * breadth
    half = [(a, 0.0), (a, b), (-a, b), (-a, 0.0)]
    pts, fl, _ = mirror_half(half)
    return waterline(pts, draft=T, flare=fl, block_coefficient=1.0, name="box")


def barge2_waterline(draft: float | None = None) -> Waterline:
    """Barge 2 (76.2 m × 24.4 m): plan-rectangular waterline whose bow and stern faces are
    raked, flare η = 47.7° (`jaxtow.barge2_rake`, a documented estimate). The local
    draft of the raked faces is the full draft T (the section behind the rake); Liu et al.'s
    effective draft there is then min(T cos η, T) = T cos η."""
    r = barge2_rake(draft)
    a, b = 0.5 * BARGE2_LENGTH, 0.5 * BARGE2_BREADTH
    half = [(a, 0.0), (a, b), (-a, b), (-a, 0.0)]
    pts, fl, _ = mirror_half(half, flare=[r.flare, 0.0, r.flare])
    return waterline(
        pts, draft=r.draft, flare=fl, block_coefficient=r.block_coefficient, name="barge2"
    )


def barge2_hull(draft: float | None = None, *, n_stations: int = 21):
    """Barge 2 for strip theory (`jaxtow.strip.raked_box`): 76.2 × 24.4 m with the raked bow
    and stern of `barge2_rake` (the same hull as the panel pipeline's `barge2_mesh`)."""
    r = barge2_rake(draft)
    return raked_box(BARGE2_LENGTH, BARGE2_BREADTH, r.draft, r.extent, n_stations=n_stations)


def _barge2(version: str, draft: float | None) -> Vessel:
    table = TABLE_3_7[version]
    d = ASSUMPTIONS["draft"]["value"] if draft is None else draft
    added = clarke_added_mass(table["m"], BARGE2_LENGTH, BARGE2_BREADTH, d)
    assumed = (
        ("draft", f"T = {d} m: {ASSUMPTIONS['draft']['note']}"),
        ("a11", ASSUMPTIONS["a11_over_m"]["note"]),
        ("a22", ASSUMPTIONS["a22,a66"]["note"]),
        ("a66", ASSUMPTIONS["a22,a66"]["note"]),
    )
    skeg = "without skegs, course unstable" if version == "2a" else "with skegs, course stable"
    return Vessel(
        **table, **added.as_parameters(), name=f"barge_{version} ({skeg})", assumed=assumed
    )


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
    return tow_resistance(
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


def sea_state(name: str, **overrides) -> SeaState:
    """Thesis sea state ``'survival'`` (1: Hs = 5 m, U_wind = 20 m/s) or ``'sailing'`` (2:
    Hs = 2.4 m, U_wind = 10 m/s), `SEA_STATES`, with any field overridden."""
    if name not in SEA_STATES:
        raise ValueError(
            f"parameter 'name': unknown sea state {name!r}; choose from {sorted(SEA_STATES)}"
        )
    return SeaState(**{**SEA_STATES[name], **overrides}, name=name)


def illustrative_tug(**overrides) -> Tug:
    """The ILLUSTRATIVE 40 t tug of the examples (`ILLUSTRATIVE_TUG`)."""
    kw = dict(ILLUSTRATIVE_TUG)
    kw["bollard_pull"] = kw.pop("bollard_pull_t") * TONNE_FORCE
    return Tug(**{**kw, **overrides})
