"""Thesis claims as testable functions: each takes a study's arrays and returns one
``claims.json`` record (see ``jaxtow report waves``)."""

from ._forms import forms_table as forms_table, sailing_forms as sailing_forms
from ._maps import (
    MAP_NAMES as MAP_NAMES,
    map_axes as map_axes,
    run_map as run_map,
    straight as straight,
    verdict_change as verdict_change,
    verdict_maps as verdict_maps,
)
from ._study import (
    CLAIM_IDS as CLAIM_IDS,
    MODEL_ESTIMATES as MODEL_ESTIMATES,
    PANEL_ESTIMATES as PANEL_ESTIMATES,
    RESISTANCE_CLAIM_IDS as RESISTANCE_CLAIM_IDS,
    SHARE_TOLERANCE as SHARE_TOLERANCE,
    THESIS_SAILING_SHARES as THESIS_SAILING_SHARES,
    THESIS_STATIONARY_WAVE_SHARE as THESIS_STATIONARY_WAVE_SHARE,
    WaveStudy as WaveStudy,
    attribute as attribute,
    slow_drift_runs as slow_drift_runs,
)
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
    "CLAIM_IDS",
    "MODEL_ESTIMATES",
    "PANEL_ESTIMATES",
    "RESISTANCE_CLAIM_IDS",
    "SHARE_TOLERANCE",
    "THESIS_SAILING_SHARES",
    "THESIS_STATIONARY_WAVE_SHARE",
    "WaveStudy",
    "attribute",
    "slow_drift_runs",
    "MAP_NAMES",
    "map_axes",
    "run_map",
    "straight",
    "verdict_change",
    "verdict_maps",
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

from ._resistance import evaluate as evaluate_resistance  # noqa: E402
from ._tow import (  # noqa: E402
    VERDICTS as VERDICTS,
    TowStudy as TowStudy,
    tow_study as tow_study,
    verdict as verdict,
)

__all__ += ["evaluate_resistance", "VERDICTS", "TowStudy", "tow_study", "verdict"]

from ._html import SECTIONS as REPORT_SECTIONS, tow_report_html as tow_report_html  # noqa: E402

__all__ += ["REPORT_SECTIONS", "tow_report_html"]
