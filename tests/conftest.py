import os

# figures are written to files in the tests; the package itself never picks a backend
os.environ.setdefault("MPLBACKEND", "Agg")

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
