"""Sweeps and batches of time-domain runs spread over processes or machines with Dask.

An optional extra (``pip install "jaxtow[dask]"``): without it nothing else changes. The work
is cut exactly as in one process: a sweep into the chunks of `jaxtow.sweep` (one task a
chunk, evaluated by the same jitted kernel, compiled once per worker process), a batch of
runs into slices of `jaxtow.simulate_batch` (`simulate_batch` here). The results therefore equal the single-process
ones (bitwise on the same kind of machine: the same program on the same inputs).

Any `dask.distributed` scheduler serves: a ``LocalCluster`` on one machine, or any Dask
cluster beyond it (for example through ``dask-jobqueue`` on an HPC batch scheduler)::

    from dask.distributed import Client, LocalCluster
    client = Client(LocalCluster(n_workers=2, threads_per_worker=1))
    ds = jaxtow.distributed.sweep(model, {"xp": xp, "l0": l0}, client=client)
    ds = ds.compute()   # or ds.to_netcdf(...): the chunks are computed as they are needed

Each worker process imports jaxtow, which enables float64 in JAX. One thread a worker is
the right setting: a worker's chunk already keeps its core busy.
"""

from __future__ import annotations

import operator
import pickle
import time
from collections.abc import Mapping

import jax
import numpy as np

from ._dynamics import TowModel
from ._parameters import check_values
from ._simulate import Simulation, simulate_batch as _simulate_batch
from ._sweep import make_batched_kernel, make_specialised_kernel, plan_sweep, sweep_options
from .io.dataset import sweep_dataset


def _dask():
    try:
        import dask
        import dask.array as da
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            'jaxtow.distributed needs Dask: pip install "jaxtow[dask]" (dask and dask.distributed)'
        ) from e
    return dask, da


def _canonical(model):
    """The model with NumPy leaves, whichever way it reached this process (a task's
    argument, ``client.run``): the array types (JAX or NumPy, weak or strong) are part of
    the compiled kernel's cache key, so every path then finds the same compiled kernel."""
    return jax.tree.map(
        lambda x: np.asarray(x) if isinstance(x, (jax.Array, np.ndarray)) else x, model
    )


def _evaluate_chunk(model, plan, c: int, specialise: bool) -> dict:
    """One task: chunk ``c`` of the plan (its points made here from the axes) through the
    jitted sweep kernel (compiled once per process and option set; a specialised kernel
    once per process and model), padding removed."""
    model = _canonical(model)
    options = plan.options
    kernel = (
        make_specialised_kernel(model, **options) if specialise else make_batched_kernel(**options)
    )
    return plan.trim(c, jax.device_get(kernel(model, plan.chunk_params(c))))


def sweep(
    model: TowModel,
    grid: Mapping[str, np.ndarray],
    *,
    client=None,
    chunk_size: int = 16384,
    specialise: bool = False,
    **options,
):
    """`jaxtow.sweep` as Dask tasks, one a chunk: a lazy `xarray.Dataset` backed by Dask
    arrays.

    The grid is checked here, before any task exists (an invalid value is an error naming
    it). ``client``: a `dask.distributed.Client`; given, the tasks start on its cluster at
    once (``client.persist``; this call returns when the first chunk is done) and the
    Dataset's arrays are the futures of their results.
    Without it the Dataset stays lazy, and is computed by whichever Dask scheduler is active
    when it is computed or written. ``options``: those of `jaxtow.sweep_arrays` except
    ``devices``, ``kernel``, ``checkpoint`` and ``progress`` (a cluster's dashboard shows the
    progress; its tasks are retried by the scheduler when a worker is lost).
    """
    dask, da = _dask()

    for bad in ("devices", "kernel", "checkpoint", "progress"):
        if bad in options:
            raise TypeError(f"jaxtow.distributed.sweep does not take parameter {bad!r}")
    solver, _ = sweep_options(**options)
    method = solver.method
    plan = plan_sweep(model, grid, solver, chunk_size=chunk_size)
    # the model and the plan (its axes, not its points) enter the graph once, as bytes: given
    # as objects, Dask takes dataclasses apart into the graph and rebuilds them by calling
    # their constructors on the worker
    model_node = dask.delayed(pickle.loads, pure=True)(pickle.dumps(model))
    plan_node = dask.delayed(pickle.loads, pure=True)(pickle.dumps(plan))
    results = [
        dask.delayed(_evaluate_chunk, pure=True)(model_node, plan_node, c, specialise)
        for c in range(plan.nchunks)
    ]
    if client is not None:
        # start every task now; the outputs' shapes and types come from the first chunk's
        # result on the cluster (tracing the kernel here would cost as much as compiling it)
        results = client.persist(results)
        spec = client.compute(dask.delayed(_spec)(results[0])).result()
    else:  # lazy: the shapes and types without computing anything
        kernel = (
            make_specialised_kernel(model, **plan.options)
            if specialise
            else make_batched_kernel(**plan.options)
        )
        spec = {
            k: (v.shape[1:], v.dtype)
            for k, v in jax.eval_shape(kernel, model, plan.chunk_params(0)).items()
        }
    columns: dict[str, list] = {k: [] for k in spec}
    for c, result in enumerate(results):
        lo, hi = plan.bounds(c)
        for k, (shape, dtype) in spec.items():
            part = dask.delayed(operator.getitem, pure=True)(result, k)
            columns[k].append(da.from_delayed(part, (hi - lo, *shape), dtype=dtype))
    arrays = {}
    for k, parts in columns.items():
        flat = da.concatenate(parts, axis=0)
        arrays[k] = flat.reshape(plan.shape + flat.shape[1:], merge_chunks=True)
    arrays["_coords"] = dict(zip(plan.names, plan.axes))
    arrays["_eig_method"] = plan.options["eig_method"]
    ds = sweep_dataset(model, arrays, method=method)
    ds.attrs["scheduler"] = "dask"
    return ds


def _spec(result: dict) -> dict:
    return {k: (v.shape[1:], v.dtype) for k, v in result.items()}


def _warm(model, plan, specialise: bool) -> float:
    t = time.perf_counter()
    _evaluate_chunk(model, plan, 0, specialise)
    return time.perf_counter() - t


def compile_on_workers(
    client,
    model: TowModel,
    grid: Mapping[str, np.ndarray],
    *,
    chunk_size: int = 16384,
    specialise: bool = False,
    **options,
) -> dict:
    """Compile the sweep kernel on every worker of ``client`` before a `sweep` with the same
    model structure, grid chunking and options (and run its first chunk once). Returns
    {worker address: seconds}. Without it each worker compiles on its first task."""
    _dask()
    plan = plan_sweep(model, grid, sweep_options(**options)[0], chunk_size=chunk_size)
    return client.run(_warm, model, plan, specialise)


def simulate_batch(
    model: TowModel,
    y0s,
    t1: float = 200.0,
    *,
    client,
    runs_per_task: int = 256,
    params: dict | None = None,
    **options,
) -> Simulation:
    """`jaxtow.simulate_batch` with its runs split into tasks of ``runs_per_task`` runs on a
    `dask.distributed.Client`, gathered into one `Simulation` (leading axis: the run, as
    from `jaxtow.simulate_batch`; NumPy arrays). ``options``: those of
    `jaxtow.simulate_batch`. Inputs are checked here, before any task is sent.

    With ``runs_per_task`` a multiple of ``batch_size`` every run is integrated in a vmapped
    group of the same width as in one process, and the results are bitwise equal; groups of
    other widths round differently in the last bits, which an unstable tow amplifies."""
    _dask()
    y0s = np.asarray(y0s, dtype=float)
    if y0s.ndim != 2 or y0s.shape[1] != 6:
        raise ValueError(f"parameter 'y0s' must have shape (B, 6), got {y0s.shape}")
    if int(runs_per_task) < 1:
        raise ValueError(f"parameter 'runs_per_task' must be >= 1, got {runs_per_task}")
    params = {k: np.asarray(v, dtype=float) for k, v in (params or {}).items()}
    for k, v in params.items():
        if v.shape != (y0s.shape[0],):
            raise ValueError(f"params[{k!r}] must have shape ({y0s.shape[0]},), got {v.shape}")
        check_values(model, k, v)
    n = int(runs_per_task)
    futures = [
        client.submit(
            _simulate_slice,
            model,
            y0s[lo : lo + n],
            t1,
            {k: v[lo : lo + n] for k, v in params.items()},
            options,
            pure=True,
        )
        for lo in range(0, y0s.shape[0], n)
    ]
    parts = client.gather(futures)
    return jax.tree.map(lambda *xs: np.concatenate(xs, axis=0), *parts)


def _simulate_slice(model, y0s, t1, params, options) -> Simulation:
    sim = _simulate_batch(model, y0s, t1, params=params or None, **options)
    return jax.tree.map(np.asarray, jax.device_get(sim))


__all__ = ["compile_on_workers", "simulate_batch", "sweep"]
