"""Writing a figure: every command saves its figures through `save`."""

from __future__ import annotations

import matplotlib.pyplot as plt

from ..io._atomic import save_figure


def save(fig_or_ax, path, dpi: int = 120) -> None:
    """Lay out the figure of ``fig_or_ax`` (a Figure or one of its Axes), write it as PNG at
    ``dpi`` to ``path`` (atomically: a killed run leaves no partial file) and close it."""
    fig = fig_or_ax.figure if hasattr(fig_or_ax, "figure") else fig_or_ax
    fig.tight_layout()
    save_figure(fig, path, dpi=dpi)
    plt.close(fig)
