"""The persistent compilation cache of the command line: a second run compiles nothing new."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

import jaxtow as jt
from jaxtow import _compile_cache as cc

RUN = "import sys; from jaxtow.cli import main; sys.exit(main())"


def _cli(args, env):
    full = {k: v for k, v in os.environ.items() if k != cc.ENV} | env
    subprocess.run([sys.executable, "-c", RUN, *args], env=full, check=True, capture_output=True)


def _entries(folder: Path) -> set:
    return {p.name for p in folder.glob("*-cache")} if folder.exists() else set()


@pytest.mark.slow  # default-suite time
def test_second_cli_run_hits_the_cache(tmp_path):
    folder = tmp_path / "xla"
    args = ["equilibria", "--tow", "barge2b"]
    _cli(args, {cc.ENV: str(folder)})
    first = _entries(folder)
    assert len(first) > 20  # every kernel of the run is stored
    _cli(args, {cc.ENV: str(folder)})
    assert _entries(folder) == first  # the second run compiled nothing new


@pytest.mark.slow  # default-suite time
def test_cache_switches(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert cc.default_cache_dir() == tmp_path / "jaxtow" / "xla"
    for off in ("off", "0", "False", "no"):
        monkeypatch.setenv(cc.ENV, off)
        assert jt.enable_compile_cache() is None
    assert not (tmp_path / "jaxtow").exists()
    # the command-line switch: no folder is made even with the environment unset
    _cli(
        ["equilibria", "--tow", "barge2b", "--no-compile-cache"],
        {"XDG_CACHE_HOME": str(tmp_path)},
    )
    assert not (tmp_path / "jaxtow").exists()
