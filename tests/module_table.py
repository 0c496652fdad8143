"""The module table of docs/architecture.md, made from the package's own docstrings and the
layer contract in pyproject.toml: one row a module, its layer and the first sentence of its
docstring. `tests/test_layers.py` keeps the page equal to it; after adding or moving a
module, write it with ``python tests/module_table.py --write``."""

from __future__ import annotations

import ast
import re
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "docs" / "architecture.md"
BEGIN = "<!-- module table: python tests/module_table.py --write -->"
END = "<!-- end of module table -->"

#: The layers' names in the contract's order (pyproject.toml, top first), as the page uses.
LAYER_NAMES = {
    "jaxtow.cli": "application",
    "jaxtow.reports": "render",
    "jaxtow.plotting": "render",
    "jaxtow.studies": "studies",
    "jaxtow.tow": "tow files",
    "jaxtow.bem": "panel method",
    "jaxtow.presets": "data",
    "jaxtow._results": "labelled runs",
    "jaxtow.distributed": "labelled runs",
    "jaxtow.io": "files",
}
CORE = ("_units", "_roots", "_interp", "_special", "_compile_cache", "_progress", "_rules")
CORE += ("_config", "_lazy", "_values", "_interrupt", "_program_cache")


def _contract_modules() -> list[str]:
    data = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    layers = data["tool"]["importlinter"]["contracts"][0]["layers"]
    return [m.strip() for layer in layers for m in re.split(r"[|:]", layer)]


def layer_of(module: str, contract: list[str]) -> str:
    """The layer of a module: that of the longest contract entry it is or lies in."""
    owner = max((c for c in contract if module == c or module.startswith(c + ".")), key=len)
    if owner in LAYER_NAMES:
        return LAYER_NAMES[owner]
    return "core" if owner.rsplit(".", 1)[-1] in CORE else "numerics"


def first_sentence(doc: str | None) -> str:
    if not doc:
        return ""
    para = " ".join(doc.strip().split("\n\n")[0].split())
    depth, end = 0, len(para)
    for i, ch in enumerate(para):
        depth += (ch == "(") - (ch == ")")
        if depth == 0 and ch in ".:;" and (i + 1 == len(para) or para[i + 1] == " "):
            end = i
            break
    return para[:end].replace("|", "\\|")


def rows() -> list[tuple[str, str, str]]:
    contract = _contract_modules()
    out = []
    for path in sorted((ROOT / "jaxtow").rglob("*.py")):
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        name = ".".join(parts)
        if name == "jaxtow":
            continue
        doc = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8")))
        out.append((name, layer_of(name, contract), first_sentence(doc)))
    return out


def table() -> str:
    lines = [BEGIN, "", "| module | layer | what it holds |", "| --- | --- | --- |"]
    lines += [f"| `{m}` | {layer} | {text} |" for m, layer, text in rows()]
    return "\n".join([*lines, "", END])


def current() -> str:
    page = PAGE.read_text(encoding="utf-8")
    i, j = page.index(BEGIN), page.index(END) + len(END)
    return page[i:j]


if __name__ == "__main__":
    if "--write" in sys.argv:
        page = PAGE.read_text(encoding="utf-8")
        PAGE.write_text(page.replace(current(), table()), encoding="utf-8")
    else:
        print(table())
