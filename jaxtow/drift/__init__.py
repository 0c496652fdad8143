"""Wave-drift forces: QTF databases, wave-drift damping, sailing drift, tow-model forces, and the
short-wave / empirical methods from the waterline."""

from .compare import (
    compare_methods as compare_methods,
    irregular_drift as irregular_drift,
    qtf_from_method as qtf_from_method,
    relative_mse as relative_mse,
    relative_mse_by_zone as relative_mse_by_zone,
)
from .damping import wave_drift_damping as wave_drift_damping
from .force import IrregularWaveDriftForce as IrregularWaveDriftForce, WaveDriftForce as WaveDriftForce
from .methods import (
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
from .qtf import QTF as QTF
from .sailing import (
    encounter_frequency as encounter_frequency,
    irregular_sailing_drift as irregular_sailing_drift,
    sailing_drift as sailing_drift,
)
from .waterline import (
    Waterline as Waterline,
    barge2_waterline as barge2_waterline,
    mirror_half as waterline_mirror_half,
    box_waterline as box_waterline,
    read_waterline as read_waterline,
    waterline as waterline,
    write_waterline as write_waterline,
)
