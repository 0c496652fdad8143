"""The run manifest: ``OUT/jaxtow_run.json`` (a study's: ``OUT/<tow>_run.json``, so that two
studies in one folder keep one each), what a command was asked, with what, and how far it
got.

Written when the run starts (status ``running``) and again when it ends (``finished``,
``interrupted`` or ``failed`` with the one-line error), each time atomically. It holds the
command line and every option's value, the versions of jaxtow and its numerical stack, the
documented estimates of `jaxtow.presets.ASSUMPTIONS` (the values the thesis lacks; which of
them a result used is in its own attributes), and the files the run wrote into the folder.
A folder whose manifest says ``running`` with no run holding its lock was left by a killed
process.

A command that can tell what decides its outputs (``jaxtow bem``: `jaxtow.cli.bem.fingerprint`)
records that digest as ``request``; run again with the same request into a folder whose run
finished and whose outputs are all there, it has nothing to do (`up_to_date`).
"""

from __future__ import annotations

import json
import platform
import time
from datetime import UTC, datetime
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import jaxtow as jt

NAME = "jaxtow_run.json"


def _versions() -> dict:
    out = {"python": platform.python_version()}
    for pkg in ("jaxtow", "jax", "jaxlib", "equinox", "diffrax", "optimistix", "numpy", "xarray"):
        try:
            out[pkg] = version(pkg)
        except PackageNotFoundError:
            out[pkg] = None
    return out


def _plain(v):
    if isinstance(v, (str, int, float, bool)) or v is None:
        return v
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    return str(v)


class Manifest:
    """The manifest of one run into ``out``: `start` writes it, `end` completes it."""

    def __init__(self, out, args, argv, request: str | None = None, name: str | None = None):
        self.path = Path(out) / (name or NAME)
        self.t0 = time.time()
        # the parser's own hooks (the command's function, its manifest's naming) are not
        # options: their repr would name a memory address, different in every run
        options = {
            k: _plain(v)
            for k, v in vars(args).items()
            if k not in ("func", "fingerprint") and not callable(v)
        }

        self.record = {
            "command": args.command,
            "argv": ["jaxtow", *argv],
            "options": options,
            "versions": _versions(),
            "estimates": {k: dict(v) for k, v in jt.presets.ASSUMPTIONS.items()},
            "started": _now(),
            "finished": None,
            "status": "running",
            "outputs": [],
            "request": request,
        }

    def start(self) -> None:
        self._write()

    def end(self, status: str, error: str | None = None) -> None:
        self.record.update(
            status=status,
            finished=_now(),
            seconds=round(time.time() - self.t0, 3),
            outputs=self._outputs(),
        )
        if error is not None:
            self.record["error"] = error
        self._write()

    def _outputs(self) -> list:
        """The files (not hidden, not the manifest) written into the folder during the run."""
        folder = self.path.parent
        found = []
        for p in sorted(folder.rglob("*")):
            rel = p.relative_to(folder)
            if (
                p.is_file()
                and p.name != self.path.name
                and not p.name.endswith("_run.json")
                and not any(part.startswith(".") for part in rel.parts)
                and p.stat().st_mtime >= self.t0 - 1.0
            ):
                found.append(str(rel))
        return found

    def _write(self) -> None:
        jt.io.write_file(self.path, json.dumps(self.record, indent=2, default=str) + "\n")


def up_to_date(out, request: str | None) -> dict | None:
    """The finished manifest in ``out`` whose ``request`` is ``request`` and whose outputs are
    all present, else None (also for a None request)."""
    if request is None or out is None:
        return None
    folder = Path(out)
    try:
        record = json.loads((folder / NAME).read_text())
    except (OSError, ValueError):
        return None
    if not isinstance(record, dict) or record.get("status") != "finished":
        return None
    outputs = record.get("outputs") or []
    if record.get("request") != request or not outputs:
        return None
    if not all((folder / rel).is_file() for rel in outputs):
        return None
    return record


def _now() -> str:
    return datetime.now(UTC).isoformat(timespec="seconds")
