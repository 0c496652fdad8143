"""Equilibrium branches with fold, branch-point and Hopf detection; the first Lyapunov coefficient."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable

import jax
import jax.numpy as jnp
import numpy as np

from .._dynamics import TowModel, vector_field
from .._equilibrium import heading_residual, state_from_heading
from .._parameters import check_values, get_parameter
from .._stability import STABLE, classify, jacobian, matrix_eigenvalues
from ._curve import Curve, parameter_setter
from ._hopf import hopf_test

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
        return np.asarray(classify(self.max_real)) == STABLE

    def points(self, kind: str):
        return [s for s in self.special if s.kind == kind]


# ------------------------------------------------------------------ equilibrium branches


class _EquilibriumProblem:
    def __init__(self, model: TowModel, parameter):
        self.model, self.set = model, parameter_setter(parameter)

        def G(x):
            return heading_residual(x[0], self.set(model, x[1]), throw=False)

        def state(x):
            return state_from_heading(x[0], self.set(model, x[1]))[0]

        def jac(x):
            return jacobian(self.set(model, x[1]), state(x), throw=False)

        self.G, self.curve = G, Curve(G)
        self.state = jax.jit(state)
        self.jac = jax.jit(jac)
        self.hopf = jax.jit(lambda x: hopf_test(jac(x)))
        self.dG = jax.jit(jax.grad(G))
        self.hessian = jax.jit(jax.hessian(G))

    def eig(self, x):
        return np.asarray(matrix_eigenvalues(self.jac(jnp.asarray(x))))


def first_lyapunov_coefficient(model: TowModel, y, omega=None):
    """First Lyapunov coefficient l₁ at a Hopf point y of the tow (see `lyapunov_coefficient`)."""
    return lyapunov_coefficient(lambda x: vector_field(0.0, x, model, throw=False), y, omega)


def lyapunov_coefficient(f: Callable, y, omega=None):
    """First Lyapunov coefficient l₁ of ẏ = f(y) at a Hopf point y (Kuznetsov 2004, eq. 3.20):

        l₁ = Re[ ⟨p, C(q,q,q̄)⟩ − 2⟨p, B(q, A⁻¹B(q,q̄))⟩ + ⟨p, B(q̄, (2iωI − A)⁻¹B(q,q))⟩ ] / (2ω),

    A q = iω q, Aᵀ p = −iω p, ⟨p, q⟩ = p̄ᵀq = 1, with B and C the second and third
    derivatives of the vector field (nested forward-mode autodiff). l₁ < 0: supercritical."""
    y = jnp.asarray(y)
    A = np.asarray(jax.jacfwd(f)(y))
    lam, V = np.linalg.eig(A)
    k = int(np.argmin(np.abs(np.real(lam)) + 1e3 * (np.imag(lam) <= 0)))
    w = float(lam[k].imag) if omega is None else float(omega)
    q = V[:, k] / np.linalg.norm(V[:, k])
    lamT, W = np.linalg.eig(A.T)
    j = int(np.argmin(np.abs(lamT - (-1j * w))))
    p = W[:, j]
    p = p / np.conj(np.vdot(p, q))  # so that p̄ᵀ q = 1

    def d2(a, b):
        return jax.jvp(lambda x: jax.jvp(f, (x,), (a,))[1], (y,), (b,))[1]

    def d3(a, b, c):
        return jax.jvp(
            lambda x: jax.jvp(lambda z: jax.jvp(f, (z,), (a,))[1], (x,), (b,))[1], (y,), (c,)
        )[1]

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
        k = int(np.argmin(np.abs(np.real(ev)) + 1e3 * (np.imag(ev) <= 0)))
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
            x = problem.curve.locate(x0, t0, h, lambda z: problem.dG(z)[0])
            out.append((kind, x, k))
        if np.sign(hopf[k]) != np.sign(hopf[k + 1]) and hopf[k] != 0:
            x = problem.curve.locate(x0, t0, h, problem.hopf)
            ev = problem.eig(x)
            pair = ev[np.argsort(np.abs(ev.real))[:2]]
            kind = "hopf" if np.all(np.abs(pair.imag) > 1e-6) else "neutral_saddle"
            out.append((kind, x, k))
    return out


def equilibrium_branch(
    model: TowModel,
    parameter="xp",
    *,
    p_range,
    psi0: float = 0.0,
    ds: float = 0.01,
    max_points: int = 2000,
    switch: bool = True,
    psi_max: float | None = None,
    p0: float | None = None,
    _depth: int = 0,
) -> Branch:
    """Continue the equilibrium through (ψ0, p0) in ``parameter`` over ``p_range``.

    ``parameter``: a name that `with_parameters` knows (``"xp"``, ``"l0"``, ``"EA"``, any
    vessel coefficient) or a callable ``(model, p) -> model`` (e.g. wave frequency, tug
    speed; then pass ``p0``). ``psi0`` must be an equilibrium heading at p0 (0 is one for
    every symmetric model). Returns a `Branch` with its special points; with ``switch`` the
    side branches born at branch points are followed too (``children``)."""
    set_model = parameter_setter(parameter)
    if p0 is None:
        if callable(parameter):
            raise ValueError("parameter 'p0' is required when 'parameter' is a callable")
        p0 = float(get_parameter(model, parameter))
    lo, hi = (float(v) for v in p_range)
    if not lo < hi:
        raise ValueError(f"parameter 'p_range' must be increasing, got {p_range}")
    if not (math.isfinite(ds) and ds > 0):
        raise ValueError(f"parameter 'ds' must be > 0 and finite, got {ds!r}")
    if not callable(parameter):  # the range inside the parameter's own rule
        try:
            check_values(model, parameter, np.array([lo, hi]))
        except ValueError as e:
            raise ValueError(f"parameter 'p_range': {e}") from None
    if not lo <= p0 <= hi:
        raise ValueError(f"parameter 'p0' = {p0} lies outside p_range {p_range}")
    psi_lim = float(model.psi_max if psi_max is None else psi_max)
    problem = _EquilibriumProblem(model, parameter)
    x0 = np.array([psi0, p0], float)
    if abs(float(problem.G(jnp.asarray(x0)))) > 1e-8:
        raise ValueError(
            f"parameter 'psi0' = {psi0} is not an equilibrium heading at p = {p0} "
            f"(residual {float(problem.G(jnp.asarray(x0))):.3g})"
        )

    def inside(x):
        return lo <= x[1] <= hi and abs(x[0]) <= psi_lim

    t0 = problem.curve.tangent(x0)
    pieces = []
    for direction in (-1.0, 1.0):
        xs, ts = problem.curve.follow(
            x0, direction * t0, ds=ds, n_max=max_points // 2, inside=inside
        )
        pieces.append((xs, ts))
    xs = np.concatenate([pieces[0][0][::-1], pieces[1][0][1:]])
    ts = np.concatenate([-pieces[0][1][::-1], pieces[1][1][1:]])
    keep = np.array([inside(x) for x in xs])  # the last step of each end may overshoot
    xs, ts = xs[keep], ts[keep]
    hs = np.array([float(np.dot(ts[k], xs[k + 1] - xs[k])) for k in range(len(xs) - 1)])
    raw = _scan_special(problem, xs, ts, hs)
    special = [_special(problem, kind, x, set_model) for kind, x, _ in raw]
    states = np.array([np.asarray(problem.state(jnp.asarray(x))) for x in xs])
    max_real = np.array([np.real(problem.eig(x)).max() for x in xs])
    name = parameter if isinstance(parameter, str) else getattr(parameter, "__name__", "p")
    branch = Branch(
        parameter=name, p=xs[:, 1], psi=xs[:, 0], states=states, max_real=max_real, special=special
    )
    if switch and _depth == 0:
        for sp in branch.points("branch_point"):
            branch.children.extend(
                _switch(problem, sp, model, parameter, lo, hi, psi_lim, ds, max_points)
            )
    return branch


def _switch(problem, sp, model, parameter, lo, hi, psi_lim, ds, max_points):
    """Follow the second branch through a branch point, both ways."""
    x = np.array([sp.psi, sp.parameter])
    H = np.asarray(problem.hessian(jnp.asarray(x)))
    # null directions of the quadratic form tᵀ H t on the unit circle
    th = np.linspace(0, np.pi, 3601)
    qv = (
        H[0, 0] * np.cos(th) ** 2
        + 2 * H[0, 1] * np.cos(th) * np.sin(th)
        + H[1, 1] * np.sin(th) ** 2
    )
    roots = [
        0.5 * (th[i] + th[i + 1])
        for i in range(len(th) - 1)
        if np.sign(qv[i]) != np.sign(qv[i + 1])
    ]
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
    return [
        equilibrium_branch(
            model,
            parameter,
            p_range=(lo, hi),
            psi0=float(start[0]),
            ds=ds,
            max_points=max_points,
            switch=False,
            psi_max=psi_lim,
            p0=float(start[1]),
            _depth=1,
        )
    ]
