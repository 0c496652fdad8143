"""Bifurcation diagrams (equilibrium branches, special points, limit cycles) and Hopf curves."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

MARKERS = {
    "branch_point": ("s", "k"),
    "fold": ("D", "tab:purple"),
    "hopf": ("*", "tab:red"),
    "neutral_saddle": ("x", "0.4"),
}


def plot_branch(branch, ax=None, orbits=None, title=None):
    """ψ [deg] along a `jaxtow.continuation.Branch` (and its children): solid stable, dotted
    unstable; special points marked; optional limit cycles drawn as ± max |ψ| of the orbit."""
    ax = ax or plt.subplots(figsize=(7, 4.5))[1]
    for b in [branch, *branch.children]:
        psi = np.degrees(b.psi)
        st = b.stable
        for mask, ls in ((st, "-"), (~st, ":")):
            y = np.where(mask, psi, np.nan)
            ax.plot(b.p, y, ls, color="tab:blue", lw=1.5)
        for s in b.special:
            m, c = MARKERS[s.kind]
            ax.plot(
                s.parameter, np.degrees(s.psi), m, color=c, ms=8, label=s.kind.replace("_", " ")
            )
    if orbits:
        p = [o.parameter for o in orbits]
        amp = [np.degrees(o.yaw_range) for o in orbits]
        ax.plot(p, amp, "o-", color="tab:orange", ms=3, label="limit cycle max |psi|")
        ax.plot(p, -np.asarray(amp), "o-", color="tab:orange", ms=3)
    h, lab = ax.get_legend_handles_labels()
    uniq = dict(zip(lab, h))
    ax.legend(uniq.values(), uniq.keys(), fontsize=7)
    ax.set_xlabel(f"{branch.parameter}' [-]")
    ax.set_ylabel("equilibrium heading psi [deg]")
    ax.set_title(title or "equilibrium branches (solid stable, dotted unstable)", fontsize=9)
    return ax


def plot_hopf_curve(curve, ax=None, labels=("xp", "l0"), **kw):
    """A Hopf curve (n, 2) in a parameter plane, e.g. over `plot_stability_map`."""
    ax = ax or plt.subplots(figsize=(6, 4.5))[1]
    ax.plot(
        curve[:, 0], curve[:, 1], "-", color=kw.pop("color", "k"), lw=2, label="Hopf curve", **kw
    )
    ax.set_xlabel(f"{labels[0]}' [-]")
    ax.set_ylabel(f"{labels[1]}' [-]")
    return ax
