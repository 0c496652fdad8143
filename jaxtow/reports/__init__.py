"""Thesis claims as testable functions: each takes a study's arrays and returns one
``claims.json`` record (see ``jaxtow report waves``)."""

from ._forms import forms_table as forms_table, sailing_forms as sailing_forms
from ._waves import (
    BAND_OMEGA_MAX as BAND_OMEGA_MAX,
    LOW_OMEGA as LOW_OMEGA,
    PATH_WIDTH_FACTOR as PATH_WIDTH_FACTOR,
    SMALL_ZETA_A as SMALL_ZETA_A,
    THESIS_PATH_WIDTHS as THESIS_PATH_WIDTHS,
    barge_2b_stays_stable as barge_2b_stays_stable,
    claim as claim,
    head_wind_reduces_path_width as head_wind_reduces_path_width,
    irregular_sea_keeps_2a_stable as irregular_sea_keeps_2a_stable,
    low_frequency_waves_keep_calm_verdict as low_frequency_waves_keep_calm_verdict,
    moderate_waves_stabilise_2a as moderate_waves_stabilise_2a,
    path_widths_match_thesis as path_widths_match_thesis,
    small_waves_add_no_equilibria as small_waves_add_no_equilibria,
    time_domain_agrees_with_linear as time_domain_agrees_with_linear,
    waves_reduce_path_width as waves_reduce_path_width,
)

__all__ = [
    "forms_table",
    "sailing_forms",
    "BAND_OMEGA_MAX",
    "LOW_OMEGA",
    "PATH_WIDTH_FACTOR",
    "SMALL_ZETA_A",
    "THESIS_PATH_WIDTHS",
    "barge_2b_stays_stable",
    "claim",
    "head_wind_reduces_path_width",
    "irregular_sea_keeps_2a_stable",
    "low_frequency_waves_keep_calm_verdict",
    "moderate_waves_stabilise_2a",
    "path_widths_match_thesis",
    "small_waves_add_no_equilibria",
    "time_domain_agrees_with_linear",
    "waves_reduce_path_width",
]
