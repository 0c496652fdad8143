"""Equilibria of the tow: analytic (no environment) and numerical (any force model).

At every equilibrium r' = 0 and the vessel moves with the tug: body velocity
(u', v') = (cos ψ, −sin ψ) (docs/model.md section 3). The towline then balances the hull and
environmental forces (X, Y, N) evaluated at that motion:

    T' cos(γ+ψ) = −X,   T' sin(γ+ψ) = Y,   T' x_p' sin(γ+ψ) = N.

Eliminating T' sin(γ+ψ) between sway and yaw leaves one scalar equation in the heading,
the heading residual (thesis eqs 6.17-6.23 generalised; docs/model.md section 4):

    F(ψ) = N(ψ) − x_p' Y(ψ) = 0.

`equilibria` brackets every sign change of F on a fine ψ grid and refines each root with
bisection to machine precision (its derivative the implicit one), so linearisation happens
exactly at the equilibrium (the thesis's ±0.5° rounding, section 7.4.3, is removed).
Roots where F touches zero without changing sign (exactly at a pitchfork or fold) are not
bracketed; away from such points every root is found.

Naming: equilibria are ordered by ascending ψ and labelled by ``branch`` = −1 (ψ < 0),
0 (straight behind the tug: `straight_behind`) and +1 (ψ > 0). Thesis chapter 2 calls these positions
1, 2 and 3; chapter 6 calls them 2, 3 and 4.
"""

from __future__ import annotations

import functools
import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Bool, Float, Int

from ._dynamics import TowModel, force_breakdown, kinematics, towline_force, vector_field
from ._program_cache import cached_call, host_program
from ._roots import bisected_root, brackets
from ._rules import check_now, guard, holds_tracers, is_concrete
from ._towline import Towline
from .forces._base import NoExternalForce

#: The largest heading an equilibrium straight behind the tug may have [rad] (1°): in a
#: symmetric sea it lies at ψ = 0 to the solver's precision; wind, waves or current from an
#: angle move it a little. `straight_behind` is the one definition.
STRAIGHT_LIMIT = math.radians(1.0)

#: The towline tension T' at or below which an equilibrium's line counts as slack: the
#: round-off of the force balance. The bisection finds a heading to 3.6e-15 rad, so a
#: towline that needs no pull (an external force that cancels the resistance) is left with
#: a tension of round-off size (1e-17 of the force scale in the tests), not exactly none.
SLACK_TENSION = 1e-12


def straight_behind(psi, found):
    """Which equilibrium is straight behind the tug (the thesis's position 3): the found
    equilibrium nearest ψ = 0, where it lies within `STRAIGHT_LIMIT` of it. ``psi``,
    ``found`` (..., k) [rad, bool] → a boolean mask (..., k) with at most one True along the
    last axis. NumPy or JAX arrays alike (the one definition of the sweeps' ``branch`` 0,
    the study's straight-behind verdict and the maps)."""
    xp = jnp if isinstance(psi, jax.Array) or isinstance(found, jax.Array) else np
    dist = xp.where(found, xp.abs(psi), xp.inf)
    nearest = xp.argmin(dist, axis=-1)
    one = xp.arange(dist.shape[-1]) == nearest[..., None]
    return one & (dist <= STRAIGHT_LIMIT)


#: Headings evaluated together in the residual scan (bounds memory for costly force models).
SCAN_BATCH = 64


class Equilibria(eqx.Module):
    """A set of equilibria (fixed number of slots; ``found`` marks the real ones).

    Fields, each with a leading axis of size k:

    - ``state`` (k, 6): (u, v, r, l, γ, ψ) at the equilibrium;
    - ``psi``, ``gamma`` [rad], ``tension`` T', ``length`` l';
    - ``found``: the slot holds a root (padding slots repeat a found root);
    - ``converged``: the root finder succeeded;
    - ``taut``: T' > `SLACK_TENSION` (the towline is not slack);
    - ``behind_tug``: |γ| < π/2;
    - ``in_range``: |ψ| <= model.psi_max (inside the manoeuvring model's range);
    - ``branch``: −1, 0, +1 (see module docstring);
    - ``residual``: max |f(y)| of the full vector field at the state;

    and ``n_roots``, the number of roots the heading scan saw (more than k means roots were
    dropped; the analytic solution gives the number found).
    """

    state: Float[Array, "k 6"]
    psi: Float[Array, " k"]
    gamma: Float[Array, " k"]
    tension: Float[Array, " k"]
    length: Float[Array, " k"]
    found: Bool[Array, " k"]
    converged: Bool[Array, " k"]
    taut: Bool[Array, " k"]
    behind_tug: Bool[Array, " k"]
    in_range: Bool[Array, " k"]
    branch: Int[Array, " k"]
    residual: Float[Array, " k"]
    n_roots: Int[Array, ""]

    @property
    def valid(self) -> Bool[Array, " k"]:
        """Found, converged, taut, behind the tug and inside the model's heading range."""
        return self.found & self.converged & self.taut & self.behind_tug & self.in_range

    def __len__(self) -> int:
        return int(self.psi.shape[-1])

    def select(self, mask) -> Equilibria:
        """Eager: keep the slots where `mask` (a concrete boolean array) holds."""

        keep = np.flatnonzero(np.asarray(mask))
        # indexed on the host (an eager jax.numpy gather compiles a program per field)
        return jax.tree_util.tree_map(
            lambda a: jnp.asarray(np.asarray(a)[keep]) if jnp.ndim(a) else a, self
        )

    def compact(self) -> Equilibria:
        """Eager: drop the padding slots (keep ``found``)."""
        return self.select(self.found)


def equilibrium_kinematics(psi):
    """State at heading ψ moving with the tug: (cos ψ, −sin ψ, 0, ·, ·, ψ) (eqs 6.7-6.10).

    l and γ are set to placeholders (1, 0); they do not enter hull or environmental forces.
    """
    psi = jnp.asarray(psi)
    one = jnp.ones_like(psi)
    return jnp.stack([jnp.cos(psi), -jnp.sin(psi), 0 * psi, one, 0 * psi, psi])


def _steady(model: TowModel) -> TowModel:
    """The model with its external force's `steady` form, for states with r = 0."""
    return eqx.tree_at(lambda m: m.external, model, model.external.steady())


def hull_forces_at_heading(psi, model: TowModel):
    """Non-towline forces (X', Y', N') on the vessel moving with the tug at heading ψ (r = 0:
    the external force's `steady` form)."""
    fb = force_breakdown(0.0, equilibrium_kinematics(psi), _steady(model), throw=False)
    return fb.manoeuvring + fb.coupling + fb.external


def heading_residual(psi, model: TowModel, *, throw: bool = True):
    """F(ψ) = N(ψ) − x_p' Y(ψ) (docs/model.md section 4; thesis eqs 6.17-6.23), + y_p' X(ψ) for
    a transverse attachment offset (the towline moment −T'(x_p' sin a + y_p' cos a) with
    T' sin a = Y, T' cos a = −X; see `jaxtow.vector_field` (docs/model.md section 2)).
    ``throw``: check the model's parameters (see `jaxtow.vector_field`)."""
    out = _heading_residual(psi, model)
    return guard(out, model.checks()) if throw else out


@host_program()
def _heading_residual(psi, model: TowModel):
    X, Y, N = hull_forces_at_heading(psi, model)
    return N - model.towline.xp * Y + model.towline.yp * X


def _residual(psi, model: TowModel):
    return heading_residual(psi, model, throw=False)


def state_from_heading(psi, model: TowModel):
    """Towline angle, tension and length that balance the forces at heading ψ."""
    X, Y, _ = hull_forces_at_heading(psi, model)
    return _balanced_state(psi, X, Y, model)


def _balanced_state(psi, X, Y, model: TowModel):
    """`state_from_heading` from the hull forces (X', Y') at heading ψ."""
    a = jnp.arctan2(Y, -X)  # γ + ψ: direction of the required towline pull
    T2 = X**2 + Y**2
    T = jnp.sqrt(jnp.where(T2 > 0, T2, 1.0)) * (T2 > 0)
    gamma = jnp.arctan2(jnp.sin(a - psi), jnp.cos(a - psi))
    # Where no pull is needed the line is slack; place it at its unstretched length.
    length = jnp.where(
        T > 0, model.towline.length_at_tension(jnp.where(T > 0, T, 1.0)), model.towline.l0
    )
    y = equilibrium_kinematics(psi)
    state = y.at[3].set(length).at[4].set(gamma)
    return state, gamma, T, length


def _state_and_residual(psi, model: TowModel):
    """`state_from_heading` and the residual max |f(y)| of the full vector field at the
    state, from one evaluation of the hull forces: they do not depend on the towline's
    length and angle (`equilibrium_kinematics`), so the vector field at the state is the
    hull forces at ψ with the towline's pull at the state (`vector_field` term by term)."""
    y0 = equilibrium_kinematics(psi)
    fb = force_breakdown(0.0, y0, _steady(model), throw=False)  # the state has r = 0
    hull = fb.manoeuvring + fb.coupling + fb.external
    state, gamma, T, length = _balanced_state(psi, hull[0], hull[1], model)
    pull, _ = towline_force(state, model.towline)
    f = jnp.concatenate(
        [(hull + pull) / fb.inertia, kinematics(state, model.towline.xp, model.towline.yp)]
    )
    return state, gamma, T, length, jnp.max(jnp.abs(f))


def _finish(psi, found, converged, model: TowModel, n_roots) -> Equilibria:
    state, gamma, T, length, residual = jax.vmap(_state_and_residual, in_axes=(0, None))(psi, model)
    branch = jnp.where(straight_behind(psi, found), 0, jnp.sign(psi)).astype(jnp.int32)
    branch = jnp.where(found, branch, branch[0])  # padding slots repeat the first root
    return Equilibria(
        state=state,
        psi=psi,
        gamma=gamma,
        tension=T,
        length=length,
        found=found,
        converged=converged & jnp.isfinite(psi),
        taut=T > SLACK_TENSION,
        behind_tug=jnp.cos(gamma) > 0,
        in_range=jnp.abs(psi) <= model.psi_max,
        branch=branch,
        residual=residual,
        n_roots=jnp.asarray(n_roots, jnp.int32),
    )


def bisection_atol(dtype) -> float:
    """The heading tolerance of the equilibrium bisection [rad]: 16 ulp of a heading of order
    one (3.6e-15 in float64, 1.9e-6 in float32), the precision of a Newton step there."""
    return 16.0 * float(jnp.finfo(dtype).eps)


def _refine(lo, hi, f_lo, f_hi, exact, model: TowModel, steps: int, enough: bool):
    """Root of F on [lo, hi] (where F takes the values ``f_lo``, ``f_hi``) to machine
    precision: ``steps`` halvings of the bracket (`jaxtow._roots.bisected_root`: F traced
    once, no solver), whose derivative with respect to the parameters is the implicit one
    by its own rule (traced only where the program is differentiated). ``enough``: whether
    the halvings reach the bisection tolerance (else the root is not ``converged``)."""
    psi = bisected_root(_residual, lo, hi, model, steps=steps, f_lo=f_lo, f_hi=f_hi)
    bracketed = (f_lo < 0) != (f_hi < 0)
    return jnp.where(exact, lo, psi), (bracketed & enough) | exact


def bisection_steps(width: float, dtype, max_steps: int) -> tuple[int, bool]:
    """(halvings of a bracket of ``width`` down to `bisection_atol`, at most ``max_steps``;
    whether that many reach it)."""
    need = max(1, math.ceil(math.log2(width / bisection_atol(dtype))))
    return min(need, max_steps), need <= max_steps


def _scan_residual(grid, model: TowModel):
    """The heading residual on ``grid``, in batches of `SCAN_BATCH` headings. The grid is
    padded with its last heading to whole batches: a remainder batch would trace (and
    compile) the force model a second time."""
    n = grid.shape[0]
    if n <= SCAN_BATCH:
        return jax.vmap(_residual, in_axes=(0, None))(grid, model)
    pad = -n % SCAN_BATCH
    padded = jnp.concatenate([grid, jnp.full((pad,), grid[-1], grid.dtype)])
    F = jax.lax.map(lambda p: _residual(p, model), padded, batch_size=SCAN_BATCH)
    return F[:n]


def equilibria_fixed(
    model: TowModel,
    *,
    n_grid: int = 2001,
    max_roots: int = 8,
    psi_range: float = math.pi / 2,
    max_steps: int = 128,
    throw: bool = True,
) -> Equilibria:
    """All equilibria in |ψ| <= psi_range, as a fixed-size, jittable, vmappable set.

    The heading residual is scanned on ``n_grid`` points (odd, so ψ = 0 is a grid point);
    each sign change is refined. At most ``max_roots`` roots are kept (``found`` marks
    them; padding slots repeat the first root so that Jacobians stay finite);
    ``n_roots`` counts the sign changes seen (more than ``max_roots`` means roots were
    dropped). With ``throw=True`` invalid parameters raise
    at run time (also under jit/vmap) with a message naming them (see `jaxtow.vector_field`);
    sweeps, which validate their grids beforehand, pass ``throw=False``, as may a user under
    a plain `jax.jit` who reads `jaxtow.parameter_status` instead.
    """
    if n_grid < 3 or n_grid % 2 == 0:
        raise ValueError(f"parameter 'n_grid' must be an odd integer >= 3, got {n_grid}")
    if max_roots < 1:
        raise ValueError(f"parameter 'max_roots' must be >= 1, got {max_roots}")
    if not 0 < psi_range <= math.pi:
        raise ValueError(f"parameter 'psi_range' must lie in (0, pi], got {psi_range}")
    grid = jnp.linspace(-psi_range, psi_range, n_grid)
    # batches of headings (not one vmap over all): an expensive force model (an irregular-sea
    # drift integral, say) would otherwise materialise n_grid copies of its intermediates
    F = _scan_residual(grid, model)
    idx, found, exact, count = brackets(F, max_roots)
    steps, enough = bisection_steps(2 * psi_range / (n_grid - 1), grid.dtype, max_steps)
    psi, ok = jax.vmap(_refine, in_axes=(0, 0, 0, 0, 0, None, None, None))(
        grid[idx], grid[idx + 1], F[idx], F[idx + 1], exact, model, steps, enough
    )
    eqs = _finish(psi, found, ok & (count > 0), model, count)
    return guard(eqs, model.checks()) if throw else eqs


def equilibria(
    model: TowModel, *, n_grid: int = 2001, max_roots: int = 8, psi_range: float = math.pi / 2
) -> Equilibria:
    """All equilibria of `model` (eager): only the found roots, ordered by ψ.

    Parameters are checked (a clear error names any invalid one). See `equilibria_fixed`
    for the jittable form used inside sweeps.
    """
    return padded_equilibria(
        model, n_grid=n_grid, max_roots=max_roots, psi_range=psi_range
    ).compact()


def padded_equilibria(
    model: TowModel, *, n_grid: int = 2001, max_roots: int = 8, psi_range: float = math.pi / 2
) -> Equilibria:
    """`equilibria` before its padding slots are dropped: ``max_roots`` slots, ``found``
    marking the roots, so that a program run on the states downstream (their stability,
    say) has one shape whatever the number of equilibria, and is traced and compiled once."""
    check_now(model)  # a clear error here rather than from inside the compiled call
    # the compiled call checks only what check_now could not see (a traced model, when
    # called under a user's jit): a program with run-time checks holds host callbacks,
    # which JAX's persistent compilation cache never stores
    options = dict(n_grid=n_grid, max_roots=max_roots, psi_range=psi_range)
    throw = holds_tracers(model)
    run = functools.partial(_equilibria_jit, **options, throw=throw)
    eqs = cached_call(f"equilibria{sorted(options.items())}{throw}", run, model)
    if int(eqs.n_roots) > max_roots:  # refuse a silently truncated result
        raise ValueError(
            f"{int(eqs.n_roots)} equilibria found but max_roots={max_roots}; raise max_roots"
        )
    return eqs


_equilibria_jit = jax.jit(
    equilibria_fixed,
    static_argnames=("n_grid", "max_roots", "psi_range", "max_steps", "throw"),
)


def analytic_equilibria(model: TowModel, *, throw: bool = True) -> Equilibria:
    """Closed-form equilibria, thesis eqs 6.7-6.13 (docs/model.md section 3).

    Valid for the calm-water model (no external force) with an elastic towline. Three
    slots ordered by ψ: the ψ < 0 side, straight behind, the ψ > 0 side; the side slots are
    ``found`` only where v'_eq² = (N_v − Y_v x_p)/(Y_vvv x_p − N_vvv) lies in (0, 1).
    """
    if not isinstance(model.external, NoExternalForce):
        raise ValueError("analytic_equilibria needs a model without external forces")
    if not isinstance(model.towline, Towline):
        raise ValueError("analytic_equilibria needs the elastic Towline (eq. 2.11)")
    if is_concrete(model.towline.yp) and float(model.towline.yp) != 0.0:
        raise ValueError("analytic_equilibria needs a centred towline (yp = 0); use equilibria")
    eqs = _analytic_equilibria(model)
    return guard(eqs, model.checks()) if throw else eqs


@host_program()
def _analytic_equilibria(model: TowModel) -> Equilibria:
    line = model.towline
    assert isinstance(line, Towline)  # checked by `analytic_equilibria`
    ves, xp, EA, l0 = model.vessel, line.xp, line.EA, line.l0
    rad = (ves.Nv - ves.Yv * xp) / (ves.Yvvv * xp - ves.Nvvv)  # eq. 6.8
    side = (rad > 0) & (rad < 1)
    vs = jnp.sqrt(jnp.where(side, rad, 0.25))
    v = jnp.stack([vs, 0.0 * vs, -vs])  # v = +sqrt gives ψ < 0
    psi = jnp.arcsin(-v)  # eq. 6.9
    u = jnp.cos(psi)  # eq. 6.10
    num = ves.R0 * u**2 - ves.Xvv * v**2
    gamma = jnp.arctan((ves.Yvvv * v**3 + ves.Yv * v) / num) - psi  # eq. 6.11
    T = num / jnp.cos(gamma + psi)  # eq. 6.12
    length = (T / EA + 1.0) * l0  # eq. 6.13
    state = jnp.stack([u, v, 0 * u, length, gamma, psi], axis=-1)
    steady = _steady(model)  # the states have r = 0
    residual = jax.vmap(lambda y: jnp.max(jnp.abs(vector_field(0.0, y, steady, throw=False))))(
        state
    )
    found = jnp.stack([side, jnp.asarray(True), side])
    branch = jnp.array([-1, 0, 1], dtype=jnp.int32)
    return Equilibria(
        state=state,
        psi=psi,
        gamma=gamma,
        tension=T,
        length=length,
        found=found,
        converged=jnp.ones(3, bool),
        taut=T > SLACK_TENSION,
        behind_tug=jnp.cos(gamma) > 0,
        in_range=jnp.abs(psi) <= model.psi_max,
        branch=branch,
        residual=residual,
        n_roots=jnp.sum(found).astype(jnp.int32),
    )
