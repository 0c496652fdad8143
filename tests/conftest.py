import os

# figures are written to files in the tests; the package itself never picks a backend
os.environ.setdefault("MPLBACKEND", "Agg")
# the command line turns on a persistent compilation cache; the suite measures cold runs and
# must not write into the user's cache (the cache's own test sets a folder explicitly)
os.environ["JAXTOW_COMPILE_CACHE"] = "off"

import jax  # noqa: E402

# float64 for the whole suite, explicitly (importing jaxtow also switches it on)
jax.config.update("jax_enable_x64", True)

import pytest  # noqa: E402

import jaxtow  # noqa: E402


@pytest.fixture(scope="session")
def barge_2a():
    return jaxtow.presets.barge_2a()


@pytest.fixture(scope="session")
def barge_2b():
    return jaxtow.presets.barge_2b()
