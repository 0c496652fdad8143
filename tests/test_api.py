"""The public API: every module path imports, no function shadows a module, and every public
name has exactly one home."""

import importlib
import inspect
import pkgutil
import types

import pytest

import jaxtow

PUBLIC = [
    "jaxtow",
    "jaxtow.forces",
    "jaxtow.drift",
    "jaxtow.waves",
    "jaxtow.resistance",
    "jaxtow.continuation",
    "jaxtow.design",
    "jaxtow.distributed",
    "jaxtow.lines",
    "jaxtow.presets",
    "jaxtow.study",
    "jaxtow.reports",
    "jaxtow.tow",
    "jaxtow.io",
    "jaxtow.plotting",
    "jaxtow.bem",
    "jaxtow.cli",
]


def _all_modules():
    names = ["jaxtow"]
    for info in pkgutil.walk_packages(jaxtow.__path__, "jaxtow."):
        names.append(info.name)
    return names


@pytest.mark.parametrize("name", _all_modules())
def test_module_imports_and_is_not_shadowed(name):
    module = importlib.import_module(name)
    assert isinstance(module, types.ModuleType)
    if "." in name:
        parent, _, leaf = name.rpartition(".")
        attr = getattr(importlib.import_module(parent), leaf)
        assert attr is module, f"{parent}.{leaf} is {attr!r}, not the module {name}"


def test_implementation_modules_are_private():
    """Below a public package, a module is either private or itself a public namespace."""
    for name in _all_modules():
        parts = name.split(".")
        if name in PUBLIC or parts[-1].startswith("_"):
            continue
        # jaxtow.io, jaxtow.plotting, jaxtow.bem and jaxtow.cli hold public submodules by design
        assert parts[1] in ("io", "plotting", "bem", "cli"), (
            f"{name} is public but not a documented namespace"
        )


def _public_names(pkg):
    mod = importlib.import_module(pkg)
    names = getattr(mod, "__all__", None) or [n for n in vars(mod) if not n.startswith("_")]
    return {n: getattr(mod, n) for n in names}


def test_every_public_name_has_one_home():
    homes = {}
    for pkg in PUBLIC:
        for name, obj in _public_names(pkg).items():
            if inspect.ismodule(obj) or not (inspect.isclass(obj) or inspect.isfunction(obj)):
                continue
            if not getattr(obj, "__module__", "").startswith("jaxtow"):
                continue
            homes.setdefault(id(obj), []).append(f"{pkg}.{name}")
    twice = [h for h in homes.values() if len(h) > 1]
    assert not twice, f"names exported from more than one place: {twice}"


@pytest.mark.parametrize(
    "pkg", [p for p in PUBLIC if p not in ("jaxtow.design", "jaxtow.presets", "jaxtow.study")]
)
def test_public_packages_declare_all(pkg):
    mod = importlib.import_module(pkg)
    if pkg == "jaxtow.cli":
        assert callable(mod.main)
        return
    assert mod.__all__, pkg
    for name in mod.__all__:
        assert hasattr(mod, name), f"{pkg}.__all__ names {name!r}, which does not exist"


def test_version_comes_from_the_package_metadata():
    from importlib.metadata import version

    assert jaxtow.__version__ == version("jaxtow")
