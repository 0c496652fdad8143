"""The persistent compilation cache of the command line: a second run compiles nothing new."""

import json
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


COUNTED = """
import atexit, json, os, sys
import jax.monitoring
counts = {"requests": 0, "hits": 0}
names = {"/jax/compilation_cache/compile_requests_use_cache": "requests",
         "/jax/compilation_cache/cache_hits": "hits"}
def count(event, **_):
    if event in names:
        counts[names[event]] += 1
jax.monitoring.register_event_listener(count)
atexit.register(lambda: open(os.environ["COUNTS"], "w").write(json.dumps(counts)))
from jaxtow.cli import main
sys.exit(main())
"""


@pytest.mark.slow  # default-suite time
def test_second_run_with_time_domain_runs_reads_every_program_from_the_cache(tmp_path):
    """The time-domain run is a program like the others: a second `jaxtow simulate` asks
    the cache for every program it compiles and finds each one there."""
    folder, counts = tmp_path / "xla", tmp_path / "counts.json"
    args = ["simulate", "--tows", "barge2b", "--t1", "20", "--n-save", "201"]
    env = {k: v for k, v in os.environ.items() if k != cc.ENV} | {cc.ENV: str(folder)}
    for run in ("first", "second"):
        out = ["--out", str(tmp_path / run)]
        subprocess.run(
            [sys.executable, "-c", COUNTED, *args, *out],
            env=env | {"COUNTS": str(counts)},
            check=True,
            capture_output=True,
        )
    second = json.loads(counts.read_text())
    assert second["requests"] > 5
    assert second["hits"] == second["requests"]


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


@pytest.mark.parametrize("waves", [False, True])
def test_the_sweep_kernel_holds_no_host_callback(waves):
    """JAX's persistent cache never stores a program holding a host callback (an
    `equinox.error_if` check compiles to one), so such a kernel compiles again in every
    run. The sweep kernel checks its grid before it runs and holds none, in calm water and
    with the regular-wave drift force of the wave study."""
    import jax.numpy as jnp

    from jaxtow._sweep import make_batched_kernel

    if waves:
        model = jt.studies.WaveStudy(n=5, n_grid=101, compile_cache=False).wave_model("2a")
        params = {"l0": jnp.linspace(0.5, 2.5, 4), "external.omega": jnp.linspace(0.4, 2.0, 4)}
    else:
        model = jt.TowModel(vessel=jt.presets.barge_2b(), towline=jt.presets.default_towline())
        params = {"l0": jnp.linspace(0.5, 2.5, 4)}
    kernel = make_batched_kernel(
        method="numerical", n_grid=101, max_roots=4, psi_range=1.5, eig_method="routh"
    )
    text = kernel.jitted.trace(model, params).lower().as_text()
    assert "callback" not in text


def test_the_model_at_another_tug_speed_shares_the_compiled_kernels():
    """`at_tug_speed` keeps the type of every leaf (dtype and weak typing): the model at the
    operating speed is the same argument type as at the design speed, so a kernel traced and
    compiled for one serves the other (a strongly typed EA' made a new trace and compile of
    every kernel the study's operating-speed conditions met)."""
    import jax

    tow = jt.tow.load("barge2a")
    model = tow.sea_model(tow.sea_states[0])

    def types(m):
        return [(x.dtype, x.weak_type, x.shape) for x in jax.tree.leaves(m)]

    moved = jt.at_tug_speed(model, 2.7)
    assert types(moved) == types(model)
    assert float(moved.towline.EA) == pytest.approx(
        float(model.towline.EA) * (float(model.reference_scales.u_tug) / 2.7) ** 2
    )
    f = jax.jit(lambda m: m.towline.EA * m.scales.u_tug)
    f(model)
    f(moved)
    assert f._cache_size() == 1
