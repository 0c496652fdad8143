"""Two variants of a tow on the same random numbers: the change of the fishtailing
probability with a design parameter (x_p, l0, a skeg span...) that is not drowned in the
Monte Carlo's noise.

Both variants run with the same seed and settings, so each run of one meets the same waves,
gusts and start heading as its partner in the other (common random numbers). The difference
of the two probabilities is then the difference of the discordant pairs,
d = (n₁₀ − n₀₁)/n, with the paired (McNemar) standard error
√((n₁₀ + n₀₁) − (n₁₀ − n₀₁)²/n)/n; its 95 % interval is d ± 1.96 s.e.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ._montecarlo import RiskResult, irregular_sea
from ._stats import Z95

__all__ = ["RiskDifference", "compare"]


@dataclasses.dataclass(frozen=True)
class RiskDifference:
    """The two results (``base``, ``changed``), the ``changes`` made, the difference of
    their fishtail probabilities (changed − base) and its 95 % ``interval``, and the
    discordant pairs (``only_base``: runs that fishtail in the base only)."""

    base: RiskResult
    changed: RiskResult
    changes: dict
    difference: float
    interval: tuple[float, float]
    only_base: int
    only_changed: int


def compare(tow, sea_state=None, changes=None, *, base_changes=None, **kw) -> RiskDifference:
    """`jaxtow.risk.irregular_sea` of ``tow`` with ``base_changes`` and with ``changes``
    (parameter name → value, `jaxtow.with_parameters` names, e.g. {"l0": 2.0}) on the same
    random numbers (module docstring); ``kw`` as for `irregular_sea`."""
    if not changes:
        raise ValueError("parameter 'changes': name at least one parameter to change")
    base = irregular_sea(tow, sea_state, parameters=dict(base_changes or {}), **kw)
    changed = irregular_sea(tow, sea_state, parameters={**(base_changes or {}), **changes}, **kw)
    both = base.completed & changed.completed
    a, b = base.fishtails & both, changed.fishtails & both
    n = max(int(np.sum(both)), 1)
    n10, n01 = int(np.sum(a & ~b)), int(np.sum(~a & b))
    d = (n01 - n10) / n
    se = math.sqrt(max((n10 + n01) - (n10 - n01) ** 2 / n, 0.0)) / n
    return RiskDifference(
        base=base,
        changed=changed,
        changes=dict(changes),
        difference=d,
        interval=(d - Z95 * se, d + Z95 * se),
        only_base=n10,
        only_changed=n01,
    )
