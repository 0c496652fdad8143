"""Bifurcation analysis of the tow: equilibrium branches, pitchfork/fold/Hopf points, Hopf
curves in two parameters, and limit cycles (the fishtailing orbit) with Floquet multipliers.

**Equilibrium branches.** Every equilibrium is fixed by its heading ψ (the vessel moves with
the tug; MODEL.md sections 3-4), so the branch through a parameter p is the curve
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

from __future__ import annotations

import dataclasses
import math
from typing import Callable

import diffrax
import jax
import jax.numpy as jnp
import numpy as np

from .dynamics import TowModel, sway_offset, vector_field
from .equilibrium import _state_from_heading, heading_residual
from .parameters import get_parameter, with_parameters
from .stability import characteristic_polynomial, jacobian

NEWTON_ITERATIONS = 12


def _setter(parameter) -> Callable:
    if callable(parameter):
        return parameter
    return lambda model, p: with_parameters(model, **{parameter: p})


def _hurwitz_matrix(a):
    """Hurwitz matrix H_ij = a_{2j−i} (1-based, a_0 = 1, zero outside 0…n) of λⁿ + a₁λⁿ⁻¹ + … + a_n."""
    n = a.shape[0] - 1
    idx = 2 * jnp.arange(1, n + 1)[None, :] - jnp.arange(1, n + 1)[:, None]
    return jnp.where((idx >= 0) & (idx <= n), a[jnp.clip(idx, 0, n)], 0.0)


def hurwitz_determinants(coeffs):
    """Leading principal minors Δ_1 … Δ_n of the Hurwitz matrix of the monic polynomial
    (``coeffs`` = (1, a₁, …, a_n)); all > 0 ⇔ every root has Re < 0."""
    H = _hurwitz_matrix(jnp.asarray(coeffs))
    return jnp.stack([jnp.linalg.det(H[:k, :k]) for k in range(1, H.shape[0] + 1)])


def hopf_test(A):
    """Δ_{n−1}, the Hopf test function of a real n×n matrix (zero when a pair λ = ±iω or ±μ)."""
    H = _hurwitz_matrix(characteristic_polynomial(A))
    return jnp.linalg.det(H[:-1, :-1])


# ------------------------------------------------------------------ generic curve following


class _Curve:
    """Pseudo-arclength continuation of G(x) = 0, x ∈ R² (jitted pieces, Python driver)."""

    def __init__(self, G: Callable):
        self.G = G
        grad = jax.grad(G)
        self.grad = jax.jit(grad)

        def correct(x_pred, t, x_prev, s):
            def body(_, x):
                g = grad(x)
                J = jnp.stack([g, t])
                r = jnp.stack([G(x), jnp.dot(t, x - x_prev) - s])
                return x - jnp.linalg.solve(J, r)

            x = jax.lax.fori_loop(0, NEWTON_ITERATIONS, body, x_pred)
            return x, jnp.abs(G(x))

        self.correct = jax.jit(correct)

    def tangent(self, x, previous=None):
        g = np.asarray(self.grad(jnp.asarray(x)))
        t = np.array([-g[1], g[0]]) / np.linalg.norm(g)
        if previous is not None and np.dot(t, previous) < 0:
            t = -t
        return t

    def point(self, x_prev, t_prev, s):
        x, res = self.correct(jnp.asarray(x_prev + s * t_prev), jnp.asarray(t_prev), jnp.asarray(x_prev),
                              jnp.asarray(s))
        return np.asarray(x), float(res)

    def follow(self, x0, t0, *, ds, n_max, inside: Callable, ds_min=1e-6, ds_max=None, tol=1e-9):
        """Points, tangents from x0 in direction t0 until ``inside(x)`` fails or n_max."""
        ds_max = ds_max or 10 * ds
        xs, ts = [np.asarray(x0, float)], [np.asarray(t0, float)]
        h = ds
        while len(xs) < n_max:
            x_new, res = self.point(xs[-1], ts[-1], h)
            ok = np.all(np.isfinite(x_new)) and res < tol and np.linalg.norm(x_new - xs[-1]) < 2 * h
            if not ok:
                h *= 0.5
                if h < ds_min:
                    break
                continue
            xs.append(x_new)
            ts.append(self.tangent(x_new, ts[-1]))
            if not inside(x_new):
                break
            h = min(h * 1.3, ds_max)
        return np.array(xs), np.array(ts)

    def locate(self, x_prev, t_prev, h, test: Callable, iterations=200):
        """Arclength s ∈ (0, h) where test(point(s)) changes sign (bisection)."""
        lo, hi = 0.0, h
        f_lo = test(self.point(x_prev, t_prev, lo)[0])
        for _ in range(iterations):
            mid = 0.5 * (lo + hi)
            f_mid = test(self.point(x_prev, t_prev, mid)[0])
            if np.sign(f_mid) == np.sign(f_lo):
                lo, f_lo = mid, f_mid
            else:
                hi = mid
            if hi - lo <= 4e-16 * max(1.0, h):
                break
        return self.point(x_prev, t_prev, 0.5 * (lo + hi))[0]


# ------------------------------------------------------------------ results


@dataclasses.dataclass
class SpecialPoint:
    """A detected bifurcation: ``kind`` in {"branch_point", "fold", "hopf", "neutral_saddle"},
    the parameter value, heading ψ [rad], full state, eigenvalues; for Hopf points the
    frequency ω (non-dimensional, by U_tug/L) and the first Lyapunov coefficient."""

    kind: str
    parameter: float
    psi: float
    state: np.ndarray
    eigenvalues: np.ndarray
    frequency: float | None = None
    lyapunov: float | None = None

    @property
    def criticality(self) -> str | None:
        if self.lyapunov is None:
            return None
        return "supercritical" if self.lyapunov < 0 else "subcritical"


@dataclasses.dataclass
class Branch:
    """An equilibrium branch: parameter values ``p``, headings ``psi``, ``states`` (n, 6),
    ``max_real`` (n,) of the Jacobian eigenvalues, ``stable`` (n,), the detected ``special``
    points and the ``children`` branches switched onto at branch points."""

    parameter: str
    p: np.ndarray
    psi: np.ndarray
    states: np.ndarray
    max_real: np.ndarray
    special: list
    children: list = dataclasses.field(default_factory=list)

    @property
    def stable(self):
        return self.max_real < 0

    def points(self, kind: str):
        return [s for s in self.special if s.kind == kind]


# ------------------------------------------------------------------ equilibrium branches


class _EquilibriumProblem:
    def __init__(self, model: TowModel, parameter):
        self.model, self.set = model, _setter(parameter)

        def G(x):
            return heading_residual(x[0], self.set(model, x[1]))

        def state(x):
            return _state_from_heading(x[0], self.set(model, x[1]))[0]

        def jac(x):
            return jacobian(self.set(model, x[1]), state(x))

        self.G, self.curve = G, _Curve(G)
        self.state = jax.jit(state)
        self.jac = jax.jit(jac)
        self.hopf = jax.jit(lambda x: hopf_test(jac(x)))
        self.dG = jax.jit(jax.grad(G))
        self.hessian = jax.jit(jax.hessian(G))

    def eig(self, x):
        return np.linalg.eigvals(np.asarray(self.jac(jnp.asarray(x))))


def first_lyapunov_coefficient(model: TowModel, y, omega=None):
    """First Lyapunov coefficient l₁ at a Hopf point y of the tow (see `lyapunov_coefficient`)."""
    return lyapunov_coefficient(lambda x: vector_field(0.0, x, model), y, omega)


def lyapunov_coefficient(f: Callable, y, omega=None):
    """First Lyapunov coefficient l₁ of ẏ = f(y) at a Hopf point y (Kuznetsov 2004, eq. 3.20):

        l₁ = Re[ ⟨p, C(q,q,q̄)⟩ − 2⟨p, B(q, A⁻¹B(q,q̄))⟩ + ⟨p, B(q̄, (2iωI − A)⁻¹B(q,q))⟩ ] / (2ω),

    A q = iω q, Aᵀ p = −iω p, ⟨p, q⟩ = p̄ᵀq = 1, with B and C the second and third
    derivatives of the vector field (nested forward-mode autodiff). l₁ < 0: supercritical."""
    y = jnp.asarray(y)
    A = np.asarray(jax.jacfwd(f)(y))
    lam, V = np.linalg.eig(A)
    k = int(np.argmin(np.abs(lam.real) + 1e3 * (lam.imag <= 0)))
    w = float(lam[k].imag) if omega is None else float(omega)
    q = V[:, k] / np.linalg.norm(V[:, k])
    lamT, W = np.linalg.eig(A.T)
    j = int(np.argmin(np.abs(lamT - (-1j * w))))
    p = W[:, j]
    p = p / np.conj(np.vdot(p, q))  # so that p̄ᵀ q = 1

    def d2(a, b):
        return jax.jvp(lambda x: jax.jvp(f, (x,), (a,))[1], (y,), (b,))[1]

    def d3(a, b, c):
        return jax.jvp(lambda x: jax.jvp(lambda z: jax.jvp(f, (z,), (a,))[1], (x,), (b,))[1], (y,), (c,))[1]

    def B(u, v):
        ur, ui, vr, vi = (jnp.asarray(z) for z in (u.real, u.imag, v.real, v.imag))
        re = d2(ur, vr) - d2(ui, vi)
        im = d2(ur, vi) + d2(ui, vr)
        return np.asarray(re) + 1j * np.asarray(im)

    def C(u, v, z):
        out = 0j
        for su, pu in ((1, u.real), (1j, u.imag)):
            for sv, pv in ((1, v.real), (1j, v.imag)):
                for sz, pz in ((1, z.real), (1j, z.imag)):
                    parts = d3(jnp.asarray(pu), jnp.asarray(pv), jnp.asarray(pz))
                    out = out + su * sv * sz * np.asarray(parts)
        return out

    qb = np.conj(q)
    n = A.shape[0]
    t1 = np.vdot(p, C(q, q, qb))
    t2 = np.vdot(p, B(q, np.linalg.solve(A, B(q, qb))))
    t3 = np.vdot(p, B(qb, np.linalg.solve(2j * w * np.eye(n) - A, B(q, q))))
    return float(np.real(t1 - 2 * t2 + t3) / (2 * w))


def _special(problem: _EquilibriumProblem, kind, x, set_model):
    y = np.asarray(problem.state(jnp.asarray(x)))
    ev = problem.eig(x)
    sp = SpecialPoint(kind=kind, parameter=float(x[1]), psi=float(x[0]), state=y, eigenvalues=ev)
    if kind == "hopf":
        k = int(np.argmin(np.abs(ev.real) + 1e3 * (ev.imag <= 0)))
        sp.frequency = float(ev[k].imag)
        sp.lyapunov = first_lyapunov_coefficient(set_model(problem.model, x[1]), y, sp.frequency)
    return sp


def _scan_special(problem, xs, ts, hs):
    """Special points between consecutive continuation points."""
    out = []
    dG = np.array([np.asarray(problem.dG(jnp.asarray(x))) for x in xs])
    hopf = np.array([float(problem.hopf(jnp.asarray(x))) for x in xs])
    for k in range(len(xs) - 1):
        x0, t0, h = xs[k], ts[k], hs[k]
        if np.sign(dG[k, 0]) != np.sign(dG[k + 1, 0]) and dG[k, 0] != 0:
            kind = "fold" if np.sign(ts[k][1]) != np.sign(ts[k + 1][1]) else "branch_point"
            x = problem.curve.locate(x0, t0, h, lambda z: float(problem.dG(jnp.asarray(z))[0]))
            out.append((kind, x, k))
        if np.sign(hopf[k]) != np.sign(hopf[k + 1]) and hopf[k] != 0:
            x = problem.curve.locate(x0, t0, h, lambda z: float(problem.hopf(jnp.asarray(z))))
            ev = problem.eig(x)
            pair = ev[np.argsort(np.abs(ev.real))[:2]]
            kind = "hopf" if np.all(np.abs(pair.imag) > 1e-6) else "neutral_saddle"
            out.append((kind, x, k))
    return out


def equilibrium_branch(model: TowModel, parameter="xp", *, p_range, psi0: float = 0.0, ds: float = 0.01,
                       max_points: int = 2000, switch: bool = True, psi_max: float | None = None,
                       p0: float | None = None, _depth: int = 0) -> Branch:
    """Continue the equilibrium through (ψ0, p0) in ``parameter`` over ``p_range``.

    ``parameter``: a name that `with_parameters` knows (``"xp"``, ``"l0"``, ``"EA"``, any
    vessel coefficient) or a callable ``(model, p) -> model`` (e.g. wave frequency, tug
    speed; then pass ``p0``). ``psi0`` must be an equilibrium heading at p0 (0 is one for
    every symmetric model). Returns a `Branch` with its special points; with ``switch`` the
    side branches born at branch points are followed too (``children``)."""
    set_model = _setter(parameter)
    if p0 is None:
        if callable(parameter):
            raise ValueError("parameter 'p0' is required when 'parameter' is a callable")
        p0 = float(get_parameter(model, parameter))
    lo, hi = (float(v) for v in p_range)
    if not lo < hi:
        raise ValueError(f"parameter 'p_range' must be increasing, got {p_range}")
    if not lo <= p0 <= hi:
        raise ValueError(f"parameter 'p0' = {p0} lies outside p_range {p_range}")
    psi_lim = float(model.psi_max if psi_max is None else psi_max)
    problem = _EquilibriumProblem(model, parameter)
    x0 = np.array([psi0, p0], float)
    if abs(float(problem.G(jnp.asarray(x0)))) > 1e-8:
        raise ValueError(f"parameter 'psi0' = {psi0} is not an equilibrium heading at p = {p0} "
                         f"(residual {float(problem.G(jnp.asarray(x0))):.3g})")

    def inside(x):
        return lo <= x[1] <= hi and abs(x[0]) <= psi_lim

    t0 = problem.curve.tangent(x0)
    pieces = []
    for direction in (-1.0, 1.0):
        xs, ts = problem.curve.follow(x0, direction * t0, ds=ds, n_max=max_points // 2, inside=inside)
        pieces.append((xs, ts))
    xs = np.concatenate([pieces[0][0][::-1], pieces[1][0][1:]])
    ts = np.concatenate([-pieces[0][1][::-1], pieces[1][1][1:]])
    keep = np.array([inside(x) for x in xs])  # the last step of each end may overshoot
    xs, ts = xs[keep], ts[keep]
    hs = np.array([float(np.dot(ts[k], xs[k + 1] - xs[k])) for k in range(len(xs) - 1)])
    raw = _scan_special(problem, xs, ts, hs)
    special = [_special(problem, kind, x, set_model) for kind, x, _ in raw]
    states = np.array([np.asarray(problem.state(jnp.asarray(x))) for x in xs])
    max_real = np.array([problem.eig(x).real.max() for x in xs])
    name = parameter if isinstance(parameter, str) else getattr(parameter, "__name__", "p")
    branch = Branch(parameter=name, p=xs[:, 1], psi=xs[:, 0], states=states, max_real=max_real, special=special)
    if switch and _depth == 0:
        for sp in branch.points("branch_point"):
            branch.children.extend(_switch(problem, sp, model, parameter, lo, hi, psi_lim, ds, max_points))
    return branch


def _switch(problem, sp, model, parameter, lo, hi, psi_lim, ds, max_points):
    """Follow the second branch through a branch point, both ways."""
    x = np.array([sp.psi, sp.parameter])
    H = np.asarray(problem.hessian(jnp.asarray(x)))
    # null directions of the quadratic form tᵀ H t on the unit circle
    th = np.linspace(0, np.pi, 3601)
    qv = H[0, 0] * np.cos(th) ** 2 + 2 * H[0, 1] * np.cos(th) * np.sin(th) + H[1, 1] * np.sin(th) ** 2
    roots = [0.5 * (th[i] + th[i + 1]) for i in range(len(th) - 1) if np.sign(qv[i]) != np.sign(qv[i + 1])]
    t_old = problem.curve.tangent(x + np.array([0.0, 1e-6]))
    dirs = [np.array([np.cos(r), np.sin(r)]) for r in roots]
    if not dirs:
        return []
    d = min(dirs, key=lambda v: abs(np.dot(v, t_old)))
    # one step onto the new branch; the child is then continued both ways (it passes
    # through the branch point again, so the other side comes with it)
    start, _ = problem.curve.point(x, d if d[0] >= 0 else -d, 5 * ds)
    if abs(start[0] - x[0]) < 1e-9 or not lo <= start[1] <= hi:
        return []
    return [equilibrium_branch(model, parameter, p_range=(lo, hi), psi0=float(start[0]), ds=ds,
                               max_points=max_points, switch=False, psi_max=psi_lim, p0=float(start[1]),
                               _depth=1)]


# ------------------------------------------------------------------ Hopf curves


def hopf_curve(model: TowModel, parameters=("xp", "l0"), *, start, ranges, ds: float = 0.01,
               max_points: int = 2000):
    """Two-parameter continuation of the Hopf condition Δ₅ = 0 of the straight-behind
    equilibrium (ψ = 0) in the plane of ``parameters`` = (p₁, p₂), from ``start`` = (p₁, p₂)
    on or near the curve (it is first corrected onto it at fixed p₂), within ``ranges`` =
    ((lo₁, hi₁), (lo₂, hi₂)). Returns an (n, 2) array of (p₁, p₂) points."""
    s1, s2 = (_setter(p) for p in parameters)

    def G(x):
        m = s2(s1(model, x[0]), x[1])
        return hopf_test(jacobian(m, _state_from_heading(jnp.asarray(0.0), m)[0]))

    x0 = np.asarray(start, float)
    # Δ₅ carries the stiff towline modes (values ~1e11): scale it by its gradient at the start
    # so that residuals and tolerances are in parameter units
    scale = float(np.linalg.norm(np.asarray(jax.grad(G)(jnp.asarray(x0)))))
    if not (np.isfinite(scale) and scale > 0):
        raise ValueError(f"parameter 'start' = {start}: the Hopf test function has no gradient there")
    curve = _Curve(lambda x: G(x) / scale)
    x0, res = curve.point(x0, np.array([1.0, 0.0]), 0.0)
    if not res < 1e-9:
        raise ValueError(f"parameter 'start' = {start} is not near a Hopf curve (|Δ5| = {res:.3g})")
    (l1, h1), (l2, h2) = ranges

    def inside(x):
        return l1 <= x[0] <= h1 and l2 <= x[1] <= h2

    t0 = curve.tangent(x0)
    a, _ = curve.follow(x0, -t0, ds=ds, n_max=max_points // 2, inside=inside)
    b, _ = curve.follow(x0, t0, ds=ds, n_max=max_points // 2, inside=inside)
    return np.concatenate([a[::-1], b[1:]])


def straight_behind_hopf(model: TowModel, parameter, bracket, *, set_model=None):
    """Hopf point of the straight-behind equilibrium in ``parameter`` within ``bracket`` =
    (lo, hi), where Δ₅ changes sign: bisection to machine precision. Returns the value."""
    s = set_model or _setter(parameter)

    def h(p):
        m = s(model, p)
        return float(hopf_test(jacobian(m, _state_from_heading(jnp.asarray(0.0), m)[0])))

    lo, hi = (float(v) for v in bracket)
    f_lo = h(lo)
    if np.sign(f_lo) == np.sign(h(hi)):
        raise ValueError(f"parameter 'bracket' {bracket}: the Hopf test function does not change sign")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        f = h(mid)
        if np.sign(f) == np.sign(f_lo):
            lo, f_lo = mid, f
        else:
            hi = mid
        if hi - lo < 4e-16 * max(1.0, abs(hi)):
            break
    return 0.5 * (lo + hi)


# ------------------------------------------------------------------ limit cycles


@dataclasses.dataclass
class PeriodicOrbit:
    """A limit cycle: initial state ``y0`` (ψ(0) = 0), period ``period`` (non-dimensional),
    ``floquet`` multipliers, the sampled orbit (``ts``, ``ys``), peak-to-peak sway offset
    ``path_width`` [L] and ``yaw_range`` (max |ψ|) [rad], Newton ``residual``."""

    parameter: float
    y0: np.ndarray
    period: float
    floquet: np.ndarray
    ts: np.ndarray
    ys: np.ndarray
    path_width: float
    yaw_range: float
    residual: float

    @property
    def stable(self) -> bool:
        mu = np.sort(np.abs(self.floquet))
        return bool(mu[-2] < 1.0)  # the largest is the trivial multiplier 1


def _flow(model, y0, T, n_save=None, rtol=1e-10, atol=1e-12):
    term = diffrax.ODETerm(vector_field)
    save = diffrax.SaveAt(t1=True) if n_save is None else diffrax.SaveAt(ts=jnp.linspace(0.0, T, n_save))
    sol = diffrax.diffeqsolve(term, diffrax.Tsit5(), 0.0, T, None, y0, args=model, saveat=save,
                              stepsize_controller=diffrax.PIDController(rtol=rtol, atol=atol),
                              max_steps=200_000, adjoint=diffrax.ForwardMode(), throw=False)
    return sol.ys


def periodic_orbit(model: TowModel, y0, period, *, tol: float = 1e-8, max_iterations: int = 25,
                   n_save: int = 4001) -> PeriodicOrbit:
    """Limit cycle through the guess (y0, period) by single shooting: Newton on
    {φ_T(y0) − y0 = 0, ψ(0) = 0} for (y0, T) with the monodromy matrix from forward-mode
    autodiff through diffrax. Raises if Newton does not reach ``tol``."""
    z = jnp.concatenate([jnp.asarray(y0, float), jnp.asarray([period], float)])

    def R(z):
        y, T = z[:6], z[6]
        return jnp.concatenate([_flow(model, y, T)[-1] - y, y[5:6]])

    Rj = jax.jit(R)
    Jj = jax.jit(jax.jacfwd(R))
    res = np.inf
    for _ in range(max_iterations):
        r = np.asarray(Rj(z))
        res = float(np.max(np.abs(r)))
        if res < tol or not np.isfinite(res):
            break
        J = np.asarray(Jj(z))
        step = np.linalg.lstsq(J, r, rcond=None)[0]
        step *= min(1.0, 0.2 * float(z[6]) / max(abs(step[6]), 1e-300))  # damp period jumps
        z = z - jnp.asarray(step)
    if not res < tol:
        raise RuntimeError(f"periodic_orbit: shooting did not converge (residual {res:.3g})")
    y0, T = z[:6], float(z[6])
    if float(jnp.max(jnp.abs(_flow(model, y0, T, n_save=64)[:, 5]))) < 1e-6:
        raise RuntimeError("periodic_orbit: shooting collapsed onto an equilibrium (no oscillation)")
    M = np.asarray(jax.jacfwd(lambda y: _flow(model, y, T)[-1])(y0))
    ys = np.asarray(_flow(model, y0, T, n_save=n_save))
    off = np.asarray(sway_offset(jnp.asarray(ys), model.towline.xp, model.towline.yp))
    return PeriodicOrbit(parameter=float("nan"), y0=np.asarray(y0), period=T, floquet=np.linalg.eigvals(M),
                         ts=np.linspace(0.0, T, n_save), ys=ys, path_width=float(off.max() - off.min()),
                         yaw_range=float(np.abs(ys[:, 5]).max()), residual=res)


def limit_cycle_from_simulation(model: TowModel, *, t1: float = 3000.0, psi0: float = 0.05, **kwargs) -> PeriodicOrbit:
    """Converge onto an attracting limit cycle: run the tow from a small disturbance of the
    straight-behind equilibrium, take the last ψ up-crossing of zero and the period between
    the last two, and refine by shooting (`periodic_orbit`)."""
    y_eq = _state_from_heading(jnp.asarray(0.0), model)[0]
    y = np.asarray(_flow(model, y_eq.at[5].set(psi0), t1, n_save=int(20 * t1) + 1))
    ts = np.linspace(0.0, t1, len(y))
    psi = y[:, 5]
    up = np.nonzero((psi[:-1] < 0) & (psi[1:] >= 0))[0]
    if len(up) < 3:
        raise RuntimeError("limit_cycle_from_simulation: no sustained oscillation (is the equilibrium unstable?)")
    k = up[-1]
    T = ts[up[-1]] - ts[up[-2]]
    return periodic_orbit(model, y[k], T, **kwargs)


def limit_cycle_branch(model: TowModel, parameter, values, *, start: PeriodicOrbit | None = None,
                       **kwargs) -> list:
    """Limit cycles at each value of ``parameter`` (natural continuation: each orbit starts
    from the previous one; the first from ``start`` or a simulation)."""
    set_model = _setter(parameter)
    out = []
    guess = start
    for p in values:
        m = set_model(model, p)
        orbit = None
        if guess is not None:
            try:
                orbit = periodic_orbit(m, guess.y0, guess.period, **kwargs)
            except RuntimeError:
                orbit = None  # fall back on a simulation
        if orbit is None:
            orbit = limit_cycle_from_simulation(m, **kwargs)
        orbit.parameter = float(p)
        out.append(orbit)
        guess = orbit
    return out
