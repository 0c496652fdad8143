"""Wave drift: QTF databases, wave-drift damping, sailing drift, and the short-wave / empirical
methods from the waterline. The tow-model wave forces built on them are in `jaxtow.forces`."""

from ._compare import (
    compare_methods as compare_methods,
    irregular_drift as irregular_drift,
    qtf_from_method as qtf_from_method,
    relative_mse as relative_mse,
    relative_mse_by_zone as relative_mse_by_zone,
)
from ._damping import wave_drift_damping as wave_drift_damping
from ._methods import (
    FROUDE_MAX as FROUDE_MAX,
    METHODS as METHODS,
    DriftEstimate as DriftEstimate,
    bluntness as bluntness,
    dnv1996 as dnv1996,
    dnv2014 as dnv2014,
    faltinsen as faltinsen,
    fujii_takahashi as fujii_takahashi,
    imo as imo,
    kashiwagi as kashiwagi,
    kuroda as kuroda,
    liu as liu,
    r_function_method as r_function_method,
    wavelength_ratio as wavelength_ratio,
    zone as zone,
)
from ._qtf import QTF as QTF
from ._sailing import (
    encounter_frequency as encounter_frequency,
    irregular_sailing_drift as irregular_sailing_drift,
    sailing_drift as sailing_drift,
)
from ._waterline import (
    Waterline as Waterline,
    barge2_waterline as barge2_waterline,
    box_waterline as box_waterline,
    mirror_half as mirror_half,
    read_waterline as read_waterline,
    waterline as waterline,
    write_waterline as write_waterline,
)

__all__ = [
    "compare_methods",
    "irregular_drift",
    "qtf_from_method",
    "relative_mse",
    "relative_mse_by_zone",
    "wave_drift_damping",
    "FROUDE_MAX",
    "METHODS",
    "DriftEstimate",
    "bluntness",
    "dnv1996",
    "dnv2014",
    "faltinsen",
    "fujii_takahashi",
    "imo",
    "kashiwagi",
    "kuroda",
    "liu",
    "r_function_method",
    "wavelength_ratio",
    "zone",
    "QTF",
    "encounter_frequency",
    "irregular_sailing_drift",
    "sailing_drift",
    "Waterline",
    "barge2_waterline",
    "box_waterline",
    "mirror_half",
    "read_waterline",
    "waterline",
    "write_waterline",
]
