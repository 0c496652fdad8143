"""One sea state's resistance summary: what ``jaxtow resistance`` tabulates and ``jaxtow
study`` reports (required bollard pull at zero speed, the worst Tp, the operating speed and
transit time; SI)."""

from __future__ import annotations


def evaluate(tow, tug, sea, heading, route_length, *, n_tp: int = 41) -> dict:
    """Everything the table prints for one sea state (SI)."""
    import jax
    import jax.numpy as jnp

    from .. import resistance as R
    from ..waves import physical_tp_range

    req = R.required_pull(tow, sea, heading=heading, tug=tug)
    out = dict(
        sea_state=sea.name,
        hs=float(sea.hs),
        tp=float(sea.tp),
        wind_speed=float(sea.wind_speed),
        current_speed=float(sea.current_speed),
        hold_resistance=dict(zip(R.COMPONENTS, map(float, req.budget.resistance))),
        hold_towing_force=float(req.towing_force),
        required_bollard_pull=float(req.bollard_pull),
    )
    if float(sea.hs) > 0:
        lo, hi = (float(t) for t in physical_tp_range(float(sea.hs)))
        tps = jnp.linspace(lo, hi, n_tp)
        bp = jax.vmap(
            lambda t: R.required_pull(tow, eqx_tp(sea, t), heading=heading, tug=tug).bollard_pull
        )(tps)
        k = int(jnp.argmax(bp))
        out.update(
            physical_tp_range=[lo, hi],
            worst_tp=float(tps[k]),
            worst_required_bollard_pull=float(bp[k]),
        )
    p = R.operating_speed(tow, tug, sea, heading=heading, throw=False)
    msg = R.status_message(p, tug, tow)
    names = ("successful", "cannot_hold", "no_crossing", "froude_too_high")
    status = next(n for n in names if bool(p.result == getattr(R.RESULTS, n)))
    out.update(status=status, message=msg)
    if status in ("successful", "froude_too_high"):
        out.update(
            operating_speed=float(p.speed),
            froude=float(p.froude),
            pull=float(p.pull),
            operating_resistance=dict(zip(R.COMPONENTS, map(float, p.budget.resistance))),
        )
        if route_length:
            out["transit_time_h"] = float(p.transit_time(route_length)) / 3600.0
    return out


def eqx_tp(sea, tp):
    import equinox as eqx

    return eqx.tree_at(lambda s: s.tp, sea, tp)
