"""The statistics of a batch of runs, on the host in NumPy: a binomial proportion's interval,
the probability over another exposure, and the extreme-value fit of the largest tension.

* **Wilson's score interval** (Wilson 1927; recommended over the normal approximation by
  Brown, Cai & DasGupta 2001, *Statistical Science* 16(2)): for k events in n runs,

      p̃ ± z √(p̂(1 − p̂)/n + z²/4n²) / (1 + z²/n),   p̃ = (p̂ + z²/2n)/(1 + z²/n),

  which stays inside [0, 1] and gives a non-zero upper bound (≈ 3.8/n at 95 %) when no run
  fishtails.
* **Exposure**: runs of duration D are independent trials of the storm; over an exposure E
  the probability is 1 − (1 − p)^(E/D).
* **Largest tension**: the per-run maxima fitted by a Gumbel distribution by moments
  (scale s√6/π, location mean − 0.5772·scale). The most probable maximum (MPM) is its mode,
  the location; over an exposure E = m·D the maximum of m independent records is Gumbel with
  the same scale and the location shifted by scale·ln m.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

__all__ = ["Z95", "wilson_interval", "exposure_probability", "GumbelFit", "gumbel_fit"]

#: The standard normal quantile of a two-sided 95 % interval.
Z95 = 1.959963984540054
_EULER = 0.5772156649015329


def wilson_interval(k, n, z: float = Z95) -> tuple[float, float]:
    """Wilson's score interval (low, high) of a proportion: ``k`` events in ``n`` trials."""
    k, n = int(k), int(n)
    if n < 1 or not 0 <= k <= n:
        raise ValueError(f"parameters 'k', 'n': need 0 <= k <= n and n >= 1, got k={k}, n={n}")
    p = k / n
    den = 1.0 + z * z / n
    centre = (p + z * z / (2 * n)) / den
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / den
    return (0.0 if k == 0 else max(0.0, centre - half)), (
        1.0 if k == n else min(1.0, centre + half)
    )


def exposure_probability(p, duration, exposure):
    """The probability over ``exposure`` of an event whose probability over ``duration`` is
    ``p`` (the same units for both), treating the records as independent trials."""
    if duration <= 0 or exposure < 0:
        raise ValueError(
            f"parameters 'duration' > 0 and 'exposure' >= 0, got {duration}, {exposure}"
        )
    p = np.clip(np.asarray(p, float), 0.0, 1.0)
    return 1.0 - (1.0 - p) ** (exposure / duration)


@dataclasses.dataclass(frozen=True)
class GumbelFit:
    """A Gumbel distribution of a record's largest value: ``location`` (its mode, the most
    probable maximum) and ``scale``, both in the values' units."""

    location: float
    scale: float

    @property
    def mode(self) -> float:
        return self.location

    def over(self, records: float) -> GumbelFit:
        """The distribution of the largest of ``records`` independent records (a real number
        > 0: an exposure over the run's duration)."""
        if records <= 0:
            raise ValueError(f"parameter 'records' must be > 0, got {records}")
        return GumbelFit(self.location + self.scale * math.log(records), self.scale)

    def exceedance(self, x) -> np.ndarray:
        """P(maximum > x)."""
        s = max(self.scale, 1e-300)
        return 1.0 - np.exp(-np.exp(-(np.asarray(x, float) - self.location) / s))

    def quantile(self, q) -> np.ndarray:
        """The value the maximum stays below with probability ``q``."""
        return self.location - self.scale * np.log(-np.log(np.asarray(q, float)))


def gumbel_fit(maxima) -> GumbelFit:
    """The Gumbel fit by moments of a sample of record maxima (finite values only)."""
    x = np.asarray(maxima, float)
    x = x[np.isfinite(x)]
    if x.size < 2:
        raise ValueError("parameter 'maxima': need at least two finite record maxima")
    scale = float(np.std(x, ddof=1)) * math.sqrt(6.0) / math.pi
    return GumbelFit(float(np.mean(x)) - _EULER * scale, scale)
