"""Two variants of a tow on the same random numbers: the change of the fishtailing
probability with a design parameter (x_p, l0, a skeg span...) that is not drowned in the
Monte Carlo's noise.

Both variants run with the same seed and settings, so each run of one meets the same waves,
gusts and start heading as its partner in the other (common random numbers). The difference
of the two probabilities is then the difference of the discordant pairs,
d = (n₀₁ − n₁₀)/n (changed − base), with the paired standard error
√((n₁₀ + n₀₁) − (n₁₀ − n₀₁)²/n)/n; its 95 % interval is d ± 1.96 s.e. (clipped to ±1).
Whether the change is real is McNemar's exact test: under no effect each discordant pair
is equally likely either way, so the two-sided p-value is the binomial tail
2·P(X ≤ min(n₁₀, n₀₁)), X ~ B(n₁₀ + n₀₁, ½) (at most 1). With few discordant pairs no
difference is significant (five pairs all one way give p = 0.0625).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ._montecarlo import RiskResult, irregular_sea
from ._stats import Z95

__all__ = ["RiskDifference", "compare", "difference"]


@dataclasses.dataclass(frozen=True)
class RiskDifference:
    """The two results (``base``, ``changed``), the ``changes`` made, the difference of
    their fishtail probabilities (changed − base) and its 95 % ``interval``, the discordant
    pairs (``only_base``: runs that fishtail in the base only) and McNemar's exact
    ``p_value``."""

    base: RiskResult
    changed: RiskResult
    changes: dict
    difference: float
    interval: tuple[float, float]
    only_base: int
    only_changed: int
    p_value: float

    @property
    def significant(self) -> bool:
        """McNemar's exact test rejects "no effect" at the 5 % level."""
        return self.p_value < 0.05


def compare(tow, sea_state=None, changes=None, *, base_changes=None, **kw) -> RiskDifference:
    """`jaxtow.risk.irregular_sea` of ``tow`` with ``base_changes`` and with ``changes``
    (parameter name → value, `jaxtow.with_parameters` names, e.g. {"l0": 2.0}) on the same
    random numbers (module docstring); ``kw`` as for `irregular_sea`."""
    if not changes:
        raise ValueError("parameter 'changes': name at least one parameter to change")
    base = irregular_sea(tow, sea_state, parameters=dict(base_changes or {}), **kw)
    changed = irregular_sea(tow, sea_state, parameters={**(base_changes or {}), **changes}, **kw)
    return difference(base, changed, changes)


def difference(base: RiskResult, changed: RiskResult, changes=None) -> RiskDifference:
    """The paired difference of two results run from the same seed and settings (their
    first k runs meet the same random numbers, k the smaller batch)."""
    k = min(base.completed.size, changed.completed.size)
    both = base.completed[:k] & changed.completed[:k]
    a, b = base.fishtails[:k] & both, changed.fishtails[:k] & both
    n = max(int(np.sum(both)), 1)
    n10, n01 = int(np.sum(a & ~b)), int(np.sum(~a & b))
    d = (n01 - n10) / n
    se = math.sqrt(max((n10 + n01) - (n10 - n01) ** 2 / n, 0.0)) / n
    m = n10 + n01
    tail = sum(math.comb(m, i) for i in range(min(n10, n01) + 1)) / 2.0**m if m else 1.0
    return RiskDifference(
        base=base,
        changed=changed,
        changes=dict(changes or {}),
        difference=d,
        interval=(max(d - Z95 * se, -1.0), min(d + Z95 * se, 1.0)),
        only_base=n10,
        only_changed=n01,
        p_value=min(1.0, 2.0 * tail),
    )
