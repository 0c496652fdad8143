"""Vectorised parameter sweeps: grids → one vmapped, jitted kernel → labelled results.

A sweep evaluates, at every point of a Cartesian grid of named parameters (see
`jaxtow.with_parameters`), all equilibria and their linear stability. The kernel for one point is
lifted with `jax.vmap`; the grid is flattened and processed in chunks of ``chunk_size``
points (memory stays bounded, a progress bar advances), each chunk sharded across all
available JAX devices with `jax.sharding` (a 1-D mesh over the point axis). The kernel is
compiled once per chunk shape and reused across chunks and across models of the same
structure.

`sweep_arrays` returns plain NumPy arrays; `jaxtow.sweep` wraps them in an `xarray.Dataset`
(assembled in `jaxtow.io.dataset`: this module imports no file format). Progress and
checkpoints are objects passed in (``progress_meter=``, ``checkpoint=``).
"""

from __future__ import annotations

import dataclasses
import functools
import math
import os
from collections.abc import Callable, Mapping, Sequence

import equinox as eqx
import jax
import jax.numpy as jnp
import numpy as np
from jax.sharding import Mesh, NamedSharding, PartitionSpec as P

from ._dynamics import TowModel, all_valid, validity
from ._equilibrium import analytic_equilibria, equilibria_fixed
from ._parameters import check_values, with_parameters
from ._program_cache import cached_call
from ._progress import AbstractProgressMeter, NoProgressMeter
from ._stability import (
    ABSCISSA_METHODS,
    EIG_METHODS,
    classify,
    default_eig_method,
    jacobian,
    matrix_eigenvalues,
    matrix_routh_hurwitz_stable,
    spectral_abscissa,
)

#: Per-slot equilibrium outputs (trailing dimension: equilibrium slot).
SLOT_FIELDS = (
    "psi",
    "gamma",
    "tension",
    "length",
    "found",
    "converged",
    "taut",
    "behind_tug",
    "in_range",
    "valid",
    "branch",
    "residual",
)


def point_kernel(
    model: TowModel,
    params: Mapping[str, jnp.ndarray],
    *,
    method: str = "numerical",
    n_grid: int = 2001,
    max_roots: int = 4,
    psi_range: float = math.pi / 2,
    routh_hurwitz: bool = True,
    eig_method: str | None = None,
) -> dict:
    """Equilibria and stability at one parameter point (pure; vmap it over points).

    ``routh_hurwitz=False`` drops the Routh-Hurwitz cross-check (about a third of the cost
    of the calm-water kernel) when only the eigenvalues are wanted. ``eig_method``: one of
    `ABSCISSA_METHODS`: "lapack" or "polynomial" compute every eigenvalue
    (`jaxtow.eigenvalues`; outputs ``eig_real``, ``eig_imag``), "routh" only max Re λ
    (`jaxtow.spectral_abscissa`, about 3x cheaper; no eigenvalue outputs).
    """
    mdl = with_parameters(model, **params)
    if method == "analytic":
        eqs = analytic_equilibria(mdl, throw=False)
    elif method == "numerical":
        eqs = equilibria_fixed(
            mdl, n_grid=n_grid, max_roots=max_roots, psi_range=psi_range, throw=False
        )
    else:
        raise ValueError(f"parameter 'method' must be 'numerical' or 'analytic', got {method!r}")
    J = jax.vmap(lambda y: jacobian(mdl, y, throw=False))(eqs.state)  # once, for both verdicts
    out = {f: getattr(eqs, f) for f in SLOT_FIELDS}
    eig_method = default_eig_method() if eig_method is None else eig_method
    if eig_method == "routh":
        max_re = jax.vmap(spectral_abscissa)(J)
    elif eig_method in EIG_METHODS:
        lam = jax.vmap(lambda A: matrix_eigenvalues(A, eig_method))(J)
        max_re = jnp.max(jnp.real(lam), axis=-1)
        out.update(eig_real=jnp.real(lam), eig_imag=jnp.imag(lam))
    else:
        raise ValueError(
            f"parameter 'eig_method' must be one of {ABSCISSA_METHODS}, got {eig_method!r}"
        )
    out.update(
        max_real=max_re,
        stability=classify(max_re),
        n_equilibria=eqs.n_roots,
        truncated=eqs.n_roots > eqs.psi.shape[0],
    )
    if routh_hurwitz:
        out["routh_hurwitz"] = jax.vmap(matrix_routh_hurwitz_stable)(J)
    # per equilibrium slot; unchecked like the rest of the kernel (the sweep checks its grids
    # beforehand): a check here is a host callback, and JAX's persistent cache never
    # stores a program that holds one, so every run would compile the kernel again
    flags = jax.vmap(lambda y: validity(mdl, y, throw=False))(eqs.state)
    out.update({f"validity_{k}": v for k, v in flags.items()})
    out["physics_valid"] = jax.vmap(all_valid)(flags)
    return out


def _mesh(devices):
    devices = list(jax.devices() if devices is None else devices)
    return Mesh(np.array(devices), ("points",)), len(devices)


def without_metadata(model: TowModel) -> TowModel:
    """The model with the vessel's static metadata (``name``, ``assumed``) set to their
    defaults. They do not enter the numbers, but as static fields they are part of the
    model's structure: without this, Barge 2a and 2b (which differ only in them) would each
    trace and compile the same sweep kernel."""
    v = model.vessel
    if v.name == "vessel" and v.assumed == ():
        return model
    return eqx.tree_at(lambda m: m.vessel, model, dataclasses.replace(v, name="vessel", assumed=()))


@functools.lru_cache(maxsize=32)
def _cached_kernel(options: tuple):
    kernel_options = dict(options)

    def batched(model, flat_params):
        return jax.vmap(lambda p: point_kernel(model, p, **kernel_options))(flat_params)

    jitted = jax.jit(batched)

    def kernel(model, flat_params):
        return cached_call(f"sweep{options}", jitted, without_metadata(model), flat_params)

    kernel.jitted = jitted  # type: ignore[attr-defined]  (for .lower/.trace in benchmarks)
    return kernel


def make_batched_kernel(**kernel_options):
    """jit(vmap(point_kernel)) with the given static options, cached: one compilation per
    option set, chunk shape and model structure, reused across chunks and sweeps."""
    return _cached_kernel(tuple(sorted(kernel_options.items())))


def make_specialised_kernel(model: TowModel, **kernel_options):
    """jit(vmap(point_kernel)) compiled for this model instance (its arrays are compile-time
    constants; see ``specialise`` in `sweep_arrays`). Pass it as ``kernel=`` to reuse the
    compilation across sweeps of the same model."""
    fixed = jax.jit(lambda p: jax.vmap(lambda q: point_kernel(model, q, **kernel_options))(p))
    return lambda _model, p: fixed(p)


@dataclasses.dataclass(frozen=True)
class SweepSolver:
    """What a sweep computes at every point (the options of `point_kernel`).

    ``method``: "numerical" (every equilibrium, by scanning ``n_grid`` headings over
    ±``psi_range`` and refining at most ``max_roots`` roots) or "analytic";
    ``routh_hurwitz``: add the Routh-Hurwitz cross-check; ``eigenvalues``: add every
    eigenvalue (``eig_real``, ``eig_imag``) to max Re λ; ``eig_method``: by default "routh"
    (the pure-JAX spectral abscissa, the fastest, on any backend) when the eigenvalues are
    not wanted; with them, "lapack" on one CPU device, else "polynomial": on a GPU (no
    batched nonsymmetric eigensolver there; `jaxtow.default_eig_method`) and when a chunk is
    sharded over several CPU devices (concurrent LAPACK calls into OpenBLAS deadlocked)."""

    method: str = "numerical"
    n_grid: int = 2001
    max_roots: int = 4
    psi_range: float = math.pi / 2
    routh_hurwitz: bool = True
    eig_method: str | None = None
    eigenvalues: bool = False


@dataclasses.dataclass(frozen=True)
class SweepExecution:
    """How a sweep runs: ``chunk_size`` points per kernel call (memory stays bounded),
    ``devices`` to shard each chunk over (default: all JAX devices), a ``kernel`` to reuse
    (`make_batched_kernel`, `make_specialised_kernel`), and ``specialise`` (compile the
    kernel for this model instance, its arrays as compile-time constants: about 2x faster for
    an expensive force model such as a QTF wave force, at one compilation per model instead
    of one per model structure)."""

    chunk_size: int = 16384
    devices: Sequence | None = None
    kernel: Callable | None = None
    specialise: bool = False


_SOLVER_FIELDS = tuple(f.name for f in dataclasses.fields(SweepSolver))
_EXECUTION_FIELDS = tuple(f.name for f in dataclasses.fields(SweepExecution))


def sweep_options(**options) -> tuple[SweepSolver, SweepExecution]:
    """The solver and execution objects of loose keyword options (those of `jaxtow.sweep`);
    an unknown keyword is an error that names it."""
    bad = sorted(set(options) - set(_SOLVER_FIELDS) - set(_EXECUTION_FIELDS))
    if bad:
        raise TypeError(
            f"unknown sweep option(s) {bad}: the solver takes {list(_SOLVER_FIELDS)}, the "
            f"execution {list(_EXECUTION_FIELDS)}"
        )
    solver = SweepSolver(**{k: v for k, v in options.items() if k in _SOLVER_FIELDS})
    execution = SweepExecution(**{k: v for k, v in options.items() if k in _EXECUTION_FIELDS})
    return solver, execution


@dataclasses.dataclass(frozen=True)
class SweepPlan:
    """A checked sweep, cut into chunks: what `sweep_arrays` evaluates chunk by chunk and
    `jaxtow.distributed` hands out as tasks (one chunk a task, the same kernel)."""

    names: tuple
    axes: tuple  # the 1-D value array of each swept parameter
    chunk: int  # points per kernel call (the last chunk is padded with a valid point)
    nchunks: int
    options: dict  # the kernel's static options (`point_kernel`)
    eigenvalues: bool
    ndev: int

    @property
    def shape(self) -> tuple:
        return tuple(a.size for a in self.axes)

    @property
    def npts(self) -> int:
        return math.prod(self.shape)

    def bounds(self, c: int) -> tuple[int, int]:
        return c * self.chunk, min((c + 1) * self.chunk, self.npts)

    def chunk_params(self, c: int) -> dict:
        """Chunk ``c``'s parameter values, padded to the chunk size (NumPy arrays)."""
        lo, hi = self.bounds(c)
        idx = np.arange(lo, lo + self.chunk)
        idx = np.where(idx < hi, idx, lo)  # pad the last chunk with a valid point
        # the Cartesian product's points of this chunk only: memory does not grow with the grid
        where = np.unravel_index(idx, self.shape)
        return {n: a[i] for n, a, i in zip(self.names, self.axes, where)}

    def trim(self, c: int, result: dict) -> dict:
        """A kernel's output for chunk ``c`` as NumPy arrays, padding removed."""
        lo, hi = self.bounds(c)
        return {k: np.asarray(v[: hi - lo]) for k, v in result.items()}

    def assemble(self, pieces: list) -> dict:
        """The chunks' outputs, in order, as arrays shaped ``grid_shape + (slots[, 6])``."""
        out = {k: np.concatenate([p[k] for p in pieces]) for k in pieces[0]}
        out = {k: v.reshape(self.shape + v.shape[1:]) for k, v in out.items()}
        out["_coords"] = dict(zip(self.names, self.axes))
        out["_eig_method"] = self.options["eig_method"]
        return out


#: Bytes of results a grid point takes in `sweep_arrays` (4 equilibrium slots, about 20
#: outputs each, float64 and bool): an estimate for the up-front memory check.
BYTES_PER_POINT = 700


def _check_memory(plan: SweepPlan) -> None:
    """Refuse, before anything runs, a grid whose results cannot fit in this machine's
    memory (`sweep_arrays` holds them all; `jaxtow.distributed.sweep` does not)."""
    need = plan.npts * BYTES_PER_POINT
    try:
        have = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (AttributeError, ValueError, OSError):  # not POSIX
        return
    if need > have:
        raise ValueError(
            f"parameter 'grid': {plan.npts:.3g} points need about {need / 2**30:.3g} GiB of "
            f"results, more than this machine's {have / 2**30:.3g} GiB; sweep a smaller grid, "
            "or use jaxtow.distributed.sweep, which keeps the results in chunks"
        )


def plan_sweep(
    model: TowModel,
    grid: Mapping[str, np.ndarray],
    solver: SweepSolver | None = None,
    *,
    chunk_size: int = 16384,
    ndev: int = 1,
    on_cpu: bool = True,
) -> SweepPlan:
    """Check ``grid`` against the model's rules and cut it into chunks (see `sweep_arrays`)."""
    solver = SweepSolver() if solver is None else solver
    eig_method, eigenvalues = solver.eig_method, solver.eigenvalues
    if not grid:
        raise ValueError("parameter 'grid' must name at least one parameter")
    names = list(grid)
    axes = []
    for n in names:
        try:
            vals = np.atleast_1d(np.asarray(grid[n], dtype=float))
        except (TypeError, ValueError):
            raise ValueError(f"grid values for {n!r} must be numbers, got {grid[n]!r}") from None
        if vals.ndim != 1 or vals.size == 0:
            raise ValueError(f"grid values for {n!r} must be a non-empty 1-D array")
        check_values(model, n, vals)
        axes.append(vals)
    if int(chunk_size) < 1:
        raise ValueError(f"parameter 'chunk_size' must be >= 1, got {chunk_size}")
    npts = math.prod(a.size for a in axes)
    if eig_method is None:
        if not eigenvalues:
            eig_method = "routh"
        else:
            eig_method = "lapack" if (ndev == 1 and on_cpu) else "polynomial"
    elif eigenvalues and eig_method not in EIG_METHODS:
        raise ValueError(
            f"eigenvalues=True needs parameter 'eig_method' in {EIG_METHODS}, got {eig_method!r}"
        )
    # Round small grids up to a power of two so that sweeps of similar size share a
    # compiled kernel (padding points repeat a valid point and are discarded).
    chunk = max(ndev, min(int(chunk_size), 1 << max(npts - 1, 1).bit_length()))
    chunk = int(math.ceil(chunk / ndev) * ndev)
    options = dict(
        method=solver.method,
        n_grid=solver.n_grid,
        max_roots=solver.max_roots,
        psi_range=solver.psi_range,
        routh_hurwitz=solver.routh_hurwitz,
        eig_method=eig_method,
    )
    return SweepPlan(
        names=tuple(names),
        axes=tuple(axes),
        chunk=chunk,
        nchunks=int(math.ceil(npts / chunk)),
        options=options,
        eigenvalues=bool(eigenvalues),
        ndev=ndev,
    )


def sweep_arrays(
    model: TowModel,
    grid: Mapping[str, np.ndarray],
    solver: SweepSolver | None = None,
    execution: SweepExecution | None = None,
    *,
    progress_meter: AbstractProgressMeter | None = None,
    checkpoint=None,
) -> dict:
    """Run the sweep and return NumPy arrays shaped ``grid_shape + (slots[, 6])``.

    ``grid`` maps parameter names to 1-D value arrays (a Cartesian product is taken).
    All values are checked before anything runs; an invalid one is an error naming it.
    ``solver`` (a `SweepSolver`): what is computed at each point; ``execution`` (a
    `SweepExecution`): chunks, devices and kernel. ``progress_meter``: where each finished
    chunk is reported (`jaxtow.TqdmProgressMeter` for a bar). ``checkpoint``: an object whose
    ``open(model, names, axes, chunk, options, nchunks)`` gives a store that ``get``s and
    ``put``s finished chunks, such as `jaxtow.io.Checkpoint` (a folder where each chunk is
    saved as it completes); a sweep interrupted and run again with the same folder, model,
    grid and options computes only the chunks that are missing. To spread the chunks over
    several processes or machines, see `jaxtow.distributed`.
    """
    solver = SweepSolver() if solver is None else solver
    execution = SweepExecution() if execution is None else execution
    for name, obj, cls in (
        ("solver", solver, SweepSolver),
        ("execution", execution, SweepExecution),
    ):
        if not isinstance(obj, cls):
            raise TypeError(
                f"parameter {name!r}: a jaxtow.{cls.__name__} (jaxtow.sweep takes loose "
                f"keywords), got {obj!r}"
            )
    mesh, ndev = _mesh(execution.devices)
    on_cpu = mesh.devices.flat[0].platform == "cpu"
    plan = plan_sweep(
        model, grid, solver, chunk_size=execution.chunk_size, ndev=ndev, on_cpu=on_cpu
    )
    _check_memory(plan)
    kernel = execution.kernel
    store = _open_checkpoint(checkpoint, model, plan, solver, execution)
    if kernel is None:
        kernel = (
            make_specialised_kernel(model, **plan.options)
            if execution.specialise
            else make_batched_kernel(**plan.options)
        )
    sharding = NamedSharding(mesh, P("points"))
    bar = (progress_meter or NoProgressMeter()).start(plan.nchunks, "sweep")
    pieces = []
    for c in range(plan.nchunks):  # chunks, not grid points: each chunk is one vmapped call
        piece = None if store is None else store.get(c)
        if piece is None:
            params = {n: jax.device_put(v, sharding) for n, v in plan.chunk_params(c).items()}
            piece = plan.trim(c, jax.device_get(kernel(model, params)))
            if store is not None:
                store.put(c, piece)
        pieces.append(piece)
        bar.update()
    bar.close()
    return plan.assemble(pieces)


def _open_checkpoint(checkpoint, model, plan: SweepPlan, solver, execution):
    """The chunk store of ``checkpoint`` for this sweep (None without one)."""
    if checkpoint is None:
        return None
    if isinstance(checkpoint, str | os.PathLike) or not callable(getattr(checkpoint, "open", None)):
        raise TypeError(
            "parameter 'checkpoint': an object with open(), such as "
            f"jaxtow.io.Checkpoint(folder), got {checkpoint!r}; jaxtow.sweep takes a folder"
        )
    opts = dict(
        plan.options,
        eigenvalues=solver.eigenvalues,
        user_kernel=execution.kernel is not None,
        specialise=execution.specialise,
    )
    return checkpoint.open(model, plan.names, plan.axes, plan.chunk, opts, plan.nchunks)
