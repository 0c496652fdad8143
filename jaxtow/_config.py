"""The package's version and its numerical precision policy.

Stability work needs float64: eigenvalue margins of order 1e-4 and equilibrium residuals of
1e-12 are below float32 resolution. Importing :mod:`jaxtow` therefore switches JAX to 64-bit
mode (``jax_enable_x64``) unless the environment variable ``JAXTOW_ENABLE_X64`` is set to
``0`` before the first import. The switch must happen before any JAX array is created; if a
program needs float32 for its own arrays, set ``JAXTOW_ENABLE_X64=0`` and call
``jax.config.update("jax_enable_x64", True)`` itself where it wants double precision.

``import jaxtow`` does not import JAX (its names load on first use). Where JAX is not loaded
yet, the switch is made through JAX's own environment variable ``JAX_ENABLE_X64=1``, which
JAX reads when it is first imported; child processes (a Dask worker, say) inherit it.
"""

from __future__ import annotations

import os
import sys
from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("jaxtow")
except PackageNotFoundError:  # running from a source tree that was never installed
    __version__ = "0+unknown"

_OFF = ("0", "false", "no", "off")


def enable_x64_from_environment() -> bool:
    """Enable float64 unless ``JAXTOW_ENABLE_X64=0``; return whether it is (or, where JAX
    is not imported yet, will be) enabled."""
    on = os.environ.get("JAXTOW_ENABLE_X64", "1").strip().lower() not in _OFF
    jax = sys.modules.get("jax")
    if jax is None or not hasattr(jax, "config"):  # not imported (or still importing)
        if on:
            os.environ["JAX_ENABLE_X64"] = "1"
        return os.environ.get("JAX_ENABLE_X64", "0").strip().lower() not in ("",) + _OFF
    if on:
        jax.config.update("jax_enable_x64", True)
    return bool(jax.config.read("jax_enable_x64"))
