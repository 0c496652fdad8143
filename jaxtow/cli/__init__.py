"""The ``jaxtow`` command line.

Subcommands:

* ``jaxtow study TOW --out DIR``: the whole assessment of one tow (a tow file or a built-in
  tow: barge1, barge2a, barge2b) as NetCDF, JSON and one self-contained HTML report.
* ``jaxtow tow show TOW`` / ``jaxtow tow new FILE``: a resolved tow file with every default
  and estimate; a commented template.
* ``jaxtow calm --out DIR``: the without-waves stability study of thesis section 6.1 for
  Barge 2a and 2b (equilibria vs x_p', max Re λ vs l0', a (x_p', l0') stability map, and
  time-domain runs from the thesis's initial condition, figs 6.5-6.7): PNG figures,
  NetCDF datasets and a JSON summary in DIR.
* ``jaxtow equilibria``: the equilibria of one configuration and their eigenvalues.
* ``jaxtow map``: any sweep over named parameters, saved as NetCDF (and a figure for 1-D
  and 2-D sweeps).
* ``jaxtow drift``: the waterline drift methods compared (thesis chapters 4-5, figs
  4.3-4.6, 5.6-5.7) for Barge 1, Barge 2 or a waterline file, with relative MSE per zone.
* ``jaxtow bifurcation``: equilibrium branches in one parameter with pitchfork, fold and
  Hopf points (first Lyapunov coefficient) and limit cycles (path width, Floquet multipliers).
* ``jaxtow bem``: panel-method (Capytaine, optional extra) RAOs and far-/near-field drift
  QTF databases for Barge 1, Barge 2 or a mesh file, and the mesh-convergence study.
* ``jaxtow simulate``: time-domain runs (time traces, phase portraits, force history,
  fishtailing metrics).

Run ``jaxtow SUBCOMMAND --help`` for the options.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from filelock import FileLock, Timeout

import jaxtow as jt

from . import (
    bem,
    bifurcation,
    calm,
    drift,
    equilibria,
    map,
    report,
    resistance,
    simulate,
    study,
    tow,
)
from ._manifest import Manifest, up_to_date

#: One module per subcommand, each with ``add_parser(sub)``; the order of ``jaxtow --help``.
SUBCOMMANDS = (
    study,
    tow,
    calm,
    equilibria,
    simulate,
    map,
    drift,
    bifurcation,
    resistance,
    report,
    bem,
)


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="jaxtow",
        description="Towing stability of a barge on an elastic towline (JAX). "
        "Non-dimensional inputs use the thesis scales: lengths by L, stiffness by 0.5*rho*T*L*U_tug^2.",
    )
    p.add_argument(
        "--no-compile-cache",
        action="store_true",
        help="do not use the persistent compilation cache nor the traced programs beside it "
        "(default: on, in $JAXTOW_COMPILE_CACHE or ~/.cache/jaxtow/xla, and <that>-programs; "
        "JAXTOW_COMPILE_CACHE=off also disables them)",
    )
    sub = p.add_subparsers(dest="command", required=True)
    for module in SUBCOMMANDS:
        module.add_parser(sub)
    return p


def main(argv=None) -> int:
    """Entry point of the ``jaxtow`` command."""
    argv = list(sys.argv[1:] if argv is None else argv)
    no_cache = "--no-compile-cache" in argv  # accepted before or after the subcommand
    argv = [a for a in argv if a != "--no-compile-cache"]
    args = build_parser().parse_args(argv)
    out = getattr(args, "out", None)
    lock = _lock_output(out)
    try:
        return _run(args, argv, out, no_cache)
    finally:
        if lock is not None:
            lock.close()


def _run(args, argv, out, no_cache: bool) -> int:
    """The command, with its manifest, under the output folder's lock (held by `main`)."""
    fingerprint = getattr(args, "fingerprint", None)
    request = fingerprint(args) if fingerprint is not None else None
    if request is not None and not getattr(args, "force", False):
        done = up_to_date(out, request)
        if done is not None:
            print(
                f"jaxtow {args.command}: {out} is up to date: its run of {done['finished']} "
                f"asked the same and wrote {len(done['outputs'])} files, all still there "
                "(--force recomputes)"
            )
            return 0
    import matplotlib

    if not (no_cache or args.no_compile_cache):
        try:
            jt.enable_compile_cache()
        except ValueError as e:
            raise SystemExit(f"error: {e}") from None

    matplotlib.use("Agg")  # the command line writes figures to files; it never opens windows
    manifest = None
    if out is not None:
        naming = getattr(args, "manifest_name", None)
        name = naming(args) if naming is not None else None
        manifest = Manifest(out, args, argv, request=request, name=name)
        manifest.start()
    status, error = "failed", None
    try:
        with jt.sticky_interrupts():  # a Ctrl-C swallowed on its way still stops a study
            args.func(args)
        status = "finished"
    except KeyboardInterrupt:
        status = "interrupted"
        kept = (
            f" Files already written in {out} are complete (each is written under a temporary "
            "name and renamed when done; the list is in its run manifest); `jaxtow map` "
            "keeps its finished chunks and resumes from them when run again; `jaxtow study` "
            "keeps its finished steps and continues from them with --resume."
            if out is not None
            else ""
        )
        print(f"\njaxtow {args.command}: interrupted.{kept}", file=sys.stderr)
        raise SystemExit(130) from None
    except (ValueError, TypeError, KeyError, OSError, RuntimeError) as e:
        error = error_message(e)
        if os.environ.get("JAXTOW_TRACEBACK", "") not in ("", "0"):
            raise
        raise SystemExit(
            f"jaxtow {args.command}: error: {error}\n(JAXTOW_TRACEBACK=1 shows where it came from)"
        ) from None
    except SystemExit as e:  # a command's own one-line error
        error = str(e.code) if isinstance(e.code, str) else f"exit status {e.code}"
        raise
    finally:
        if manifest is not None:
            manifest.end(status, error)
    return 0


def error_message(e: BaseException) -> str:
    """One line for an error: the message of a check made under jit (`equinox.error_if`,
    which JAX wraps in a runtime error with the callback's traceback) or the first line of
    any other error's message."""
    text = str(e.args[0]) if isinstance(e, KeyError) and e.args else str(e)
    lines = [ln.strip() for ln in text.splitlines() if ln.strip()]
    for ln in lines:
        if "EquinoxRuntimeError: " in ln:
            return ln.split("EquinoxRuntimeError: ", 1)[1]
    return lines[0] if lines else type(e).__name__


def _lock_output(out):
    """Create the output folder and hold an exclusive lock on it for the run (filelock's
    `FileLock` on ``.jaxtow.lock``, removed when the run ends), so that two runs into one
    folder cannot overwrite each other's files: the second stops at once with a message.
    None where the command has no --out."""
    if out is None:
        return None
    path = Path(out)
    if path.exists() and not path.is_dir():
        raise SystemExit(f"error: --out {out} is a file; give a folder for the outputs")
    try:
        path.mkdir(parents=True, exist_ok=True)
        # an explicit probe: how a lock library treats a folder it cannot write to varies
        # (a soft-lock fallback, say), and the run would fail only at its first file
        probe = path / ".jaxtow.write-test"
        probe.touch()
        probe.unlink()
    except OSError as e:
        raise SystemExit(
            f"error: --out {out}: cannot write there ({e.strerror or e}); give a folder you can write to"
        ) from None
    lock = FileLock(path / ".jaxtow.lock", is_singleton=False)
    try:
        lock.acquire(timeout=0)
    except Timeout:
        raise SystemExit(
            f"error: another jaxtow run is writing into {path}; wait for it to finish or "
            "give another --out"
        ) from None
    return _Held(lock)


class _Held:
    """A held lock, released by ``close`` (the run's end)."""

    def __init__(self, lock: FileLock):
        self.lock = lock

    def close(self) -> None:
        self.lock.release()
        Path(self.lock.lock_file).unlink(missing_ok=True)  # no empty lock file left behind


if __name__ == "__main__":
    sys.exit(main())
