"""Sailing drift: the mean drift of a vessel moving through waves (thesis eqs 2.35-2.42, 5.1;
docs/model.md section 8). Every consumer (tow-model wave forces, irregular integrals, the
resistance budget) goes through `sailing_drift`."""

from __future__ import annotations

import jax
import jax.numpy as jnp
from jaxtyping import Array, ArrayLike, Float

from .._program_cache import host_program
from .._rules import guard, is_concrete
from .._units import G
from ..waves._irregular import mean_drift
from ..waves._spectra import check_ascending
from ._damping import (
    aranha,
    drift_and_damping,
    encounter_frequency,
    yaw_rate_damping,
)
from ._qtf import QTF

#: The forward-speed forms of `sailing_drift`.
FORMS = ("aranha", "linear", "thesis", "stationary")


def check_form(form: str) -> str:
    """A clear error naming ``form`` unless it is one of `FORMS`."""
    if form not in FORMS:
        raise ValueError(f"parameter 'form' must be one of {FORMS}, got {form!r}")
    return form


def sailing_drift(
    q: QTF,
    omega0: ArrayLike,
    beta: ArrayLike,
    u: ArrayLike,
    v: ArrayLike = 0.0,
    r: ArrayLike = 0.0,
    *,
    form: str = "aranha",
    yaw_rate: bool = True,
    g: float = G,
    throw: bool = True,
) -> Float[Array, "3"]:
    """Mean drift (Fx, Fy, Nz) per ζa² of a vessel moving with (u, v, r) [m/s, m/s, rad/s] in
    regular waves of absolute frequency ω0 from β.

    ``form``:

    * ``"aranha"`` (default): Aranha's finite form [1 + (4ω/g) U·ê] F(ω_e, β_e; 0) plus the
      yaw-rate column B_·6(ω, β) r (`jaxtow.drift.aranha`);
    * ``"linear"``: its linearisation F(ω, β) + B(ω, β)·(u, v, r) (eq. 2.38), no frequency
      shift;
    * ``"thesis"``: the thesis's reading F(ω_e, β) + B(ω_e, β)·(u, v, r) (eq. 2.38 with the
      encounter frequency of eq. 5.1), which counts the encounter-frequency shift twice (the
      ω ∂F/∂ω term of B is that shift); kept to reproduce the thesis;
    * ``"stationary"``: the zero-speed drift F(ω, β), no speed correction and no damping: the
      bound that holds where the forward-speed theory does not (a tow faster than the waves'
      orbital velocity), used by the study to say whether a verdict depends on it.

    ``yaw_rate=False`` drops the yaw-rate column (it is zero anyway when the table has no
    sectional moments).

    Overtaken waves (encounter frequency ω_e ≤ 0: following seas the vessel outruns) lie
    outside the forward-speed theory (τ = ω0 U/g ≥ 1 there, far beyond its small-τ range),
    which gives no drift (the QTF is zero at ω ≤ 0). ``throw=True`` (default) refuses them:
    a `ValueError` eagerly, `equinox.error_if` when traced, naming ω_e; ``throw=False``
    accepts the zero drift, as the tow model and the resistance budget do, which carry their
    own flags (``encounter_positive``, ``overtaken_energy``; `sailing_validity`).
    """
    check_form(form)
    F = _sailing_drift(q, omega0, beta, u, v, r, form=form, yaw_rate=yaw_rate, g=g)
    if not throw:
        return F
    we = encounter_frequency(omega0, beta, u, v, g=g)
    return guard(F, [(we <= 0, _overtaken_message(we, "omega_e"))])


@host_program(static_argnames=("form", "yaw_rate"))
def _sailing_drift(q: QTF, omega0, beta, u, v, r, *, form: str, yaw_rate: bool, g: float):
    u, v, r = (jnp.asarray(x, float) for x in (u, v, r))
    omega0 = jnp.asarray(omega0, float)
    if form == "stationary":
        F = q(omega0, beta)
    elif form == "thesis":
        we = encounter_frequency(omega0, beta, u, v, g=g)
        F0, B = drift_and_damping(q, we, beta, g=g)
        if not yaw_rate:
            B = B.at[:, 2].set(0.0)
        F = F0 + B @ jnp.stack([u, v, r])
    elif form == "linear":
        F0, B = drift_and_damping(q, omega0, beta, g=g)
        if not yaw_rate:
            B = B.at[:, 2].set(0.0)
        F = F0 + B @ jnp.stack([u, v, r])
    else:
        col_r = yaw_rate_damping(q, omega0, beta, g=g) if yaw_rate else jnp.zeros(3)
        F = aranha(q, omega0, beta, u, v, g=g) + col_r * r
    return F


def _overtaken_message(x, what: str) -> str:
    value = f" ({what} = {float(x):.4g})" if is_concrete(x) else ""
    return (
        f"the vessel overtakes the waves{value}: the encounter frequency is <= 0, outside the "
        "forward-speed drift theory (see jaxtow.drift.sailing_validity); pass throw=False to "
        "take the drift there as zero"
    )


def irregular_sailing_drift(
    q: QTF,
    omega: Float[ArrayLike, " nw"],
    S: Float[ArrayLike, " nw"],
    beta: ArrayLike,
    u: ArrayLike,
    v: ArrayLike = 0.0,
    r: ArrayLike = 0.0,
    *,
    form: str = "aranha",
    yaw_rate: bool = True,
    g: float = G,
    throw: bool = True,
) -> Float[Array, "3"]:
    """Mean drift in an irregular sea with forward speed: 2 ∫ S(ω0) F_sail(ω0) dω0
    (eq. 2.29 with `sailing_drift` of the given ``form``), per unit of the spectrum's scale.
    ``omega`` is the absolute wave-frequency grid of the spectrum ``S`` (see `jaxtow.waves`).

    ``throw=True`` refuses a sea the vessel partly outruns: a frequency carrying more than
    0.1 % of the peak spectral density with encounter frequency ≤ 0 (see `sailing_drift`;
    the error gives the share of m0 overtaken). ``throw=False`` counts no drift there."""
    check_form(form)
    check_ascending(omega)  # eagerly, before the program (which sees no values)
    out = _irregular_sailing_drift(q, omega, S, beta, u, v, r, form=form, yaw_rate=yaw_rate, g=g)
    if not throw:
        return out
    return guard(out, [overtaken_check(omega, S, beta, u, v, g=g)])


@host_program(static_argnames=("form", "yaw_rate"))
def _irregular_sailing_drift(q: QTF, omega, S, beta, u, v, r, *, form, yaw_rate, g):
    omega, S = jnp.asarray(omega), jnp.asarray(S)
    F = jax.vmap(
        lambda w: sailing_drift(q, w, beta, u, v, r, form=form, yaw_rate=yaw_rate, g=g, throw=False)
    )(omega)
    return mean_drift(omega, S, F)


def overtaken_check(omega, S, beta, u, v=0.0, *, g: float = G):
    """The check `irregular_sailing_drift` makes with ``throw=True``, as (predicate,
    message): the predicate holds where the vessel outruns part of the sea, a frequency
    carrying more than 0.1 % of the peak spectral density at encounter frequency ≤ 0."""
    significant, share = _overtaken(omega, S, beta, u, v, g=g)
    return significant, _overtaken_message(share, "share of the sea's m0")


@host_program()
def _overtaken(omega, S, beta, u, v, *, g: float):
    omega, S = jnp.asarray(omega), jnp.asarray(S)
    over = encounter_frequency(omega, beta, u, v, g=g) <= 0
    significant = jnp.any(over & (S > 1e-3 * jnp.max(S)))
    share = jnp.sum(jnp.where(over, S, 0.0)) / jnp.maximum(jnp.sum(S), 1e-300)
    return significant, share
