"""Figures of the towing-stability-in-waves report (thesis figs 6.13-6.22, 6.26, 7.5)."""

from __future__ import annotations

import matplotlib.pyplot as plt
import numpy as np

from .._metrics import trajectory
from ..studies import outside_validity, straight, valid_count


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
        axes[0].plot(tr.t, tr.sway_offset, lw=0.8, label=tag)
        axes[1].plot(tr.t, np.degrees(tr.psi), lw=0.8, label=tag)
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


def wave_study_figures(study) -> dict:
    """The figures of a `jaxtow.studies.WaveStudy` (its primary drift source and form):
    file stem → an Axes of the figure. Maps, equilibrium counts and headings of Barge 2a
    and 2b (thesis figs 6.13-6.28), and the time-domain runs (figs 6.20-6.22, 7.5)."""
    figs = {}
    for v in ("2a", "2b"):
        figs.update(_version_figures(study, v))
    omega, tps = study.axes["omega"], study.axes["tp"]
    for tag, y, ylab, fig in (
        ("omega", omega, "omega [rad/s]", "6.13"),
        ("tp", tps, "Tp [s]", "6.23"),
    ):
        figs[f"barge_2a_heading_xp_{tag}"] = plot_heading_map(
            study.xp_grid,
            y,
            straight(study.maps_xp[tag], "psi"),
            "x_p' [-]",
            ylabel=ylab,
            title=f"Barge 2a: heading nearest straight behind (fig. {fig})",
            invalid=outside_validity(study.maps_xp[tag]),
        )
    runs = {k: (m, sim) for k, (m, sim, _) in study.runs.items()}
    figs["barge_2a_time_domain"] = plot_runs(
        runs, title=f"Barge 2a, l0' = 2.5, zeta_a = {study.zeta_a} m (figs 6.20-6.22, 7.5)"
    )
    return figs


def _version_figures(study, v: str) -> dict:
    """The maps of Barge ``v`` over (l0', ω), (ζa, ω), (l0', Tp) and (U_tug, ω)."""
    src, za, ax = study.source, study.zeta_a, study.axes
    l0, omega, tps = ax["l0"], ax["omega"], ax["tp"]
    figs = {}
    ds = study.maps_l0_omega[v]
    figs[f"barge_{v}_map_l0_omega"] = plot_max_real_map(
        l0,
        omega,
        straight(ds),
        title=f"Barge {v}: max Re lambda, straight behind, zeta_a = {za} m (figs 6.17-6.19)",
        note=src,
        invalid=outside_validity(ds),
    )
    mp = straight(ds)
    picks = {
        f"omega = {omega[k]:.2f} rad/s": mp[:, k]
        for k in sorted({int(np.argmin(np.abs(omega - w))) for w in (0.5, 0.8, 1.0, 1.5)})
    }
    figs[f"barge_{v}_with_without_waves"] = plot_with_without(
        l0,
        study.calm[v],
        picks,
        title=f"Barge {v}: with and without waves, zeta_a = {za} m (figs 6.27-6.28)",
        note=src,
    )
    ds = study.equilibria_zeta_omega[v]
    figs[f"barge_{v}_equilibria_zeta_omega"] = plot_count_map(
        study.zeta_grid,
        omega,
        valid_count({"valid": ds["valid"].values}),
        title=f"Barge {v}: number of equilibria, l0' = 2.5 (calm: {study.calm_counts[v]})",
        note=src,
    )
    figs[f"barge_{v}_heading_zeta_omega"] = plot_heading_map(
        study.zeta_grid,
        omega,
        straight(ds, "psi"),
        "zeta_a [m]",
        title=f"Barge {v}: heading of the equilibrium nearest straight behind",
        invalid=outside_validity(ds),
    )
    ds = study.maps_l0_tp[v]
    figs[f"barge_{v}_map_l0_tp"] = plot_max_real_map(
        l0,
        tps,
        straight(ds),
        ylabel="Tp [s]",
        title=f"Barge {v}: max Re lambda, Hs = {study.hs} m (fig. 6.26)",
        note=src,
        invalid=outside_validity(ds),
    )
    ds = study.maps_utug_omega[v]
    figs[f"barge_{v}_map_utug_omega"] = plot_max_real_map(
        study.tug_speeds,
        omega,
        straight(ds),
        xlabel="U_tug [m/s]",
        title=f"Barge {v}: max Re lambda over tug speed, l0' = 2.5, zeta_a = {za} m",
        note=src,
        invalid=outside_validity(ds),
    )
    figs[f"barge_{v}_heading_utug_omega"] = plot_heading_map(
        study.tug_speeds,
        omega,
        straight(ds, "psi"),
        "U_tug [m/s]",
        title=f"Barge {v}: heading nearest straight behind over tug speed",
        invalid=outside_validity(ds),
    )
    return figs
