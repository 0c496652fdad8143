"""Bifurcation analysis of the tow: equilibrium branches, pitchfork/fold/Hopf points, Hopf
curves in two parameters, and limit cycles (the fishtailing orbit) with Floquet multipliers.

**Equilibrium branches.** Every equilibrium is fixed by its heading ψ (the vessel moves with
the tug; docs/model.md sections 3-4), so the branch through a parameter p is the curve
G(ψ, p) = F(ψ; model(p)) = 0 of the heading residual F = N − x_p' Y. It is followed by
pseudo-arclength continuation (Keller 1977; Allgower & Georg 2003, ch. 2) in the (ψ, p)
plane: tangent from the autodiff gradient of G, Euler predictor, Newton corrector on
{G = 0, tᵀ(x − x_k) = Δs}, step-size control by corrector effort. The full state
(u, v, r, l, γ, ψ) at each point follows from the force balance, and its Jacobian
(autodiff, 6×6) gives the stability.

**Special points** are located to machine precision by bisection in the arclength of the
step where a test function changes sign (each trial point corrected back onto the branch):

* fold (limit point): the p-component of the oriented tangent changes sign;
* branch point: ∂G/∂ψ changes sign while the branch keeps its direction in p. On the
  straight-behind branch this is the pitchfork where the side equilibria are born,
  ∂F/∂ψ(0) = −(N_v' − x_p' Y_v') = 0, i.e. x_p' = N_v'/Y_v'. Branch switching follows the
  second null direction of the Hessian of G there;
* Hopf: the (n−1)-th Hurwitz determinant Δ₅ of the characteristic polynomial of the 6×6
  Jacobian changes sign (Liu 1994: a pair of eigenvalues crosses the imaginary axis at
  Δ_{n−1} = 0). Δ₅ is a polynomial in the matrix entries, smooth and differentiable, unlike
  max Re λ. Each zero is checked: a purely imaginary pair makes a Hopf point, a real pair
  ±μ a "neutral saddle" (reported, not called Hopf). The first Lyapunov coefficient l₁
  (Kuznetsov 2004, eq. 3.20, multilinear forms by nested forward-mode autodiff) says
  whether the Hopf is supercritical (l₁ < 0: a small stable limit cycle is born) or
  subcritical.

**Hopf curves**: on the straight-behind branch (ψ = 0, which exists for every parameter by
symmetry) the Hopf condition Δ₅(p₁, p₂) = 0 is one equation in two parameters, followed
with the same continuation. **Limit cycles**: single shooting through diffrax with forward-
mode sensitivities (period T and initial state, phase condition ψ(0) = 0), Newton to
1e-8 (the integration tolerances, rtol 1e-10, limit it near Hopf points); Floquet multipliers are the eigenvalues of the monodromy matrix; path width and yaw
range are measured on the converged orbit.
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._branches import (
        Branch as Branch,
        SpecialPoint as SpecialPoint,
        equilibrium_branch as equilibrium_branch,
        first_lyapunov_coefficient as first_lyapunov_coefficient,
        lyapunov_coefficient as lyapunov_coefficient,
    )
    from ._cycles import (
        PeriodicOrbit as PeriodicOrbit,
        limit_cycle_branch as limit_cycle_branch,
        limit_cycle_from_simulation as limit_cycle_from_simulation,
        periodic_orbit as periodic_orbit,
    )
    from ._hopf import (
        hopf_curve as hopf_curve,
        hopf_test as hopf_test,
        straight_behind_hopf as straight_behind_hopf,
    )

__getattr__, __dir__, __all__ = _attach(__name__, __file__)
