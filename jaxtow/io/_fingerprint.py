"""One fingerprint for every folder store of jaxtow: a sweep's chunk checkpoints, a study's
finished steps, the panel method's per-frequency cache and the command line's run manifest
each name what their files depend on by a SHA-256 `Fingerprint` of it, so that a folder made
by another request is refused (or recomputed), never mixed in."""

from __future__ import annotations

import hashlib
import json

import jax
import numpy as np

__all__ = ["Fingerprint", "fingerprint"]


class Fingerprint:
    """An incremental SHA-256 digest of the values a stored result depends on: `value` adds a
    JSON-able value (sorted keys; anything else by its ``repr``), `array` an array with its
    dtype and shape, `tree` every leaf of a JAX pytree and its structure, `labelled` bytes
    under a label with their length (files and texts), `raw` bytes as they are. Each method
    returns the fingerprint, so calls chain; `hexdigest` ends it."""

    def __init__(self):
        self._h = hashlib.sha256()

    def raw(self, data: bytes) -> Fingerprint:
        self._h.update(data)
        return self

    def labelled(self, label: str, data: bytes) -> Fingerprint:
        return self.raw(f"{label}:{len(data)}:".encode() + data)

    def value(self, obj) -> Fingerprint:
        return self.raw(json.dumps(obj, sort_keys=True, default=repr).encode())

    def array(self, a) -> Fingerprint:
        a = np.asarray(a)
        return self.raw(str(a.dtype).encode() + str(a.shape).encode() + a.tobytes())

    def tree(self, tree) -> Fingerprint:
        leaves, treedef = jax.tree_util.tree_flatten(tree)
        self.raw(str(treedef).encode())
        for leaf in leaves:
            self.array(leaf)
        return self

    def hexdigest(self, length: int | None = None) -> str:
        d = self._h.hexdigest()
        return d if length is None else d[:length]


def fingerprint(obj) -> str:
    """The fingerprint of one JSON-able value (a study's resolved tow file and options)."""
    return Fingerprint().value(obj).hexdigest()
