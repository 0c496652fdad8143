"""Figures of the towing-stability-in-waves report (thesis figs 6.13-6.22, 6.26, 7.5)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from .._metrics import trajectory


def _note(ax, note):
    if note:
        ax.text(0.01, -0.16, note[:150], transform=ax.transAxes, fontsize=6, color="0.4", va="top")


def hatch_invalid(ax, x, y, invalid, label="outside the model's validity (xx)"):
    """Cross-hatch the points of a map where the physics' validity flags fail (``invalid``
    (len(x), len(y)) boolean, e.g. ``~physics_valid`` of a sweep), with a legend entry."""
    bad = np.asarray(invalid, dtype=float).T
    if not np.any(bad > 0.5):
        return
    ax.contourf(x, y, bad, levels=[0.5, 1.5], hatches=["xx"], colors="none")
    from matplotlib.patches import Patch

    ax.legend(
        handles=[Patch(facecolor="none", edgecolor="0.3", hatch="xx", label=label)],
        loc="upper right",
        fontsize=7,
        framealpha=0.7,
    )


def plot_max_real_map(
    l0, y, max_real, *, ylabel="omega [rad/s]", title="", note="", invalid=None, xlabel="l0' [-]"
):
    """max Re λ of the straight-behind equilibrium over (l0', y), the stability boundary
    (zero contour) in black; hatched (//) where no such equilibrium exists and cross-hatched
    (xx) where it lies outside the model's validity (``invalid``, see `hatch_invalid`)."""
    fig, ax = plt.subplots(figsize=(6.8, 5))
    z = np.asarray(max_real).T
    lim = float(np.nanmax(np.abs(z))) if np.isfinite(z).any() else 1.0
    cs = ax.pcolormesh(l0, y, z, cmap="RdBu_r", vmin=-lim, vmax=lim, shading="auto")
    plt.colorbar(cs, ax=ax, label="max Re lambda [U/L] (< 0 stable)")
    if np.nanmin(z) < 0 < np.nanmax(z):
        ax.contour(l0, y, z, levels=[0.0], colors="k", linewidths=1.2)
    if np.isnan(z).any():
        ax.contourf(
            l0, y, np.isnan(z).astype(float), levels=[0.5, 1.5], hatches=["//"], colors="none"
        )
    if invalid is not None:
        hatch_invalid(ax, l0, y, invalid)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    _note(ax, note)
    return fig


def plot_count_map(x, omega, count, *, title="", note=""):
    """Number of equilibria over (ζa, ω) (thesis figs 6.14-6.16)."""
    fig, ax = plt.subplots(figsize=(6.8, 5))
    levels = np.arange(-0.5, max(int(np.max(count)), 1) + 1.5)
    cs = ax.contourf(x, omega, np.asarray(count).T, levels=levels, cmap="viridis")
    plt.colorbar(cs, ax=ax, label="number of equilibria", ticks=np.arange(0, levels[-1]))
    ax.axvline(0.8, color="w", ls="--", lw=1)
    ax.set_xlabel("zeta_a [m]")
    ax.set_ylabel("omega [rad/s]")
    ax.set_title(title, fontsize=9)
    _note(ax, note)
    return fig


def plot_heading_map(x, omega, psi, xlabel, *, ylabel="omega [rad/s]", title="", invalid=None):
    """Heading [deg] of the equilibrium nearest straight behind over (x, ω) (or (x, Tp)),
    cross-hatched where it lies outside the model's validity (``invalid``)."""
    fig, ax = plt.subplots(figsize=(6.8, 5))
    cs = ax.pcolormesh(x, omega, np.degrees(np.asarray(psi)).T, cmap="coolwarm", shading="auto")
    plt.colorbar(cs, ax=ax, label="psi_eq [deg]")
    if invalid is not None:
        hatch_invalid(ax, x, omega, invalid)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=9)
    return fig


def plot_runs(runs: dict, title=""):
    """Sway offset and heading of several runs (thesis figs 6.20-6.22, 7.5)."""

    fig, axes = plt.subplots(2, 1, figsize=(8, 5.5), sharex=True)
    for tag, (model, sim) in runs.items():
        tr = trajectory(model, sim)
        axes[0].plot(tr["t"], tr["sway_offset"], lw=0.8, label=tag)
        axes[1].plot(tr["t"], np.degrees(tr["psi"]), lw=0.8, label=tag)
    axes[0].set_ylabel("sway offset y' [L]")
    axes[1].set_ylabel("psi [deg]")
    axes[1].set_xlabel("t' [-]")
    axes[0].legend(fontsize=8)
    axes[0].set_title(title, fontsize=9)
    return fig


def plot_with_without(l0, calm, waves: dict, *, title="", note=""):
    """max Re λ of the straight-behind equilibrium against l0' without waves and with waves
    of a few frequencies (thesis figs 6.27-6.28)."""
    fig, ax = plt.subplots(figsize=(6.8, 4.5))
    ax.plot(l0, calm, "k", lw=2, label="without waves")
    for label, a in waves.items():
        ax.plot(l0, a, lw=1, label=label)
    ax.axhline(0.0, color="0.5", lw=0.8)
    ax.set_xlabel("l0' [-]")
    ax.set_ylabel("max Re lambda [U/L]")
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=9)
    _note(ax, note)
    return fig
