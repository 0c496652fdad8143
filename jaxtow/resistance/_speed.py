"""Operating (transit) speed of a tow: where the tug's pull meets the resistance (thesis fig. 2.1, section 7.2)."""

from __future__ import annotations

import math

import equinox as eqx
import jax
import jax.numpy as jnp

from .._program_cache import persistent
from .._roots import bisect, brackets
from .._rules import check_positive, guard, is_concrete
from .._units import TONNE_FORCE, G, froude_number
from ..drift import FROUDE_MAX
from ._budget import Budget, TowResistance, resistance
from ._sea import SeaState
from ._tug import Tug


class RESULTS(eqx.Enumeration):
    """Result codes of `operating_speed` (``OperatingPoint.result``)."""

    successful = ""
    cannot_hold = "operating_speed: the tug cannot hold the tow at zero speed (call with throw=False to get the result)"
    no_crossing = "operating_speed: no crossing of pull and resistance below the tug's top speed (call with throw=False)"
    froude_too_high = (
        "operating_speed: Froude number at the operating speed >= 0.15 (call with throw=False)"
    )


class OperatingPoint(eqx.Module):
    """`operating_speed` result: ``speed`` [m/s] where available pull = total resistance,
    ``pull`` [N] there, the ``budget`` there, ``froude``, ``result`` (a `RESULTS` item;
    ``RESULTS.successful`` when the point is valid), and ``margin`` = pull − resistance at
    zero speed [N] (the holding margin)."""

    speed: jnp.ndarray
    pull: jnp.ndarray
    budget: Budget
    froude: jnp.ndarray
    result: RESULTS
    margin: jnp.ndarray

    @property
    def valid(self):
        return self.result == RESULTS.successful

    def transit_time(self, route_length):
        """Time [s] to sail ``route_length`` [m] at the operating speed."""
        return jnp.asarray(route_length, float) / self.speed


def _excess(speed, args):
    tow, tug, sea, heading = args
    return (
        tug.pull(speed) - resistance(tow, sea, speed, heading=heading, tug=tug, throw=False).total
    )


@persistent
@eqx.filter_jit
def _operating_point(tow, tug, sea, heading, n_scan, rtol):
    args = (tow, tug, sea, heading)
    umax = jax.lax.stop_gradient(tug.max_speed)
    grid = jnp.linspace(0.0, 1.0, n_scan + 1) * umax
    g = jax.vmap(lambda s: _excess(s, args))(grid)
    i, found, exact, _ = brackets(g, 1)  # the first crossing (scan-then-refine, `jaxtow._roots`)
    i, found, exact = i[0], found[0], exact[0]
    hold = g[0] >= 0.0
    crosses = found & hold
    lo, hi = jax.lax.stop_gradient(grid[i]), jax.lax.stop_gradient(grid[i + 1])
    # a valid bracket for the solver in every case (the result code says when it is not the answer)
    lo = jnp.where(crosses, lo, 0.0)
    hi = jnp.where(crosses, hi, umax)
    fn = lambda s, a: jnp.where(crosses, _excess(s, a), s - 0.5 * (lo + hi))
    root, _ = bisect(fn, lo, hi, args, rtol=rtol, atol=rtol * umax, max_steps=256)
    root = jnp.where(exact, lo, root)
    speed = jnp.where(hold, jnp.where(crosses, root, umax), 0.0)
    fn_op = froude_number(speed, tow.length)
    result = RESULTS.where(
        ~hold,
        RESULTS.cannot_hold,
        RESULTS.where(
            ~crosses,
            RESULTS.no_crossing,
            RESULTS.where(fn_op >= FROUDE_MAX, RESULTS.froude_too_high, RESULTS.successful),
        ),
    )
    b = resistance(tow, sea, speed, heading=heading, tug=tug, throw=False)
    return OperatingPoint(
        speed=speed, pull=tug.pull(speed), budget=b, froude=fn_op, result=result, margin=g[0]
    )


def status_message(p: OperatingPoint, tug: Tug, tow: TowResistance) -> str | None:
    """The eager error message of a concrete `OperatingPoint` (None when it is valid): which
    limit was hit and by how much."""
    if bool(p.result == RESULTS.successful):
        return None
    if bool(p.result == RESULTS.cannot_hold):
        need = float(p.pull) - float(p.margin)
        return (
            f"no intersection of the pull and resistance curves: at zero speed the available pull "
            f"{float(p.pull) / 1e3:.1f} kN is below the resistance {need / 1e3:.1f} kN, so the tug "
            f"cannot hold the tow in this sea state (a tug of at least "
            f"{need / float(tug.efficiency) / TONNE_FORCE:.1f} t bollard pull is needed: tow file "
            f"[tug] bollard_pull_t, Tug.bollard_pull = {need / float(tug.efficiency) / 1e3:.1f} "
            "kN; see required_pull)"
        )
    if bool(p.result == RESULTS.no_crossing):
        return (
            f"no intersection of the pull and resistance curves below the tug's top speed "
            f"{float(tug.max_speed):.3g} m/s: the resistance stays below the pull (a following "
            f"environment?); check 'free_speed' and the sea state"
        )
    umax = FROUDE_MAX * math.sqrt(G * float(tow.length))
    return (
        f"operating speed {float(p.speed):.3f} m/s gives Froude number Fn = {float(p.froude):.3f} >= "
        f"{FROUDE_MAX}: outside the validity of the slow-speed manoeuvring and wave-drift models "
        f"(U < {umax:.2f} m/s for L = {float(tow.length):g} m); pass throw=False to get the "
        f"result flagged instead"
    )


def operating_speed(
    tow: TowResistance,
    tug: Tug,
    sea: SeaState,
    *,
    heading=0.0,
    throw: bool = True,
    n_scan: int = 64,
    rtol: float = 1e-12,
) -> OperatingPoint:
    """Operating (transit) speed of the tow: the lowest speed U in [0, U_free] where the tug's
    available pull meets the total resistance, η P(U) = R_tow(U) + R_tug(U) (thesis fig. 2.1,
    section 7.2), found by scanning ``n_scan`` speeds for the first crossing and refining it
    by bisection to ``rtol`` (`jaxtow._roots`). Use ``.transit_time(route_length)`` for the
    transit time.

    Differentiable with respect to every input (implicit function theorem through the root).
    Outside validity — the tug cannot hold the tow at zero speed, no crossing below the tug's
    top speed, or Fn ≥ 0.15 at the operating speed — ``throw=True`` raises an error that
    says which and by how much (the `RESULTS` message under jit/grad); with ``throw=False``
    the result carries ``result`` (a `RESULTS` item) for maps over many sea states.
    """
    if is_concrete(tug.bollard_pull):
        check_positive("bollard_pull", tug.bollard_pull)
    if isinstance(n_scan, bool) or int(n_scan) != n_scan or int(n_scan) < 2:
        raise ValueError(
            f"parameter 'n_scan' must be a whole number of speeds >= 2, got {n_scan!r}"
        )
    p = _operating_point(
        tow, tug, sea.unnamed(), jnp.asarray(heading, float), int(n_scan), float(rtol)
    )
    if not throw:
        return p
    if not p.result.is_traced():
        msg = status_message(p, tug, tow)
        if msg is not None:
            raise ValueError(msg)
        return p
    p = guard(p, tug.checks() + sea.checks())
    return p.result.error_if(p, p.result != RESULTS.successful)
