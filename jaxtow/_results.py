"""Labelled results of the numerical functions: a sweep or a sensitivity study as an
`xarray.Dataset` with coordinates, units and provenance. The numerics return arrays and
result objects (`jaxtow.sweep_arrays`, `jaxtow.design.sensitivity_arrays`); `jaxtow.io` turns
them into datasets; this module joins the two for the common case."""

from __future__ import annotations

import os
from collections.abc import Mapping

import numpy as np

from ._dynamics import TowModel
from ._progress import progress_meter
from ._sweep import SweepExecution, SweepSolver, sweep_arrays, sweep_options
from .design import sensitivity_arrays
from .io.checkpoint import Checkpoint
from .io.dataset import sweep_dataset
from .io.design import sensitivity_dataset


def sweep(
    model: TowModel,
    grid: Mapping[str, np.ndarray],
    solver: SweepSolver | None = None,
    execution: SweepExecution | None = None,
    *,
    progress: bool = False,
    checkpoint=None,
    **options,
):
    """`jaxtow.sweep_arrays` as an `xarray.Dataset` with coordinates, units and provenance.
    The options are a `jaxtow.SweepSolver` and a `jaxtow.SweepExecution`, or their fields
    as keywords (``method="analytic"``, ``chunk_size=4096``, ...). ``progress=True`` shows a
    bar; ``checkpoint``: a folder (or a `jaxtow.io.Checkpoint`) where each finished chunk is
    kept, so that a sweep run again with the same folder computes only the chunks that are
    missing."""
    if options:
        if solver is not None or execution is not None:
            raise TypeError("give the sweep's options as objects or as keywords, not both")
        solver, execution = sweep_options(**options)
    solver = SweepSolver() if solver is None else solver
    if isinstance(checkpoint, str | os.PathLike):
        checkpoint = Checkpoint(checkpoint)
    arrays = sweep_arrays(
        model,
        grid,
        solver,
        execution,
        progress_meter=progress_meter(progress),
        checkpoint=checkpoint,
    )
    return sweep_dataset(model, arrays, method=solver.method)


def sensitivities(model: TowModel, parameters=None, *, sweep: dict | None = None, psi0=0.0):
    """Sensitivity of the stability margin to every (uncertain) input, as an xarray Dataset
    over (point, parameter): ``gradient`` ∂(max Re λ)/∂p, ``elasticity`` p·∂(max Re λ)/∂p
    (the change of max Re λ for a 100 % change of p: comparable across parameters),
    ``value`` p, ``abscissa``, and ``importance``, the rank by mean |elasticity| (1 = largest). See
    `jaxtow.design.sensitivity_arrays` for the arguments."""
    return sensitivity_dataset(
        *sensitivity_arrays(model, parameters, sweep=sweep, psi0=psi0), model=model
    )
