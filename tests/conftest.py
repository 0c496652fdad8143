import ctypes
import gc
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


#: A worker's resident memory (3 GB) above which the compiled programs of the modules it has
#: run are dropped after a module. JAX keeps every compiled executable for the life of the process;
#: a worker running fifty slow tests grew past 5 GB (12.5 GB for the two), and on CI's
#: 24 GB machine a worker aborted inside XLA's compiler late in the slow suite, most likely
#: out of memory. Tests in one module share their kernels, so the caches are cleared between
#: modules only.
RSS_LIMIT_BYTES = 3 * 1024**3


def _rss_bytes() -> int:
    try:
        with open("/proc/self/statm") as f:
            return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):  # not Linux: no guard
        return 0


@pytest.fixture(autouse=True, scope="module")
def _bounded_compile_caches():
    yield
    if _rss_bytes() > RSS_LIMIT_BYTES:
        jax.clear_caches()
        gc.collect()
        _trim()


def _trim() -> None:
    """Hand freed heap back to the system (glibc), so that the next module's RSS is read
    against what is live."""
    try:
        ctypes.CDLL("libc.so.6").malloc_trim(0)
    except (OSError, AttributeError):
        pass
