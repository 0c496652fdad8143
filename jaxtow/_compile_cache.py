"""A persistent compilation cache for jaxtow's kernels (on by default in the command line
and the wave study).

JAX compiles every kernel on its first call in a process; without a cache a second
``jaxtow calm`` compiles the same programs again. `enable_compile_cache` points JAX's
persistent cache at one folder:

* the folder: ``$JAXTOW_COMPILE_CACHE`` if set, else ``$XDG_CACHE_HOME/jaxtow/xla`` (by
  default ``~/.cache/jaxtow/xla``);
* the switch: ``JAXTOW_COMPILE_CACHE=off`` (or ``0``, ``false``, ``no``), or
  ``jaxtow --no-compile-cache ...``;
* a cache the user already set for JAX (``JAX_COMPILATION_CACHE_DIR`` or
  ``jax.config.update("jax_compilation_cache_dir", ...)``) is kept as it is;
* sharing: the size cap (`MAX_SIZE_BYTES`) turns on JAX's file lock (the ``filelock``
  package), which guards every read and write of the folder, so two runs that share it
  neither read a half-written entry nor write one twice. The least recently used entries
  are evicted past the cap.

Every program is stored (`MIN_COMPILE_SECONDS` = 0), so that what the cache holds does not
depend on how loaded the machine was when it compiled. The traced programs of jaxtow's entry
points are kept beside it, in ``<folder>-programs`` (`jaxtow._program_cache`), on and off
with it.
"""

from __future__ import annotations

import os
from pathlib import Path

import jax

from ._program_cache import set_folder

#: Environment variable: the cache folder, or "off" / "0" / "false" / "no" to disable.
ENV = "JAXTOW_COMPILE_CACHE"
#: Programs compiling faster than this are not cached. JAX's default is 1 s; jaxtow keeps
#: every program: a threshold on measured compile time makes what is stored depend on the
#: machine's load, so a second run would still compile (and add) the borderline ones.
MIN_COMPILE_SECONDS = 0.0
#: Size cap of the folder (least recently used entries are evicted past it); a cap also
#: turns on JAX's file lock for runs that share the folder.
MAX_SIZE_BYTES = 2 * 1024**3
_OFF = {"off", "0", "false", "no", "none", ""}


def default_cache_dir() -> Path:
    """``$XDG_CACHE_HOME/jaxtow/xla`` (``~/.cache/jaxtow/xla`` by default)."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "jaxtow" / "xla"


def enable_compile_cache(path=None) -> Path | None:
    """Turn on the persistent compilation cache (see the module docstring) and return its
    folder, or None where it is switched off. ``path`` overrides the environment.
    Idempotent; a folder the user set for JAX beforehand is kept."""

    current = getattr(jax.config, "jax_compilation_cache_dir")  # noqa: B009 (untyped flag)
    if path is None:
        if current:
            return Path(current)
        env = os.environ.get(ENV)
        if env is not None and env.strip().lower() in _OFF:
            return None
        path = env or default_cache_dir()
    path = Path(path).expanduser()
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise ValueError(
            f"compile cache folder {str(path)!r} ({ENV}) cannot be created: {e}"
        ) from e
    set_folder(path.with_name(path.name + "-programs"))  # the traced programs beside it
    if current and Path(current) == path:
        return path
    jax.config.update("jax_compilation_cache_dir", str(path))
    jax.config.update("jax_persistent_cache_min_compile_time_secs", MIN_COMPILE_SECONDS)
    jax.config.update("jax_persistent_cache_min_entry_size_bytes", 0)
    jax.config.update("jax_compilation_cache_max_size", MAX_SIZE_BYTES)
    return path
