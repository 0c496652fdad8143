"""Wave spectra and irregular seas (thesis sections 2.3, 3.1, 6.3; docs/model.md section 6).

SI units and rad/s inside; helpers convert periods and Hz at the boundary.
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._gusts import (
        GUST_BAND as GUST_BAND,
        NPD_EXPONENT as NPD_EXPONENT,
        NPDWind as NPDWind,
        npd_wind_spectrum as npd_wind_spectrum,
    )
    from ._irregular import (
        DEFAULT_OMEGA as DEFAULT_OMEGA,
        mean_drift as mean_drift,
        mean_drift_damping as mean_drift_damping,
        slow_drift_force_spectrum as slow_drift_force_spectrum,
        spectral_integral as spectral_integral,
        synthesise_drift_force as synthesise_drift_force,
        synthesise_elevation as synthesise_elevation,
    )
    from ._spectra import (
        AbstractSpectrum as AbstractSpectrum,
        Jonswap as Jonswap,
        PiersonMoskowitz as PiersonMoskowitz,
        SpectralPeriods as SpectralPeriods,
        check_frequency_grid as check_frequency_grid,
        hz_to_omega as hz_to_omega,
        jonswap as jonswap,
        period_to_omega as period_to_omega,
        physical_tp_range as physical_tp_range,
        pierson_moskowitz as pierson_moskowitz,
        spectral_moment as spectral_moment,
        spectral_periods as spectral_periods,
        spectrum_per_hz as spectrum_per_hz,
    )

__getattr__, __dir__, __all__ = _attach(__name__, __file__)
