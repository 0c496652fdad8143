"""Fishtailing risk and towline loads in an irregular sea, from batched time-domain runs.

`irregular_sea` runs a Monte Carlo of a tow in a sea state (slowly varying wave drift, wind
gusts and current on the elastic towline; `_montecarlo`) and returns a `RiskResult`: the
probability of fishtailing with its 95 % interval, the runs' largest yaw and tension, the
most probable maximum tension and the probabilities of exceeding the MBL. `compare` runs
two variants of a tow on the same random numbers, so that their difference is not noise
(`_compare`). `linear_response` is the frequency-domain response of the linearised tow to
the same slow drift, against which the runs are checked (`_linear`). The statistics (Wilson
intervals, exposure, Gumbel fits) are in `_stats`.
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._compare import (
        RiskDifference as RiskDifference,
        compare as compare,
        difference as difference,
    )
    from ._linear import LinearResponse as LinearResponse, linear_response as linear_response
    from ._montecarlo import (
        RiskResult as RiskResult,
        RiskSettings as RiskSettings,
        TowLike as TowLike,
        irregular_sea as irregular_sea,
        risk_model as risk_model,
    )
    from ._stats import (
        Z95 as Z95,
        GumbelFit as GumbelFit,
        exposure_probability as exposure_probability,
        gumbel_fit as gumbel_fit,
        wilson_interval as wilson_interval,
    )

__getattr__, __dir__, __all__ = _attach(__name__, __file__)
