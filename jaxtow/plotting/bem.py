"""Figures of the panel-method results (thesis figs 2.11, 4.3c, 4.4c, 4.5a, B.1-B.4)."""

from __future__ import annotations

import json

import matplotlib.pyplot as plt
import numpy as np

from .._units import RHO_SEA, G
from ..bem.database import rao

_LABELS = {
    "fx": "Fx / (rho g zeta_a^2 B)",
    "fy": "Fy / (rho g zeta_a^2 L)",
    "nz": "Nz / (rho g zeta_a^2 L^2)",
}


def _dims(ds):
    p = json.loads(ds.attrs.get("mesh_params", "{}"))
    return float(p.get("length", 1.0)), float(p.get("breadth", 1.0))


def _norm(ds, component):
    L, B = _dims(ds)
    scale = {"fx": B, "fy": L, "nz": L * L}[component]
    return RHO_SEA * G * scale


def plot_rao(ds, beta_deg: float = 0.0, dofs=("Heave", "Roll", "Pitch")):
    """Amplitude and phase of the RAOs at one heading (thesis figs B.2, B.3): translations in
    m/m, rotations in deg/m."""

    b = float(np.radians(beta_deg))
    X = rao(ds).sel(beta=b, method="nearest")
    w = ds.omega.values
    fig, axes = plt.subplots(2, len(dofs), figsize=(4 * len(dofs), 5.5), sharex=True)
    for k, d in enumerate(dofs):
        x = X.sel(dof=d).values
        rot = d in ("Roll", "Pitch", "Yaw")
        axes[0, k].plot(w, np.abs(x) * (180 / np.pi if rot else 1.0), "k-")
        axes[0, k].set_title(f"{d} RAO, beta = {beta_deg:g} deg")
        axes[0, k].set_ylabel("deg/m" if rot else "m/m")
        axes[1, k].plot(w, np.degrees(np.angle(x)), "k-")
        axes[1, k].set_ylabel("phase [deg]")
        axes[1, k].set_xlabel("omega [rad/s]")
    fig.tight_layout()
    return fig


def plot_bem_qtf(ds, beta_deg=(0.0, 15.0), components=("fx", "fy", "nz")):
    """Far-field and near-field mean drift against ω at the given headings, normalised as in
    the thesis (figs 4.3c, 4.4c, 4.5a, B.4)."""
    fig, axes = plt.subplots(1, len(components), figsize=(4.6 * len(components), 4))
    axes = np.atleast_1d(axes)
    w = ds.omega.values
    for k, c in enumerate(components):
        s = _norm(ds, c)
        for j, bd in enumerate(beta_deg):
            b = float(np.radians(bd))
            col = f"C{j}"
            axes[k].plot(
                w,
                ds.far_field.sel(component=c).sel(beta=b, method="nearest") / s,
                "-",
                color=col,
                label=f"far field, beta {bd:g}",
            )
            axes[k].plot(
                w,
                ds.near_field.sel(component=c).sel(beta=b, method="nearest") / s,
                "--",
                color=col,
                label=f"near field, beta {bd:g}",
            )
        axes[k].set_xlabel("omega [rad/s]")
        axes[k].set_ylabel(_LABELS[c])
        axes[k].axhline(0, color="0.7", lw=0.6)
    axes[0].legend(fontsize=7)
    fig.suptitle(
        f"{ds.attrs.get('mesh_name', '')}: {ds.attrs.get('n_panels', '?')} panels "
        f"({ds.attrs.get('panel_size_m', '?')} m), Capytaine {ds.attrs.get('capytaine_version', '')}"
    )
    fig.tight_layout()
    return fig


def plot_nearfield_parts(ds, beta_deg: float = 15.0, component: str = "fx"):
    """The near-field parts I-IV against ω (thesis fig. 2.11)."""
    b = float(np.radians(beta_deg))
    s = _norm(ds, component)
    fig, ax = plt.subplots(figsize=(6.5, 4))
    w = ds.omega.values
    for p in ds.part.values:
        ax.plot(
            w,
            ds.near_field_parts.sel(component=component, part=p).sel(beta=b, method="nearest") / s,
            label=f"part {p}",
        )
    ax.plot(
        w,
        ds.near_field.sel(component=component).sel(beta=b, method="nearest") / s,
        "k-",
        lw=2,
        label="total",
    )
    ax.plot(
        w,
        ds.far_field.sel(component=component).sel(beta=b, method="nearest") / s,
        "k:",
        label="far field",
    )
    ax.set_xlabel("omega [rad/s]")
    ax.set_ylabel(_LABELS[component])
    ax.set_title(f"near-field parts, beta = {beta_deg:g} deg")
    ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def plot_mesh_convergence(summary, runs=None, beta_deg: float = 15.0):
    """Thesis fig. B.1: (a, b) surge and sway drift per mesh at one heading (when ``runs`` are
    given), (c, d) relative MSE against panels per breadth and per length."""
    n = 4 if runs is not None else 2
    fig, axes = plt.subplots(1, n, figsize=(4.4 * n, 4))
    k = 0
    if runs is not None:
        b = float(np.radians(beta_deg))
        for c, ax in zip(("fx", "fy"), axes[:2]):
            for i, (p, ds) in enumerate(sorted(runs.items(), reverse=True)):
                s = _norm(ds, c)
                ax.plot(
                    ds.omega,
                    ds.near_field.sel(component=c).sel(beta=b, method="nearest") / s,
                    "--",
                    color=f"C{i}",
                    label=f"NF {p:g} m",
                )
                ax.plot(
                    ds.omega,
                    ds.far_field.sel(component=c).sel(beta=b, method="nearest") / s,
                    "-",
                    color=f"C{i}",
                    label=f"FF {p:g} m",
                )
            ax.set_xlabel("omega [rad/s]")
            ax.set_ylabel(_LABELS[c])
            ax.set_title(f"beta = {beta_deg:g} deg")
        axes[0].legend(fontsize=6)
        k = 2
    for ax, per in zip(axes[k:], ("panels_per_breadth", "panels_per_length")):
        x = summary[per].values
        for c, mk in (("fx", "o"), ("fy", "s")):
            ax.plot(
                x,
                summary.near_vs_far.sel(component=c, zone="all"),
                mk + "-",
                label=f"{c}: NF vs own FF",
            )
            ax.plot(
                x,
                summary.mse.sel(component=c, zone="all", drift_method="near_field"),
                mk + ":",
                label=f"{c}: NF vs finest FF",
            )
        ax.set_yscale("log")
        ax.set_xlabel(per.replace("_", " "))
        ax.set_ylabel("relative MSE")
    axes[k].legend(fontsize=7)
    fig.tight_layout()
    return fig
