"""Figures of the drift-method comparison (thesis figs 4.3-4.6, 5.6-5.7)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from .._units import RHO_SEA, G
from ..studies._drift import SWAY_METHODS, TP

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


def drift_study_figures(study) -> dict:
    """The figures of a `jaxtow.studies.DriftMethodsStudy` (thesis figs 4.3-4.6, 5.6, 5.7):
    file stem → an Axes of the figure."""
    wl, hs, deg = study.waterline, study.hs, np.degrees(study.sway_heading)
    norm_x, norm_y = study.normalisation
    irr = study.irregular
    figs = {
        "fig4_3_stationary_surge": plot_drift_methods(
            study.head, "fx", title=f"{wl.name}: stationary surge, beta = 0 (fig. 4.3)"
        ),
        "fig4_4_stationary_sway": plot_drift_methods(
            study.oblique, "fy", title=f"{wl.name}: stationary sway, beta = {deg:g} deg (fig. 4.4)"
        ),
        "fig4_5_irregular_surge": plot_irregular_methods(
            TP,
            {k: v[0] for k, v in irr.items()},
            hs,
            0,
            norm_x,
            study.tp_range,
            title=f"{wl.name}: stationary surge in JONSWAP, Hs = {hs} m, beta = 0 (fig. 4.5)",
            ylabel="Fx / (rho g B Hs^2/8)",
        ),
        "fig4_6_irregular_sway": plot_irregular_methods(
            TP,
            {k: irr[k][1] for k in SWAY_METHODS},
            hs,
            1,
            norm_y,
            study.tp_range,
            title=f"{wl.name}: stationary sway in JONSWAP, Hs = {hs} m (fig. 4.6)",
            ylabel="Fy / (rho g L Hs^2/8)",
        ),
    }
    for tag, comp, beta, stem in (
        ("surge", "fx", 0.0, "fig5_6_sailing_surge"),
        ("sway", "fy", study.sway_heading, "fig5_7_sailing_sway"),
    ):
        fig, axes = plt.subplots(2, 3, figsize=(13, 7), sharex=True)
        for ax, (name, dss) in zip(axes.ravel(), study.sailing[tag].items()):
            plot_drift_methods(
                dss,
                comp,
                ax=ax,
                labels=[f"{'u' if tag == 'surge' else 'v'} = {s:g} m/s" for s in study.speeds],
                title=name,
            )
        fig.suptitle(
            f"{wl.name}: sailing {tag}, beta = {np.degrees(beta):g} deg (figs 5.6/5.7)",
            fontsize=10,
        )
        figs[stem] = axes[0, 0]
    return figs
