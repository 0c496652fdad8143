"""Mean wave-drift forces as a tow-model force term (thesis eqs 6.14-6.16, 6.17-6.23)."""

from __future__ import annotations

import equinox as eqx
import jax.numpy as jnp
from jaxtyping import Array, Float

from .. import _rules as V
from .._units import G, Scales
from ..drift._damping import encounter_frequency, sailing_validity
from ..drift._methods import FROUDE_MAX
from ..drift._qtf import QTF
from ..drift._sailing import check_form, irregular_sailing_drift, sailing_drift
from ..waves import AbstractSpectrum, spectral_integral
from ._base import AbstractExternalForce


def _hull_validity(scales: Scales, y) -> tuple:
    """Speed U [m/s] of the vessel at state y and its Froude flags (Fn < 0.15)."""
    U = scales.u_tug * jnp.sqrt(y[0] ** 2 + y[1] ** 2)
    fn = U / jnp.sqrt(G * scales.length)
    return U, dict(froude=fn, froude_ok=fn < FROUDE_MAX)


class WaveDriftForce(AbstractExternalForce):
    """Mean drift in regular head waves (ω, ζa) on the towed vessel, for `TowModel.external`.

    At state (u', v', r', ·, ·, ψ) the relative wave heading is β = −ψ (head waves along the
    tug's track, docs/model.md section 4); the dimensional velocities u = u'U, v = v'U,
    r = r'U/L enter the sailing drift of `jaxtow.drift.sailing_drift` (``form``: Aranha's
    finite form by default; ``yaw_rate``: the yaw-rate damping column from the table's
    sectional moments, zero without them), and the result is made non-dimensional with
    ½ρTLU² (forces) and ½ρTL²U² (moment), eqs 6.14-6.16. With ζa = 0 the force is exactly
    zero.
    """

    qtf: QTF
    omega: jnp.ndarray = V.rule_field(rule=V.POSITIVE)
    zeta_a: jnp.ndarray = V.rule_field(rule=V.NONNEGATIVE)
    scales: Scales
    form: str = eqx.field(static=True, default="aranha")
    yaw_rate: bool = eqx.field(static=True, default=True)

    def __check_init__(self):
        check_form(self.form)

    def dimensional(self, y: Float[Array, "6"]) -> Float[Array, "3"]:
        """(Fx [N], Fy [N], Nz [N·m]) at non-dimensional state y."""
        U, L = self.scales.u_tug, self.scales.length
        u, v, r, psi = y[0] * U, y[1] * U, y[2] * U / L, y[5]
        F = sailing_drift(
            self.qtf, self.omega, -psi, u, v, r, form=self.form, yaw_rate=self.yaw_rate
        )
        return self.zeta_a**2 * F

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.scales.nondimensional(self.dimensional(y))

    def validity(self, y: Float[Array, "6"]) -> dict:
        """The model's validity limits at state y (docs/model.md section 8): Froude number
        Fn = U/√(gL) < 0.15; no flow separation, U/(ω ζa) < 1; τ = ωU/g small; encounter
        frequency ω_e > 0 (not overtaking the waves); the heading inside the table; and
        whether the yaw-rate damping column is present (the table has sectional moments)."""
        sc = self.scales
        U, out = _hull_validity(sc, y)
        sep = U / jnp.maximum(self.omega * self.zeta_a, 1e-300)
        out.update(separation_ratio=sep, no_separation=sep < 1.0)
        out.update(sailing_validity(self.omega, -y[5], y[0] * sc.u_tug, y[1] * sc.u_tug))
        out["heading_in_table"] = self.qtf.in_table(-y[5])
        out["yaw_rate_damping"] = jnp.asarray(self.qtf.has_sectional and self.yaw_rate)
        return out


class IrregularWaveDriftForce(AbstractExternalForce):
    """Mean drift in an irregular head sea (a `jaxtow.waves` spectrum, e.g. Jonswap(Hs, Tp))
    on the towed vessel: 2 ∫ S(ω) F_sail(ω, β = −ψ; u, v, r) dω, non-dimensional and with
    ``form`` and ``yaw_rate`` as in `WaveDriftForce`. ``omega``: the integration grid [rad/s]
    (check it with `jaxtow.waves.check_frequency_grid`)."""

    qtf: QTF
    spectrum: AbstractSpectrum
    omega: jnp.ndarray = V.rule_field(rule=V.POSITIVE)
    scales: Scales
    form: str = eqx.field(static=True, default="aranha")
    yaw_rate: bool = eqx.field(static=True, default=True)

    def __check_init__(self):
        check_form(self.form)

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
            form=self.form,
            yaw_rate=self.yaw_rate,
        )

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.scales.nondimensional(self.dimensional(y))

    def validity(self, y: Float[Array, "6"]) -> dict:
        """As `WaveDriftForce.validity`, for the sea state: the separation ratio with the
        peak frequency and the significant amplitude, U/(ω_p Hs/2); τ at the peak frequency;
        ``encounter_positive`` where no frequency carrying more than 0.1 % of the peak
        spectral density is overtaken (ω_e ≤ 0), with ``overtaken_energy`` the fraction of
        the spectrum's m0 at ω_e ≤ 0."""
        sc = self.scales
        U, out = _hull_validity(sc, y)
        wp = self.spectrum.omega_peak
        sep = U / jnp.maximum(wp * 0.5 * self.spectrum.hs, 1e-300)
        out.update(separation_ratio=sep, no_separation=sep < 1.0)
        u, v = y[0] * sc.u_tug, y[1] * sc.u_tug
        peak = sailing_validity(wp, -y[5], u, v)
        S = self.spectrum(self.omega)
        overtaken = encounter_frequency(self.omega, -y[5], u, v) <= 0
        m0 = spectral_integral(self.omega, S, jnp.ones_like(S))
        out.update(
            tau=peak["tau"],
            tau_ok=peak["tau_ok"],
            encounter_positive=~jnp.any(overtaken & (S > 1e-3 * jnp.max(S))),
            overtaken_energy=spectral_integral(self.omega, S, overtaken.astype(S.dtype)) / m0,
            heading_in_table=self.qtf.in_table(-y[5]),
            yaw_rate_damping=jnp.asarray(self.qtf.has_sectional and self.yaw_rate),
        )
        return out
