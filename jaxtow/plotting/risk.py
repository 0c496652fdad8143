"""Figures of the irregular-sea Monte Carlo (`jaxtow.risk`): sample runs, the distribution of
the largest towline tension against the MBL, and the fishtail probability against Hs."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

__all__ = ["plot_risk_runs", "plot_risk_tension", "plot_risk_against_hs"]


def plot_risk_runs(result, title: str = ""):
    """The heading of the kept sample runs against time [min], the yaw threshold shaded."""
    smp = result.samples
    fig, ax = plt.subplots(figsize=(7, 3.6))
    if smp:
        t = np.asarray(smp["t"]) / 60.0
        for k, psi in enumerate(np.asarray(smp["psi"])):
            ax.plot(t, psi, lw=0.7, label=f"run {k}" if k < 4 else None)
    thr = result.settings.yaw_threshold
    ax.axvspan(0, result.settings.transient / 60.0, color="0.9", label="start-up (left out)")
    ax.set_xlabel("time [min]")
    ax.set_ylabel("heading psi [deg]")
    ax.set_title(f"{title}: sample runs; fishtail = yaw amplitude over {thr:g} deg", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right", ncol=3)
    return fig


def plot_risk_tension(result, title: str = ""):
    """The histogram of the runs' largest tension [kN] with the static tension, the most
    probable maximum in 3 h, the MBL and the guideline's design load where known."""
    fig, ax = plt.subplots(figsize=(7, 3.6))
    T = np.asarray(result.max_tension)[result.completed] / 1e3
    ax.hist(
        T,
        bins=min(30, max(5, T.size // 4)),
        color="tab:blue",
        alpha=0.7,
        label="largest tension of a run",
    )
    lines = [("static", result.static_tension, "0.3", ":")]
    if result.n >= 2:
        lines.append(("most probable maximum, 3 h", result.mpm_tension, "tab:orange", "--"))
    if result.design_load is not None:
        lines.append(("MBL / f(BP) (guideline)", result.design_load, "tab:purple", "-."))
    if result.mbl is not None:
        lines.append(("MBL", result.mbl, "tab:red", "-"))
    for label, x, c, ls in lines:
        ax.axvline(x / 1e3, color=c, ls=ls, lw=1.5, label=f"{label} {x / 1e3:.0f} kN")
    ax.set_xlabel("towline tension [kN]")
    ax.set_ylabel("runs")
    ax.set_title(f"{title}: largest towline tension of each run", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return fig


def plot_risk_against_hs(record, tow: str = ""):
    """The fishtail probability against Hs with its 95 % intervals (a `RiskRecord`)."""
    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    pts = sorted(record.hs_curve, key=lambda p: p.hs)
    hs = [p.hs for p in pts]
    val = np.array([p.fishtail.value for p in pts])
    lo = np.array([p.fishtail.low for p in pts])
    hi = np.array([p.fishtail.high for p in pts])
    ax.errorbar(hs, 100 * val, yerr=[100 * (val - lo), 100 * (hi - val)], marker="o", capsize=3)
    for p in pts:
        ax.annotate(
            f"{p.runs}",
            (p.hs, 100 * p.fishtail.value),
            textcoords="offset points",
            xytext=(4, 4),
            fontsize=7,
        )
    ax.set_xlabel("significant wave height Hs [m]")
    ax.set_ylabel("P(fishtail in a run) [%]")
    ax.set_ylim(-2, 102)
    ax.set_title(
        f"{tow}: sea state {record.sea_state} (Tp {record.tp:g} s; runs labelled)", fontsize=9
    )
    ax.grid(alpha=0.3)
    return fig
