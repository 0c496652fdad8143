"""Figures of `jaxtow study` (one tow): the hull's head-sea drift, the operating point per
sea state, the stability map around the design point and the time-domain check."""

from __future__ import annotations

import io
import textwrap

import matplotlib.pyplot as plt
import numpy as np

from .._units import RHO_SEA, G
from .calm import plot_stability_map
from .resistance import plot_operating_point
from .risk import plot_risk_against_hs, plot_risk_runs, plot_risk_tension
from .timedomain import plot_time_traces


def study_figures(study) -> dict:
    """name → matplotlib Figure for a `jaxtow.studies.TowStudy` (the report's order)."""
    return {k: make() for k, make in study_figure_makers(study).items()}


def study_figure_makers(study) -> dict:
    """name → a function drawing that figure, for the parts the study finished (an
    incomplete study has fewer); the command line draws them one by one, so a figure that
    fails costs only itself."""
    s, makers = study.summary, {}
    if study.drift_curve is not None:
        makers["drift"] = lambda: _drift_figure(s, *study.drift_curve)
    for name, b in study.budgets.items():
        makers[f"operating_point_{name}"] = lambda name=name, b=b: _operating_point(s, name, b)
    if "map_xp_l0" in study.datasets and s.map is not None:
        makers["map"] = lambda: _map_figure(s, study.datasets["map_xp_l0"])
    if "calm" in study.runs and s.time_domain is not None:
        makers["time_domain"] = lambda: _time_domain_figure(s, *study.runs["calm"])
    for rec in s.risk:
        if rec.sea_state not in study.risk:
            continue
        result, _ = study.risk[rec.sea_state]
        name = rec.sea_state
        makers[f"risk_runs_{name}"] = lambda r=result, n=name: plot_risk_runs(
            r, f"{s.tow}: sea state {n}"
        )
        makers[f"risk_tension_{name}"] = lambda r=result, n=name: plot_risk_tension(
            r, f"{s.tow}: sea state {n}"
        )
        makers[f"risk_hs_{name}"] = lambda rec=rec: plot_risk_against_hs(rec, s.tow)
    return makers


def _drift_figure(s, w, fx):
    fig, ax = plt.subplots(figsize=(6.5, 4))
    ax.plot(w, np.asarray(fx) / 1e3, color="tab:blue", label="F_x / zeta_a^2, head seas")
    ax.axhline(
        -0.5 * RHO_SEA * G * s.breadth / 1e3,
        color="0.5",
        ls="--",
        lw=1,
        label="wall limit -rho g B / 2",
    )
    ax.set_xlabel("wave frequency omega [rad/s]")
    ax.set_ylabel("mean drift [kN/m^2]")
    ax.set_title("\n".join(textwrap.wrap(f"{s.tow}: {s.drift_source}", 90)[:3]), fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def _operating_point(s, name: str, b):
    row = next(r for r in s.resistance if r.sea_state == name)
    pt = None
    if row.operating_speed is not None and row.available_pull is not None:
        pt = (row.operating_speed, float(np.interp(row.operating_speed, b.speeds, b.pull)))
    ax = plot_operating_point(
        b.speeds,
        b.pull,
        {"total": b.total},
        pt,
        title=f"{s.tow}: sea state {name} (Hs {row.hs:g} m, Tp {row.tp:g} s)",
    )
    return ax.figure


def _map_figure(s, ds):
    m = s.map
    ax = plot_stability_map(
        ds,
        "xp",
        "l0",
        title=f"{s.tow}: straight-behind max Re(lambda), calm water",
        length=m.length,
    )
    ax.plot(
        [m.design_xp * m.length],
        [m.design_l0 * m.length],
        marker="*",
        ms=14,
        color="gold",
        mec="k",
        label="design point",
        ls="none",
    )
    ax.legend(fontsize=8, loc="upper right")
    return ax.figure


def _time_domain_figure(s, traj, met):
    t = s.time_domain
    return plot_time_traces(
        traj,
        f"{s.tow}: calm water from heading {t.psi0_deg:g} deg and sway "
        f"offset {t.y0 * s.length:.1f} m ({met.outcome})",
        length=s.length,
        time_scale=s.time_scale,
    )


def png_bytes(fig) -> bytes:
    """The figure as PNG bytes (closed afterwards)."""
    buf = io.BytesIO()
    fig.tight_layout()
    fig.savefig(buf, format="png", dpi=110)
    plt.close(fig)
    return buf.getvalue()
