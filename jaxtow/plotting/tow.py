"""Figures of `jaxtow study` (one tow): the hull's head-sea drift, the operating point per
sea state, the stability map around the design point and the time-domain check."""

from __future__ import annotations

import io

import matplotlib.pyplot as plt
import numpy as np

from .calm import plot_stability_map
from .resistance import plot_operating_point
from .timedomain import plot_time_traces


def study_figures(study) -> dict:
    """name → matplotlib Figure for a `jaxtow.studies.TowStudy` (the report's order)."""
    s, figs = study.summary, {}
    w, fx = study.drift_curves["head_sea_fx"]
    fig, ax = plt.subplots(figsize=(6.5, 4))
    ax.plot(w, np.asarray(fx) / 1e3, color="tab:blue", label="F_x / zeta_a^2, head seas")
    B = s["breadth"]
    ax.axhline(
        -0.5 * 1025.0 * 9.80665 * B / 1e3,
        color="0.5",
        ls="--",
        lw=1,
        label="wall limit -rho g B / 2",
    )
    ax.set_xlabel("wave frequency omega [rad/s]")
    ax.set_ylabel("mean drift [kN/m^2]")
    ax.set_title(f"{s['tow']}: {s['drift_source'][:90]}", fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    figs["drift"] = fig
    for name, b in study.budgets.items():
        row = next(r for r in s["resistance"] if r["sea_state"] == name)
        pt = (row["operating_speed"], row["pull"]) if "operating_speed" in row else None
        ax = plot_operating_point(
            b["speeds"],
            b["pull"],
            {"total": b["total"]},
            pt,
            title=f"{s['tow']}: sea state {name} (Hs {row['hs']:g} m, Tp {row['tp']:g} s)",
        )
        figs[f"operating_point_{name}"] = ax.figure
    if "map_xp_l0" in study.datasets:
        ax = plot_stability_map(
            study.datasets["map_xp_l0"],
            "xp",
            "l0",
            title=f"{s['tow']}: straight-behind max Re(lambda), calm water",
        )
        t = s["towline"]
        ax.plot(
            [t["xp"]],
            [t["l0"]],
            marker="*",
            ms=14,
            color="gold",
            mec="k",
            label="design point",
            ls="none",
        )
        ax.legend(fontsize=8, loc="upper right")
        figs["map"] = ax.figure
    if "calm" in study.runs:
        traj, met = study.runs["calm"]
        figs["time_domain"] = plot_time_traces(
            traj,
            f"{s['tow']}: calm water from psi0 = {s['time_domain']['psi0_deg']:g} deg, "
            f"y0' = {s['time_domain']['y0']:g} ({met['outcome']})",
        )
    return figs


def png_bytes(fig) -> bytes:
    """The figure as PNG bytes (closed afterwards)."""
    buf = io.BytesIO()
    fig.tight_layout()
    fig.savefig(buf, format="png", dpi=110)
    plt.close(fig)
    return buf.getvalue()
