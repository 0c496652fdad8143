"""Addressing model parameters by name, for sweeps, sensitivities and the command line.

A parameter name is a field of the vessel (``m``, ``a22``, ``Yv`` ...), of the towline
(``l0``, ``xp``, ``yp``, ``EA``, ``Sb``, ``q``) or of the model (``psi_max``), the tug speed
``u_tug`` [m/s] (`jaxtow.at_tug_speed`: the towline stiffness' and every force scale follow
it; applied before the other parameters, so a towline stiffness' given with it refers to
the new speed), or a dotted
path into the model for anything else, e.g. ``external.omega`` and ``external.zeta_a`` of a
regular-wave drift force, ``external.spectrum.tp`` of an irregular one, or
``external.forces.1.speed`` inside a `CombinedForce`.
"""

from __future__ import annotations

import dataclasses
import functools

import equinox as eqx
import jax.numpy as jnp

from ._dynamics import TowModel, at_tug_speed
from ._rules import POSITIVE, rule_of
from ._vessel import VESSEL_PARAMETERS

PARAMETER_UNITS = {
    "l0": ("1", "unstretched towline length l0' (by L)"),
    "xp": ("1", "bow-hawser attachment point x_p' ahead of the CoG (by L)"),
    "yp": ("1", "transverse attachment offset y_p' to port (by L)"),
    "EA": ("1", "towline axial stiffness EA' (by 0.5 rho T L U_tug^2)"),
    "Sb": ("1", "power-law towline stiffness Sb' (by 0.5 rho T L U_tug^2)"),
    "q": ("1", "power-law towline exponent q"),
    "psi_max": ("rad", "largest trusted heading"),
    "u_tug": ("m s-1", "tug speed U_tug"),
    "external.omega": ("rad/s", "regular-wave frequency omega"),
    "external.zeta_a": ("m", "regular-wave amplitude zeta_a"),
    "external.spectrum.hs": ("m", "significant wave height Hs"),
    "external.spectrum.tp": ("s", "spectral peak period Tp"),
    "external.speed": ("m/s", "wind speed"),
}


def _parts(name: str) -> list:
    return name.split(".")


def _step(obj, part: str):
    return obj[int(part)] if part.isdigit() else getattr(obj, part)


def _resolve(model, name: str):
    try:
        return functools.reduce(_step, _parts(name), model)
    except (AttributeError, IndexError, TypeError):
        raise ValueError(f"unknown parameter {name!r}: the model has no such field path") from None


def _owner(model: TowModel, name: str) -> str:
    if "." in name:
        _resolve(model, name)
        return "path"
    if name in VESSEL_PARAMETERS:
        return "vessel"
    if name in {f.name for f in dataclasses.fields(model.towline)}:
        return "towline"
    if name == "psi_max":
        return "model"
    if name == "u_tug":
        return "tug"
    raise ValueError(
        f"unknown parameter {name!r}: expected a vessel field {VESSEL_PARAMETERS}, a towline "
        f"field of {type(model.towline).__name__}, 'psi_max' or 'u_tug'"
    )


def get_parameter(model: TowModel, name: str):
    owner = _owner(model, name)
    if owner == "path":
        return _resolve(model, name)
    if owner == "tug":
        ref = model.reference_scales
        if ref is None:
            raise ValueError("parameter 'u_tug': the model has no reference scales")
        return ref.u_tug
    obj = model if owner == "model" else getattr(model, owner)
    return getattr(obj, name)


def with_parameters(model: TowModel, **values) -> TowModel:
    """Copy of `model` with the named parameters replaced (works under jit and vmap).
    Concrete values are checked against each parameter's rule (`check_values`: the check
    the constructors make, which `eqx.tree_at` alone would bypass); traced ones are checked
    where the model is used (`TowModel.checks`)."""
    for name, val in values.items():
        check_values(model, name, val)
    if "u_tug" in values:  # first: the other non-dimensional values refer to the new speed
        values = dict(values)
        model = at_tug_speed(model, values.pop("u_tug"))
    for name, val in values.items():
        owner = _owner(model, name)
        if owner == "path":
            model = eqx.tree_at(lambda m, n=name: _resolve(m, n), model, jnp.asarray(val))
        elif owner == "model":
            model = eqx.tree_at(lambda m: m.psi_max, model, jnp.asarray(val))
        else:
            model = eqx.tree_at(
                lambda m, o=owner, n=name: getattr(getattr(m, o), n), model, jnp.asarray(val)
            )
    return model


def check_values(model: TowModel, name: str, values) -> None:
    """Eager check of concrete values for a parameter: a clear error naming it if invalid.

    Applies the rule declared on the field (`jaxtow._rules`), the same rule that checks the
    field at construction and under jit."""
    owner = _owner(model, name)
    if owner == "tug":
        if model.reference_scales is None:
            at_tug_speed(model, 1.0)  # the error that names the missing scales
        POSITIVE.check(name, values)
        return
    if owner == "path":
        parts = _parts(name)
        obj, field = functools.reduce(_step, parts[:-1], model), parts[-1]
    else:
        obj, field = (model if owner == "model" else getattr(model, owner)), name
    rule = rule_of(obj, field) if dataclasses.is_dataclass(obj) else None
    if rule is not None:
        rule.check(field, values)


def describe(name: str) -> tuple[str, str]:
    """(units, long name) of a parameter."""
    if name in PARAMETER_UNITS:
        return PARAMETER_UNITS[name]
    if name in VESSEL_PARAMETERS:
        return ("1", f"vessel parameter {name}' (non-dimensional, thesis Table 3.7 scales)")
    return ("1", name)
