"""jaxtow: a JAX differentiable hydrodynamics and towing-stability engine.

Importing jaxtow enables float64 in JAX (see `jaxtow._config`; set ``JAXTOW_ENABLE_X64=0``
before import to opt out).
"""

from ._config import enable_x64_from_environment as _enable_x64

_enable_x64()

from . import drift as drift
from . import presets as presets
from . import waves as waves
from .dynamics import (
    AbstractExternalForce as AbstractExternalForce,
    CombinedForce as CombinedForce,
    ConstantBodyForce as ConstantBodyForce,
    NoExternalForce as NoExternalForce,
    STATE_NAMES as STATE_NAMES,
    TowModel as TowModel,
    force_breakdown as force_breakdown,
    sway_offset as sway_offset,
    vector_field as vector_field,
)
from .equilibrium import (
    Equilibria as Equilibria,
    analytic_equilibria as analytic_equilibria,
    equilibria as equilibria,
    equilibria_fixed as equilibria_fixed,
    heading_residual as heading_residual,
)
from .parameters import get_parameter as get_parameter, with_parameters as with_parameters
from .stability import (
    STABILITY_LABELS as STABILITY_LABELS,
    characteristic_polynomial as characteristic_polynomial,
    classify as classify,
    eigenvalues as eigenvalues,
    jacobian as jacobian,
    max_real_eigenvalue as max_real_eigenvalue,
    routh_hurwitz_stable as routh_hurwitz_stable,
    stability as stability,
)
from .drift import QTF as QTF, wave_drift_damping as wave_drift_damping
from .metrics import (
    damping_ratio as damping_ratio,
    fishtail_metrics as fishtail_metrics,
    force_history as force_history,
    trajectory as trajectory,
)
from .simulate import (
    Simulation as Simulation,
    initial_state as initial_state,
    simulate as simulate,
    simulate_batch as simulate_batch,
)
from . import design as design
from . import resistance as resistance
from . import study as study
from .resistance import operating_speed as operating_speed, required_pull as required_pull
from .sweep import sweep as sweep, sweep_arrays as sweep_arrays
from .towline import (
    AbstractTowline as AbstractTowline,
    Bridle as Bridle,
    PowerLawTowline as PowerLawTowline,
    Towline as Towline,
)
from .units import Scales as Scales, froude_number as froude_number
from .vessel import Vessel as Vessel

__version__ = "0.1.0"


def __getattr__(name):
    # `jt.io`, `jt.plotting` and `jt.bem` load on first use: the numerics never import
    # xarray/matplotlib, and nothing imports Capytaine until a panel solve is asked for
    if name in ("io", "plotting", "bem", "cli"):
        import importlib

        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'jaxtow' has no attribute {name!r}")
