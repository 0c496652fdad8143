"""Atomic file writes: write under a temporary name beside the target, then rename.

A Ctrl-C (SIGINT) that arrives while the file is being written is held until the writer
returns: interrupting the HDF5/NetCDF library inside a call can leave its global lock
taken, and the process then hangs at exit. The held interrupt then discards the temporary
file instead of renaming it, and is raised as `KeyboardInterrupt`: nothing is left under the
final name, and the process exits as soon as the write call returns. A second Ctrl-C during
the write interrupts at once.
"""

from __future__ import annotations

import contextlib
import os
import signal
import threading
from pathlib import Path

from .._interrupt import request


@contextlib.contextmanager
def _held_interrupts():
    """Hold SIGINT for the block (main thread only; elsewhere signals cannot be handled and
    nothing changes). Yields a callable: whether a SIGINT arrived."""
    if threading.current_thread() is not threading.main_thread():
        yield lambda: False
        return
    seen = []

    def handler(signum, frame):
        request()  # remembered past the block, even if the raise below is swallowed
        if seen:  # a second Ctrl-C: the user insists
            raise KeyboardInterrupt
        seen.append(signum)

    previous = signal.signal(signal.SIGINT, handler)
    try:
        yield lambda: bool(seen)
    finally:
        signal.signal(signal.SIGINT, previous)


@contextlib.contextmanager
def atomic_path(path):
    """Yield a temporary path beside ``path``; on success it is renamed onto ``path``, on
    any error (or interruption) removed, so ``path`` is never left half written. A SIGINT
    during the block is held until the block ends (see the module's note), then the
    temporary file is removed and `KeyboardInterrupt` raised."""
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        with _held_interrupts() as interrupted:
            yield tmp
            if interrupted():
                raise KeyboardInterrupt
            os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()


def write_file(path, data: str | bytes) -> None:
    """Write ``data`` (text or bytes) to ``path`` atomically (`atomic_path`)."""
    with atomic_path(path) as tmp:
        if isinstance(data, str):
            tmp.write_text(data)
        else:
            tmp.write_bytes(data)


def save_figure(fig, path, **kwargs) -> None:
    """``fig.savefig(path, **kwargs)`` atomically (`atomic_path`); the format comes from
    ``path``'s extension, not the temporary name's."""
    kwargs.setdefault("format", Path(path).suffix.lstrip(".") or None)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, **kwargs)


def save_netcdf(ds, path) -> None:
    """``ds.to_netcdf(path)`` atomically (`atomic_path`)."""
    with atomic_path(path) as tmp:
        ds.to_netcdf(tmp)
