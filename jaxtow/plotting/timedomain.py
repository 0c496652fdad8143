"""Time traces and phase portraits of a run (thesis figs 6.5-6.7, 7.6)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np


def plot_time_traces(
    traj, title: str = "", *, length: float | None = None, time_scale: float | None = None
):
    """Sway offset and heading against time (thesis fig. 6.5), one panel each. With the
    ship ``length`` [m] and the ``time_scale`` L/U [s], in metres and minutes; else in L and
    t' = t U/L."""
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(10, 5.5), sharex=True)
    dimensional = length is not None and time_scale is not None
    t = np.asarray(traj.t) * (time_scale / 60.0 if time_scale is not None else 1.0)
    y = np.asarray(traj.sway_offset) * (length if length is not None else 1.0)
    if not dimensional:  # both or neither
        t, y = np.asarray(traj.t), np.asarray(traj.sway_offset)
    ax.plot(t, y, color="tab:blue", lw=0.9)
    ax.set_ylabel("sway offset of the CoG [m]" if dimensional else "sway offset y' [L]")
    ax2.plot(t, np.degrees(traj.psi), color="k", lw=0.9)
    ax2.set_ylabel("heading [deg]")
    ax2.set_xlabel("time [min]" if dimensional else "t' [-]  (time by L/U_tug)")
    for a in (ax, ax2):
        a.grid(alpha=0.3)
    ax.set_title(title, fontsize=9)
    return fig


def plot_phase_portraits(traj, title: str = ""):
    """Phase portraits of surge position, sway offset and heading (thesis figs 6.6, 6.7)."""
    t = traj.t
    x = traj.cog_x - traj.tug_x
    series = [
        ("x' - x_tug' [L]", x),
        ("y' [L]", traj.sway_offset),
        ("psi [deg]", np.degrees(traj.psi)),
    ]
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.4))
    for ax, (label, s) in zip(axes, series):
        ax.plot(s, np.gradient(s, t), lw=0.7)
        ax.set_xlabel(label)
        ax.set_ylabel(f"d({label.split(' ')[0]})/dt'")
    fig.suptitle(title, fontsize=9)
    return fig


def plot_force_history(fh, title: str = ""):
    """Force breakdown per DOF along a run (thesis fig. 7.6; a `jaxtow.ForceHistory`)."""
    fig, axes = plt.subplots(3, 1, figsize=(7, 6), sharex=True)
    for i, (ax, dof) in enumerate(zip(axes, ("X'", "Y'", "N'"))):
        for k in ("manoeuvring", "towline", "coupling", "external"):
            ax.plot(fh.t, getattr(fh.forces, k)[:, i], lw=0.8, label=k)
        ax.set_ylabel(dof)
    axes[0].legend(fontsize=7, ncol=4)
    axes[-1].set_xlabel("t' [-]")
    fig.suptitle(title, fontsize=9)
    return fig
