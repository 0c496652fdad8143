"""Figures of the calm-water stability study (thesis figs 6.3, 6.4) and stability maps."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from .waves_report import hatch_invalid

BRANCH_STYLE = {
    -1: ("psi < 0 side", "tab:orange"),
    0: ("straight behind", "tab:blue"),
    1: ("psi > 0 side", "tab:green"),
}


def _assumed_note(ds):
    return "uses estimated values: see attrs 'note'" if ds.attrs.get("note") else ""


def plot_equilibria_vs(ds, param: str, ax=None, title: str | None = None):
    """Equilibrium heading ψ [deg] against a swept parameter (thesis fig. 6.3); filled
    markers stable, open markers unstable."""
    ax = ax or plt.subplots(figsize=(6, 4))[1]
    x = ds[param].values
    psi = np.degrees(ds["psi"].transpose(param, "equilibrium").values)
    st = ds["stability"].transpose(param, "equilibrium").values
    valid = ds["valid"].transpose(param, "equilibrium").values
    X = np.broadcast_to(x[:, None], psi.shape)
    stable = valid & (st < 0)
    unstable = valid & (st == 1)
    ax.plot(X[stable], psi[stable], "o", ms=3, color="tab:blue", label="stable")
    ax.plot(X[unstable], psi[unstable], "o", ms=3, mfc="none", color="tab:red", label="unstable")
    ax.set_xlabel(f"{param}' [-]")
    ax.set_ylabel("equilibrium heading psi [deg]")
    ax.axhline(0, color="0.8", lw=0.5)
    ax.legend(loc="best", fontsize=8)
    ax.set_title(title or f"{ds.attrs.get('vessel', '')}", fontsize=9)
    ax.text(0.01, 0.01, _assumed_note(ds), transform=ax.transAxes, fontsize=6, color="0.4")
    return ax


def plot_max_real_vs(ds, param: str, ax=None, title: str | None = None):
    """max Re λ of each equilibrium branch against a swept parameter (thesis fig. 6.4)."""
    ax = ax or plt.subplots(figsize=(6, 4))[1]
    x = ds[param].values
    mr = ds["max_real"].transpose(param, "equilibrium").values
    br = ds["branch"].transpose(param, "equilibrium").values
    valid = ds["valid"].transpose(param, "equilibrium").values
    for b, (label, color) in BRANCH_STYLE.items():
        sel = valid & (br == b)
        if not sel.any():
            continue
        y = np.max(np.where(sel, mr, -np.inf), axis=1)
        y[~sel.any(axis=1)] = np.nan
        ax.plot(x, y, "-", color=color, label=label)
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xlabel(f"{param}' [-]")
    ax.set_ylabel("max Re(lambda) [-]  (> 0 unstable)")
    ax.legend(loc="best", fontsize=8)
    ax.set_title(title or f"{ds.attrs.get('vessel', '')}", fontsize=9)
    ax.text(0.01, 0.01, _assumed_note(ds), transform=ax.transAxes, fontsize=6, color="0.4")
    return ax


#: The dimensional axis labels of the map's length parameters (`plot_stability_map`).
_METRES = {"xp": "attachment ahead of the CoG [m]", "l0": "towline length [m]"}


def plot_stability_map(
    ds, x: str, y: str, branch: int = 0, ax=None, title: str | None = None, length=None
):
    """max Re λ of one branch over a 2-D parameter grid, with the stability boundary;
    cross-hatched where the branch's equilibrium is outside the physics' validity (the
    dataset's ``physics_valid``, present for sweeps with validity flags). With the ship's
    ``length`` [m], the length parameters (x_p', l0') are drawn in metres."""
    ax = ax or plt.subplots(figsize=(6, 4.5))[1]
    on = ds["valid"] & (ds["branch"] == branch)
    mr = ds["max_real"].where(on).max("equilibrium")
    mr = mr.transpose(y, x).values
    lim = np.nanmax(np.abs(mr)) if np.isfinite(mr).any() else 1.0
    scale = {k: (length if length is not None and k in _METRES else 1.0) for k in (x, y)}
    xs, ys = ds[x].values * scale[x], ds[y].values * scale[y]
    pc = ax.pcolormesh(xs, ys, mr, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="auto")
    if np.isfinite(mr).any() and np.nanmin(mr) < 0 < np.nanmax(mr):
        ax.contour(xs, ys, mr, levels=[0.0], colors="k", linewidths=1)
    plt.colorbar(pc, ax=ax, label="max Re(lambda) [-] (by U/L)")
    if "physics_valid" in ds:
        bad = (on & ~ds["physics_valid"].astype(bool)).any("equilibrium")
        hatch_invalid(ax, xs, ys, bad.transpose(x, y).values)
    ax.set_xlabel(_METRES[x] if scale[x] != 1.0 else f"{x}' [-]")
    ax.set_ylabel(_METRES[y] if scale[y] != 1.0 else f"{y}' [-]")
    ax.set_title(title or f"{ds.attrs.get('vessel', '')}: {BRANCH_STYLE[branch][0]}", fontsize=9)
    return ax
