"""Figures of the drift-method comparison (thesis figs 4.3-4.6, 5.6-5.7)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from .._units import RHO_SEA, G

ZONE_COLOURS = ("0.95", "0.88", "0.80")
NORMALISATION = {
    "fx": ("breadth", 1, "Fx / (rho g zeta_a^2 B)"),
    "fy": ("length", 1, "Fy / (rho g zeta_a^2 L)"),
    "nz": ("length", 2, "Nz / (rho g zeta_a^2 L^2)"),
}


def _norm(ds, component):
    dim, power, label = NORMALISATION[component]
    return RHO_SEA * G * float(ds.attrs[dim]) * (
        float(ds.attrs["length"]) ** (power - 1) if power > 1 else 1.0
    ), label


def shade_zones(ax, x, zone, names=("motion", "transition", "reflection")):
    """Shade the motion / transition / reflection zones along x."""
    for z in range(3):
        sel = np.asarray(zone) == z
        if sel.any():
            ax.axvspan(x[sel].min(), x[sel].max(), color=ZONE_COLOURS[z], zorder=0, lw=0)
            ax.text(
                0.5 * (x[sel].min() + x[sel].max()),
                0.98,
                names[z],
                transform=ax.get_xaxis_transform(),
                ha="center",
                va="top",
                fontsize=7,
                color="0.35",
            )


def plot_drift_methods(datasets, component="fx", ax=None, title=None, labels=None):
    """Normalised mean drift against L/λ for one or more `drift_methods_dataset` results
    (e.g. several speeds), one line per method; dashed where the method is outside its range."""
    datasets = datasets if isinstance(datasets, (list, tuple)) else [datasets]
    labels = labels or [""] * len(datasets)
    ax = ax or plt.subplots(figsize=(7, 4.2))[1]
    ds0 = datasets[0]
    x = ds0["L_over_lambda"].values
    shade_zones(ax, x, ds0["zone"].values)
    scale, ylabel = _norm(ds0, component)
    styles = ["-", "--", ":", "-."]
    for k, (ds, lab) in enumerate(zip(datasets, labels)):
        for i, m in enumerate(ds.method.values):
            y = ds[component].sel({"method": m}).values / scale
            ax.plot(
                x,
                y,
                styles[k % len(styles)],
                color=f"C{(i + k) % 10}",
                lw=1.2,
                label=f"{m} {lab}".strip(),
            )
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("L / lambda [-]")
    ax.set_ylabel(ylabel)
    ax.set_title(
        title
        or f"{ds0.attrs.get('waterline', '')}, beta = {np.degrees(ds0.attrs['beta']):.0f} deg",
        fontsize=9,
    )
    ax.legend(fontsize=6, ncol=2, loc="best")
    return ax


def plot_irregular_methods(
    tp,
    forces: dict,
    hs,
    component_index=0,
    normalise=1.0,
    tp_range=None,
    ax=None,
    title=None,
    ylabel=None,
):
    """Mean drift in irregular seas against Tp, one line per method (thesis figs 4.5-4.6,
    5.6-5.7 b/d); the physical Tp range for Hs (eq. 3.5) shaded."""
    ax = ax or plt.subplots(figsize=(6, 4))[1]
    if tp_range is not None:
        ax.axvspan(*tp_range, color="0.9", zorder=0, lw=0, label="physical Tp range")
    for i, (m, F) in enumerate(forces.items()):
        ax.plot(tp, np.asarray(F)[:, component_index] / normalise, color=f"C{i}", label=m)
    ax.set_xlabel("Tp [s]")
    ax.set_ylabel(ylabel or "mean drift")
    ax.set_title(title or f"irregular seas, Hs = {hs} m", fontsize=9)
    ax.legend(fontsize=6, ncol=2)
    return ax
