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
    "jaxtow.strip",
    "jaxtow.continuation",
    "jaxtow.design",
    "jaxtow.risk",
    "jaxtow.distributed",
    "jaxtow.lines",
    "jaxtow.guidelines",
    "jaxtow.presets",
    "jaxtow.studies",
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


@pytest.mark.parametrize("pkg", [p for p in PUBLIC if p not in ("jaxtow.design",)])
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


def _fresh(code: str, **env) -> str:
    import os
    import subprocess
    import sys

    r = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        timeout=300,
        check=True,
        env={**os.environ, **env},
    )
    return r.stdout


def test_import_loads_nothing_heavy_until_a_name_is_used():
    """`import jaxtow` and `import jaxtow.cli` load neither JAX nor xarray, matplotlib or
    Capytaine; the first use of a name loads its module, and float64 is on as before."""
    out = _fresh(
        "import sys, jaxtow, jaxtow.cli\n"
        "heavy = ('jax', 'xarray', 'matplotlib', 'capytaine', 'equinox')\n"
        "print('LOADED', [m for m in heavy if m in sys.modules])\n"
        "import jax.numpy as jnp\n"
        "print('DTYPE', jnp.ones(1).dtype)\n"
        "print('NAME', jaxtow.TowModel.__module__, 'jaxtow.drift' in sys.modules)\n"
        "print('DIR', set(jaxtow.__all__) <= set(dir(jaxtow)))\n"
    )
    assert "LOADED []" in out
    assert "DTYPE float64" in out
    assert "NAME jaxtow._dynamics" in out
    assert "DIR True" in out
    # the opt-out still works, before and after JAX is imported
    assert "float32" in _fresh(
        "import jaxtow, jax.numpy as jnp; print(jnp.ones(1).dtype)", JAXTOW_ENABLE_X64="0"
    )
    assert "float64" in _fresh("import jax, jaxtow, jax.numpy as jnp; print(jnp.ones(1).dtype)")
    with pytest.raises(AttributeError, match="no attribute 'nonexistent'"):
        _ = jaxtow.nonexistent  # type: ignore[attr-defined]


def test_lazy_table_reads_the_type_checking_block():
    from jaxtow._lazy import lazy_table

    src = (
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n"
        "    from . import sub as sub\n    from ._impl import f as f, g as h\n"
    )
    assert lazy_table(src) == {"sub": (None, "sub"), "f": ("_impl", "f"), "h": ("_impl", "g")}
    with pytest.raises(ValueError, match="relative"):
        lazy_table("if TYPE_CHECKING:\n    import numpy\n")
