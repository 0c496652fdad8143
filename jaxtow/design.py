"""Gradient-based towline and bridle design, and sensitivities of the stability margin
(thesis section 8.4; Kolthoff's bridle studies).

Everything here differentiates the stability of the straight-behind equilibrium:

* `straight_equilibrium` finds the equilibrium nearest ψ = 0 (Newton on the heading
  residual, optimistix, implicit adjoint: dψ/dθ = −(∂F/∂θ)/(∂F/∂ψ)); with a transverse
  attachment offset y_p' ≠ 0 it sits at a small heading;
* `spectral_abscissa` is max Re λ of the Jacobian there (gradients through the eigenvalues,
  exact away from eigenvalue crossings); `smooth_abscissa` replaces the max by the
  log-sum-exp τ·log Σ exp(Re λ_i/τ), C^∞ through crossings, with
  max Re λ ≤ smooth ≤ max Re λ + τ log 6 (the documented smoothing, tested);
* `optimise_towline` minimises the (smoothed, worst-case or mean over scenarios) abscissa
  over a box of (l0', x_p', y_p', EA') with BFGS on a sine-mapped box, plus C¹
  penalties for the constraints (tension limit, equilibrium heading); `grid_search` is the
  dense-grid reference;
* `sensitivities` gives ∂(max Re λ)/∂(every vessel and towline parameter) in one reverse
  pass per configuration, vmapped over a sweep.

A model whose straight-behind equilibrium is lost (a fold, or the Newton iteration falls onto
a side branch) is reported by ``converged`` / the heading constraint; the optimiser's
penalty on |ψ_eq| keeps designs on the branch that starts straight behind the tug.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
import optimistix as optx
from jaxtyping import Array

from ._dynamics import TowModel
from ._equilibrium import heading_residual, state_from_heading
from ._parameters import check_values, get_parameter, with_parameters
from ._program_cache import persistent
from ._roots import newton
from ._stability import STABLE, classify, eigenvalues, max_real_eigenvalue
from ._vessel import VESSEL_PARAMETERS

__all__ = [
    "DESIGN_BOUNDS",
    "SMOOTHING",
    "straight_equilibrium",
    "spectral_abscissa",
    "smooth_abscissa",
    "margin_terms",
    "MarginTerms",
    "StableValue",
    "design_objective",
    "DesignResult",
    "optimise_towline",
    "grid_search",
    "sensitivity_arrays",
    "ADVICE_MARGIN",
    "stable_value",
]

#: Design variables and their default box (non-dimensional): l0' towline length, x_p'
#: attachment (bridle apex) ahead of the CoG, y_p' transverse offset (to port), EA'.
DESIGN_BOUNDS = {"l0": (0.3, 3.0), "xp": (0.3, 1.0), "yp": (-0.15, 0.15), "EA": (50.0, 1000.0)}
#: Default smoothing temperature τ of the eigenvalue max (non-dimensional growth rate).
SMOOTHING = 1e-3


def straight_equilibrium(model: TowModel, psi0=0.0, *, rtol: float = 1e-12, max_steps: int = 64):
    """The equilibrium reached by Newton's method on the heading residual from ψ0 (default
    straight behind). Returns (state (6,), ψ, converged). Differentiable in the model by
    the implicit function theorem (optimistix's implicit adjoint)."""
    psi, ok = newton(
        lambda p, m: heading_residual(p, m, throw=False),
        jnp.asarray(psi0, float),
        model,
        rtol=rtol,
        atol=rtol,
        max_steps=max_steps,
    )
    state = state_from_heading(psi, model)[0]
    return state, psi, ok & jnp.isfinite(psi)


def spectral_abscissa(model: TowModel, y=None):
    """max Re λ of the Jacobian at ``y`` (default: `straight_equilibrium`)."""
    if y is None:
        y = straight_equilibrium(model)[0]
    return max_real_eigenvalue(model, y)


def smooth_abscissa(model: TowModel, y=None, tau: float = SMOOTHING):
    """τ·log Σ_i exp(Re λ_i/τ): a C^∞ upper bound of max Re λ within τ log 6 of it (the
    smoothing of the max over eigenvalues; at a crossing of two real parts the exact max
    has a kink and this has a finite, FD-consistent gradient)."""
    if y is None:
        y = straight_equilibrium(model)[0]
    return tau * jax.nn.logsumexp(jnp.real(eigenvalues(model, y)) / tau)


class MarginTerms(eqx.Module):
    """Stability terms of the straight-behind equilibrium (`margin_terms`): ``abscissa``
    (max Re λ'), ``smooth`` (`smooth_abscissa`), ``psi`` (its heading) [rad], ``tension``
    T' and ``converged``."""

    abscissa: Array
    smooth: Array
    psi: Array
    tension: Array
    converged: Array


def margin_terms(model: TowModel, psi0=0.0, tau: float = SMOOTHING) -> MarginTerms:
    """The `MarginTerms` of the straight-behind equilibrium (differentiable)."""
    y, psi, ok = straight_equilibrium(model, psi0)
    re = jnp.real(eigenvalues(model, y))
    return MarginTerms(
        abscissa=jnp.max(re),
        smooth=tau * jax.nn.logsumexp(re / tau),
        psi=psi,
        tension=model.towline.tension(y[3]),
        converged=ok,
    )


def _apply(model, params: dict, ea_scale):
    p = dict(params)
    if "EA" in p:
        p["EA"] = p["EA"] * ea_scale
    return with_parameters(model, **p)


def _scenarios(model, scenarios, ea_scales):
    models = [model] if scenarios is None else list(scenarios)
    if not models:
        raise ValueError("parameter 'scenarios' must hold at least one TowModel")
    scales = [1.0] * len(models) if ea_scales is None else [float(s) for s in ea_scales]
    if len(scales) != len(models):
        raise ValueError("parameter 'ea_scales' must have one entry per scenario")
    return models, scales


def design_objective(
    params: dict,
    models,
    ea_scales,
    *,
    aggregate: str = "worst",
    tau: float = SMOOTHING,
    psi_limit: float = math.radians(10.0),
    tension_limit=None,
    penalty: float = 1000.0,
):
    """The design objective (to minimise) and its terms.

    J = agg_k smooth_abscissa_k + penalty·Σ_k [max(0, |ψ_k| − ψ_lim)² + max(0, T'_k − T'_lim)²]
    + 1 per scenario whose straight-behind equilibrium was not found. ``agg`` is the smooth
    worst case τ·log Σ exp(·/τ) (``aggregate="worst"``) or the mean (``"mean"``) over the
    scenarios (sea states, tug speeds: one `TowModel` each; ``ea_scales`` rescales the
    design EA' per scenario, e.g. (U_ref/U)² for another tug speed).
    """
    terms = [
        margin_terms(_apply(m, params, s), tau=tau) for m, s in zip(models, ea_scales)
    ]  # few scenarios
    a = jnp.stack([t.smooth for t in terms])
    agg = tau * jax.nn.logsumexp(a / tau) if aggregate == "worst" else jnp.mean(a)
    pen = 0.0
    for t in terms:
        pen = pen + jnp.maximum(jnp.abs(t.psi) - psi_limit, 0.0) ** 2
        if tension_limit is not None:
            pen = pen + jnp.maximum(t.tension - tension_limit, 0.0) ** 2
        pen = pen + jnp.where(t.converged, 0.0, 1.0 / penalty)
    return agg + penalty * pen, terms


@dataclasses.dataclass(frozen=True)
class DesignResult:
    """`optimise_towline` / `grid_search` result: the design ``params`` (dict name → value),
    the ``objective`` there, per-scenario ``abscissa`` (max Re λ), ``psi``, ``tension``,
    ``n_evaluations`` (objective evaluations; one BFGS step evaluates the objective and its
    gradient once), ``converged`` (optimiser), ``method``; for a grid also ``grid`` (dict
    name → values) and ``values`` (objective on the grid)."""

    params: dict
    objective: float
    abscissa: np.ndarray
    psi: np.ndarray
    tension: np.ndarray
    n_evaluations: int
    converged: bool
    method: str
    grid: dict | None = None
    values: np.ndarray | None = None
    options: dict | None = None

    @property
    def stable(self) -> bool:
        return bool(np.all(np.asarray(classify(self.abscissa)) == STABLE))


def _check_bounds(variables, bounds, model=None):
    out = {}
    for v in variables:
        if v not in bounds:
            raise ValueError(f"parameter 'bounds': no range for design variable {v!r}")
        lo, hi = (float(b) for b in bounds[v])
        if not lo < hi:
            raise ValueError(
                f"parameter 'bounds': range of {v!r} must have lo < hi, got {(lo, hi)}"
            )
        if model is not None:  # the range must lie inside the parameter's own rule
            try:
                check_values(model, v, np.array([lo, hi]))
            except ValueError as e:
                raise ValueError(f"parameter 'bounds': range of {v!r}: {e}") from None
        out[v] = (lo, hi)
    return out


def _summary(params, models, scales, opts):
    J, terms = design_objective(params, models, scales, **opts)
    return (
        float(J),
        np.array([float(t.abscissa) for t in terms]),
        np.array([float(t.psi) for t in terms]),
        np.array([float(t.tension) for t in terms]),
    )


def optimise_towline(
    model: TowModel,
    *,
    variables=("l0", "xp", "yp", "EA"),
    bounds=None,
    x0=None,
    scenarios=None,
    ea_scales=None,
    aggregate: str = "worst",
    tau: float = SMOOTHING,
    psi_limit: float = math.radians(10.0),
    tension_limit=None,
    penalty: float = 1000.0,
    rtol: float = 1e-9,
    atol: float = 1e-9,
    max_steps: int = 200,
) -> DesignResult:
    """Gradient-based design of the towline / bridle attachment (thesis section 8.4).

    Minimises `design_objective` over ``variables`` (any of l0', x_p', y_p', EA'; others are
    kept at the model's values) inside ``bounds`` (default `DESIGN_BOUNDS`) with optimistix
    BFGS on the unconstrained z, θ = lo + (hi − lo)(1 + sin z)/2 (an active bound is a smooth
    stationary point in z, reached at finite z, unlike a sigmoid map). ``x0``: start (dict; default
    the model's values, clipped into the box). The problem is port-starboard symmetric: from
    y_p' = 0 exactly the y_p' gradient vanishes, so start slightly off the centreline to let
    the optimiser find an offset design. ``scenarios``: a list of TowModels (sea states,
    tug speeds) for the worst-case (``aggregate="worst"``) or mean objective; default
    ``[model]``. Gradients flow through the equilibrium (implicit) and the eigenvalues.
    """
    if aggregate not in ("worst", "mean"):
        raise ValueError(f"parameter 'aggregate' must be 'worst' or 'mean', got {aggregate!r}")
    variables = tuple(variables)
    box = _check_bounds(variables, {**DESIGN_BOUNDS, **(bounds or {})}, model)
    models, scales = _scenarios(model, scenarios, ea_scales)
    opts = dict(
        aggregate=aggregate,
        tau=tau,
        psi_limit=psi_limit,
        tension_limit=tension_limit,
        penalty=penalty,
    )
    lo = jnp.array([box[v][0] for v in variables])
    hi = jnp.array([box[v][1] for v in variables])
    start = {v: float(get_parameter(model, v)) for v in variables}
    start.update(x0 or {})
    s0 = jnp.array([start[v] for v in variables])
    frac = jnp.clip((s0 - lo) / (hi - lo), 0.0, 1.0)
    z0 = jnp.arcsin(2.0 * frac - 1.0)

    def theta(
        z,
    ):  # the box as a smooth periodic map: a bound is a stationary point in z, reached at finite z
        return lo + (hi - lo) * 0.5 * (1.0 + jnp.sin(z))

    def fn(z, _):
        return design_objective(dict(zip(variables, theta(z))), models, scales, **opts)[0]

    sol = optx.minimise(fn, optx.BFGS(rtol=rtol, atol=atol), z0, max_steps=max_steps, throw=False)
    best = {v: float(x) for v, x in zip(variables, theta(sol.value))}
    J, a, psi, T = _summary(best, models, scales, opts)
    return DesignResult(
        params=best,
        objective=J,
        abscissa=a,
        psi=psi,
        tension=T,
        n_evaluations=int(sol.stats["num_steps"]) + 1,
        converged=bool(sol.result == optx.RESULTS.successful),
        method="BFGS",
        options=dict(opts, variables=variables, bounds=box),
    )


def grid_search(
    model: TowModel,
    grid: dict,
    *,
    scenarios=None,
    ea_scales=None,
    aggregate: str = "worst",
    tau: float = SMOOTHING,
    psi_limit: float = math.radians(10.0),
    tension_limit=None,
    penalty: float = 1000.0,
    batch_size: int = 256,
) -> DesignResult:
    """Dense-grid reference for `optimise_towline`: `design_objective` on the tensor grid
    ``grid`` (dict name → 1-D values), evaluated in vmapped batches (no Python loop over
    the grid); returns the best grid point."""
    names = tuple(grid)
    for n in names:  # the grid inside each parameter's rule (the sweeps' eager check)
        check_values(model, n, np.asarray(grid[n], float))
    axes = [jnp.asarray(grid[n], float) for n in names]
    mesh = jnp.stack([g.ravel() for g in jnp.meshgrid(*axes, indexing="ij")], axis=-1)
    models, scales = _scenarios(model, scenarios, ea_scales)
    opts = dict(
        aggregate=aggregate,
        tau=tau,
        psi_limit=psi_limit,
        tension_limit=tension_limit,
        penalty=penalty,
    )

    @jax.jit
    def run(pts):
        return jax.lax.map(
            lambda p: design_objective(dict(zip(names, p)), models, scales, **opts)[0],
            pts,
            batch_size=batch_size,
        )

    vals = np.asarray(run(mesh)).reshape([a.size for a in axes])
    k = np.unravel_index(int(np.nanargmin(vals)), vals.shape)
    best = {n: float(axes[i][k[i]]) for i, n in enumerate(names)}
    J, a, psi, T = _summary(best, models, scales, opts)
    return DesignResult(
        params=best,
        objective=J,
        abscissa=a,
        psi=psi,
        tension=T,
        n_evaluations=int(vals.size),
        converged=True,
        method="grid",
        grid={n: np.asarray(g) for n, g in zip(names, axes)},
        values=vals,
        options=dict(opts, variables=names),
    )


def _external_parameters(model: TowModel) -> tuple:
    ext = model.external
    names = []
    for f in getattr(ext, "__dataclass_fields__", {}):
        val = getattr(ext, f)
        if isinstance(val, jax.Array) and val.ndim == 0 and jnp.issubdtype(val.dtype, jnp.floating):
            names.append(f)
    return tuple(names)


def sensitivity_arrays(model: TowModel, parameters=None, *, sweep: dict | None = None, psi0=0.0):
    """∂(max Re λ)/∂p of the straight-behind equilibrium for every parameter p (default:
    all vessel fields, the towline's fields, the scalar fields of the external force,
    e.g. a wave amplitude, named ``external.<field>``, and the tug speed ``u_tug`` when the
    model has reference scales), by one reverse pass per point;
    vmapped over a ``sweep`` (dict name → values, one parameter). Returns (names, values
    (n_sweep, n_par), gradients (n_sweep, n_par), abscissa (n_sweep,), sweep values)."""
    line = tuple(
        f
        for f in getattr(model.towline, "__dataclass_fields__", {})
        if isinstance(getattr(model.towline, f), jax.Array)
        and jnp.ndim(getattr(model.towline, f)) == 0
    )  # scalar fields (a composite line's per-segment arrays are not swept by name)
    ext = tuple(f"external.{f}" for f in _external_parameters(model))
    tug = ("u_tug",) if model.reference_scales is not None else ()
    names = (
        tuple(parameters) if parameters is not None else tuple(VESSEL_PARAMETERS) + line + ext + tug
    )

    def one(m):
        x = jnp.stack([jnp.asarray(get_parameter(m, n), float) for n in names])

        def f(xx):
            mm = with_parameters(m, **dict(zip(names, xx)))
            return spectral_abscissa(mm, straight_equilibrium(mm, psi0)[0])

        a, g = jax.value_and_grad(f)(x)
        return x, g, a

    if sweep is None:
        x, g, a = jax.jit(one)(model)
        return names, np.asarray(x)[None], np.asarray(g)[None], np.asarray(a)[None], None
    if len(sweep) != 1:
        raise ValueError("parameter 'sweep' must name exactly one parameter")
    ((sname, svals),) = sweep.items()
    check_values(model, sname, np.asarray(svals, float))
    svals = jnp.asarray(svals, float)
    x, g, a = jax.jit(jax.vmap(lambda s: one(with_parameters(model, **{sname: s}))))(svals)
    return names, np.asarray(x), np.asarray(g), np.asarray(a), (sname, np.asarray(svals))


#: Default margin of `stable_value`: the suggested value makes max Re λ' of the straight-behind
#: equilibrium at most −0.01 (per L/U_tug), clear of the stability tolerance and of the
#: boundary's round-off.
ADVICE_MARGIN = 0.01


@dataclasses.dataclass(frozen=True)
class StableValue:
    """`stable_value`'s answer: the parameter's ``value``, max Re λ' there (``abscissa``), its
    ``present`` value, and whether Newton's method ``converged`` to a stable point."""

    value: float
    abscissa: float
    present: float
    converged: bool


def _abscissa_of(model: TowModel, name: str, value):
    """(max Re λ', converged) of the straight-behind equilibrium with parameter ``name`` set to
    ``value`` (no host callback: the caller checks the grid)."""
    m = with_parameters(model, **{name: value})
    y, _, ok = straight_equilibrium(m)
    return max_real_eigenvalue(m, y, throw=False), ok


@persistent
@functools.partial(jax.jit, static_argnames=("names",))
def _scan_abscissa(model: TowModel, names: tuple[str, ...], which, values):
    """(max Re λ', converged) with parameter ``names[which]`` set to each of ``values``:
    the index is an argument, so the scans of every name in ``names`` are one program
    (traced and compiled once), each setting the others to their present values."""

    def one(v):
        present = [jnp.asarray(get_parameter(model, n), float) for n in names]
        new = {n: jnp.where(which == i, v, p) for i, (n, p) in enumerate(zip(names, present))}
        m = with_parameters(model, **new)
        y, _, ok = straight_equilibrium(m)
        return max_real_eigenvalue(m, y, throw=False), ok

    return jax.vmap(one)(values)


def stable_value(
    model: TowModel,
    name: str,
    lo: float,
    hi: float,
    *,
    n: int = 17,
    margin: float = ADVICE_MARGIN,
    among: tuple[str, ...] | None = None,
) -> StableValue | None:
    """The value of parameter ``name`` in [lo, hi] nearest its present one at which the
    straight-behind equilibrium is stable with max Re λ' = −``margin``: the smallest change
    of that one parameter that makes the tow follow the tug.

    A scan of ``n`` values (one vmapped program) brackets the crossings of max Re λ' +
    margin; the one nearest the present value is refined by Newton's method with the
    derivative of the abscissa by autodiff through the equilibrium (implicit function
    theorem) and the eigenvalues. Returns a `StableValue`, or None when no value in the
    range makes the tow stable.

    ``among``: the scalar parameters whose scans share one compiled program (``name``
    among them; default ``name`` alone), for a caller that asks for several in turn."""
    present = float(get_parameter(model, name))
    grid = np.linspace(lo, hi, n)
    check_values(model, name, grid)
    names = (name,) if among is None else tuple(among)
    if name not in names:
        raise ValueError(f"parameter 'among' must hold {name!r}, got {names}")
    # the index as an array: a Python int would be a static part of the program cache's key
    # (one exported program per name instead of one for all)
    which = jnp.asarray(names.index(name), dtype=jnp.int32)
    scan = _scan_abscissa(model, names, which, jnp.asarray(grid))
    a, ok = (np.asarray(x) for x in scan)
    g = np.where(ok, a + margin, np.nan)
    cross = [
        i
        for i in range(n - 1)
        if np.isfinite(g[i]) and np.isfinite(g[i + 1]) and np.sign(g[i]) != np.sign(g[i + 1])
    ]
    if not cross:
        return None
    i = min(cross, key=lambda k: min(abs(grid[k] - present), abs(grid[k + 1] - present)))

    def f(v, m):
        return _abscissa_of(m, name, v)[0] + margin

    v0 = grid[i] if g[i] < 0 else grid[i + 1]  # start on the stable side
    value, converged = newton(f, jnp.asarray(v0), model, lower=grid[i], upper=grid[i + 1])
    value = float(value)
    abscissa = float(_abscissa_of(model, name, value)[0])
    return StableValue(
        value=value, abscissa=abscissa, present=present, converged=bool(converged) and abscissa < 0
    )
