"""The finished steps of a study, one file a step, so that a study that fails or is killed
loses nothing and ``jaxtow study --resume`` continues where it stopped.

The folder holds ``manifest.json`` (the `jaxtow.io.fingerprint` of the tow file's resolved
values, the study's options and the jaxtow version) and one ``<step>.pickle`` a finished step, each
written atomically (a temporary name renamed into place), so a step killed while writing
leaves no file. The step files are pickles of the step's own results (numbers, arrays,
xarray datasets): they are the study's cache in its own output folder, read back only by
``--resume`` of the same tow and options and never from elsewhere. A folder made by another
tow or other options is refused, never mixed in.
"""

from __future__ import annotations

import json
import pickle
import re
import shutil
from pathlib import Path

from ._atomic import atomic_path
from ._fingerprint import fingerprint

__all__ = ["StepStore"]


def _file_key(key: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", key) + "-" + fingerprint(key)[:8]


class StepStore:
    """A study's step folder. ``resume=False`` starts afresh (removing the steps of an earlier
    run); ``resume=True`` keeps the finished steps of the same study and refuses those of
    another. `get` a finished step (None if not there), `put` one, `clear` at the end."""

    def __init__(self, folder, fingerprint: str, *, resume: bool):
        self.folder = Path(folder)
        manifest = self.folder / "manifest.json"
        if self.folder.exists() and not resume:
            shutil.rmtree(self.folder)
        if resume and manifest.exists():
            got = json.loads(manifest.read_text()).get("fingerprint")
            if got != fingerprint:
                raise ValueError(
                    f"--resume: {self.folder} holds the steps of another study (a different "
                    "tow file, options or jaxtow version); run without --resume to start afresh"
                )
        self.folder.mkdir(parents=True, exist_ok=True)
        if not manifest.exists():
            with atomic_path(manifest) as tmp:
                tmp.write_text(json.dumps(dict(fingerprint=fingerprint)))
        self.resumed: list[str] = []

    def _path(self, key: str) -> Path:
        return self.folder / f"{_file_key(key)}.pickle"

    def get(self, key: str):
        """The stored result of step ``key``, or None."""
        p = self._path(key)
        if not p.exists():
            return None
        with p.open("rb") as f:
            out = pickle.load(f)
        self.resumed.append(key)
        return out

    def put(self, key: str, value) -> None:
        """Store the result of step ``key`` (atomically)."""
        with atomic_path(self._path(key)) as tmp:
            with open(tmp, "wb") as f:
                pickle.dump(value, f, protocol=pickle.HIGHEST_PROTOCOL)

    def clear(self) -> None:
        """Remove the folder (the study finished and its files are written)."""
        shutil.rmtree(self.folder, ignore_errors=True)
