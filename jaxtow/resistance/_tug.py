"""The tug's available pull against speed (thesis fig. 2.1)."""

from __future__ import annotations

import jax.numpy as jnp
import numpy as np

from .._interp import hermite
from .._rules import NONNEGATIVE, POSITIVE, Checked, in_range, rule_field


def _float(x):
    return jnp.asarray(x, dtype=float)


class Tug(Checked):
    """The tug's available pull against speed.

    Quadratic pull curve (default): P(U) = BP (1 − (U/U_free)²) with the bollard pull
    ``bollard_pull`` [N] and the free-running speed ``free_speed`` [m/s] where the pull
    vanishes; or a table (`Tug.from_table`) of pulls [N] at speeds [m/s] from 0, interpolated
    by a C¹ cubic Hermite curve. The towing ``efficiency`` η (e.g. 0.75 offshore) scales
    the pull; the tug's own calm-water resistance ``resistance_coefficient`` c [N s²/m²]
    adds R_tug = c U² to the budget (0 when the pull curve is already net of it, as the
    thesis's fig. 2.1).
    """

    bollard_pull: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    free_speed: jnp.ndarray = rule_field(rule=POSITIVE, converter=_float)
    efficiency: jnp.ndarray = rule_field(rule=in_range(1e-12, 1.0), converter=_float, default=1.0)
    resistance_coefficient: jnp.ndarray = rule_field(
        rule=NONNEGATIVE, converter=_float, default=0.0
    )
    speeds: jnp.ndarray | None = None
    pulls: jnp.ndarray | None = rule_field(rule=NONNEGATIVE, converter=lambda x: x, default=None)

    @classmethod
    def from_table(cls, speeds, pulls, *, efficiency=1.0, resistance_coefficient=0.0):
        """Pull curve from a table: ``speeds`` [m/s] ascending from 0, ``pulls`` [N] ≥ 0 with
        pulls[0] the bollard pull."""
        s, p = np.asarray(speeds, float), np.asarray(pulls, float)
        if s.ndim != 1 or s.size < 2 or s[0] != 0.0 or np.any(np.diff(s) <= 0):
            raise ValueError("parameter 'speeds' must ascend from 0 m/s (>= 2 points)")
        if p.shape != s.shape:
            raise ValueError("parameter 'pulls' must have the length of 'speeds'")
        if not np.all(np.isfinite(p)) or np.any(p < 0):
            raise ValueError(
                f"parameter 'pulls' must be >= 0 N (a tug pulls forward), got {p.tolist()}"
            )
        return cls(
            bollard_pull=p[0],
            free_speed=s[-1],
            efficiency=efficiency,
            resistance_coefficient=resistance_coefficient,
            speeds=jnp.asarray(s),
            pulls=jnp.asarray(p),
        )

    @property
    def max_speed(self):
        """Highest speed of the pull curve [m/s] (the free-running speed)."""
        return self.free_speed

    def shape(self, speed):
        """P(U)/BP."""
        if self.pulls is None:
            return 1.0 - (speed / self.free_speed) ** 2
        return hermite(self.speeds, self.pulls, speed) / self.bollard_pull

    def pull(self, speed):
        """Available pull η P(U) [N]."""
        return self.efficiency * self.bollard_pull * self.shape(speed)

    def resistance(self, speed):
        """The tug's own resistance c U|U| [N]."""
        return self.resistance_coefficient * speed * jnp.abs(speed)
