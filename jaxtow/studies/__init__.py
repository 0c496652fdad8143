"""What runs: the thesis's wave study and its claims (`WaveStudy`, thesis chapters 6.2-6.3
and 7), the stability maps and the forward-speed forms it compares, and the assessment of one
tow (`tow_study`, the command ``jaxtow study``). Each returns numbers and result records;
`jaxtow.reports` and `jaxtow.plotting` render them, the command line writes them.

Modules: `_claims` (each thesis claim as a function of a study's arrays), `_maps` (the
stability maps of the wave study and their reductions), `_forms` (the forward-speed forms of
the drift compared), `_waves` (`WaveStudy`, the attribution of claims), `_resistance` (one sea
state's resistance summary), `_assessment` (the assessment of one tow), `_drift` (the
waterline drift methods compared, ``jaxtow drift``), `_bifurcation` (branches and limit
cycles in one parameter, ``jaxtow bifurcation``).
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._advice import (
        ADVICE_RANGES as ADVICE_RANGES,
        advice as advice,
        seabed_advice as seabed_advice,
        skeg_advice as skeg_advice,
        tug_advice as tug_advice,
        yaw_advice as yaw_advice,
    )
    from ._assessment import (
        OperatingCurve as OperatingCurve,
        TowStudy as TowStudy,
        map_grids as map_grids,
        tow_study as tow_study,
    )
    from ._bifurcation import (
        BifurcationStudy as BifurcationStudy,
        bifurcation_study as bifurcation_study,
    )
    from ._calm import (
        CalmRecord as CalmRecord,
        CalmStudy as CalmStudy,
        TimeDomainRun as TimeDomainRun,
        calm_study as calm_study,
        time_domain_run as time_domain_run,
    )
    from ._claims import (
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
    from ._conditions import (
        BOUND_FORMS as BOUND_FORMS,
        SPEED_FLAGS as SPEED_FLAGS,
        VALIDITY_WORDS as VALIDITY_WORDS,
        YAW_VERDICTS as YAW_VERDICTS,
        condition as condition,
        yaw_verdict as yaw_verdict,
    )
    from ._criteria import (
        UNDETERMINING_FLAGS as UNDETERMINING_FLAGS,
        assessment as assessment,
        weather_pull as weather_pull,
    )
    from ._drift import (
        SWAY_METHODS as SWAY_METHODS,
        DriftMethodsStudy as DriftMethodsStudy,
        drift_methods_study as drift_methods_study,
    )
    from ._forms import (
        forms_table as forms_table,
        sailing_forms as sailing_forms,
    )
    from ._maps import (
        MAP_NAMES as MAP_NAMES,
        map_axes as map_axes,
        nearest_straight as nearest_straight,
        outside_validity as outside_validity,
        run_map as run_map,
        straight as straight,
        valid_count as valid_count,
        validity_share as validity_share,
        verdict_change as verdict_change,
        verdict_maps as verdict_maps,
    )
    from ._records import (
        CHECK_VERDICTS as CHECK_VERDICTS,
        VERDICTS as VERDICTS,
        AdviceRow as AdviceRow,
        Assessment as Assessment,
        Bounds as Bounds,
        CheckRow as CheckRow,
        Condition as Condition,
        EquilibriumRow as EquilibriumRow,
        OperatingRow as OperatingRow,
        Probability as Probability,
        ResistanceRow as ResistanceRow,
        RiskDesignRow as RiskDesignRow,
        RiskHsPoint as RiskHsPoint,
        RiskRecord as RiskRecord,
        StudySummary as StudySummary,
        to_json as to_json,
    )
    from ._report import (
        WaveReport as WaveReport,
        source_key as source_key,
        wave_report as wave_report,
    )
    from ._resistance import (
        BUDGET_TP as BUDGET_TP,
        ResistanceStudy as ResistanceStudy,
        evaluate_resistance as evaluate_resistance,
        resistance_study as resistance_study,
        resistance_table as resistance_table,
    )
    from ._risk import (
        RISK_SETTINGS as RISK_SETTINGS,
        risk_advice as risk_advice,
        risk_seas as risk_seas,
        risk_step as risk_step,
    )
    from ._waves import (
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


__getattr__, __dir__, __all__ = _attach(__name__, __file__)
