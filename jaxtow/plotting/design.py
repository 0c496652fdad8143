"""Figures of towline/bridle design and stability sensitivities."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np


def plot_sensitivity_ranking(ds, ax=None, title: str = "", top: int | None = None):
    """Horizontal bars of the elasticity p·∂(max Re λ)/∂p (mean over the sweep, with its
    range as an error bar), ranked by |elasticity|: which uncertain input matters most."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 0.32 * ds.sizes["parameter"] + 1.2))
    el = np.asarray(ds.elasticity)
    mean = el.mean(axis=0)
    order = np.argsort(np.asarray(ds.importance))[: top or el.shape[1]][::-1]
    lo, hi = mean - el.min(axis=0), el.max(axis=0) - mean
    colours = ["tab:red" if m > 0 else "tab:blue" for m in mean[order]]
    ax.barh(
        np.arange(order.size), mean[order], xerr=[lo[order], hi[order]], color=colours, alpha=0.8
    )
    ax.set_yticks(np.arange(order.size), [str(ds.parameter.values[i]) for i in order])
    ax.axvline(0.0, color="k", lw=0.8)
    ax.set_xlabel("p * d(max Re lambda)/dp  (red: raising p destabilises)")
    ax.set_title(title, fontsize=9)
    ax.grid(alpha=0.3, axis="x")
    return ax


def plot_design_map(grid_result, optimum=None, ax=None, title: str = "", levels=21):
    """The grid-search objective over two design variables with the grid optimum (x) and an
    optimiser's design (*), and the zero contour of max Re λ where it exists."""
    if ax is None:
        _, ax = plt.subplots(figsize=(6.5, 5))
    (nx, gx), (ny, gy) = list(grid_result.grid.items())[:2]
    cs = ax.contourf(gx, gy, np.asarray(grid_result.values).T, levels=levels, cmap="RdBu_r")
    plt.colorbar(cs, ax=ax, label="objective (smoothed max Re lambda + penalties)")
    ax.plot(grid_result.params[nx], grid_result.params[ny], "kx", ms=10, label="grid optimum")
    if optimum is not None:
        ax.plot(
            optimum.params[nx],
            optimum.params[ny],
            "*",
            color="gold",
            mec="k",
            ms=14,
            label=f"optimiser ({optimum.n_evaluations} evaluations)",
        )
    ax.set_xlabel(f"{nx}'")
    ax.set_ylabel(f"{ny}'")
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=9)
    return ax
