"""The waterline drift methods compared (thesis chapters 4-5, ``jaxtow drift``): regular
head and oblique waves at rest (figs 4.3, 4.4), JONSWAP seas over Tp at rest (figs 4.5, 4.6)
and at forward speed in surge and sway (figs 5.6, 5.7), with the relative mean square error
of each method against a base method per zone (thesis eq. 4.1)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import jax
import jax.numpy as jnp
import numpy as np

from .._units import RHO_SEA, G
from ..drift import (
    WATERLINE_METHODS,
    Waterline,
    compare_methods,
    irregular_drift,
    relative_mse,
    relative_mse_by_zone,
)
from ..io import drift_methods_dataset
from ..waves import physical_tp_range

#: The methods that give a sway force (the oblique-sea comparisons).
SWAY_METHODS = ("faltinsen", "liu", "fujii_takahashi", "kuroda", "kashiwagi")
#: Faltinsen's speed factors as published (2, 2), and as the thesis printed them (4, 2).
OPTIONS = {"faltinsen": {"speed_factor": (2.0, 2.0)}}
THESIS_FALTINSEN = {"speed_factor": (4.0, 2.0)}
#: The Tp grid of the irregular comparison [s].
TP = np.linspace(4.0, 16.0, 61)


@dataclass(frozen=True)
class DriftMethodsStudy:
    """What `drift_methods_study` computed: the regular-wave datasets at rest (``head``,
    ``oblique``), the irregular-sea mean drift per method over `TP` at rest
    (``irregular``: name → (head-sea, oblique) arrays (Tp, 3)), the sailing datasets
    (``sailing``: "surge"/"sway" → method → one dataset a speed), and ``summary``."""

    waterline: Waterline
    base: str
    hs: float
    sway_heading: float  # rad
    speeds: tuple
    head: object
    oblique: object
    irregular: dict
    tp_range: tuple
    sailing: dict
    summary: dict

    @property
    def normalisation(self) -> tuple[float, float]:
        """ρgBHs²/8 and ρgLHs²/8, the scales of the irregular-sea figures [N]."""
        wl, hs = self.waterline, self.hs
        return RHO_SEA * G * float(wl.breadth) * hs**2 / 8, RHO_SEA * G * float(
            wl.length
        ) * hs**2 / 8


def zone_mse(ds, component: str, base: str) -> dict:
    """Relative MSE of every method's ``component`` against ``base``, per zone."""
    b = ds[component].sel({"method": base}).values
    return {
        m: relative_mse_by_zone(
            ds[component].sel({"method": m}).values, b, ds.omega.values, float(ds.attrs["length"])
        )
        for m in ds.method.values
        if m != base
    }


def _irregular(wl, hs: float, b_sway: float) -> dict:
    out = {}
    tp = jnp.asarray(TP)
    for name in WATERLINE_METHODS:
        f = jax.jit(
            jax.vmap(
                lambda t, b, n=name: irregular_drift(n, wl, hs, t, b, **OPTIONS.get(n, {})),
                in_axes=(0, None),
            )
        )
        out[name] = (np.asarray(f(tp, 0.0)), np.asarray(f(tp, b_sway)))
    return out


def _sailing(wl, omega, b_sway: float, speeds) -> dict:
    """Surge speeds in head seas, sway speeds at the oblique heading (figs 5.6, 5.7)."""
    opts = dict(OPTIONS, faltinsen_thesis=THESIS_FALTINSEN)
    out = {}
    for tag, beta in (("surge", 0.0), ("sway", b_sway)):
        out[tag] = {}
        for name in ["faltinsen", "faltinsen_thesis", *SWAY_METHODS[1:]]:
            fn = WATERLINE_METHODS["faltinsen" if name == "faltinsen_thesis" else name]
            dss = []
            for s in speeds:
                uv = (s, 0.0) if tag == "surge" else (0.0, s)
                e = fn(wl, omega, beta, *uv, **opts.get(name, {}))
                dss.append(
                    drift_methods_dataset(
                        {name: e}, omega, beta=beta, u=uv[0], v=uv[1], waterline=wl
                    )
                )
            out[tag][name] = dss
    return out


def _irregular_mse(irr: dict, base: str, phys) -> dict:
    b = irr[base]
    return {
        m: dict(
            surge=relative_mse(v[0][:, 0], b[0][:, 0], phys),
            sway=relative_mse(v[1][:, 1], b[1][:, 1], phys) if m in SWAY_METHODS else None,
        )
        for m, v in irr.items()
        if m != base
    }


def drift_methods_study(
    wl: Waterline,
    *,
    base: str = "faltinsen",
    omega_max: float = 2.1,
    n_omega: int = 191,
    sway_heading_deg: float = -15.0,
    hs: float = 5.0,
    speeds=(0.0, 1.0, 2.0, 3.0),
) -> DriftMethodsStudy:
    """Every waterline method of `jaxtow.drift.WATERLINE_METHODS` on ``wl``: regular waves from 0.2
    rad/s to ``omega_max`` at rest, head and oblique (``sway_heading_deg``); JONSWAP seas of
    ``hs`` over `TP`; forward ``speeds`` [m/s]. Errors are relative to ``base``."""
    if base not in WATERLINE_METHODS:
        raise ValueError(
            f"parameter 'base': {base!r} is not a drift method; choose from {sorted(WATERLINE_METHODS)}"
        )
    omega = jnp.linspace(0.2, omega_max, n_omega)
    b_sway = math.radians(sway_heading_deg)
    head = drift_methods_dataset(
        compare_methods(wl, omega, 0.0, options=OPTIONS), omega, beta=0.0, waterline=wl, base=base
    )
    est_s = compare_methods(wl, omega, b_sway, methods=SWAY_METHODS, options=OPTIONS)
    oblique = drift_methods_dataset(est_s, omega, beta=b_sway, waterline=wl, base=base)
    irr = _irregular(wl, hs, b_sway)
    tp_lo, tp_hi = (float(t) for t in physical_tp_range(hs))
    phys = (TP >= tp_lo) & (TP <= tp_hi)
    summary = dict(
        waterline=wl.name,
        length=float(wl.length),
        breadth=float(wl.breadth),
        draft=float(wl.draft),
        block_coefficient=float(wl.block_coefficient),
        base=base,
        assumptions="Barge 2 rake and drafts: jaxtow.presets.ASSUMPTIONS; garbled formulas: "
        "see jaxtow.drift.WATERLINE_METHODS docstrings",
        regular_relative_mse_by_zone=dict(
            surge=zone_mse(head, "fx", base), sway=zone_mse(oblique, "fy", base)
        ),
        irregular_relative_mse_physical_tp=_irregular_mse(irr, base, phys),
        physical_tp_range=[tp_lo, tp_hi],
    )
    return DriftMethodsStudy(
        waterline=wl,
        base=base,
        hs=hs,
        sway_heading=b_sway,
        speeds=tuple(speeds),
        head=head,
        oblique=oblique,
        irregular=irr,
        tp_range=(tp_lo, tp_hi),
        sailing=_sailing(wl, omega, b_sway, speeds),
        summary=summary,
    )
