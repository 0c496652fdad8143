"""The data layer: built-in vessels, tows, drift databases and the values the thesis text does
not give.

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

Modules: `_values` (re-exports `jaxtow._values`: the thesis's Barge 2 data and every documented estimate, `ASSUMPTIONS`),
`_particulars` (a vessel from L, B, T, C_B by published regressions, and its skegs), `_barge2` (the
built-in vessels, waterlines, towline, resistance model, sea states and tug),
`_databases` (the shipped panel-method drift databases), `_sources` (the typed drift
sources and `drift_source`, the one way to name one), `_tows` (the Barge 2 tow models of the thesis's wave studies).
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._barge2 import (
        VESSELS as VESSELS,
        Rake as Rake,
        barge2_hull as barge2_hull,
        barge2_rake as barge2_rake,
        barge2_resistance as barge2_resistance,
        barge2_scales as barge2_scales,
        barge2_waterline as barge2_waterline,
        barge2_wind_table as barge2_wind_table,
        barge_2a as barge_2a,
        barge_2b as barge_2b,
        box_waterline as box_waterline,
        default_towline as default_towline,
        illustrative_tug as illustrative_tug,
        sea_state as sea_state,
        steel_wire_EA_nd as steel_wire_EA_nd,
    )
    from ._databases import (
        APPROXIMATE_QTF as APPROXIMATE_QTF,
        DATABASE_METHODS as DATABASE_METHODS,
        DATABASES as DATABASES,
        DEFAULT_METHOD as DEFAULT_METHOD,
        QTF_BETA_DEG as QTF_BETA_DEG,
        QTF_OMEGA as QTF_OMEGA,
        STANDIN as STANDIN,
        approximate_qtf as approximate_qtf,
        database as database,
        database_attrs as database_attrs,
        database_file as database_file,
        describe_database as describe_database,
    )
    from ._particulars import (
        CLARKE_LB_RANGE as CLARKE_LB_RANGE,
        REGRESSIONS as REGRESSIONS,
        AddedMasses as AddedMasses,
        LinearDerivatives as LinearDerivatives,
        SkegDerivatives as SkegDerivatives,
        Skegs as Skegs,
        block_coefficient_from_mass as block_coefficient_from_mass,
        clarke_added_mass as clarke_added_mass,
        clarke_linear_derivatives as clarke_linear_derivatives,
        helmbold_lift_slope as helmbold_lift_slope,
        kijima_linear_derivatives as kijima_linear_derivatives,
        particulars_derivatives as particulars_derivatives,
        skeg_derivatives as skeg_derivatives,
        vessel_from_particulars as vessel_from_particulars,
    )
    from ._sources import (
        FILE_OPTIONS as FILE_OPTIONS,
        AbstractDriftSource as AbstractDriftSource,
        DatabaseSource as DatabaseSource,
        FileSource as FileSource,
        GivenQTF as GivenQTF,
        StandInSource as StandInSource,
        StripSource as StripSource,
        WaterlineSource as WaterlineSource,
        describe_file as describe_file,
        drift_source as drift_source,
    )
    from ._tows import (
        barge2_irregular_model as barge2_irregular_model,
        barge2_wave_model as barge2_wave_model,
    )
    from ._values import (
        ASSUMPTIONS as ASSUMPTIONS,
        BARGE2_BREADTH as BARGE2_BREADTH,
        BARGE2_LENGTH as BARGE2_LENGTH,
        BARGE2_WIND_TABLE as BARGE2_WIND_TABLE,
        ILLUSTRATIVE_TUG as ILLUSTRATIVE_TUG,
        PLAUSIBLE_RANGES as PLAUSIBLE_RANGES,
        SEA_STATES as SEA_STATES,
        U_TUG_DEFAULT as U_TUG_DEFAULT,
    )


__getattr__, __dir__, __all__ = _attach(__name__, __file__)
