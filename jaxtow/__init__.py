"""jaxtow: a JAX differentiable hydrodynamics and towing-stability engine.

The public API is this package and its public subpackages; every implementation module is
private (a leading underscore) and re-exported here or by its subpackage:

* ``jaxtow`` — the tow model (`TowModel`, `Vessel`, towlines), its vector field, equilibria,
  stability, sweeps, time-domain runs and metrics, parameter paths, scales;
* ``jaxtow.forces`` — environmental forces (the hook, waves, wind, combinations);
* ``jaxtow.drift`` — wave-drift QTFs, wave-drift damping, sailing drift, waterline methods;
* ``jaxtow.waves`` — spectra and irregular-sea integrals;
* ``jaxtow.resistance`` — tow resistance, tug, operating speed;
* ``jaxtow.continuation`` — branches, bifurcations, limit cycles;
* ``jaxtow.design`` — towline and bridle design, sensitivities;
* ``jaxtow.risk`` — the fishtailing risk and towline loads in an irregular sea (batched
  time-domain Monte Carlo);
* ``jaxtow.lines`` — the towline catalogue (wire, chain, fibre rope) and composite lines;
* ``jaxtow.presets`` — the built-in vessels, tows, drift databases and every documented
  estimate;
* ``jaxtow.studies`` — what runs: the thesis's wave study and its claims, the assessment of
  one tow (``jaxtow study``);
* ``jaxtow.reports`` — the HTML report and the claims' text;
* ``jaxtow.io``, ``jaxtow.plotting``, ``jaxtow.bem`` — files, figures and the optional
  panel-method pre-processor (loaded on first use);
* ``jaxtow.cli`` — the command line, the application on top of the library (import it as a
  module; it is the one part of jaxtow that may use this facade).

Importing jaxtow enables float64 in JAX (see `jaxtow._config`; set ``JAXTOW_ENABLE_X64=0``
before import to opt out).
"""

from typing import TYPE_CHECKING

from ._config import __version__ as __version__, enable_x64_from_environment as _enable_x64
from ._lazy import attach as _attach

_enable_x64()

# The public names, loaded on first use (`jaxtow._lazy`): `import jaxtow` loads none of JAX,
# xarray, matplotlib or Capytaine until a name that needs them is used.
if TYPE_CHECKING:
    from . import (
        bem as bem,
        continuation as continuation,
        design as design,
        distributed as distributed,
        drift as drift,
        forces as forces,
        guidelines as guidelines,
        io as io,
        lines as lines,
        plotting as plotting,
        presets as presets,
        reports as reports,
        resistance as resistance,
        risk as risk,
        studies as studies,
        tow as tow,
        waves as waves,
    )
    from ._body import (
        Loading as Loading,
        hydrostatic_restoring as hydrostatic_restoring,
        mass_matrix as mass_matrix,
        radii_of_gyration as radii_of_gyration,
        roll_damping_coefficient as roll_damping_coefficient,
    )
    from ._compile_cache import enable_compile_cache as enable_compile_cache
    from ._dynamics import (
        STATE_NAMES as STATE_NAMES,
        ForceBreakdown as ForceBreakdown,
        TowModel as TowModel,
        all_valid as all_valid,
        at_tug_speed as at_tug_speed,
        force_breakdown as force_breakdown,
        sway_offset as sway_offset,
        validity as validity,
        vector_field as vector_field,
    )
    from ._equilibrium import (
        STRAIGHT_LIMIT as STRAIGHT_LIMIT,
        Equilibria as Equilibria,
        analytic_equilibria as analytic_equilibria,
        equilibria as equilibria,
        equilibria_fixed as equilibria_fixed,
        heading_residual as heading_residual,
        padded_equilibria as padded_equilibria,
        straight_behind as straight_behind,
    )
    from ._interrupt import sticky_interrupts as sticky_interrupts
    from ._metrics import (
        DampingRatio as DampingRatio,
        FishtailMetrics as FishtailMetrics,
        ForceHistory as ForceHistory,
        Trajectory as Trajectory,
        damping_ratio as damping_ratio,
        fishtail_metrics as fishtail_metrics,
        force_history as force_history,
        trajectory as trajectory,
    )
    from ._parameters import get_parameter as get_parameter, with_parameters as with_parameters
    from ._progress import (
        AbstractProgressMeter as AbstractProgressMeter,
        NoProgressMeter as NoProgressMeter,
        TqdmProgressMeter as TqdmProgressMeter,
    )
    from ._results import sensitivities as sensitivities, sweep as sweep
    from ._rules import (
        FINITE as FINITE,
        NONNEGATIVE as NONNEGATIVE,
        POSITIVE as POSITIVE,
        ParameterError as ParameterError,
        ParameterStatus as ParameterStatus,
        Rule as Rule,
        at_least as at_least,
        in_range as in_range,
        parameter_status as parameter_status,
        rule_field as rule_field,
    )
    from ._simulate import (
        Simulation as Simulation,
        initial_state as initial_state,
        simulate as simulate,
        simulate_batch as simulate_batch,
    )
    from ._stability import (
        STABILITY_LABELS as STABILITY_LABELS,
        STABILITY_TOL as STABILITY_TOL,
        StabilityResult as StabilityResult,
        characteristic_polynomial as characteristic_polynomial,
        classify as classify,
        default_eig_method as default_eig_method,
        eigenvalues as eigenvalues,
        hurwitz_determinants as hurwitz_determinants,
        jacobian as jacobian,
        max_real_eigenvalue as max_real_eigenvalue,
        routh_hurwitz_stable as routh_hurwitz_stable,
        spectral_abscissa as spectral_abscissa,
        stability as stability,
    )
    from ._sweep import (
        SweepExecution as SweepExecution,
        SweepSolver as SweepSolver,
        sweep_arrays as sweep_arrays,
        sweep_options as sweep_options,
    )
    from ._towline import (
        AbstractTowline as AbstractTowline,
        Bridle as Bridle,
        CatenaryTowline as CatenaryTowline,
        CompositeTowline as CompositeTowline,
        PowerLawTowline as PowerLawTowline,
        Towline as Towline,
        catenary_span as catenary_span,
        composite_geometry as composite_geometry,
    )
    from ._units import (
        KNOT as KNOT,
        NAUTICAL_MILE as NAUTICAL_MILE,
        RHO_SEA as RHO_SEA,
        SEA_WATER as SEA_WATER,
        TONNE_FORCE as TONNE_FORCE,
        G as G,
        Scales as Scales,
        Water as Water,
        froude_number as froude_number,
    )
    from ._vessel import VESSEL_PARAMETERS as VESSEL_PARAMETERS, Vessel as Vessel


__getattr__, __dir__, __all__ = _attach(__name__, __file__)
