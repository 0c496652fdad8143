"""Numerical precision policy.

Stability work needs float64: eigenvalue margins of order 1e-4 and equilibrium residuals of
1e-12 are below float32 resolution. Importing :mod:`jaxtow` therefore switches JAX to 64-bit
mode (``jax_enable_x64``) unless the environment variable ``JAXTOW_ENABLE_X64`` is set to
``0`` before the first import. The switch must happen before any JAX array is created; if a
program needs float32 for its own arrays, set ``JAXTOW_ENABLE_X64=0`` and call
``jax.config.update("jax_enable_x64", True)`` itself where it wants double precision.
"""

from __future__ import annotations

import os

import jax


def enable_x64_from_environment() -> bool:
    """Enable float64 unless ``JAXTOW_ENABLE_X64=0``; return whether it is enabled."""
    flag = os.environ.get("JAXTOW_ENABLE_X64", "1").strip().lower()
    if flag not in ("0", "false", "no", "off"):
        jax.config.update("jax_enable_x64", True)
    return bool(jax.config.read("jax_enable_x64"))
