"""Matplotlib figures of jaxtow results. Only this package imports matplotlib; importing it
never changes the matplotlib backend. One module a study: `calm`, `timedomain`,
`bifurcation`, `design`, `drift`, `resistance`, `tow`, `waves`, `waves_report`, `bem`;
`save` writes every figure (loaded on first use, `jaxtow._lazy`)."""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from . import (
        bem as bem,
        bifurcation as bifurcation,
        calm as calm,
        design as design,
        drift as drift,
        resistance as resistance,
        risk as risk,
        timedomain as timedomain,
        tow as tow,
        waves as waves,
        waves_report as waves_report,
    )
    from ._files import save as save
    from .calm import (
        plot_equilibria_vs as plot_equilibria_vs,
        plot_max_real_vs as plot_max_real_vs,
        plot_stability_map as plot_stability_map,
    )


__getattr__, __dir__, __all__ = _attach(__name__, __file__)
