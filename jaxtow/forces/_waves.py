"""Mean wave-drift forces as a tow-model force term (thesis eqs 6.14-6.16, 6.17-6.23)."""

from __future__ import annotations

import dataclasses

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Float

from .._interp import cell_index
from .._rules import FINITE, NONNEGATIVE, POSITIVE, check_type, rule_field
from .._units import G, Scales
from ..drift._damping import encounter_frequency, sailing_validity
from ..drift._methods import FROUDE_MAX
from ..drift._qtf import QTF, FullQTF
from ..drift._sailing import check_form, irregular_sailing_drift, sailing_drift
from ..waves import AbstractSpectrum, spectral_integral
from ..waves._spectra import check_ascending
from ._base import AbstractExternalForce


def _hull_validity(scales: Scales, y) -> tuple:
    """Speed U [m/s] of the vessel at state y and its Froude flags (Fn < 0.15)."""
    U = scales.u_tug * jnp.sqrt(y[0] ** 2 + y[1] ** 2)
    fn = U / jnp.sqrt(G * scales.length)
    return U, dict(froude=fn, froude_ok=fn < FROUDE_MAX)


def _steady(self):
    """`AbstractExternalForce.steady` of the wave-drift forces: the yaw-rate damping column
    multiplies r, zero in a steady tow."""
    return dataclasses.replace(self, yaw_rate=False)


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
    omega: jnp.ndarray = rule_field(rule=POSITIVE)
    zeta_a: jnp.ndarray = rule_field(rule=NONNEGATIVE)
    scales: Scales
    form: str = eqx.field(static=True, default="aranha")
    yaw_rate: bool = eqx.field(static=True, default=True)
    steady = _steady

    def __check_init__(self):
        check_form(self.form)
        check_type("qtf", self.qtf, QTF)
        check_type("scales", self.scales, Scales)

    def dimensional(self, y: Float[Array, "6"]) -> Float[Array, "3"]:
        """(Fx [N], Fy [N], Nz [N·m]) at non-dimensional state y."""
        U, L = self.scales.u_tug, self.scales.length
        u, v, r, psi = y[0] * U, y[1] * U, y[2] * U / L, y[5]
        F = sailing_drift(
            self.qtf,
            self.omega,
            -psi,
            u,
            v,
            r,
            form=self.form,
            yaw_rate=self.yaw_rate,
            throw=False,
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
    """Mean drift in an irregular sea (a `jaxtow.waves` spectrum, e.g. Jonswap(Hs, Tp)) on
    the towed vessel: 2 ∫ S(ω) F_sail(ω, β = α − ψ; u, v, r) dω, non-dimensional and with
    ``form`` and ``yaw_rate`` as in `WaveDriftForce`; the waves come from ``angle`` α [rad]
    relative to the tug's course (0: head seas, the thesis's case). ``omega``: the
    integration grid [rad/s] (check it with `jaxtow.waves.check_frequency_grid`)."""

    qtf: QTF
    spectrum: AbstractSpectrum
    omega: jnp.ndarray = rule_field(rule=POSITIVE)
    scales: Scales
    form: str = eqx.field(static=True, default="aranha")
    yaw_rate: bool = eqx.field(static=True, default=True)
    angle: jnp.ndarray = rule_field(rule=FINITE, default=0.0)
    steady = _steady

    def __check_init__(self):
        check_form(self.form)
        check_type("qtf", self.qtf, QTF)
        check_type("scales", self.scales, Scales)
        check_ascending(self.omega)

    def dimensional(self, y):
        U, L = self.scales.u_tug, self.scales.length
        return irregular_sailing_drift(
            self.qtf,
            self.omega,
            self.spectrum.density(self.omega),
            self.angle - y[5],
            y[0] * U,
            y[1] * U,
            y[2] * U / L,
            form=self.form,
            yaw_rate=self.yaw_rate,
            throw=False,
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
        beta = self.angle - y[5]
        peak = sailing_validity(wp, beta, u, v)
        S = self.spectrum.density(self.omega)
        overtaken = encounter_frequency(self.omega, beta, u, v) <= 0
        m0 = spectral_integral(self.omega, S, jnp.ones_like(S))
        out.update(
            tau=peak["tau"],
            tau_ok=peak["tau_ok"],
            encounter_positive=~jnp.any(overtaken & (S > 1e-3 * jnp.max(S))),
            overtaken_energy=spectral_integral(self.omega, S, overtaken.astype(S.dtype)) / m0,
            heading_in_table=self.qtf.in_table(beta),
            yaw_rate_damping=jnp.asarray(self.qtf.has_sectional and self.yaw_rate),
        )
        return out


def _nodes(omega, lo: float, hi: float, k: int | None) -> dict:
    """The ``nodes`` and ``node_weights`` fields of a `SlowDriftForce` (empty for None): k
    equally spaced nodes over [lo, hi] and the Catmull-Rom cubic weights that carry values
    at the nodes to ``omega`` (exact for cubics inside, one-sided at the ends)."""
    if k is None:
        return {}
    if not (isinstance(k, int) and k >= 4):
        raise ValueError(f"parameter 'nodes' must be an integer >= 4 or None, got {k!r}")
    nodes = np.linspace(lo, hi, k)
    x = np.clip((np.asarray(omega) - lo) / (nodes[1] - nodes[0]), 0.0, k - 1 - 1e-12)
    j = np.floor(x).astype(int)
    t = x - j
    basis = (
        (-(t**3) + 2 * t**2 - t) / 2,
        (3 * t**3 - 5 * t**2 + 2) / 2,
        (-3 * t**3 + 4 * t**2 + t) / 2,
        (t**3 - t**2) / 2,
    )
    weights = np.zeros((x.size, k))
    rows = np.arange(x.size)
    for offset, b in zip((-1, 0, 1, 2), basis):
        np.add.at(weights, (rows, np.clip(j + offset, 0, k - 1)), b)
    return dict(nodes=jnp.asarray(nodes), node_weights=jnp.asarray(weights))


class SlowDriftForce(AbstractExternalForce):
    """Mean plus slowly varying drift in an irregular sea, Newman's approximation, for
    time-domain runs (thesis 6.3 uses the mean only).

    The sea is the sum of ``n`` seeded components ζ_i = a_i cos(ω_e,i t + ε_i), a_i =
    √(2 S(ω_i) Δω_i), with one random frequency in each of ``n`` equal bins (so the record
    does not repeat), coming from ``angle`` α relative to the tug's course (0: head seas), and
    ω_e,i = ω_i + (ω_i²/g) U_tug cos α the encounter frequency on the tug's track
    (`jaxtow.drift.encounter_frequency`). With T_i the sailing mean drift per ζa² at ω_i
    (`jaxtow.drift.sailing_drift` at the vessel's state and heading β = α − ψ,
    ``form``/``yaw_rate`` as in `IrregularWaveDriftForce`),
    the force is the difference-frequency double sum with Newman's off-diagonal
    T_ij = (T_i + T_j)/2:

        F(t) = Σ_i Σ_j a_i a_j T_ij cos((ω_e,i − ω_e,j) t + ε_i − ε_j) = Re[A(t) Z(t)*],
        A = Σ_i a_i T_i e^{iφ_i},  Z = Σ_i a_i e^{iφ_i},

    evaluated in O(n). Its time average is Σ a_i² T_i = 2 ∫ S T dω, the mean drift. Newman's
    approximation needs T to vary slowly with ω over the difference frequencies that matter
    (the tow's slow yaw and sway periods).

    With a full difference-frequency QTF (``seeded(..., full_qtf=...)``, a
    `jaxtow.drift.FullQTF`) the force adds what Newman's approximation leaves out,

        ΔF(t) = Re Σ_i Σ_j z_i z_j* D_ij(β),   D_ij = T_ij − (T_ii + T_jj)/2,

    with T_ij the full QTF at the component frequencies (bilinear in (ω_i, ω_j)) and D
    linear in β between its headings (clamped outside them, periodic on a full circle). So
    the mean and its forward-speed correction stay those of the mean-drift table (D_ii =
    0), and the off-diagonal terms are the full QTF's (at zero speed). Components outside
    the full QTF's frequency range keep Newman's approximation (``full_qtf_energy`` gives
    the share of the spectrum inside it). Build with `seeded`; ``validity`` is that of the
    mean force."""

    qtf: QTF
    spectrum: AbstractSpectrum
    omega: jnp.ndarray = rule_field(rule=POSITIVE)
    domega: jnp.ndarray = rule_field(rule=POSITIVE)
    phase: jnp.ndarray
    scales: Scales
    form: str = eqx.field(static=True, default="aranha")
    yaw_rate: bool = eqx.field(static=True, default=True)
    steady = _steady
    offdiagonal: Array | None = None  # (nβ, 3, n, n) complex D_ij of the full QTF
    offdiagonal_beta: Array | None = None  # (nβ,) its headings [rad]
    full_qtf_energy: Array | None = None  # share of Σ a_i² inside the full QTF's range
    angle: jnp.ndarray = rule_field(rule=FINITE, default=0.0)
    nodes: Array | None = None  # (K,) frequencies where T is evaluated [rad/s]
    node_weights: Array | None = None  # (n, K) cubic interpolation from the nodes

    def __check_init__(self):
        check_form(self.form)

    @classmethod
    def seeded(
        cls,
        qtf: QTF,
        spectrum: AbstractSpectrum,
        scales: Scales,
        *,
        seed: int = 0,
        n: int = 256,
        omega_range=(0.1, 4.0),
        form: str = "aranha",
        yaw_rate: bool = True,
        full_qtf=None,
        angle: float = 0.0,
        nodes: int | None = None,
    ) -> SlowDriftForce:
        """Components from ``seed``: ``n`` bins over ``omega_range`` [rad/s]; ``full_qtf``
        (a `jaxtow.drift.FullQTF`) replaces Newman's off-diagonal terms by the full QTF's;
        ``angle`` [rad] the direction the waves come from (0: ahead); ``nodes``: evaluate the
        drift T at that many equally spaced frequencies over ``omega_range`` and interpolate
        it to the components by cubic (Catmull-Rom) weights (a run's cost is that of the nodes, not of the
        components; None: at every component)."""

        if not (isinstance(n, int) and n >= 2):
            raise ValueError(f"parameter 'n' must be an integer >= 2, got {n!r}")
        lo, hi = (float(w) for w in omega_range)
        if not (0 < lo < hi):
            raise ValueError(
                f"parameter 'omega_range' must be (low, high) with 0 < low < high, got {omega_range!r}"
            )
        rng = np.random.default_rng(seed)
        edges = np.linspace(lo, hi, n + 1)
        w = edges[:-1] + rng.uniform(size=n) * np.diff(edges)
        off = off_b = share = None
        if full_qtf is not None:
            if not isinstance(full_qtf, FullQTF):
                raise TypeError(
                    f"parameter 'full_qtf' must be a jaxtow.drift.FullQTF, got {type(full_qtf).__name__}"
                )
            T, inside = full_qtf.at(w)  # (3, n, n, nβ)
            d = np.real(np.diagonal(T, axis1=1, axis2=2))  # (3, nβ, n)
            D = T - 0.5 * (
                d.transpose(0, 2, 1)[:, :, None, :] + d.transpose(0, 2, 1)[:, None, :, :]
            )
            D = np.where((inside[:, None] & inside[None, :])[None, :, :, None], D, 0.0)
            off = jnp.asarray(np.moveaxis(D, -1, 0))
            off_b = full_qtf.beta
            a2 = 2.0 * np.asarray(spectrum(jnp.asarray(w))) * np.diff(edges)
            share = jnp.asarray(float(np.sum(a2[inside]) / max(np.sum(a2), 1e-300)))
        return cls(
            qtf=qtf,
            spectrum=spectrum,
            omega=jnp.asarray(w),
            domega=jnp.asarray(np.diff(edges)),
            phase=jnp.asarray(rng.uniform(0.0, 2 * np.pi, n)),
            scales=scales,
            form=form,
            yaw_rate=yaw_rate,
            offdiagonal=off,
            offdiagonal_beta=off_b,
            full_qtf_energy=share,
            angle=jnp.asarray(float(angle)),
            **_nodes(w, lo, hi, nodes),
        )

    def amplitudes(self):
        """a_i = √(2 S(ω_i) Δω_i) [m]."""
        return jnp.sqrt(2.0 * self.spectrum.density(self.omega) * self.domega)

    def encounter(self):
        """ω_e,i [rad/s]: the components' frequencies on the tug's track."""
        return encounter_frequency(self.omega, self.angle, self.scales.u_tug)

    def components(self, t):
        """z_i = a_i e^{i(ω_e,i t + ε_i)} at non-dimensional time t (complex, (n,))."""
        sc = self.scales
        ts = t * sc.length / sc.u_tug
        return self.amplitudes() * jnp.exp(1j * (self.encounter() * ts + self.phase))

    def dimensional(self, t, y):
        """(Fx [N], Fy [N], Nz [N·m]) at non-dimensional time t and state y."""

        z = self.components(t)
        if self.nodes is None:
            A = jnp.sum(z[:, None] * self.transfer(y), axis=0)
        else:  # Σ_i z_i Σ_k W_ik T_k = Σ_k (Σ_i z_i W_ik) T_k: the drift at the nodes only
            assert self.node_weights is not None  # set with the nodes
            A = jnp.sum((z @ self.node_weights)[:, None] * self._drift(self.nodes, y), axis=0)
        F = jnp.real(A * jnp.conj(jnp.sum(z)))
        if self.offdiagonal is None:
            return F
        D = self._offdiagonal_at(self.angle - y[5])  # (3, n, n)
        return F + jnp.real(jnp.einsum("i,cij,j->c", z, D, jnp.conj(z)))

    def _drift(self, omega, y):
        """The sailing mean drift per ζa² (n, 3) at the frequencies ``omega`` and state y."""
        U, L = self.scales.u_tug, self.scales.length
        u, v, r, psi = y[0] * U, y[1] * U, y[2] * U / L, y[5]
        return jax.vmap(
            lambda w: sailing_drift(
                self.qtf,
                w,
                self.angle - psi,
                u,
                v,
                r,
                form=self.form,
                yaw_rate=self.yaw_rate,
                throw=False,
            )
        )(omega)

    def transfer(self, y):
        """T_i (n, 3): the sailing mean drift per ζa² at each component's frequency and the
        state y (interpolated from the ``nodes`` where it has them) [N/m², N·m/m²]."""
        if self.nodes is None:
            return self._drift(self.omega, y)
        assert self.node_weights is not None  # set with the nodes
        return self.node_weights @ self._drift(self.nodes, y)

    def _offdiagonal_at(self, beta):
        """D(β), linear between the full QTF's headings; clamped, or periodic on a circle."""
        b, D = self.offdiagonal_beta, self.offdiagonal
        assert b is not None and D is not None
        if b.shape[0] == 1:
            return D[0]
        full = (jnp.abs(b[0] + jnp.pi) < 1e-9) & (jnp.abs(b[-1] - jnp.pi) < 1e-9)
        beta = jnp.where(full, jnp.mod(beta + jnp.pi, 2 * jnp.pi) - jnp.pi, beta)
        beta = jnp.clip(beta, b[0], b[-1])
        k = cell_index(b, beta)
        f = (beta - b[k]) / (b[k + 1] - b[k])
        return D[k] * (1 - f) + D[k + 1] * f

    def __call__(self, t, y: Float[Array, "6"], model) -> Float[Array, "3"]:
        return self.scales.nondimensional(self.dimensional(t, y))

    def mean_force(self) -> IrregularWaveDriftForce:
        """The mean drift of the same sea on the component grid."""
        return IrregularWaveDriftForce(
            qtf=self.qtf,
            spectrum=self.spectrum,
            omega=self.omega,
            scales=self.scales,
            form=self.form,
            yaw_rate=self.yaw_rate,
            angle=self.angle,
        )

    def validity(self, y: Float[Array, "6"]) -> dict:
        """That of the mean force (`IrregularWaveDriftForce.validity`)."""
        return self.mean_force().validity(y)
