"""A Ctrl-C that is not lost.

Python delivers SIGINT as a `KeyboardInterrupt` raised wherever the main thread is at the
next bytecode; when that is a finaliser or a callback whose exceptions are printed and
ignored, the interrupt is gone and a long job runs on. The command line therefore installs
`sticky_interrupts` around each command: the handler also records the request, and the study's steps
(`jaxtow.studies`) look at `requested` between steps, so an interrupt that was swallowed
stops the job at the next step boundary all the same.
"""

from __future__ import annotations

import contextlib
import signal
import threading

_REQUESTED = threading.Event()
_ACTIVE = threading.Event()  # inside `sticky_interrupts`


def requested() -> bool:
    """Whether a Ctrl-C arrived since `sticky_interrupts` began (always False outside it)."""
    return _ACTIVE.is_set() and _REQUESTED.is_set()


def request() -> None:
    """Record a Ctrl-C (for handlers that hold the interrupt for a while); outside `sticky_interrupts`
    nothing is recorded, so a notebook's interrupt does not stop a later study."""
    if _ACTIVE.is_set():
        _REQUESTED.set()


def _handler(signum, frame):
    _REQUESTED.set()
    raise KeyboardInterrupt


@contextlib.contextmanager
def sticky_interrupts():
    """Record every Ctrl-C in the block (main thread only; elsewhere nothing changes)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _REQUESTED.clear()
    _ACTIVE.set()
    previous = signal.signal(signal.SIGINT, _handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        _ACTIVE.clear()
        _REQUESTED.clear()
