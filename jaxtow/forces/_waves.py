"""Mean wave-drift forces as a tow-model force term (thesis eqs 6.14-6.16, 6.17-6.23)."""

from __future__ import annotations

import equinox as eqx
import jax.numpy as jnp
from jaxtyping import Array, Float

from .. import _rules as V
from .._units import G, Scales
from ..drift._qtf import QTF
from ..drift._sailing import encounter_frequency, irregular_sailing_drift, sailing_drift
from ..waves import AbstractSpectrum
from ._base import AbstractExternalForce


class WaveDriftForce(AbstractExternalForce):
    """Mean drift in regular head waves (ω, ζa) on the towed vessel, for `TowModel.external`.

    At state (u', v', r', ·, ·, ψ) the relative wave heading is β = −ψ (head waves along the
    tug's track, docs/model.md section 4); the dimensional velocities u = u'U, v = v'U,
    r = r'U/L enter the sailing drift F(ω_e, β) + B(ω_e, β)·(u, v, r) (eqs 2.38, 5.1), and
    the result is made non-dimensional with ½ρTLU² (forces) and ½ρTL²U² (moment), eqs
    6.14-6.16. With ζa = 0 the force is exactly zero.

    ``yaw_column``: optional yaw-rate column of B per ζa² (see `wave_drift_damping`).
    """

    qtf: QTF
    omega: jnp.ndarray = V.rule_field(rule=V.POSITIVE)
    zeta_a: jnp.ndarray = V.rule_field(rule=V.NONNEGATIVE)
    scales: Scales = eqx.field(static=True)
    yaw_column: jnp.ndarray | None = None

    def dimensional(self, y: Float[Array, "6"]) -> Float[Array, "3"]:
        """(Fx [N], Fy [N], Nz [N·m]) at non-dimensional state y."""
        U, L = self.scales.u_tug, self.scales.length
        u, v, r, psi = y[0] * U, y[1] * U, y[2] * U / L, y[5]
        F = sailing_drift(self.qtf, self.omega, -psi, u, v, r, yaw_column=self.yaw_column)
        return self.zeta_a**2 * F

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.scales.nondimensional(self.dimensional(y))

    def validity(self, y: Float[Array, "6"]) -> dict:
        """The thesis's validity limits at state y: Froude number Fn = U/√(gL) < 0.15, and no
        flow separation, U/(ω ζa) < 1 (docs/model.md section 8), plus the heading in the table."""
        U = self.scales.u_tug * jnp.sqrt(y[0] ** 2 + y[1] ** 2)
        fn = U / jnp.sqrt(G * self.scales.length)
        sep = U / jnp.maximum(self.omega * self.zeta_a, 1e-300)
        return dict(
            froude=fn,
            froude_ok=fn < 0.15,
            separation_ratio=sep,
            no_separation=sep < 1.0,
            heading_in_table=self.qtf.in_table(-y[5]),
            encounter_frequency=encounter_frequency(
                self.omega, -y[5], y[0] * self.scales.u_tug, y[1] * self.scales.u_tug
            ),
        )


class IrregularWaveDriftForce(AbstractExternalForce):
    """Mean drift in an irregular head sea (a `jaxtow.waves` spectrum, e.g. Jonswap(Hs, Tp))
    on the towed vessel: 2 ∫ S(ω) F_sail(ω, β = −ψ; u, v, r) dω, non-dimensional as in
    `WaveDriftForce`. ``omega``: the integration grid [rad/s] (check it with
    `jaxtow.waves.check_frequency_grid`)."""

    qtf: QTF
    spectrum: AbstractSpectrum
    omega: jnp.ndarray = V.rule_field(rule=V.POSITIVE)
    scales: Scales = eqx.field(static=True)
    yaw_column: jnp.ndarray | None = None

    def dimensional(self, y):
        U, L = self.scales.u_tug, self.scales.length
        return irregular_sailing_drift(
            self.qtf,
            self.omega,
            self.spectrum(self.omega),
            -y[5],
            y[0] * U,
            y[1] * U,
            y[2] * U / L,
            yaw_column=self.yaw_column,
        )

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.scales.nondimensional(self.dimensional(y))
