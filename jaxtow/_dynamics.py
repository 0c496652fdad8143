"""The tow model and its vector field, thesis eqs 6.1-6.6 (docs/model.md section 2).

State y = (u', v', r', l', γ, ψ): surge, sway, yaw rate of the towed vessel (body axes, at
the CoG), towline length, towline angle to the tug's track, heading. The tug moves at unit
non-dimensional speed along the earth x-axis and does not deviate (thesis assumption).
The bow-hawser point H lies at (−l cos γ, +l sin γ) relative to the tug, the CoG at
H − x_p (cos ψ, sin ψ); the towline pulls H toward the tug.

Transverse attachment offset (bridle studies, thesis section 8.4): with H at body
coordinates (x_p', y_p') (y to port) the towline force F = T'(cos(γ+ψ), −sin(γ+ψ)) in body
axes has the moment N = x_p' F_y − y_p' F_x = −T'(x_p' sin(γ+ψ) + y_p' cos(γ+ψ)), and H moves
with the body velocity (u' − r' y_p', v' + r' x_p'), which replaces (u', v' + r' x_p') in the
towline kinematics (eqs 6.4-6.5): l̇' gains + r' y_p' cos(γ+ψ) and γ̇ gains
− r' y_p' sin(γ+ψ)/l'. The CoG lies at H − x_p'(cos ψ, sin ψ) − y_p'(−sin ψ, cos ψ). With
y_p' = 0 every expression is the thesis's (the added terms are exactly zero).
"""

from __future__ import annotations

import math

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jaxtyping import Array, Float

from ._program_cache import host_program
from ._rules import POSITIVE, Checked, guard, in_range, is_concrete, rule_field
from ._towline import AbstractTowline
from ._units import Scales
from ._vessel import Vessel
from .forces._base import AbstractExternalForce, NoExternalForce

STATE_NAMES = ("u", "v", "r", "l", "gamma", "psi")
STATE_LONG_NAMES = (
    "surge velocity u' (by U_tug)",
    "sway velocity v' (by U_tug)",
    "yaw rate r' (by U_tug/L)",
    "towline length l' (by L)",
    "towline angle gamma [rad]",
    "heading psi [rad]",
)


class TowModel(Checked):
    """A vessel on a towline behind a tug: the full parameter set of eqs 6.1-6.6.

    ``psi_max``: largest |ψ| [rad] at which the manoeuvring model is trusted; equilibria
    beyond it are flagged (default π/2: the vessel must move bow first).

    ``scales``: the reference scales (L, T, ρ, U_tug) the non-dimensional towline and force
    parameters refer to. Optional: by default the scales of the external force are used
    (`reference_scales`); the tug speed can be changed (swept, differentiated) only when the
    model has them (`jaxtow.at_tug_speed`, parameter ``u_tug``). Every `Scales` inside the
    model must agree with them.
    """

    vessel: Vessel
    towline: AbstractTowline
    external: AbstractExternalForce = NoExternalForce()
    psi_max: Float[Array, ""] = rule_field(rule=in_range(0.0, math.pi), default=math.pi / 2)
    scales: Scales | None = None

    def __check_init__(self):
        found = all_scales(self)
        concrete = [s for s in found if is_concrete(s.u_tug)]
        keys = {(s.length, s.draft, s.rho, float(s.u_tug)) for s in concrete}
        if len(keys) > 1:
            raise ValueError(
                "parameter 'scales': the reference scales inside the model disagree "
                f"(length, draft, rho, u_tug) = {sorted(keys)}; build every force and the "
                "model with the same Scales"
            )

    @property
    def reference_scales(self) -> Scales | None:
        """The model's `Scales`: ``scales`` if given, else those of the external force (None
        for a calm-water model built without them)."""
        found = all_scales(self)
        return found[0] if found else None

    @property
    def assumed(self) -> tuple:
        """Values of this model that are documented estimates, not published data."""
        return self.vessel.assumed


def _is_scales(x) -> bool:
    return isinstance(x, Scales)


def all_scales(tree) -> list:
    """Every `Scales` inside a pytree (the model's own first)."""
    leaves = jax.tree_util.tree_leaves(tree, is_leaf=_is_scales)
    return [x for x in leaves if isinstance(x, Scales)]


def at_tug_speed(model: TowModel, u_tug) -> TowModel:
    """The model at tug speed ``u_tug`` [m/s] (pure, differentiable, works under jit/vmap).

    The non-dimensional force scale ½ρTLU² follows U_tug: the towline's stiffness' is
    multiplied by (U_old/U_tug)² (`AbstractTowline.rescaled`) and every `Scales` in the model
    (the model's and each force's) gets the new U_tug, so the wave, wind and current forces
    are made non-dimensional at the new speed. The vessel's non-dimensional derivatives and
    masses do not depend on U_tug (the usual assumption of the manoeuvring model at low
    Froude number, docs/model.md section 1). Needs the model's reference scales."""
    ref = model.reference_scales
    if ref is None:
        raise ValueError(
            "parameter 'u_tug': the model has no reference scales to change the tug speed of; "
            "build it with TowModel(..., scales=jaxtow.Scales(length=..., draft=..., u_tug=...))"
        )
    # eager (a zero speed made EA' infinite and the error named EA); a traced speed is checked
    # where the model is used, by the rule on `Scales.u_tug` (no host callback in the sweeps)
    POSITIVE.check("u_tug", u_tug)
    u_tug = jnp.asarray(u_tug, dtype=float)
    towline = model.towline.rescaled((ref.u_tug / u_tug) ** 2)
    model = eqx.tree_at(lambda m: m.towline, model, typed_like(model.towline, towline))
    n = len(all_scales(model))
    return eqx.tree_at(lambda m: [s.u_tug for s in all_scales(m)], model, [u_tug] * n)


def typed_like(old, new):
    """``new`` with each concrete scalar leaf as weakly typed as ``old``'s: a number times a
    strongly typed factor becomes strongly typed, and a model whose leaves differ from
    another's only in weak typing is a new argument type to every compiled kernel (a new
    trace and compile of each, at every other speed)."""

    def match(a, b):
        weak = getattr(a, "weak_type", None)
        if weak is None or not is_concrete(b) or np.ndim(b) != 0 or b.weak_type == weak:
            return b
        return jnp.asarray(float(b)) if weak else jnp.asarray(b, dtype=b.dtype)

    return jax.tree.map(match, old, new)


class ForceBreakdown(eqx.Module):
    """Forces acting on the vessel, per DOF (X', Y', N'), split by origin (each (3,)):
    ``manoeuvring`` (MMG hull forces), ``towline`` (eqs 2.8-2.10), ``coupling`` (the
    inertia-coupling terms (m+a22) v r, −(m+a11) u r, 0 of eqs 6.1-6.2), ``external`` (the
    environmental hook), ``inertia`` (the generalised masses (m+a11, m+a22, Izz+a66)); and
    the scalar ``tension`` T'."""

    manoeuvring: Float[Array, "3"]
    towline: Float[Array, "3"]
    coupling: Float[Array, "3"]
    external: Float[Array, "3"]
    inertia: Float[Array, "3"]
    tension: Float[Array, ""]

    @property
    def total(self) -> Float[Array, "3"]:
        """The sum of the forces (without the inertia)."""
        return self.manoeuvring + self.towline + self.coupling + self.external


def towline_force(y, towline) -> tuple[Float[Array, "3"], Float[Array, ""]]:
    """The towline's pull on the vessel (X', Y', N') at state y (eqs 2.8-2.10) and its
    tension T'."""
    l, gamma, psi = y[3], y[4], y[5]
    T = towline.tension(l)
    a = gamma + psi
    xp, yp = towline.xp, towline.yp
    pull = jnp.stack([T * jnp.cos(a), -T * jnp.sin(a), -T * (xp * jnp.sin(a) + yp * jnp.cos(a))])
    return pull, T


def force_breakdown(t, y, model: TowModel, *, throw: bool = True) -> ForceBreakdown:
    """The `ForceBreakdown` of the vessel at time t and state y. ``throw``: check the
    model's parameters (see `vector_field`)."""
    u, v, r = y[0], y[1], y[2]
    ves = model.vessel
    towline, T = towline_force(y, model.towline)
    coupling = jnp.stack([(ves.m + ves.a22) * v * r, -(ves.m + ves.a11) * u * r, jnp.zeros_like(r)])
    out = ForceBreakdown(
        manoeuvring=ves.manoeuvring_forces(u, v, r),
        towline=towline,
        coupling=coupling,
        external=model.external(t, y, model),
        inertia=ves.inertia(),
        tension=T,
    )
    return guard(out, model.checks()) if throw else out


def validity(model: TowModel, y, *, throw: bool = True) -> dict:
    """The physics' validity limits at state y, as named flags (True = valid) and the numbers
    behind them: ``line_taut`` (the towline carries tension; a slack line is outside the
    equilibrium theory of the tow), ``moving_ahead`` (u' > 0: the hull moves bow first
    through the water; a tow that has turned stern first, as a wild fishtail can, is
    outside the manoeuvring model, whose derivatives are for ahead motion) and the flags of the external force
    (`AbstractExternalForce.validity`, e.g. Froude number, flow separation, encounter
    frequency, heading in the table). Pure; vmap it over states."""
    y = jnp.asarray(y)
    out = {"line_taut": model.towline.tension(y[3]) > 0, "moving_ahead": y[0] > 0}
    out.update(model.external.validity(y))
    return guard(out, model.checks()) if throw else out


def all_valid(flags: dict):
    """The logical and of every boolean flag of a `validity` dict."""
    ok = jnp.asarray(True)
    for v in flags.values():
        v = jnp.asarray(v)
        if v.dtype == bool:
            ok = ok & v
    return ok


def kinematics(y, xp, yp=0.0) -> Float[Array, "3"]:
    """Towline kinematics (l̇', γ̇, ψ̇), thesis eqs 6.4-6.6 (docs/model.md section 2), with the
    transverse offset y_p' of the module docstring."""
    u, v, r, l, gamma, psi = (y[i] for i in range(6))
    a = gamma + psi
    # velocity of the attachment point (body axes); with yp = 0, uP = u exactly, so the
    # rest of the arithmetic is the thesis's whatever the compiler folds (batch = single runs)
    uP = u - r * yp
    vP = v + r * xp
    ldot = -uP * jnp.cos(a) + vP * jnp.sin(a) + jnp.cos(gamma)
    gdot = (uP * jnp.sin(a) + vP * jnp.cos(a) - jnp.sin(gamma)) / l
    return jnp.stack([ldot, gdot, r])


def vector_field(
    t, y: Float[Array, "6"], model: TowModel, *, throw: bool = True
) -> Float[Array, "6"]:
    """dy/dt' of the tow, thesis eqs 6.1-6.6; signature f(t, y, args) as in diffrax.
    ``y`` is the state (u', v', r', l', γ, ψ): shape (6,).

    ``throw=True`` (default): the model's parameters are checked, eagerly with a
    `ValueError`, and under `jax.jit`/`jax.vmap` with `equinox.error_if`, whose message
    names the parameter (under a plain `jax.jit` it stands below XLA's "CpuCallback error"
    line; `equinox.filter_jit` shows it first). ``throw=False``: no check, no host callback
    in the program; read `jaxtow.parameter_status` (a result code) instead. jaxtow's own
    compiled programs pass ``throw=False``: they check their models before running."""
    y = jnp.asarray(y)
    if y.shape != (6,):
        raise ValueError(
            f"y must be the state (u', v', r', l', gamma, psi) of shape (6,), got shape "
            f"{y.shape} (vmap the vector field over a batch of states)"
        )
    out = _vector_field(t, y, model)
    return guard(out, model.checks()) if throw else out


@host_program()
def _vector_field(t, y, model: TowModel):
    fb = force_breakdown(t, y, model, throw=False)
    return jnp.concatenate(
        [fb.total / fb.inertia, kinematics(y, model.towline.xp, model.towline.yp)]
    )


def unchecked_vector_field(t, y, model: TowModel):
    """`vector_field` with ``throw=False``, as a diffrax term's f(t, y, args)."""
    return vector_field(t, y, model, throw=False)


def sway_offset(y, xp, yp=0.0):
    """Sway offset of the CoG from the tug's track, y' = l' sin γ − x_p' sin ψ (eqs 2.16,
    2.18; − y_p' cos ψ with a transverse attachment offset); the fishtailing path width is
    its peak-to-peak value. NumPy in, NumPy out (a run's record, on the host)."""
    xnp = np if isinstance(y, np.ndarray) else jnp
    return y[..., 3] * xnp.sin(y[..., 4]) - xp * xnp.sin(y[..., 5]) - yp * xnp.cos(y[..., 5])
