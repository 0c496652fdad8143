"""Wave drift: QTF tables, wave-drift damping, sailing drift, and the short-wave / empirical
methods from the waterline (the shipped panel-method databases are in `jaxtow.presets`). The tow-model wave forces built on them are in `jaxtow.forces`."""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._compare import (
        compare_methods as compare_methods,
        irregular_drift as irregular_drift,
        qtf_from_method as qtf_from_method,
        relative_mse as relative_mse,
        relative_mse_by_zone as relative_mse_by_zone,
    )
    from ._damping import (
        TAU_MAX as TAU_MAX,
        aranha as aranha,
        encounter_frequency as encounter_frequency,
        sailing_validity as sailing_validity,
        wave_drift_damping as wave_drift_damping,
        yaw_rate_damping as yaw_rate_damping,
    )
    from ._methods import (
        FROUDE_MAX as FROUDE_MAX,
        WATERLINE_METHODS as WATERLINE_METHODS,
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
    from ._qtf import (
        QTF as QTF,
        SYMMETRY_TOL as SYMMETRY_TOL,
        FullQTF as FullQTF,
        symmetry_residual as symmetry_residual,
    )
    from ._sailing import (
        FORMS as FORMS,
        irregular_sailing_drift as irregular_sailing_drift,
        sailing_drift as sailing_drift,
    )
    from ._waterline import (
        Waterline as Waterline,
        mirror_half as mirror_half,
        waterline as waterline,
    )

__getattr__, __dir__, __all__ = _attach(__name__, __file__)
