"""Figures of the tow-resistance budget (thesis figs 7.2-7.4) and the operating point (fig. 2.1)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

COLOURS = {"hull": "tab:blue", "wind": "tab:green", "waves": "tab:red", "tug": "tab:purple"}


def _components(ds):
    """Components that are not zero everywhere."""
    return [
        c for c in ds.component.values if np.any(np.abs(ds.resistance.sel(component=c).values) > 0)
    ]


def _note(ds, ax):
    if any("ILLUSTRATIVE" in str(v) for k, v in ds.attrs.items() if k.startswith("assumed_")):
        ax.text(
            0.01,
            0.01,
            "ILLUSTRATIVE wind table/height: see dataset attrs",
            transform=ax.transAxes,
            fontsize=7,
            color="0.4",
        )


def _finish_budget_axes(ds, axes, xlabel, title, legend_both: bool):
    """Labels, grid, share limits, legend and the ILLUSTRATIVE note of a (kN, %) axes pair."""
    for ax in axes:
        ax.set_xlabel(xlabel)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("resistance [kN]")
    axes[1].set_ylabel("share of total [%]")
    axes[1].set_ylim(0, 100)
    for ax in axes if legend_both else axes[:1]:
        ax.legend(fontsize=7)
    axes[0].set_title(title, fontsize=9)
    _note(ds, axes[0])
    return axes


def plot_budget_vs_tp(ds, speeds=None, tp_range=None, axes=None, title: str = ""):
    """Resistance per component and total [kN] (left) and shares [%] (right) against Tp at
    the given speeds (thesis figs 7.2, 7.3); ``tp_range`` shades the physical Tp range."""
    if axes is None:
        _, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    speeds = ds.speed.values if speeds is None else speeds
    styles = ("-", "--", ":", "-.")
    for j, s in enumerate(speeds):
        d = ds.sel(speed=s, method="nearest")
        ls = styles[j % len(styles)]
        axes[0].plot(d.tp, d.total / 1e3, "k" + ls, label=f"total, U = {float(d.speed):g} m/s")
        for c in _components(ds):
            axes[0].plot(
                d.tp,
                d.resistance.sel(component=c) / 1e3,
                ls,
                color=COLOURS[c],
                label=f"{c}, U = {float(d.speed):g} m/s",
            )
            axes[1].plot(
                d.tp,
                d.share.sel(component=c),
                ls,
                color=COLOURS[c],
                label=f"{c}, U = {float(d.speed):g} m/s",
            )
    if tp_range is not None:
        for ax in axes:
            ax.axvspan(*tp_range, color="0.9", zorder=0, lw=0, label="physical Tp range")
    return _finish_budget_axes(ds, axes, "Tp [s]", title, legend_both=False)


def plot_budget_vs_speed(ds, tp, axes=None, title: str = ""):
    """Resistance per component and shares against speed at one Tp (thesis fig. 7.4)."""
    if axes is None:
        _, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    d = ds.sel(tp=tp, method="nearest")
    axes[0].plot(d.speed, d.total / 1e3, "k", label="total")
    bottom = np.zeros(d.speed.size)
    for c in _components(ds):
        axes[0].plot(d.speed, d.resistance.sel(component=c) / 1e3, color=COLOURS[c], label=c)
        share = d.share.sel(component=c).values
        axes[1].fill_between(d.speed, bottom, bottom + share, color=COLOURS[c], alpha=0.6, label=c)
        bottom = bottom + share
    return _finish_budget_axes(
        ds, axes, "tow speed U [m/s]", title or f"Tp = {float(d.tp):g} s", legend_both=True
    )


def plot_operating_point(speeds, pull, resist, point=None, ax=None, title: str = ""):
    """Available pull and total resistance against speed with their intersection (thesis
    fig. 2.1): arrays in N and m/s; ``point`` = (speed, force)."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.plot(speeds, np.asarray(pull) / 1e3, "k", label="available pull")
    for name, r in resist.items():
        ax.plot(speeds, np.asarray(r) / 1e3, label=f"resistance, {name}")
    if point is not None:
        ax.plot([point[0]], [point[1] / 1e3], "o", color="tab:red")
        ax.annotate(
            f"U = {point[0]:.2f} m/s",
            (point[0], point[1] / 1e3),
            textcoords="offset points",
            xytext=(6, 6),
            fontsize=8,
        )
    ax.set_xlabel("tow speed U [m/s]")
    ax.set_ylabel("force [kN]")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=9)
    return ax


def resistance_figures(study) -> dict:
    """The figures of a `jaxtow.studies.ResistanceStudy` per sea state: the budget over Tp
    (figs 7.2, 7.3), over speed (fig. 7.4) and the operating point (fig. 2.1); file stem →
    an Axes of the figure."""
    tow, figs = study.tow, {}
    for i, sea in enumerate(study.seas):
        ds, tag, rng = study.budgets[sea.name], sea.name.replace(" ", "_"), study.tp_range(sea)
        figs[f"budget_vs_tp_{tag}"] = plot_budget_vs_tp(
            ds,
            speeds=[0.0] if i == 0 else [0.0, 2.0],
            tp_range=rng,
            title=f"{tow.name}: {sea.name}, Hs = {float(sea.hs):g} m, wind {float(sea.wind_speed):g} m/s "
            "(figs 7.2/7.3)",
        )[0]
        tp_fig = 7.0 if rng is None or rng[0] <= 7.0 <= rng[1] else float(sea.tp)
        figs[f"budget_vs_speed_{tag}"] = plot_budget_vs_speed(
            ds, tp_fig, title=f"{tow.name}: {sea.name}, Tp = {tp_fig:g} s (fig. 7.4)"
        )[0]
        u, pull, total = study.curves[sea.name]
        r = study.rows[i]
        held = r.operating_speed is not None
        pt = (r.operating_speed, float(np.interp(r.operating_speed, u, pull))) if held else None
        figs[f"operating_point_{tag}"] = plot_operating_point(
            u, pull, {"total": total}, pt, title=f"{tow.name}: {sea.name} (fig. 2.1)"
        )
    return figs
