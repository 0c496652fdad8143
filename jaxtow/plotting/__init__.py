"""Matplotlib figures of jaxtow results. Only this package imports matplotlib."""

from .calm import (
    plot_equilibria_vs as plot_equilibria_vs,
    plot_max_real_vs as plot_max_real_vs,
    plot_stability_map as plot_stability_map,
)

__all__ = [
    "plot_equilibria_vs",
    "plot_max_real_vs",
    "plot_stability_map",
]
