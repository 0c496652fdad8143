"""The package's layers run one way: its import graph, read from the source with every import
counted (those inside functions and under ``TYPE_CHECKING`` too), has no cycle, and the
numerical layers import no file format, no built-in data and no figure.

The layer contract itself (which layer may import which) is import-linter's, in
pyproject.toml, run by ``lint-imports`` in CI; this module checks what import-linter does not:
the graph as a whole, and the rules of docs/architecture.md."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "jaxtow"

#: The numerical layers (docs/architecture.md): arrays and result objects only.
NUMERICS = (
    "jaxtow._",  # the core and the tow model's private modules
    "jaxtow.lines",
    "jaxtow.guidelines",
    "jaxtow.strip",
    "jaxtow.waves",
    "jaxtow.drift",
    "jaxtow.resistance",
    "jaxtow.forces",
    "jaxtow.continuation",
    "jaxtow.design",
    "jaxtow.risk",
)
#: Modules of the numerical layers' own namespace that are not numerics: the labelled-results
#: module joins the numerics with `jaxtow.io` and sits above it; the progress meters are the
#: protocol a chunked loop reports to and its tqdm implementation (diffrax ships its
#: ``TqdmProgressMeter`` beside its solvers the same way), passed in as objects.
NOT_NUMERICS = ("jaxtow._results", "jaxtow._progress")
#: What the numerics never import.
ABOVE_NUMERICS = (
    "jaxtow.io",
    "jaxtow.presets",
    "jaxtow.studies",
    "jaxtow.tow",
    "jaxtow.bem",
    "jaxtow.reports",
    "jaxtow.plotting",
    "jaxtow.cli",
    "jaxtow._results",
    "jaxtow.distributed",
    "xarray",
    "netCDF4",
    "matplotlib",
    "tqdm",
)


def _modules() -> dict[str, Path]:
    out = {}
    for path in PACKAGE.rglob("*.py"):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = path
    return out


def _imports(name: str, path: Path) -> list[tuple[str, int, bool]]:
    """(imported module, line, inside a function) of every import statement in a module;
    relative imports resolved. ``from pkg import name`` counts as an import of ``pkg.name``
    where that is a module, else of ``pkg``."""
    is_package = path.name == "__init__.py"
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found: list[tuple[str, int, bool]] = []

    def visit(node, in_function: bool):
        for child in ast.iter_child_nodes(node):
            inside = in_function or isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef)
            if isinstance(child, ast.Import):
                found.extend((a.name, child.lineno, in_function) for a in child.names)
            elif isinstance(child, ast.ImportFrom):
                if child.level:
                    base = name.split(".") if is_package else name.split(".")[:-1]
                    base = base[: len(base) - (child.level - 1)]
                    module = ".".join(base + ([child.module] if child.module else []))
                else:
                    module = child.module or ""
                found.extend((f"{module}.{a.name}", child.lineno, in_function) for a in child.names)
            visit(child, inside)

    visit(tree, False)
    return found


def _graph() -> dict[str, set[str]]:
    """module -> the package modules it imports (a name imported from a module counts as
    an import of that module)."""
    mods = _modules()
    edges: dict[str, set[str]] = {m: set() for m in mods}
    for m, path in mods.items():
        for target, _, _ in _imports(m, path):
            t = target
            while t not in mods and "." in t:
                t = t.rsplit(".", 1)[0]
            if t in mods and t != m:
                edges[m].add(t)
    return edges


def _cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10_000))

    def connect(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(edges[v]):
            if w not in index:
                connect(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(edges):
        if v not in index:
            connect(v)
    return out


def test_the_graph_reader_sees_imports_inside_functions(tmp_path):
    src = "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from .b import x\n"
    src += "def f():\n    from ..c import d\n    import jaxtow.e\n"
    path = tmp_path / "a.py"
    path.write_text(src)
    got = _imports("jaxtow.p.a", path)
    assert ("jaxtow.p.b.x", 3, False) in got
    assert ("jaxtow.c.d", 5, True) in got
    assert ("jaxtow.e", 6, True) in got
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert _cycles({"a": {"b"}, "b": set()}) == []


def test_the_import_graph_is_acyclic():
    edges = _graph()
    cycles = _cycles(edges)
    detail = [
        {m: sorted(t for t in edges[m] if t in c) for m in c} for c in cycles
    ]  # who imports whom inside each cycle
    assert not cycles, f"import cycles: {detail}"


def test_no_module_imports_the_package_facade():
    """`jaxtow/__init__.py` re-exports the whole library; only the application (the command
    line) may import it, or every module would depend on every other one."""
    edges = _graph()
    users = sorted(m for m in edges if "jaxtow" in edges[m] and not m.startswith("jaxtow.cli"))
    assert not users, f"modules importing the facade `jaxtow`: {users}"


def _is_numerics(m: str) -> bool:
    return m.startswith(NUMERICS) and not m.startswith(NOT_NUMERICS)


def test_numerics_import_no_files_data_or_figures():
    mods = _modules()
    bad = []
    for m, path in mods.items():
        if not _is_numerics(m):
            continue
        for target, line, _ in _imports(m, path):
            if target.startswith(ABOVE_NUMERICS):
                bad.append(f"{path.relative_to(PACKAGE.parent)}:{line} imports {target}")
    assert not bad, "\n".join(bad)


#: Optional heavy dependencies that a function may import where it needs them (one reason
#: each, docs/architecture.md): they are extras, or slow to import for a path that rarely
#: needs them.
LOCAL_IMPORTS_ALLOWED = {
    "capytaine": "an optional extra (jaxtow[bem])",
    "dask": "an optional extra (jaxtow[dask])",
    "distributed": "an optional extra (jaxtow[dask])",
    "matplotlib": "its import costs about a second and selects a backend",
    "tqdm": "a progress display: a chunked loop loads it only where a bar is shown",
}


def test_the_library_has_no_internal_imports_inside_functions():
    """Below the command line, an import inside a function is one of an optional heavy
    dependency (`LOCAL_IMPORTS_ALLOWED`)."""
    mods = _modules()
    bad = []
    for m, path in mods.items():
        if m.startswith("jaxtow.cli"):
            continue
        for target, line, in_function in _imports(m, path):
            if in_function and target.split(".")[0] not in LOCAL_IMPORTS_ALLOWED:
                bad.append(f"{path.relative_to(PACKAGE.parent)}:{line} imports {target}")
    assert not bad, "\n".join(bad)


def test_the_layer_contract_holds():
    """import-linter's contract (pyproject.toml) on the installed source."""
    lint = Path(sys.executable).with_name("lint-imports")
    if not lint.exists():
        pytest.skip("import-linter is not installed (pip install -e '.[dev]')")
    r = subprocess.run([str(lint)], capture_output=True, text=True, cwd=PACKAGE.parent, timeout=300)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-3000:]
    assert "1 kept, 0 broken" in r.stdout


def test_the_architecture_page_lists_every_module():
    """docs/architecture.md holds the module table made from the docstrings and the layer
    contract (`python tests/module_table.py --write` after adding or moving a module)."""
    import module_table

    assert module_table.current() == module_table.table(), (
        "docs/architecture.md's module table is out of date: run python tests/module_table.py --write"
    )


#: The functions allowed over `MAX_LINES` (docs/architecture.md, "Function size").
LONG_FUNCTIONS = {"jaxtow._simulate.integrate", "jaxtow.bem.solve.solve_frequency"}
MAX_LINES = 80


def test_no_function_is_longer_than_80_lines_but_the_listed_kernels():
    long = {}
    for m, path in _modules().items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                n = node.end_lineno - node.lineno + 1
                if n > MAX_LINES:
                    long[f"{m}.{node.name}"] = n
    assert set(long) <= LONG_FUNCTIONS, {k: v for k, v in long.items() if k not in LONG_FUNCTIONS}
    page = (PACKAGE.parent / "docs" / "architecture.md").read_text(encoding="utf-8")
    for name in LONG_FUNCTIONS:
        assert f"`{name}`" in page


def _private(module: str) -> bool:
    return any(part.startswith("_") for part in module.split(".")[1:])


def test_no_underscore_name_crosses_a_module():
    """A name that starts with an underscore is its module's own: no other module imports it
    (a package's private modules share their public names, `from ._x import name`)."""
    mods = _modules()
    bad = []
    for path in mods.values():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not isinstance(node, ast.ImportFrom):
                continue
            for a in node.names:
                name = a.name
                if not name.startswith("_") or name.startswith("__"):
                    continue
                if not any(k.endswith("." + name) for k in mods):  # a module is no name
                    bad.append(f"{path.relative_to(PACKAGE.parent)}:{node.lineno} imports {name}")
    assert not bad, "\n".join(bad)


def test_the_command_line_uses_public_names_only():
    """The application imports the library through its public names: the facade `jaxtow`, a
    public package or module, or its own modules; never another package's private module."""
    bad = []
    for m, path in _modules().items():
        if not m.startswith("jaxtow.cli"):
            continue
        for target, line, _ in _imports(m, path):
            if not target.startswith("jaxtow.") or target.startswith("jaxtow.cli"):
                continue
            mod = target
            while mod not in _modules() and "." in mod:
                mod = mod.rsplit(".", 1)[0]
            if _private(mod):
                bad.append(f"{path.relative_to(PACKAGE.parent)}:{line} imports {target}")
    assert not bad, "\n".join(bad)


def test_the_sweep_loop_loads_no_progress_display():
    """The numerics' chunked loops take a progress meter as an object: importing them loads
    neither tqdm nor matplotlib (the command line's bar loads tqdm when it is shown)."""
    code = (
        "import sys, jaxtow._sweep, jaxtow._simulate, jaxtow._progress\n"
        "print(sorted(m for m in ('tqdm', 'matplotlib', 'xarray') if m in sys.modules))"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]", r.stdout


def _contract_layers() -> list[list[str]]:
    import tomllib

    cfg = tomllib.loads((PACKAGE.parent / "pyproject.toml").read_text(encoding="utf-8"))
    (contract,) = cfg["tool"]["importlinter"]["contracts"]
    return [[p.strip() for p in layer.split("|")] for layer in contract["layers"]]


def test_numerics_covers_every_numerical_layer_of_the_contract():
    """`NUMERICS` (what may import no file format, data or figure) holds every module that
    the import contract places in the numerical layers or the core, and the architecture
    page's numerics row names every numerical package of the contract."""
    layers = _contract_layers()
    top = next(i for i, layer in enumerate(layers) if "jaxtow.design" in layer)
    below = [m for layer in layers[top:] for m in layer]
    missing = [m for m in below if not m.startswith(NUMERICS) or m.startswith(NOT_NUMERICS)]
    assert missing in ([], ["jaxtow._progress"]), missing
    page = (PACKAGE.parent / "docs" / "architecture.md").read_text(encoding="utf-8")
    row = next(line for line in page.splitlines() if line.startswith("| numerics |"))
    core = next(line for line in page.splitlines() if line.startswith("| core |"))
    for m in below:
        short = m if not m.startswith("jaxtow._") else m.removeprefix("jaxtow.")
        assert f"`{short}`" in row + core, f"docs/architecture.md's layer table lacks {m}"
