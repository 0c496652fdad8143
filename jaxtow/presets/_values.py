"""The Barge 2 data of the thesis and every documented estimate, re-exported from
`jaxtow._values` (which sits below every layer so that the numerical packages can read it)."""

from .._values import (
    ASSUMPTIONS as ASSUMPTIONS,
    BARGE2_BREADTH as BARGE2_BREADTH,
    BARGE2_LENGTH as BARGE2_LENGTH,
    BARGE2_WIND_TABLE as BARGE2_WIND_TABLE,
    ILLUSTRATIVE_TUG as ILLUSTRATIVE_TUG,
    PLAUSIBLE_RANGES as PLAUSIBLE_RANGES,
    SEA_STATES as SEA_STATES,
    TABLE_3_7 as TABLE_3_7,
    U_TUG_DEFAULT as U_TUG_DEFAULT,
)
