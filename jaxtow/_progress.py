"""Progress meters, passed in to long loops of chunks as objects (diffrax's
``progress_meter=`` is the pattern): `NoProgressMeter` (the default of the library) and
`TqdmProgressMeter` (a tqdm bar on stderr, what the command line uses). A loop calls
``meter.start(total, label)`` and then ``update(n)`` and ``close()`` on what it returns."""

from __future__ import annotations

from typing import Protocol


class ProgressBar(Protocol):
    def update(self, n: int = 1) -> object: ...
    def close(self) -> None: ...


class AbstractProgressMeter:
    """What a chunked loop reports its progress to."""

    def start(self, total: int, label: str) -> ProgressBar:
        raise NotImplementedError


class _Silent:
    def update(self, n: int = 1) -> None:
        pass

    def close(self) -> None:
        pass


class NoProgressMeter(AbstractProgressMeter):
    """Reports nothing."""

    def start(self, total: int, label: str) -> ProgressBar:
        return _Silent()


class TqdmProgressMeter(AbstractProgressMeter):
    """A tqdm bar on stderr, one step a chunk."""

    def start(self, total: int, label: str) -> ProgressBar:
        from tqdm.auto import tqdm  # a display: loaded only where a bar is shown

        return tqdm(total=total, desc=label, unit="chunk", leave=True)


def progress_meter(enabled: bool) -> AbstractProgressMeter:
    """The meter of a ``progress=True/False`` switch of the studies and the command line."""
    return TqdmProgressMeter() if enabled else NoProgressMeter()
