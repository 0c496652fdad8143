import faulthandler
import sys

import jaxtow  # noqa: F401  (enables float64 before any array is created)
import pytest

# A stuck test prints every thread's stack instead of hanging CI silently.
faulthandler.dump_traceback_later(1200, exit=True, file=sys.stderr)


@pytest.fixture(scope="session")
def barge_2a():
    return jaxtow.presets.barge_2a()


@pytest.fixture(scope="session")
def barge_2b():
    return jaxtow.presets.barge_2b()
