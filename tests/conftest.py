import jaxtow  # noqa: F401  (enables float64 before any array is created)
import pytest


@pytest.fixture(scope="session")
def barge_2a():
    return jaxtow.presets.barge_2a()


@pytest.fixture(scope="session")
def barge_2b():
    return jaxtow.presets.barge_2b()
