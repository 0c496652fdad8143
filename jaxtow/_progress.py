"""A minimal text progress bar for chunked sweeps (stderr; no dependency)."""

from __future__ import annotations

import sys
import time


class Progress:
    def __init__(self, total: int, label: str = "sweep", enabled: bool = True, stream=None):
        self.total, self.label, self.enabled = total, label, enabled
        self.stream = stream or sys.stderr
        self.done = 0
        self.t0 = time.perf_counter()

    def update(self, n: int = 1) -> None:
        self.done += n
        if not self.enabled:
            return
        frac = self.done / max(self.total, 1)
        bar = "#" * int(30 * frac)
        dt = time.perf_counter() - self.t0
        self.stream.write(f"\r{self.label} [{bar:<30}] {self.done}/{self.total} chunks {dt:6.1f}s")
        if self.done >= self.total:
            self.stream.write("\n")
        self.stream.flush()
