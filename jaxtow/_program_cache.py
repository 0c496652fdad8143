"""A persistent cache of traced programs, beside the compilation cache (on wherever it is).

JAX's persistent compilation cache (`jaxtow.enable_compile_cache`) skips XLA's compile on a
second run, but not the tracing and lowering that come before it: the cache key is computed
from the lowered program, so every run traces every kernel again. For the sweep kernel and
a study's condition programs that is most of what a warm run costs (the calm sweep kernel
in a warm process, measured: 0.88 s traced, lowered and read from the compile cache,
against 0.29 s read back exported). `cached_call` keeps the lowered program itself, exported with
`jax.export` and serialised (StableHLO, the format JAX guarantees to read back), so that a
later process deserialises it in milliseconds and finds its compiled form in the
compilation cache.

* The folder: ``<compile cache folder>-programs`` (by default ``~/.cache/jaxtow/xla-programs``),
  set by `enable_compile_cache` where it chooses the folder (not where the user set JAX's
  own folder beforehand); off with it (``JAXTOW_COMPILE_CACHE=off``,
  ``--no-compile-cache``). Under it, one subfolder per `code_digest`: a new jaxtow, JAX,
  Equinox, diffrax, optimistix, lineax or NumPy, or an edited jaxtow source, starts an
  empty one and the others are removed.
* The key of a program: its name, the code digest, the pickled static part of its
  arguments (everything but arrays, as `equinox.filter_jit` treats them) with the
  arguments' tree structure, and each array's shape, dtype and weak type. A static part
  that cannot be pickled or that names a class or function from outside jaxtow and the
  libraries the digest covers (`TRUSTED`: a user's own force model is pickled by its name
  only, so its edited definition would find the old program), a call under a trace,
  several devices, or a program that cannot be exported (one that holds a host callback)
  runs as it is, traced as before; the last is remembered with a marker file so that it
  is not tried again.
* What comes back equals the direct call's arrays (the same program; tested to
  round-off), as NumPy-compatible JAX arrays in the same tree.

Only host-level entry points use it (a sweep's chunks, a condition's equilibria and
stability): an exported program carries no derivative rules, so nothing that is
differentiated goes through it.

`host_program` is the in-memory counterpart for the library's public functions called
eagerly (a notebook's ``jt.eigenvalues(model, y)``): one compiled program instead of their
operations one by one.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.metadata as md
import inspect
import io
import os
import pickle
import shutil
import tempfile
import types
from collections.abc import Callable
from pathlib import Path
from typing import TypeVar, cast

import equinox as eqx
import jax
import numpy as np
from jax import export
from jax.core import Tracer

try:  # Equinox's marker of a missing field, found in its modules' tree structures
    from equinox._module._flatten import MISSING as _EQX_MISSING
except ImportError:  # another Equinox: its trees may not round-trip; the check in `_export` says
    _EQX_MISSING = object()

_FOLDER: Path | None = None
#: (key) -> (exported program, output tree, its compiled call) for this process
_LOADED: dict = {}
#: XLA options of the programs run from the cache. XLA:CPU's legacy elemental emitters
#: instead of the fusion emitters it uses by default: on 2 cores they compile a
#: tow's equilibria and stability programs in about 60 % of the time and run its kernels as
#: fast or faster (docs/benchmarks.md, "Compile options"). GPU backends ignore the option.
#: An XLA that no longer knows an option refuses it with an error, and the programs then
#: compile with XLA's defaults (`_OPTIONS_OK`).
COMPILER_OPTIONS: dict = {"xla_cpu_use_fusion_emitters": False}
_OPTIONS_OK = True


def set_folder(folder) -> None:
    """Turn the cache on in ``folder`` (None: off). Called by `enable_compile_cache`."""
    global _FOLDER
    _FOLDER = None if folder is None else Path(folder)
    _LOADED.clear()


def folder() -> Path | None:
    """The current digest's subfolder, created (and the others removed) on first use; None
    where the cache is off."""
    if _FOLDER is None:
        return None
    return _digest_folder(_FOLDER, code_digest())


@functools.lru_cache(maxsize=4)
def _digest_folder(base: Path, digest: str) -> Path | None:
    here = base / digest
    try:
        here.mkdir(parents=True, exist_ok=True)
        for other in base.iterdir():
            if other.is_dir() and other.name != digest:
                shutil.rmtree(other, ignore_errors=True)
    except OSError:
        return None
    return here


@functools.lru_cache(maxsize=1)
def code_digest() -> str:
    """A digest of what a traced program depends on besides its arguments: jaxtow's source
    and data files (by name, size and modification time), the versions of the `TRUSTED`
    libraries that change (JAX, jaxlib, Equinox, diffrax, optimistix, lineax, NumPy), float64
    on or off, and the backend."""
    h = hashlib.blake2b(digest_size=10)
    root = Path(__file__).parent
    for path in sorted(root.rglob("*")):
        if not path.is_file() or "__pycache__" in path.parts:
            continue
        rel = path.relative_to(root).as_posix().encode()
        if path.suffix == ".py":
            h.update(rel + b"\0" + path.read_bytes())
        else:
            st = path.stat()
            h.update(rel + f"\0{st.st_size}\0{st.st_mtime_ns}".encode())
    for dist in ("jax", "jaxlib", "equinox", "diffrax", "optimistix", "lineax", "numpy"):
        try:
            h.update(f"{dist}={md.version(dist)}".encode())
        except md.PackageNotFoundError:
            h.update(dist.encode())
    h.update(f"x64={jax.config.jax_enable_x64}".encode())  # pyright: ignore[reportAttributeAccessIssue]
    h.update(jax.default_backend().encode())
    return h.hexdigest()


#: Packages whose classes and functions may be named in a key: the code digest covers their
#: versions (jaxtow's source, JAX, Equinox) or they do not change what a program computes.
#: A class or function from anywhere else (a user's force model in a notebook, say) is
#: pickled by its name only, so an edited definition would find the old program: no key.
TRUSTED = frozenset(
    {"jaxtow", "jax", "jaxlib", "equinox", "diffrax", "optimistix", "lineax", "numpy"}
    | {"builtins", "functools", "collections", "copyreg", "_operator", "operator", "math"}
)


class _Untrusted(Exception):
    pass


class _KeyPickler(pickle.Pickler):
    """Pickles a key; refuses classes and functions from outside `TRUSTED`."""

    def reducer_override(self, obj):  # pyright: ignore[reportIncompatibleMethodOverride]
        if isinstance(obj, (type, types.FunctionType, types.BuiltinFunctionType)):
            module = getattr(obj, "__module__", None) or ""
            if module.split(".")[0] not in TRUSTED:
                raise _Untrusted(f"{module}.{getattr(obj, '__qualname__', obj)}")
        return NotImplemented


def _key(name: str, static, treedef, leaves) -> str | None:
    buf = io.BytesIO()
    try:
        _KeyPickler(buf, protocol=5).dump((name, static, treedef))
    except Exception:  # unpicklable (a lambda), or code from outside `TRUSTED`: no caching
        return None
    blob = buf.getvalue()
    h = hashlib.blake2b(blob, digest_size=16)
    for leaf in leaves:
        weak = getattr(leaf, "weak_type", False)
        h.update(f"{leaf.shape}{leaf.dtype}{weak};".encode())
    return h.hexdigest()


class _Pickler(pickle.Pickler):
    """Pickles Equinox's MISSING marker by name: it is compared by identity, so an unpickled
    copy would be a different object and the tree structure would not match its own."""

    def persistent_id(self, obj):  # pyright: ignore[reportIncompatibleMethodOverride]
        return "equinox.MISSING" if obj is _EQX_MISSING else None


class _Unpickler(pickle.Unpickler):
    def persistent_load(self, pid):
        if pid == "equinox.MISSING":
            return _EQX_MISSING
        raise pickle.UnpicklingError(f"unknown persistent id {pid!r}")


def _dumps(obj) -> bytes:
    buf = io.BytesIO()
    _Pickler(buf, protocol=5).dump(obj)
    return buf.getvalue()


def _loads(data: bytes):
    return _Unpickler(io.BytesIO(data)).load()


def _write(path: Path, data: bytes) -> None:
    """Atomically (a reader sees the whole file or none); a folder removed meanwhile by a run
    of another jaxtow version, or a full disk, only costs the next run a trace."""
    try:
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp-")
    except OSError:
        return
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError:
        Path(tmp).unlink(missing_ok=True)


def _parse(data: bytes):
    out_tree, blob = _loads(data)
    return export.deserialize(bytearray(blob)), out_tree


def _load(path: Path):
    try:
        return _parse(path.read_bytes())
    except Exception:  # missing, half-removed or from another version: trace instead
        return None


def cached_call(name: str, fn, *args, **kwargs):
    """``fn(*args, **kwargs)`` through the program cache (the module docstring): ``fn`` a
    jitted function (`jax.jit` or `equinox.filter_jit`); ``name`` names it in the key."""
    here = folder()
    if here is None or jax.device_count() > 1:
        return fn(*args, **kwargs)
    dynamic, static = eqx.partition((args, kwargs), eqx.is_array)
    leaves, treedef = jax.tree_util.tree_flatten(dynamic)
    if any(isinstance(leaf, Tracer) for leaf in leaves):
        return fn(*args, **kwargs)
    key = _key(name, static, treedef, leaves)
    if key is None:
        return fn(*args, **kwargs)
    hit = _LOADED.get(key)
    if hit is None:
        path, skip = here / f"{key}.program", here / f"{key}.skip"
        if skip.exists():
            return fn(*args, **kwargs)
        hit = _load(path) if path.exists() else None
        if hit is None:
            hit = _export(fn, static, treedef, leaves)
            if hit is None:
                _write(skip, b"")
                return fn(*args, **kwargs)
            _write(path, hit)
            # call what a later run reads back, not the fresh export: the deserialised program
            # drops the outputs' weak typing, and a run that saw the fresh one would type them
            # differently from the next and compile what follows it twice
            hit = _parse(hit)
        hit = (*hit, _compiled_call(hit[0]))
        _LOADED[key] = hit
    exported, out_tree, call = hit
    return jax.tree_util.tree_unflatten(out_tree, _run(call, exported, leaves))


def _compiled_call(exported):
    """``exported.call`` as a program compiled with `COMPILER_OPTIONS`."""
    options = COMPILER_OPTIONS if _OPTIONS_OK else None
    return jax.jit(exported.call, compiler_options=options or None)


def _run(call, exported, leaves):
    """``call(*leaves)``; where XLA refuses `COMPILER_OPTIONS` (an XLA without one of them),
    the program with XLA's defaults, and every later one too."""
    global _OPTIONS_OK
    try:
        return call(*leaves)
    except jax.errors.JaxRuntimeError as e:
        if not (_OPTIONS_OK and COMPILER_OPTIONS and "compile option" in str(e)):
            raise
        _OPTIONS_OK = False
        _LOADED.clear()  # their calls hold the options
        return exported.call(*leaves)


class persistent:  # noqa: N801 (used as a decorator)
    """``fn`` (a jitted function) with every host-level call through `cached_call`; calls
    under a trace (inside another program, or differentiated) go straight to ``fn``. Its
    other attributes (``lower``, ``trace``) are ``fn``'s."""

    def __init__(self, fn):
        functools.update_wrapper(self, fn)
        self._name = f"{getattr(fn, '__module__', '')}.{getattr(fn, '__qualname__', repr(fn))}"

    def __call__(self, *args, **kwargs):
        return cached_call(self._name, self.__wrapped__, *args, **kwargs)

    def __getattr__(self, attr):
        return getattr(self.__wrapped__, attr)


def _export(fn, static, treedef, leaves):
    out_tree = []

    def flat(*dynamic_leaves):
        args, kwargs = eqx.combine(jax.tree_util.tree_unflatten(treedef, dynamic_leaves), static)
        out_leaves, tree = jax.tree_util.tree_flatten(fn(*args, **kwargs))
        out_tree.append(tree)
        return out_leaves

    try:
        exported = export.export(jax.jit(flat))(*leaves)
        blob = _dumps((out_tree[0], exported.serialize()))
        if _loads(blob)[0] != out_tree[0]:  # a tree that does not come back as it went
            return None
    except Exception:  # a host callback, an unexportable custom call, an unpicklable output
        return None
    return blob


F = TypeVar("F", bound=Callable)
#: What `host_program` passes to its program: concrete arrays and Python numbers.
_CONCRETE = (jax.Array, np.ndarray, np.generic, bool, int, float, complex)


def host_program(*, static_argnames: tuple[str, ...] = ()) -> Callable[[F], F]:
    """Decorator: the function compiled as one program (`jax.jit`, ``static_argnames``
    static) where it is called at host level, no traced array among its arguments; the
    function itself where one is traced (under the caller's jit, grad or vmap, whose program
    it joins as before) or where an argument is no array (a table given as a Python
    function, say).

    Called eagerly, a function of hundreds of small operations (a drift table's look-ups, a
    Jacobian by forward-mode autodiff, eigenvalues) compiles each operation on its first
    use and dispatches them one by one on every call: 0.7-3.4 s for a first call and up to
    83 ms for the next, measured on 2 cores (`benchmarks/bench_first_call.py`). As one
    program it compiles once per static options and argument shapes (0.07-0.9 s) and then
    runs in 0.04-1 ms. Python numbers among the arguments are traced (weakly typed), so
    another value reuses the program. The function holds no value checks of its own (under
    the program they would be host callbacks, or see no values): its public function checks
    the concrete result (`jaxtow._rules.guard`) and its grids before the program, and raises
    the same `ValueError` as before."""

    def wrap(fn: F) -> F:
        jitted = jax.jit(fn, static_argnames=static_argnames)
        names = tuple(inspect.signature(fn).parameters)

        @functools.wraps(fn)
        def call(*args, **kwargs):
            dynamic = [a for n, a in zip(names, args) if n not in static_argnames]
            dynamic += [a for n, a in kwargs.items() if n not in static_argnames]
            leaves = jax.tree_util.tree_leaves(dynamic)
            if all(isinstance(x, _CONCRETE) and not isinstance(x, Tracer) for x in leaves):
                return jitted(*args, **kwargs)
            return fn(*args, **kwargs)

        return cast(F, call)

    return wrap
