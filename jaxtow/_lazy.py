"""Lazy public names of a package (PEP 562).

A package lists its public names once, as ordinary re-exports inside ``if TYPE_CHECKING:``
(so type checkers and the API docs read them as they always did), and hands its own source
to `attach`. Each name is imported on first access and then kept in the package, so that
``import jaxtow`` costs a few milliseconds and ``jaxtow bem`` or ``jaxtow --help`` never
load JAX, xarray or Capytaine unless they use them. A submodule that is not listed loads on
first use as well (``jaxtow.plotting.calm``), so that the command line can name everything
through the package facade at no cost until it runs.
"""

from __future__ import annotations

import ast
import importlib
import importlib.util
import sys
from pathlib import Path


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING"
    )


def lazy_table(source: str) -> dict[str, tuple[str | None, str]]:
    """name -> (submodule or None for ``from . import name``, name in it), read from the
    relative imports inside the top-level ``if TYPE_CHECKING:`` blocks of ``source``."""
    table: dict[str, tuple[str | None, str]] = {}
    for node in ast.parse(source).body:
        if not (isinstance(node, ast.If) and _is_type_checking(node.test)):
            continue
        for stmt in node.body:
            if not (isinstance(stmt, ast.ImportFrom) and stmt.level == 1):
                raise ValueError(
                    f"line {stmt.lineno}: only relative 'from . import' statements belong in a "
                    "lazy package's TYPE_CHECKING block"
                )
            for alias in stmt.names:
                table[alias.asname or alias.name] = (stmt.module, alias.name)
    return table


def attach(package: str, file: str):
    """``(__getattr__, __dir__, __all__)`` of ``package`` (its ``__name__``) whose source
    file ``file`` (its ``__file__``) lists its lazy names as described in the module
    docstring. ``__all__`` is read from the same block (its names, less the submodules it
    lists with ``from . import name``), so that a package lists its public names once."""
    table = lazy_table(Path(file).read_text(encoding="utf-8"))
    public = [name for name, (module, _) in table.items() if module is not None]

    def __getattr__(name: str):
        try:
            module, attr = table[name]
        except KeyError:
            # a submodule not listed (``jaxtow.plotting.calm``) loads on first use too
            if importlib.util.find_spec(f"{package}.{name}") is None:
                raise AttributeError(f"module {package!r} has no attribute {name!r}") from None
            module, attr = None, name
        if module is None:
            value = importlib.import_module(f"{package}.{attr}")
        else:
            value = getattr(importlib.import_module(f"{package}.{module}"), attr)
        setattr(sys.modules[package], name, value)
        return value

    def __dir__():
        return sorted(set(vars(sys.modules[package])) | set(table))

    return __getattr__, __dir__, public
