"""Time traces and phase portraits of a run (thesis figs 6.5-6.7, 7.6)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np


def plot_time_traces(traj: dict, title: str = ""):
    """Sway offset y' [L] and heading ψ [deg] against time (thesis fig. 6.5)."""
    fig, ax = plt.subplots(figsize=(7, 3.8))
    ax.plot(traj["t"], traj["sway_offset"], color="tab:blue")
    ax.set_xlabel("t' [-]  (time by L/U_tug)")
    ax.set_ylabel("sway offset y' [L]", color="tab:blue")
    ax2 = ax.twinx()
    ax2.plot(traj["t"], np.degrees(traj["psi"]), color="k", lw=0.8)
    ax2.set_ylabel("heading psi [deg]")
    ax.set_title(title, fontsize=9)
    return fig


def plot_phase_portraits(traj: dict, title: str = ""):
    """Phase portraits of surge position, sway offset and heading (thesis figs 6.6, 6.7)."""
    t = traj["t"]
    x = traj["cog_x"] - traj["tug_x"]
    series = [
        ("x' - x_tug' [L]", x),
        ("y' [L]", traj["sway_offset"]),
        ("psi [deg]", np.degrees(traj["psi"])),
    ]
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.4))
    for ax, (label, s) in zip(axes, series):
        ax.plot(s, np.gradient(s, t), lw=0.7)
        ax.set_xlabel(label)
        ax.set_ylabel(f"d({label.split(' ')[0]})/dt'")
    fig.suptitle(title, fontsize=9)
    return fig


def plot_force_history(fh: dict, title: str = ""):
    """Force breakdown per DOF along a run (thesis fig. 7.6)."""
    fig, axes = plt.subplots(3, 1, figsize=(7, 6), sharex=True)
    for i, (ax, dof) in enumerate(zip(axes, ("X'", "Y'", "N'"))):
        for k in ("manoeuvring", "towline", "coupling", "external"):
            ax.plot(fh["t"], fh[k][:, i], lw=0.8, label=k)
        ax.set_ylabel(dof)
    axes[0].legend(fontsize=7, ncol=4)
    axes[-1].set_xlabel("t' [-]")
    fig.suptitle(title, fontsize=9)
    return fig
