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

from collections.abc import Mapping

import jax
import numpy as np

from ._dynamics import TowModel
from ._parameters import check_values
from ._simulate import Simulation, simulate_batch as _simulate_batch
from ._sweep import make_batched_kernel, make_specialised_kernel, plan_sweep


def _dask():
    try:
        import dask
        import dask.array as da
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(
            'jaxtow.distributed needs Dask: pip install "jaxtow[dask]" (dask and dask.distributed)'
        ) from e
    return dask, da


def _evaluate_chunk(model, params: dict, options: dict, specialise: bool) -> dict:
    """One task: a chunk through the jitted sweep kernel (compiled once per process and
    option set; a specialised kernel once per process and model)."""
    kernel = (
        make_specialised_kernel(model, **options) if specialise else make_batched_kernel(**options)
    )
    return {k: np.asarray(v) for k, v in jax.device_get(kernel(model, params)).items()}


def _trimmed(result: dict, key: str, n: int):
    return result[key][:n]


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
    once (``client.persist``) and the Dataset's arrays are the futures of their results.
    Without it the Dataset stays lazy, and is computed by whichever Dask scheduler is active
    when it is computed or written. ``options``: those of `jaxtow.sweep_arrays` except
    ``devices``, ``kernel``, ``checkpoint`` and ``progress`` (a cluster's dashboard shows the
    progress; its tasks are retried by the scheduler when a worker is lost).
    """
    dask, da = _dask()
    from .io.dataset import sweep_dataset

    for bad in ("devices", "kernel", "checkpoint", "progress"):
        if bad in options:
            raise TypeError(f"jaxtow.distributed.sweep does not take parameter {bad!r}")
    method = options.get("method", "numerical")
    plan = plan_sweep(model, grid, chunk_size=chunk_size, **options)
    kernel = (
        make_specialised_kernel(model, **plan.options)
        if specialise
        else make_batched_kernel(**plan.options)
    )
    # the outputs' shapes and types, without computing anything
    spec = jax.eval_shape(kernel, model, plan.chunk_params(0))
    model_node = dask.delayed(model, pure=True)
    columns: dict[str, list] = {k: [] for k in spec}
    for c in range(plan.nchunks):
        lo, hi = plan.bounds(c)
        result = dask.delayed(_evaluate_chunk, pure=True)(
            model_node, plan.chunk_params(c), plan.options, specialise
        )
        for k, s in spec.items():
            part = dask.delayed(_trimmed, pure=True)(result, k, hi - lo)
            columns[k].append(da.from_delayed(part, (hi - lo, *s.shape[1:]), dtype=s.dtype))
    arrays = {}
    for k, parts in columns.items():
        flat = da.concatenate(parts, axis=0)
        arrays[k] = flat.reshape(plan.shape + flat.shape[1:], merge_chunks=True)
    if client is not None:
        arrays = dict(zip(arrays, client.persist(list(arrays.values()))))
    arrays["_coords"] = dict(zip(plan.names, plan.axes))
    arrays["_eig_method"] = plan.options["eig_method"]
    ds = sweep_dataset(model, arrays, method=method)
    ds.attrs["scheduler"] = "dask"
    return ds


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


__all__ = ["simulate_batch", "sweep"]
