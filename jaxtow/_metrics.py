"""Post-processing of time-domain runs: earth-frame trajectory, force histories, fishtailing
and damping metrics (thesis sections 6.1, 7.3; eqs 2.15-2.18, 7.4, 7.5), as typed results
(`Trajectory`, `FishtailMetrics`, `DampingRatio`).

These run on the host, in NumPy, over the saved series after the solve (the solve itself
stays in JAX): they find extrema and crossings of one record, which no kernel needs to
differentiate or batch.
"""

from __future__ import annotations

import dataclasses
import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np

from ._dynamics import ForceBreakdown, TowModel, force_breakdown, sway_offset
from ._equilibrium import equilibria as find_equilibria
from ._program_cache import persistent
from ._rules import check_now


@dataclasses.dataclass(frozen=True)
class Trajectory:
    """Earth-frame positions (in L) along a run at the times ``t`` (by L/U): the tug at
    (``tug_x``, ``tug_y``), the hawser point, the CoG, the sway offset y' and the heading
    ``psi`` [rad]."""

    t: np.ndarray
    tug_x: np.ndarray
    tug_y: np.ndarray
    hawser_x: np.ndarray
    hawser_y: np.ndarray
    cog_x: np.ndarray
    cog_y: np.ndarray
    sway_offset: np.ndarray
    psi: np.ndarray


@dataclasses.dataclass(frozen=True)
class DampingRatio:
    """`damping_ratio`'s answer: ``zeta`` (None where no oscillation was seen), the
    ``method`` (log_decrement | overshoot | no_oscillation | not_converged), the number of
    peaks used, and the log decrement δ or the overshoot where that method was used."""

    zeta: float | None
    method: str
    n_peaks: int
    delta: float | None = None
    overshoot: float | None = None


@dataclasses.dataclass(frozen=True)
class FishtailMetrics:
    """`fishtail_metrics`'s answer: the ``outcome`` (converged, limit_cycle, growing,
    undetermined), ``converged``, the ``path_width`` (peak-to-peak sway offset y', by L),
    the ``yaw_range`` (min, max ψ) [deg], the ``slewing_period`` (by L/U; None without a
    cycle), the ``equilibrium`` it converged to (an index, else None), the heading's
    ``damping``, and whether the run ``ended_early``, where (``t_end``), and the share of
    samples with a ``slack`` line."""

    outcome: str
    converged: bool
    path_width: float | None
    yaw_range: tuple[float, float] | None
    slewing_period: float | None
    equilibrium: int | None
    damping: DampingRatio
    ended_early: bool
    t_end: float
    slack: float


def trajectory(model: TowModel, sim) -> Trajectory:
    """Earth-frame positions (in L) along a run: the tug at (t', 0), the hawser point
    H = tug + (−l cos γ, l sin γ), the CoG = H − x_p (cos ψ, sin ψ), and the sway offset
    y' = l sin γ − x_p sin ψ (eqs 2.15-2.18). Only valid (finite) samples are returned."""
    ok = np.asarray(sim.valid)
    t = np.asarray(sim.ts)[ok]
    y = np.asarray(sim.ys)[ok]
    xp, yp = float(model.towline.xp), float(model.towline.yp)
    l, g, psi = y[:, 3], y[:, 4], y[:, 5]
    hx, hy = t - l * np.cos(g), l * np.sin(g)
    return Trajectory(
        t=t,
        tug_x=t,
        tug_y=np.zeros_like(t),
        hawser_x=hx,
        hawser_y=hy,
        cog_x=hx - xp * np.cos(psi) + yp * np.sin(psi),
        cog_y=hy - xp * np.sin(psi) - yp * np.cos(psi),
        sway_offset=np.asarray(sway_offset(y, xp, yp)),
        psi=psi,
    )


@dataclasses.dataclass(frozen=True)
class ForceHistory:
    """`force_history`'s answer: the times ``t`` (by L/U) and the `jaxtow.ForceBreakdown`
    ``forces`` at each (every field with a leading time axis: (n, 3), the tension (n,))."""

    t: np.ndarray
    forces: ForceBreakdown


def force_history(model: TowModel, sim) -> ForceHistory:
    """The force breakdown (manoeuvring, towline, coupling, external; each (n, 3)) and the
    tension along a run (thesis fig. 7.6)."""
    ok = np.asarray(sim.valid)
    check_now(model)  # checked here, then one compiled program over the whole save grid
    fb = _force_history(model, jnp.asarray(sim.ts), jnp.asarray(sim.ys))
    return ForceHistory(
        t=np.asarray(sim.ts)[ok], forces=jax.tree_util.tree_map(lambda a: np.asarray(a)[ok], fb)
    )


@persistent
@eqx.filter_jit
def _force_history(model, ts, ys):
    """The force breakdown at every saved state (the rows after a failed run, inf, are
    dropped by the caller), without run-time checks: one shape per save grid."""
    return jax.vmap(lambda t, y: force_breakdown(t, y, model, throw=False))(ts, ys)


def _extrema(t, x):
    """Local extrema of a sampled series, refined by a parabola through three samples.
    Returns (times, values, kinds) with kind +1 for maxima and −1 for minima."""
    t, x = np.asarray(t, float), np.asarray(x, float)
    d = np.diff(x)
    idx = np.flatnonzero((np.sign(d[:-1]) != np.sign(d[1:])) & (d[:-1] != 0)) + 1
    out_t, out_x, kind = [], [], []
    for i in idx:
        x0, x1, x2 = x[i - 1], x[i], x[i + 1]
        den = x0 - 2 * x1 + x2
        h = t[i + 1] - t[i]
        off = 0.5 * (x0 - x2) / den if den != 0 else 0.0
        out_t.append(t[i] + off * h)
        out_x.append(x1 - 0.25 * (x0 - x2) * off)
        kind.append(1 if den < 0 else -1)
    return np.array(out_t), np.array(out_x), np.array(kind)


def damping_ratio(t, x, x_final: float | None = None) -> DampingRatio:
    """Damping ratio of a decaying oscillation about ``x_final`` (default: last sample).

    Chosen automatically (thesis section 7.3.2):
    - logarithmic decrement (eq. 7.4) when at least two extrema of the same sign exist:
      δ = (1/n) ln(x(1)/x(1+n)), ζ = δ/√(4π² + δ²);
    - overshoot (eq. 7.5) when only the first overshoot exists: PO = |first overshoot| /
      |initial deviation|, ζ = √(ln²PO/(π² + ln²PO));
    - otherwise no oscillation was seen (ζ ≥ 1 or too short a record): ``zeta`` is None.
    """
    t, x = np.asarray(t, float), np.asarray(x, float)
    ref = float(x[-1]) if x_final is None else float(x_final)
    e = x - ref
    _, ev, kind = _extrema(t, e)
    # keep extrema on the correct side of the reference (true oscillation peaks)
    keep = (kind > 0) & (ev > 0) | (kind < 0) & (ev < 0)
    ev, kind = ev[keep], kind[keep]
    scale = np.max(np.abs(e)) if e.size else 0.0
    sig = np.abs(ev) > 1e-9 * max(scale, 1e-300)
    ev, kind = ev[sig], kind[sig]
    same = [ev[kind == k] for k in (1, -1)]
    best = max(same, key=len)
    if len(best) >= 2:
        n = len(best) - 1
        delta = math.log(abs(best[0]) / abs(best[-1])) / n
        return DampingRatio(
            zeta=delta / math.sqrt(4 * math.pi**2 + delta**2),
            method="log_decrement",
            delta=delta,
            n_peaks=len(best),
        )
    if len(ev) >= 1 and abs(e[0]) > 0 and np.sign(ev[0]) != np.sign(e[0]):
        lnpo = math.log(abs(ev[0]) / abs(e[0]))
        return DampingRatio(
            zeta=math.sqrt(lnpo**2 / (math.pi**2 + lnpo**2)),
            method="overshoot",
            overshoot=abs(ev[0]) / abs(e[0]),
            n_peaks=1,
        )
    return DampingRatio(zeta=None, method="no_oscillation", n_peaks=int(len(ev)))


def fishtail_metrics(
    model: TowModel, sim, *, transient: float = 0.5, tol: float = 1e-3, equilibria=None
) -> FishtailMetrics:
    """Behaviour of a run after the transient (the last ``1 − transient`` of the record), as
    `FishtailMetrics`: the outcome, path width, yaw range and slewing period, the
    equilibrium it converged to (an index into ``equilibria``), the heading's damping ratio
    (`damping_ratio`), and the ``slack`` share (zero tension, l' < l0' for the elastic
    laws; a line with weight never goes slack)."""

    tr = trajectory(model, sim)
    t, yoff, psi = tr.t, tr.sway_offset, tr.psi
    ok = np.asarray(sim.valid)
    ys = np.asarray(sim.ys)[ok]
    run = dict(
        ended_early=not bool(sim.success),
        t_end=float(t[-1]) if t.size else float(sim.ts[0]),
        slack=float(np.mean(np.asarray(jax.vmap(model.towline.tension)(ys[:, 3])) <= 0.0))
        if ys.size
        else 0.0,
    )
    if t.size < 8:
        return FishtailMetrics(
            **run,
            outcome="undetermined",
            converged=False,
            path_width=None,
            yaw_range=None,
            slewing_period=None,
            equilibrium=None,
            damping=DampingRatio(zeta=None, method="no_oscillation", n_peaks=0),
        )
    tail = t >= t[0] + transient * (t[-1] - t[0])
    yt, pt = yoff[tail], psi[tail]
    width = float(np.ptp(yt))
    yaw = (float(np.degrees(pt.min())), float(np.degrees(pt.max())))
    n = yt.size
    q1, q2 = np.ptp(yt[: n // 2]), np.ptp(yt[n // 2 :])
    converged = width < tol and np.ptp(pt) < tol
    if converged:
        outcome = "converged"
    elif q2 > 1.5 * q1:
        outcome = "growing"
    elif q2 > 0.8 * q1:
        outcome = "limit_cycle"
    else:
        outcome = "undetermined"  # still decaying: run longer
    period = None
    e = yt - yt.mean()
    up = np.flatnonzero((e[:-1] < 0) & (e[1:] >= 0))
    if outcome == "limit_cycle" and up.size >= 2:
        tt = t[tail]
        cross = tt[up] - e[up] * (tt[up + 1] - tt[up]) / (e[up + 1] - e[up])
        period = float(np.mean(np.diff(cross)))
    eq_index = None
    if converged:
        eqs = equilibria if equilibria is not None else find_equilibria(model)
        eq_index = int(np.argmin(np.abs(np.asarray(eqs.psi) - psi[-1])))
    return FishtailMetrics(
        **run,
        outcome=outcome,
        converged=bool(converged),
        path_width=width,
        yaw_range=yaw,
        slewing_period=period,
        equilibrium=eq_index,
        damping=damping_ratio(t, psi)
        if converged
        else DampingRatio(zeta=None, method="not_converged", n_peaks=0),
    )
