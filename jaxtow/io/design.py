"""Labelled results of towline/bridle design and stability sensitivities (xarray)."""

from __future__ import annotations

import numpy as np
import xarray as xr

from .dataset import model_attributes


def design_dataset(result) -> xr.Dataset:
    """A `jaxtow.design.DesignResult` as a Dataset: the design point (variables as data),
    per-scenario abscissa / heading / tension, and for a grid search the objective on the grid."""
    data = {f"design_{k}": ((), v) for k, v in result.params.items()}
    data["objective"] = ((), result.objective)
    data["abscissa"] = (
        ("scenario",),
        result.abscissa,
        {"long_name": "max Re lambda at the design"},
    )
    data["psi"] = (("scenario",), result.psi, {"units": "rad", "long_name": "equilibrium heading"})
    data["tension"] = (("scenario",), result.tension, {"long_name": "towline tension T'"})
    coords = {"scenario": np.arange(result.abscissa.size)}
    if result.grid is not None:
        dims = tuple(f"grid_{k}" for k in result.grid)
        data["grid_objective"] = (dims, result.values)
        coords.update({f"grid_{k}": v for k, v in result.grid.items()})
    attrs = dict(
        method=result.method,
        n_evaluations=result.n_evaluations,
        converged=int(result.converged),
        stable=int(result.stable),
    )
    attrs.update({k: str(v) for k, v in (result.options or {}).items()})
    return xr.Dataset(data, coords=coords, attrs=attrs)


def sensitivity_dataset(
    names, values, gradients, abscissa, sweep=None, *, model=None
) -> xr.Dataset:
    """Dataset over (point, parameter) from `jaxtow.design.sensitivity_arrays`."""
    elasticity = values * gradients
    order = np.argsort(-np.mean(np.abs(elasticity), axis=0))
    rank = np.empty(len(names), int)
    rank[order] = np.arange(1, len(names) + 1)
    data = {
        "gradient": (("point", "parameter"), gradients, {"long_name": "d(max Re lambda)/dp"}),
        "elasticity": (
            ("point", "parameter"),
            elasticity,
            {"long_name": "p d(max Re lambda)/dp (change for a 100 % change of p)"},
        ),
        "value": (("point", "parameter"), values),
        "abscissa": (
            ("point",),
            abscissa,
            {"long_name": "max Re lambda, straight-behind equilibrium"},
        ),
        "importance": (
            ("parameter",),
            rank,
            {"long_name": "rank by mean |elasticity| (1 = matters most)"},
        ),
    }
    coords = {"parameter": list(names), "point": np.arange(abscissa.size)}
    if sweep is not None:
        coords[sweep[0]] = ("point", sweep[1])
    attrs = model_attributes(model) if model is not None else {}
    return xr.Dataset(data, coords=coords, attrs=attrs)
