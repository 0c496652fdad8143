"""Tow resistance and operating speed: wind, current/calm water, mean wave drift and the tug
(thesis sections 2 intro, 2.2, 7.1-7.2, appendix A; docs/model.md section 9).

The planning questions of an ocean tow (thesis fig. 2.1):

* **required towing force** — in a survival sea state the tug must hold the tow in place, so
  the required pull is the total resistance at zero speed (`required_pull`);
* **operating speed** — in a sailing sea state the tow sails where the tug's available pull
  equals the total resistance, both speed dependent (`operating_speed`), which gives the
  transit time of a route.

Conventions. SI units and radians. The tow sails along the global x axis at speed U ≥ 0 with
the barge at heading ψ (counter-clockwise, ψ = 0 straight ahead); body axes are x forward,
y to port, N counter-clockwise (as the QTF and the waterline methods). Wind, current and
waves are given by the direction they come *from*, counter-clockwise from the course
(0 = head wind / head current / head seas), so relative to the bow their angle is α − ψ.
The resistance of a component is minus the along-course component of its force,
R = −(Fx cos ψ − Fy sin ψ), so a force that holds the tow back is a positive resistance.

Relative flow (eqs 2.23, 2.24, with the barge's sway velocity added): a flow of speed W from
angle α meets a vessel with body velocity (u, v) as the apparent flow
(W cos α + u, W sin α + v); for v = 0 its speed is √(u² + W² + 2uW cos α) and its angle
atan2(W sin α, u + W cos α), exactly eqs 2.23-2.24. OCIMF form (eqs 2.25-2.27):
F_x = ½ C_x ρ U_r² B H, F_y = ½ C_y ρ U_r² L H, N = ½ C_n ρ U_r² L² H, with air density and
the above-water height H for wind (the text prints ρ_w; it is air), water density and the
draft T for current. The coefficients come from a table over the relative angle
(`CoefficientTable`, C¹ periodic cubic Hermite; the thesis fits cubic splines) or, for
current/calm water, from the vessel's manoeuvring derivatives (`ManoeuvringCoefficients`,
the thesis's fig. 7.1b).

Mean wave drift in irregular seas with forward speed (`WaveDrift`): 2∫S(ω)F(ω; u, v)dω
(eq. 2.29) of a waterline method of `jaxtow.drift` (default Kashiwagi: Fujii-Takahashi
diffraction, which vanishes in long waves, with Kashiwagi's speed factor) or of a panel QTF
with encounter frequency and wave-drift damping (`jaxtow.drift.irregular_sailing_drift`).
The waterline methods miss the motion-induced drift peak in the motion zone (their
relative MSE ≈ 1 there), so results that use them say so in ``assumed``.

Everything is a pure JAX function of pytrees: jit, vmap over grids of speed/Tp/Hs, and
grad with respect to every input. `operating_speed` brackets the first crossing of
pull − resistance on a speed grid and refines it with optimistix's bisection, whose implicit
adjoint gives exact derivatives dU/dθ = −(∂g/∂θ)/(∂g/∂U).
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._budget import (
        COMPONENTS as COMPONENTS,
        OVERTAKEN_TOL as OVERTAKEN_TOL,
        Budget as Budget,
        PullRequirement as PullRequirement,
        TowResistance as TowResistance,
        WaveDrift as WaveDrift,
        required_pull as required_pull,
        resistance as resistance,
        resistance_grid as resistance_grid,
        tow_resistance as tow_resistance,
        worst_bollard_pull as worst_bollard_pull,
    )
    from ._flow import (
        RHO_AIR as RHO_AIR,
        CoefficientTable as CoefficientTable,
        ManoeuvringCoefficients as ManoeuvringCoefficients,
        OCIMFLoad as OCIMFLoad,
        relative_flow as relative_flow,
    )
    from ._sea import SeaState as SeaState
    from ._speed import (
        RESULTS as RESULTS,
        OperatingPoint as OperatingPoint,
        operating_speed as operating_speed,
        status_message as status_message,
    )
    from ._tug import Tug as Tug

__getattr__, __dir__, __all__ = _attach(__name__, __file__)
