"""Chunk checkpoints of a sweep: each finished chunk is written to a folder as it completes,
so an interrupted sweep resumes where it stopped (`jaxtow.sweep(..., checkpoint=DIR)`, or
`jaxtow.sweep_arrays(..., checkpoint=Checkpoint(DIR))`).

The folder holds ``manifest.json`` (a fingerprint of the model, the grid, the chunking and
the options) and one ``chunk_NNNNN.npz`` a chunk, each written atomically (a temporary name
renamed into place). A folder made by another sweep is refused, never mixed in.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from ._atomic import atomic_path
from ._fingerprint import Fingerprint


def sweep_fingerprint(model, names, axes, chunk: int, options: dict) -> str:
    """The `Fingerprint` of everything a sweep's results depend on: the model's array values
    and its structure, the grid, the chunk size and the kernel options."""
    f = Fingerprint().tree(model)
    for n, a in zip(names, axes):
        f.raw(n.encode() + np.asarray(a, float).tobytes())
    return f.value([chunk, options]).hexdigest()


class ChunkStore:
    """A sweep's checkpoint folder: `get` a finished chunk (None if not there), `put` one."""

    def __init__(self, folder, key: str, nchunks: int):
        self.folder = Path(folder)
        if self.folder.exists() and not self.folder.is_dir():
            raise ValueError(f"parameter 'checkpoint': {folder} is a file; give a folder")
        self.folder.mkdir(parents=True, exist_ok=True)
        manifest = self.folder / "manifest.json"
        want = dict(fingerprint=key, chunks=int(nchunks))
        if manifest.exists():
            got = json.loads(manifest.read_text())
            if got != want:
                raise ValueError(
                    f"parameter 'checkpoint': {folder} holds the chunks of another sweep (a "
                    "different model, grid, chunk size or options); give another folder or "
                    "remove it"
                )
        else:
            with atomic_path(manifest) as tmp:
                tmp.write_text(json.dumps(want))

    def _path(self, c: int) -> Path:
        return self.folder / f"chunk_{c:05d}.npz"

    def get(self, c: int) -> dict | None:
        path = self._path(c)
        if not path.exists():
            return None
        with np.load(path) as z:
            return {k: z[k] for k in z.files}

    def put(self, c: int, arrays: dict) -> None:
        with atomic_path(self._path(c)) as tmp, open(tmp, "wb") as f:
            np.savez(f, **arrays)


class Checkpoint:
    """A checkpoint folder for `jaxtow.sweep_arrays` (its ``checkpoint=``): the sweep opens it
    with what its results depend on and gets the `ChunkStore` of that sweep."""

    def __init__(self, folder):
        self.folder = folder

    def open(self, model, names, axes, chunk: int, options: dict, nchunks: int) -> ChunkStore:
        return ChunkStore(
            self.folder, sweep_fingerprint(model, names, axes, chunk, options), nchunks
        )
