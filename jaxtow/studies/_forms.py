"""How much the forward-speed form of the drift matters (docs/model.md section 8): the three
forms of `jaxtow.drift.sailing_drift` compared on one QTF, in the numbers a tow is planned
with."""

from __future__ import annotations

import jax
import jax.numpy as jnp
import numpy as np

from ..drift._sailing import FORMS, irregular_sailing_drift, sailing_drift
from ..resistance import operating_speed
from ..waves import DEFAULT_OMEGA, jonswap


def sailing_forms(
    qtf,
    *,
    speed: float = 2.0,
    hs: float = 2.4,
    tp: float = 7.0,
    gamma: float = 3.3,
    resistance=None,
    tug=None,
    sea=None,
    omega_peak_grid=None,
    omega=None,
) -> dict:
    """For each form of `jaxtow.drift.FORMS`, in head seas (β = 0) at ``speed`` [m/s]:

    * ``peak_omega`` [rad/s] and ``peak_fx`` [N/m²] of the surge QTF against the absolute
      wave frequency: its motion peak, the lowest-frequency local maximum of |F_x| that
      reaches 20 % of the largest (on ``omega_peak_grid``, default 0.05-2.5 rad/s by
      0.0025), with ``peak_shift`` from the zero-speed peak; None where |F_x| has no
      interior maximum (a short-wave QTF that only grows with ω);
    * ``mean_fx`` [N]: the mean surge drift in a JONSWAP sea (``hs``, ``tp``, ``gamma``),
      integrated on ``omega`` (default `jaxtow.waves.DEFAULT_OMEGA`);
    * ``operating_speed`` [m/s] (with ``resistance``, a `jaxtow.resistance.TowResistance`
      factory ``form -> TowResistance``, a ``tug`` and a ``sea`` state), or None.

    Returns {"zero_speed": {...}, form: {...}} of plain floats."""
    w = np.arange(0.05, 2.5, 0.0025) if omega_peak_grid is None else np.asarray(omega_peak_grid)
    wj = jnp.asarray(w)

    def peak(fx):
        a = np.abs(fx)
        k = np.flatnonzero((a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:]) & (a[1:-1] >= 0.2 * a.max()))
        if k.size == 0:
            return None, None
        return float(w[k[0] + 1]), float(fx[k[0] + 1])

    fx0 = np.asarray(jax.vmap(lambda x: qtf(x, 0.0)[0])(wj))
    w0, p0 = peak(fx0)
    wi = DEFAULT_OMEGA if omega is None else jnp.asarray(omega, float)
    S = jonswap(wi, hs=hs, tp=tp, gamma=gamma)
    out = {
        "zero_speed": dict(
            peak_omega=w0,
            peak_fx=p0,
            mean_fx=float(irregular_sailing_drift(qtf, wi, S, 0.0, 0.0)[0]),
        ),
        "inputs": dict(speed=speed, hs=hs, tp=tp, gamma=gamma),
    }
    for form in FORMS:
        fx = np.asarray(
            jax.vmap(lambda x, f=form: sailing_drift(qtf, x, 0.0, speed, form=f)[0])(wj)
        )
        wp, pp = peak(fx)
        row = dict(
            peak_omega=wp,
            peak_fx=pp,
            peak_shift=None if wp is None or w0 is None else wp - w0,
            mean_fx=float(irregular_sailing_drift(qtf, wi, S, 0.0, speed, form=form)[0]),
            operating_speed=None,
        )
        if resistance is not None:
            p = operating_speed(resistance(form), tug, sea, throw=False)
            row["operating_speed"] = float(p.speed) if bool(p.valid) else None
        out[form] = row
    return out


def forms_table(results: dict) -> str:
    """A Markdown table of `sailing_forms` results {hull label: result}."""
    lines = [
        "| hull | form | surge QTF peak ω [rad/s] (shift) | peak F_x [kN/m²] | "
        "mean F_x at Tp [kN] | operating speed [m/s] |",
        "|---|---|---|---|---|---|",
    ]

    def num(x, fmt, scale=1.0):
        return "none" if x is None else format(x / scale, fmt)

    for label, r in results.items():
        z = r["zero_speed"]
        lines.append(
            f"| {label} | U = 0 | {num(z['peak_omega'], '.3f')} | "
            f"{num(z['peak_fx'], '.2f', 1e3)} | {z['mean_fx'] / 1e3:.1f} | |"
        )
        for form in FORMS:
            f = r[form]
            op = "n/a" if f["operating_speed"] is None else f"{f['operating_speed']:.3f}"
            lines.append(
                f"| {label} | {form} | {num(f['peak_omega'], '.3f')} "
                f"({num(f['peak_shift'], '+.3f')}) | {num(f['peak_fx'], '.2f', 1e3)} | "
                f"{f['mean_fx'] / 1e3:.1f} | {op} |"
            )
    return "\n".join(lines)
