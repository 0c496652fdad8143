"""Environmental forces on the towed vessel: the one hook of the tow model.

Every environmental force is an `AbstractExternalForce`: ``force(t, y, model)`` returns the
non-dimensional body-axis load (X', Y', N') at the CoG in the scales of the manoeuvring
forces (thesis eqs 6.14-6.16); forces with a physical size also give ``dimensional(y)`` in
SI, and ``validity(y)`` the physics' own limits at that state. Several forces add up with
`CombinedForce`. Equilibria, stability, sweeps, gradients and time-domain runs take any of
them through ``TowModel(external=...)``; a new force (a drogue, a current profile) is a
subclass with a ``__call__`` (see ``docs/howto/new-force.md`` and notebook 04).
"""

from typing import TYPE_CHECKING

from .._lazy import attach as _attach

if TYPE_CHECKING:
    from ._base import (
        AbstractExternalForce as AbstractExternalForce,
        CombinedForce as CombinedForce,
        ConstantBodyForce as ConstantBodyForce,
        NoExternalForce as NoExternalForce,
        combine as combine,
        force_terms as force_terms,
    )
    from ._current import CurrentForce as CurrentForce
    from ._waves import (
        IrregularWaveDriftForce as IrregularWaveDriftForce,
        SlowDriftForce as SlowDriftForce,
        WaveDriftForce as WaveDriftForce,
    )
    from ._wind import GustWindForce as GustWindForce, WindForce as WindForce

__getattr__, __dir__, __all__ = _attach(__name__, __file__)
