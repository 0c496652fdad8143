"""``jaxtow tow show|new``: print a resolved tow file, write a commented template."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import jaxtow as jt


def load_tow(spec, command: str):
    """The `jaxtow.tow.Tow` of a built-in name or a file, with a one-line error (and the
    deprecation message for an old spelling) on stderr."""

    name, msg = jt.tow.canonical_name(str(spec))
    if msg:
        print(f"jaxtow {command}: warning: {msg}", file=sys.stderr)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            tow = jt.tow.load(name)
        except jt.tow.TowFileError as e:
            raise SystemExit(f"jaxtow {command}: error: {e}") from None
    for w in caught:
        if not issubclass(w.category, DeprecationWarning):
            print(f"jaxtow {command}: warning: {w.message}", file=sys.stderr)
    return tow


def cmd_show(args):
    print(load_tow(args.tow, "tow show").show())


def cmd_new(args):
    out = Path(args.file)
    if out.exists() and not args.force:
        raise SystemExit(f"jaxtow tow new: error: {out} exists (use --force to overwrite)")
    jt.io.write_file(out, jt.tow.template())
    print(f"wrote a commented tow-file template to {out}; check it with: jaxtow tow show {out}")


def add_parser(sub):
    t = sub.add_parser("tow", help="tow files: show a resolved one, write a template")
    tsub = t.add_subparsers(dest="tow_command", required=True)
    s = tsub.add_parser("show", help="print the resolved tow file: every default and estimate")
    s.add_argument("tow", help="tow file, or a built-in tow: barge1, barge2a, barge2b")
    s.set_defaults(func=cmd_show)
    n = tsub.add_parser("new", help="write a commented tow-file template")
    n.add_argument("file", nargs="?", default="tow.toml", help="file to write (default tow.toml)")
    n.add_argument("--force", action="store_true", help="overwrite an existing file")
    n.set_defaults(func=cmd_new)
