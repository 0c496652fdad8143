"""Figures of sea states: spectra (thesis fig. 3.1) and irregular-sea quantities against
Tp with the physical range shaded (thesis fig. 4.3b)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from ..waves import physical_tp_range


def plot_spectra(omega, spectra: dict, ax=None, title: str = "wave spectra"):
    """S(ω) curves; ``spectra`` maps a label to an array over ``omega``."""
    ax = ax or plt.subplots(figsize=(6, 4))[1]
    for label, S in spectra.items():
        ax.plot(np.asarray(omega), np.asarray(S), label=label)
    ax.set_xlabel("omega [rad/s]")
    ax.set_ylabel("S(omega) [m^2 s/rad]")
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=9)
    return ax


def plot_against_tp(tp, values: dict, hs: float, ax=None, ylabel: str = "", title: str = ""):
    """Irregular-sea quantities against Tp with the physical Tp range (eq. 3.5) shaded."""
    ax = ax or plt.subplots(figsize=(6, 4))[1]
    lo, hi = (float(x) for x in physical_tp_range(hs))
    ax.axvspan(lo, hi, color="0.9", label=f"physical Tp range, Hs = {hs} m")
    for label, v in values.items():
        ax.plot(np.asarray(tp), np.asarray(v), label=label)
    ax.set_xlabel("Tp [s]")
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=9)
    return ax
