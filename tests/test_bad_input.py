"""Bad input gives a clear error that names the parameter, never a silent wrong answer:
the cases a campaign of bad inputs found silent, each with its reproduction."""

import jax
import jax.numpy as jnp
import numpy as np
import pytest

import jaxtow as jt

P = jt.presets


@pytest.fixture(scope="module")
def model():
    return jt.TowModel(vessel=P.barge_2a(), towline=P.default_towline(), scales=P.barge2_scales())


def test_nan_eigenvalues_are_invalid_not_marginal():
    code = int(jt.classify(jnp.nan))
    assert jt.STABILITY_LABELS[code].startswith("invalid")
    assert (
        int(jt.classify(0.0)) == 0 and int(jt.classify(-1.0)) == -1 and int(jt.classify(1.0)) == 1
    )


def test_vector_field_wants_the_six_states(model):
    with pytest.raises(ValueError, match=r"y must be the state .* shape \(6,\), got shape \(5,\)"):
        jt.vector_field(0.0, jnp.ones(5), model)


def test_eigenvalues_under_jit_check_the_model(model):
    y = jt.equilibria(model).state[0]
    with pytest.raises(Exception, match="l0"):  # traced l0: only the traced check can see it
        jax.jit(lambda l0: jt.eigenvalues(jt.with_parameters(model, l0=l0), y))(-1.0)
    with pytest.raises(Exception, match="l0"):
        jax.jit(lambda l0: jt.max_real_eigenvalue(jt.with_parameters(model, l0=l0), y))(-1.0)


def test_simulate_needs_a_finite_end(model):
    with pytest.raises(ValueError, match="'t1' must be finite"):
        jt.simulate(model, jt.initial_state(model, y0=0.3), t1=float("inf"))


def test_spectra_and_integrals_on_bad_grids():
    W = jt.waves
    w = jnp.linspace(0.2, 2.0, 50)
    with pytest.raises(ValueError, match="'omega' must be strictly ascending"):
        W.jonswap(w[::-1], hs=2.0, tp=8.0, normalise=True)
    with pytest.raises(ValueError, match="at least 2 frequencies"):
        W.jonswap(jnp.array([0.8]), hs=2.0, tp=8.0, normalise=True)
    with pytest.raises(ValueError, match="strictly ascending"):
        W.spectral_integral(w[::-1], jnp.ones(50), jnp.ones(50))
    # under jit and vmap the same rules, traced
    with pytest.raises(Exception, match="'hs' must be > 0"):
        jax.jit(lambda h: W.jonswap(w, hs=h, tp=8.0))(-1.0).block_until_ready()
    with pytest.raises(Exception, match="'tp' must be > 0"):
        jax.vmap(lambda tp: W.jonswap(w, hs=2.0, tp=tp))(jnp.array([8.0, 0.0])).block_until_ready()
    # a descending integration grid for the irregular-sea force is refused at construction
    qtf = jt.presets.database("barge2", "near_field")
    with pytest.raises(ValueError, match="ascending"):
        jt.forces.IrregularWaveDriftForce(
            qtf=qtf, spectrum=W.Jonswap(hs=2.0, tp=8.0), omega=w[::-1], scales=P.barge2_scales()
        )


def test_required_pull_speed_is_checked():
    R = jt.resistance
    tow = P.barge2_resistance("2a")
    sea = P.sea_state("survival")
    tug = P.illustrative_tug()
    with pytest.raises(ValueError, match="'speed' must be >= 0"):
        R.required_pull(tow, sea, speed=-1.0, tug=tug)
    with pytest.raises(ValueError, match="below the tug's free speed"):
        R.required_pull(tow, sea, speed=float(tug.free_speed) + 1.0, tug=tug)


def test_design_grids_and_ranges_inside_the_rules(model):
    D = jt.design
    with pytest.raises(ValueError, match="xp"):
        D.grid_search(model, {"xp": [0.5, 1.5], "l0": [2.0, 2.5]})
    with pytest.raises(ValueError, match="bounds.*xp"):
        D.optimise_towline(model, variables=("xp",), bounds={"xp": (0.5, 1.4)})
    with pytest.raises(ValueError, match="l0"):
        D.sensitivity_arrays(model, ["Yv"], sweep={"l0": [2.0, -1.0]})


def test_continuation_range_and_step(model):
    ct = jt.continuation
    with pytest.raises(ValueError, match="'ds' must be > 0"):
        ct.equilibrium_branch(model, "l0", p_range=(1.0, 3.0), ds=0.0)
    with pytest.raises(ValueError, match="p_range.*l0"):
        ct.equilibrium_branch(model, "l0", p_range=(-1.0, 3.0))


def test_save_dataset_is_atomic(tmp_path, monkeypatch):
    """A write that fails part-way leaves the previous file (or none), never a partial one
    under the final name."""
    import xarray as xr

    from jaxtow.io import load_dataset, save_dataset

    good = xr.Dataset({"a": ("x", np.arange(3.0)), "ok": ("x", np.array([True, False, True]))})
    path = tmp_path / "map.nc"
    save_dataset(good, path)

    def broken(self, target, *a, **k):
        open(target, "wb").write(b"partial")
        raise KeyboardInterrupt

    monkeypatch.setattr(xr.Dataset, "to_netcdf", broken)
    with pytest.raises(KeyboardInterrupt):
        save_dataset(good.assign(a=("x", np.ones(3))), path)
    monkeypatch.undo()
    back = load_dataset(path)
    np.testing.assert_array_equal(back["a"].values, np.arange(3.0))
    assert back["ok"].dtype == bool
    assert [p.name for p in tmp_path.iterdir()] == ["map.nc"]


def _cli_error(argv, capsys):
    from jaxtow.cli import main

    with pytest.raises(SystemExit) as e:
        main(argv)
    assert e.value.code not in (0, None)
    err = capsys.readouterr().err + (e.value.code if isinstance(e.value.code, str) else "")
    assert "Traceback" not in err
    return err


def test_cli_counts_and_steps_must_be_positive(capsys):
    assert "expected a whole number >= 1, got 0" in _cli_error(["drift", "--n-omega", "0"], capsys)
    assert "expected a whole number >= 1" in _cli_error(
        ["bem", "barge2a", "--n-omega", "-3"], capsys
    )
    assert "expected a finite number > 0" in _cli_error(
        ["bifurcation", "--param", "xp", "--ds", "0"], capsys
    )


def test_resistance_config_sections_and_route_are_checked(tmp_path, capsys):
    from importlib import resources

    text = resources.files("jaxtow").joinpath("data", "resistance_barge2.toml").read_text()
    bad = tmp_path / "routex.toml"
    bad.write_text(text.replace("[route]", "[routex]"))
    assert "unknown section(s) ['routex']" in _cli_error(["resistance", str(bad)], capsys)
    neg = tmp_path / "neg.toml"
    neg.write_text(
        text.replace("[route]", "[route]\nlength_m = -5.0\n").replace("length_nm", "# length_nm")
    )
    assert "route length must be > 0" in _cli_error(["resistance", str(neg)], capsys)


def test_overtaken_waves_are_flagged_in_the_resistance_budget():
    """Following seas at speed: waves faster than ω = g/U are overtaken (ω_e <= 0), where
    no drift is counted; the budget says how much of the sea's energy that is."""
    import math

    R = jt.resistance
    tow = P.barge2_resistance("2a")
    head = P.sea_state("sailing")
    follow = P.sea_state("sailing", wave_angle=math.pi)
    assert float(R.resistance(tow, head, 4.0).overtaken_energy) == 0.0
    assert float(R.resistance(tow, follow, 1.0).overtaken_energy) == 0.0
    over = [float(R.resistance(tow, follow, U).overtaken_energy) for U in (4.0, 6.0)]
    assert 0.0 < over[0] < over[1] < 0.1
    # by hand: the JONSWAP energy above ω = g/U (following seas: ω_e = ω − ω²U/g)
    w = jt.waves.DEFAULT_OMEGA
    S = jt.waves.jonswap(w, hs=float(follow.hs), tp=float(follow.tp), gamma=float(follow.gamma))
    frac = jt.waves.spectral_integral(w, S, (w >= 9.80665 / 6.0).astype(float))
    assert over[1] == pytest.approx(
        float(frac / jt.waves.spectral_integral(w, S, jnp.ones_like(S))), rel=0.05
    )


def test_two_runs_into_one_folder_cannot_overwrite_each_other(tmp_path, capsys):
    """The output folder is locked for the run: a second run into it stops at once with a
    message (here the first run is simulated by holding the lock), and --out naming a file
    is refused before any computing."""
    pytest.importorskip("fcntl", reason="output locks are POSIX")
    from jaxtow.cli import _lock_output

    first = _lock_output(tmp_path / "out")
    assert first is not None
    try:
        with pytest.raises(SystemExit, match="another jaxtow run is writing into"):
            _lock_output(tmp_path / "out")
    finally:
        first.close()
    again = _lock_output(tmp_path / "out")  # free once the first run ends
    assert again is not None
    again.close()
    (tmp_path / "file").write_text("x")
    assert "is a file" in _cli_error(["calm", "--out", str(tmp_path / "file")], capsys)


def test_with_parameters_checks_concrete_values(model):
    """`eqx.tree_at` bypasses the constructors' checks; `with_parameters` applies the same
    rules to concrete values."""
    with pytest.raises(ValueError, match="'EA' must be > 0"):
        jt.with_parameters(model, EA=-1.0)
    with pytest.raises(ValueError, match="'l0' must be a number"):
        jt.with_parameters(model, l0="long")
    with pytest.raises(ValueError, match="'xp' must lie in"):
        jt.with_parameters(model, xp=3.0)
    assert float(jt.with_parameters(model, EA=200.0).towline.EA) == 200.0


@pytest.mark.slow  # default-suite time
def test_an_interrupted_sweep_resumes_from_its_checkpoint(tmp_path, monkeypatch, model):
    """Each finished chunk is saved as it completes; a sweep interrupted in its third chunk
    and run again computes only the two chunks left, and equals the uninterrupted sweep. A
    folder of another sweep is refused."""
    import jaxtow._sweep as S

    grid = {"xp": np.linspace(0.1, 0.9, 8), "l0": np.linspace(1.0, 3.0, 4)}  # 4 chunks of 8
    ref = jt.sweep_arrays(model, grid, execution=jt.SweepExecution(chunk_size=8))
    real = S.make_batched_kernel
    state = {"calls": 0, "fail_at": 3}

    def flaky(**options):
        kernel = real(**options)

        def run(m, p):
            state["calls"] += 1
            if state["calls"] == state["fail_at"]:
                raise KeyboardInterrupt
            return kernel(m, p)

        return run

    monkeypatch.setattr(S, "make_batched_kernel", flaky)
    ck = tmp_path / "chunks"
    with pytest.raises(KeyboardInterrupt):
        jt.sweep_arrays(
            model, grid, execution=jt.SweepExecution(chunk_size=8), checkpoint=jt.io.Checkpoint(ck)
        )
    assert sorted(p.name for p in ck.glob("chunk_*.npz")) == ["chunk_00000.npz", "chunk_00001.npz"]
    state.update(calls=0, fail_at=None)
    got = jt.sweep_arrays(
        model, grid, execution=jt.SweepExecution(chunk_size=8), checkpoint=jt.io.Checkpoint(ck)
    )
    assert state["calls"] == 2
    for k in ("psi", "max_real", "valid", "stability"):
        np.testing.assert_array_equal(got[k], ref[k])
    with pytest.raises(ValueError, match="chunks of another sweep"):
        jt.sweep_arrays(
            model,
            {**grid, "l0": np.linspace(1.0, 2.0, 4)},
            execution=jt.SweepExecution(chunk_size=8),
            checkpoint=jt.io.Checkpoint(ck),
        )


def test_cli_options_are_checked_before_anything_runs(capsys):
    """Option values a user can mistype: refused with a one-line message naming the option."""
    assert "--u-tug: expected a finite number > 0" in _cli_error(
        ["equilibria", "--u-tug", "0"], capsys
    )
    assert "--param xp: N must be a whole number of points, got 'abc'" in _cli_error(
        ["map", "--param", "xp", "0", ".5", "abc"], capsys
    )
    assert "--panel-size: expected a finite number > 0" in _cli_error(
        ["bem", "barge2a", "--panel-size", "0"], capsys
    )
    assert "--base 'foo' is not a drift method" in _cli_error(["drift", "--base", "foo"], capsys)


def test_cli_errors_are_one_line_without_a_traceback(monkeypatch, capsys):
    """An error from inside a command (here: a check made under jit, which JAX wraps in a
    long runtime error) reaches the user as one line naming the parameter; the traceback is
    there on request."""
    import equinox as eqx

    import jaxtow.cli.equilibria as E
    from jaxtow.cli import error_message

    def failing(args):
        jax.jit(lambda x: eqx.error_if(x, x < 0, "parameter 'EA' must be > 0 and finite"))(-1.0)

    monkeypatch.setattr(E, "cmd_equilibria", failing)
    message = _cli_error(["equilibria"], capsys)
    assert message.splitlines()[0] == (
        "jaxtow equilibria: error: parameter 'EA' must be > 0 and finite"
    )
    assert "Traceback" not in message
    monkeypatch.setenv("JAXTOW_TRACEBACK", "1")
    with pytest.raises(Exception) as e:
        jt.cli.main(["equilibria"])
    assert error_message(e.value) == "parameter 'EA' must be > 0 and finite"


def test_tug_speed_must_be_positive(model):
    """A zero tug speed made EA' infinite, and the error then named EA."""
    with pytest.raises(ValueError, match="'u_tug' must be > 0"):
        jt.at_tug_speed(model, 0.0)
    with pytest.raises(Exception, match="'u_tug' must be > 0"):  # traced: the model's rule
        jax.jit(lambda u: jt.equilibria_fixed(jt.at_tug_speed(model, u)).psi)(-1.0)
    assert float(jt.at_tug_speed(model, 2 * 2.0).towline.EA) > 0


def test_parameters_of_the_wrong_kind_are_named(model):
    with pytest.raises(ValueError, match="parameter 'l0' must be a number, got 'abc'"):
        jt.Towline(l0="abc", xp=0.4, EA=10.0)
    with pytest.raises(ValueError, match="parameter 'l0' must be a single number, got shape"):
        jt.Towline(l0=np.array([1.0, 2.0]), xp=0.4, EA=10.0)
    with pytest.raises(ValueError, match="grid values for 'l0' must be numbers"):
        jt.sweep_arrays(model, {"l0": ["a", "b"]})
    with pytest.raises(ValueError, match="'chunk_size' must be >= 1"):
        jt.sweep_arrays(model, {"l0": [1.0, 2.0]}, execution=jt.SweepExecution(chunk_size=0))
    with pytest.raises(TypeError, match="parameter 'qtf' must be a jaxtow.drift.QTF"):
        jt.forces.WaveDriftForce(qtf="x", omega=1.0, zeta_a=1.0, scales=P.barge2_scales())
    with pytest.raises(ValueError, match="parameter 'hs' must be a number"):
        jt.resistance.SeaState(hs="x", tp=8.0)
    assert float(jt.resistance.SeaState(hs=0.0, tp=8.0).hs) == 0.0  # calm water, as documented
    box = np.array([[0, 0], [10, 0], [10, 5], [0, 5], [0, 0]], float)
    with pytest.raises(ValueError, match="parameter 'draft' must be > 0"):
        jt.drift.waterline(box, draft=float("nan"))


def test_a_grid_too_large_for_memory_is_refused_up_front(model):
    """10^12 points: refused before anything is allocated, naming the grid."""
    huge = {"l0": np.linspace(1, 2, 10**6), "xp": np.linspace(0.1, 0.5, 10**6)}
    with pytest.raises(ValueError, match="parameter 'grid': 1e\\+12 points need about"):
        jt.sweep_arrays(model, huge)
    # the chunk plan holds the axes, not the product: a chunk is made on demand
    from jaxtow._sweep import plan_sweep

    plan = plan_sweep(model, huge, chunk_size=4)
    assert plan.npts == 10**12 and plan.nchunks == 25 * 10**10
    last = plan.chunk_params(plan.nchunks - 1)
    np.testing.assert_array_equal(last["l0"], [2.0] * 4)
    np.testing.assert_array_equal(last["xp"], huge["xp"][-4:])


def test_eager_entry_points_check_a_model_edited_past_its_constructor(model):
    """`eqx.tree_at` bypasses the constructor; `equilibria` and `simulate` used to fail deep
    inside the compiled call ("INTERNAL: CpuCallback error")."""
    import equinox as eqx

    bad = eqx.tree_at(lambda m: m.towline.EA, model, jnp.asarray(-1.0))
    with pytest.raises(ValueError, match="parameter 'EA' must be > 0"):
        jt.equilibria(bad)
    with pytest.raises(ValueError, match="parameter 'EA' must be > 0"):
        jt.simulate(bad, jt.initial_state(model, psi0=0.0, y0=0.1), t1=1.0)
    with pytest.raises(ValueError, match="parameter 'max_roots' must be >= 1"):
        jt.equilibria(model, max_roots=0)


def test_a_tow_turned_stern_first_is_flagged(model):
    y = np.array([1.0, 0.0, 0.0, 2.5, 0.0, 0.0])
    assert bool(jt.validity(model, y)["moving_ahead"])
    y[0], y[5] = -0.5, np.radians(200.0)  # a wild fishtail, turned round
    flags = jt.validity(model, y)
    assert not bool(flags["moving_ahead"]) and not bool(jt.all_valid(flags))


_INTERRUPTIBLE_MAP = r"""
import sys, time
from pathlib import Path
stage, out = sys.argv[1], sys.argv[2]
marker = Path(out).parent / f"{stage}.ready"
if stage == "sweep":  # hold the sweep after its first chunk is saved
    from jaxtow.io import checkpoint
    real_put = checkpoint.ChunkStore.put
    def put(self, c, arrays):
        real_put(self, c, arrays)
        if c == 0:
            marker.touch()
            time.sleep(60)
    checkpoint.ChunkStore.put = put
elif stage == "write":  # hold the final NetCDF write, its temporary file written
    import xarray as xr
    real_write = xr.Dataset.to_netcdf
    def to_netcdf(self, *a, **k):
        result = real_write(self, *a, **k)
        assert list(Path(out).glob(".*.tmp")), "the write goes to a temporary file"
        marker.touch()
        time.sleep(3)
        return result
    xr.Dataset.to_netcdf = to_netcdf
from jaxtow.cli import main
sys.exit(main(["map", "--param", "l0", "1", "3", "5", "--chunk-size", "2", "--quiet", "--out", out]))
"""


@pytest.mark.slow  # three processes, each importing jaxtow (about a minute)
def test_a_map_interrupted_by_sigint_resumes_and_never_leaves_a_partial_file(tmp_path):
    """Ctrl-C (SIGINT) in the middle of a sweep, then during the final write: each run exits
    at once with a message saying what was kept, no file is left under the final name,
    and the run that completes gives the same result as an uninterrupted sweep."""
    import os
    import signal
    import subprocess
    import sys
    import time

    out = tmp_path / "out"
    script = tmp_path / "run.py"
    script.write_text(_INTERRUPTIBLE_MAP)
    env = dict(os.environ, JAXTOW_COMPILE_CACHE=str(tmp_path / "xla"))
    final = out / "barge2a_l0.nc"

    def interrupted(stage):
        proc = subprocess.Popen(
            [sys.executable, str(script), stage, str(out)],
            env=env,
            stderr=subprocess.PIPE,
            text=True,
        )
        marker = tmp_path / f"{stage}.ready"
        deadline = time.monotonic() + 300
        while not marker.exists():
            assert proc.poll() is None, proc.stderr.read() if proc.stderr else ""
            assert time.monotonic() < deadline, "the run never reached the point to interrupt"
            time.sleep(0.1)
        sent = time.monotonic()
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=30)  # a deadlock fails here
        return proc.returncode, time.monotonic() - sent, err

    rc, took, err = interrupted("sweep")
    assert rc == 130 and "interrupted" in err and "resumes" in err, err
    assert took < 10
    chunks = sorted(p.name for p in (out / ".barge2a_l0.chunks").glob("chunk_*.npz"))
    assert chunks == ["chunk_00000.npz"]
    assert not final.exists()

    rc, took, err = interrupted("write")  # resumes the sweep, then is stopped while writing
    assert rc == 130 and "interrupted" in err, err
    assert took < 10  # the held interrupt ends the run when the write call returns
    assert not final.exists()
    assert not list(out.glob(".*.tmp")) and not list(out.glob("*.nc"))

    done = subprocess.run(
        [sys.executable, str(script), "plain", str(out)], env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    got = jt.io.load_dataset(final)
    ref = jt.sweep(jt.tow.load("barge2a").model(), {"l0": np.linspace(1, 3, 5)}, chunk_size=2)
    for k in ("psi", "max_real", "valid", "stability", "tension"):
        np.testing.assert_array_equal(got[k].values, ref[k].values, err_msg=k)
    assert not (out / ".barge2a_l0.chunks").exists()


def test_no_unexplained_nan_in_a_wide_calm_sweep(model):
    """The NaN audit (benchmarks/nan_audit.py runs it on 10^6 calm and 10^5 wave points) on
    a small grid over the same wide ranges: slack lines, headings near ±90° and the
    pitchfork. Every NaN is a slot without an equilibrium or a flagged one."""
    grid = {
        "xp": np.linspace(0.0, 1.0, 9),
        "l0": np.geomspace(0.02, 10.0, 9),
        "EA": np.geomspace(1.0, 1e4, 5),
    }
    a = jt.io.nan_audit(jt.sweep(model, grid, n_grid=401))
    assert a["points"] == 405
    assert a["unexplained"] == 0, a["unexplained_variables"]
    assert a["nan"] == a["masked"] + a["flagged"] > 0  # empty slots exist: the audit sees them


@pytest.mark.heavy  # minutes on 2 cores: pytest -m heavy
@pytest.mark.slow  # about a minute on 2 cores once compiled
def test_the_full_nan_audit_finds_no_unexplained_nan():
    """The scale audit itself: 10^6 calm points and 10^5 points in regular waves over wide
    ranges (benchmarks/nan_audit.py, whose committed result is
    benchmarks/data/perf/nan_audit.json), through the layered sweep, datasets and io."""
    from helpers import benchmark_script

    results = benchmark_script("nan_audit").main([])
    assert results["calm"]["points"] == 10**6 and results["waves"]["points"] > 9 * 10**4
    for name, r in results.items():
        assert r["unexplained"] == 0, (name, r["unexplained_variables"])
        assert r["nan"] == r["masked"] + r["flagged"], name


def test_a_run_writes_its_manifest(tmp_path, monkeypatch):
    """OUT/jaxtow_run.json: the command, its options, versions, the documented estimates,
    the files written and how the run ended (finished, failed with its error, interrupted)."""
    import json

    import jaxtow.cli.map as M
    import jaxtow.cli.study as S
    from jaxtow.cli import main

    def writes(args):
        (tmp_path / "ok" / "result.nc").write_text("x")

    monkeypatch.setattr(M, "cmd_map", writes)
    main(["map", "--param", "l0", "1", "2", "3", "--out", str(tmp_path / "ok")])
    run = json.loads((tmp_path / "ok" / "jaxtow_run.json").read_text())
    assert run["status"] == "finished" and run["command"] == "map"
    assert run["outputs"] == ["result.nc"]
    assert run["options"]["param"] == [["l0", "1", "2", "3"]]
    assert run["versions"]["jax"] and "EA" in run["estimates"]
    assert run["started"] <= run["finished"]

    monkeypatch.setattr(S, "cmd_study", writes)
    main(["study", "barge2a", "--out", str(tmp_path / "ok"), "--no-compile-cache"])
    run = json.loads((tmp_path / "ok" / "barge2a_run.json").read_text())
    assert run["command"] == "study" and run["options"]["tow_positional"] == "barge2a"
    # the parser's hooks (the manifest's naming function) are not options: no memory address
    assert not [k for k, v in run["options"].items() if "<function" in str(v)], run["options"]

    def fails(args):
        raise ValueError("parameter 'l0' must be > 0 and finite")

    monkeypatch.setattr(M, "cmd_map", fails)
    with pytest.raises(SystemExit):
        main(["map", "--param", "l0", "1", "2", "3", "--out", str(tmp_path / "bad")])
    run = json.loads((tmp_path / "bad" / "jaxtow_run.json").read_text())
    assert run["status"] == "failed" and "'l0' must be > 0" in run["error"]

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(M, "cmd_map", interrupted)
    with pytest.raises(SystemExit) as e:
        main(["map", "--param", "l0", "1", "2", "3", "--out", str(tmp_path / "int")])
    assert e.value.code == 130
    run = json.loads((tmp_path / "int" / "jaxtow_run.json").read_text())
    assert run["status"] == "interrupted" and run["outputs"] == []


def test_damping_outside_a_partial_table_is_refused():
    """A table over 0-90 deg only: damping at 120 deg was an extrapolation without a flag."""
    w, b = np.linspace(0.2, 2.0, 10), np.radians([0.0, 30.0, 60.0, 90.0])
    q = jt.drift.QTF(
        omega=w, beta=b, fx=np.ones((10, 4)), fy=np.zeros((10, 4)), nz=np.zeros((10, 4))
    )
    assert jt.drift.wave_drift_damping(q, 1.0, np.radians(45.0)).shape == (3, 3)
    with pytest.raises(ValueError, match=r"'beta' must lie inside the table's headings \[0, 90\]"):
        jt.drift.wave_drift_damping(q, 1.0, np.radians(120.0))


def test_wave_synthesis_on_a_descending_grid_is_refused():
    """Δω < 0 gave NaN amplitudes: the elevation record was all NaN."""
    w = np.linspace(0.3, 1.5, 20)
    S = jt.waves.jonswap(w, hs=2.0, tp=8.0)
    t = np.linspace(0.0, 100.0, 11)
    key = jax.random.PRNGKey(0)
    assert np.all(np.isfinite(jt.waves.synthesise_elevation(key, w, S, t)))
    with pytest.raises(ValueError, match="'omega' must be strictly ascending"):
        jt.waves.synthesise_elevation(key, w[::-1], S[::-1], t)


@pytest.mark.parametrize(
    "argv, message",
    [
        (
            ["map", "--param", "xp", "0", "1", "3", "--chunk-size", "0"],
            "argument --chunk-size: expected a whole number >= 1, got 0",
        ),
        (
            ["map", "--param", "xp", "0", "1", "3", "--max-roots", "0"],
            "argument --max-roots: expected a whole number >= 1, got 0",
        ),
        (["simulate", "--psi0", "nan"], "argument --psi0: expected a finite number, got nan"),
        (["simulate", "--t1", "-5"], "argument --t1: expected a finite number > 0, got -5"),
        (["report", "waves", "--n", "-3"], "argument --n: expected a whole number >= 1, got -3"),
        (["calm", "--out", "/proc/jaxtow-out"], "--out /proc/jaxtow-out: cannot write there"),
    ],
)
def test_cli_messages_name_the_flag(argv, message, capsys):
    """A bad command-line value is refused before anything runs, naming the flag (not the
    Python parameter behind it) and the value."""
    assert message in _cli_error(argv, capsys)


def test_an_unknown_waterline_method_and_an_empty_speed_scan_are_named():
    wl = jt.presets.box_waterline()
    with pytest.raises(ValueError, match="parameter 'method': 'nosuch' is not a waterline drift"):
        jt.drift.irregular_drift("nosuch", wl, 2.0, 7.0, 0.0)
    tow, tug = jt.presets.barge2_resistance("2a"), jt.presets.illustrative_tug()
    with pytest.raises(
        ValueError, match="parameter 'n_scan' must be a whole number of speeds >= 2"
    ):
        jt.resistance.operating_speed(tow, tug, jt.presets.sea_state("sailing"), n_scan=0)


@pytest.mark.parametrize(
    "cfg, message",
    [
        ({"hull": {"panel_size": "a"}}, "config [hull] panel_size: expected a number, got 'a'"),
        ({"waves": {"omega": [0.1, "x", 3]}}, "config [waves] omega: expected a number, got 'x'"),
        ({"waves": {"water_depth": "deep"}}, "config [waves] water_depth: expected a number"),
        ({"waves": {"beta_deg": [0, 180, 2.5]}}, "count must be a whole number >= 1, got 2.5"),
    ],
)
def test_a_bem_config_names_the_key_that_is_not_a_number(cfg, message):
    from jaxtow.cli.bem import build

    with pytest.raises(ValueError) as e:
        build(cfg)
    assert message in str(e.value)


# ------------------------------------------------------------------ files and shapes


@pytest.fixture(scope="module")
def table():
    """A small full-circle table and its jaxtow NetCDF file's dataset."""
    w, b = np.linspace(0.2, 2.0, 6), np.radians([-180.0, -90.0, 0.0, 90.0, 180.0])
    fx = np.outer(w, np.cos(b) ** 2 + 1.0)
    fy = np.outer(w, np.sin(b))
    return jt.drift.QTF(omega=w, beta=b, fx=fx, fy=fy, nz=0.1 * fy)


def test_a_file_that_is_not_netcdf_or_not_text_is_named(tmp_path):
    junk = tmp_path / "junk.nc"
    junk.write_bytes(bytes(range(256)) * 8)
    for reader in (jt.io.load_qtf, jt.io.load_dataset):
        with pytest.raises(ValueError, match=r"junk.nc: not a NetCDF file that xarray can read"):
            reader(junk)
    binary = tmp_path / "run.8"
    binary.write_bytes(b"\x89HDF\r\n\x1a\n" + bytes(range(256)))
    with pytest.raises(ValueError, match=r"run.8: not a text file \(a WAMIT numeric output"):
        jt.io.read_wamit_drift(binary)
    with pytest.raises(ValueError, match=r"run.8: not a text file"):
        jt.io.read_qtf(binary)
    csv = tmp_path / "t.csv"
    csv.write_text("omega,beta,fx,fy,nz\n1,a,2,3,4\n")
    with pytest.raises(ValueError, match=r"t.csv: not a jaxtow CSV drift table"):
        jt.io.load_qtf(csv)


def test_a_netcdf_table_with_a_missing_or_transposed_variable(tmp_path, table):
    path = tmp_path / "q.nc"
    jt.io.save_qtf(table, path)
    ds = jt.io.load_dataset(path)
    # transposed: read by its dimension names, the same table
    ds.assign(fx=ds["fx"].transpose("beta", "omega")).to_netcdf(tmp_path / "t.nc")
    back = jt.io.load_qtf(tmp_path / "t.nc")
    np.testing.assert_array_equal(np.asarray(back.values), np.asarray(table.values))
    ds.drop_vars("fy").to_netcdf(tmp_path / "m.nc")
    with pytest.raises(ValueError, match=r"m.nc: no variable 'fy' \(the file holds"):
        jt.io.load_qtf(tmp_path / "m.nc")
    ds.assign(nz=ds["nz"].isel(beta=0)).to_netcdf(tmp_path / "d.nc")
    with pytest.raises(ValueError, match=r"variable 'nz' has dimensions \('omega',\), expected"):
        jt.io.load_qtf(tmp_path / "d.nc")


def test_a_nan_in_a_wamit_file_or_a_table_is_named_as_such(tmp_path, table):
    path = tmp_path / "q.8"
    jt.io.write_wamit_drift(table, path)
    lines = path.read_text().splitlines()
    parts = lines[3].split()
    parts[-2] = "NaN"
    lines[3] = " ".join(parts)
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=r"q.8, line 4: a non-finite number in a WAMIT record"):
        jt.io.read_wamit_drift(path)
    w, b = np.asarray(table.omega), np.radians([0.0, 90.0, 180.0])
    fx = np.ones((6, 3))
    fx[2, 1] = np.nan
    with pytest.raises(
        ValueError, match=r"'fx' must be finite: nan at omega = 0.92 rad/s, beta = 90"
    ):
        jt.drift.QTF.symmetric(omega=w, beta=b, fx=fx, fy=np.zeros((6, 3)), nz=np.zeros((6, 3)))


def test_shapes_of_tables_and_spectra_are_named(table):
    w = np.asarray(table.omega)
    with pytest.raises(
        ValueError, match=r"parameter 'fy' must have shape .* = \(6, 5\), got \(6, 4\)"
    ):
        jt.drift.QTF(
            omega=w,
            beta=np.asarray(table.beta),
            fx=np.ones((6, 5)),
            fy=np.ones((6, 4)),
            nz=np.ones((6, 5)),
        )
    S = jt.waves.jonswap(w, hs=2.0, tp=8.0)
    with pytest.raises(ValueError, match=r"parameter 'S' must hold the spectrum on the grid"):
        jt.waves.mean_drift(w, S[:4], np.ones((6, 3)))
    with pytest.raises(ValueError, match=r"parameter 'P' must have the frequency grid omega \(6\)"):
        jt.waves.mean_drift(w, S, np.ones((3, 6)))
    with pytest.raises(ValueError, match=r"parameter 'T' must be > 0"):
        jt.waves.period_to_omega(0.0)
    with pytest.raises(ValueError, match=r"parameter 'S' must have a positive area"):
        jt.waves.spectral_periods(w, np.zeros(6))


# ------------------------------------------------------------------ named, not a NaN or a crash


@pytest.mark.parametrize(
    "call, message",
    [
        (
            lambda: jt.waves.jonswap(jnp.array([np.nan, 1.0]), hs=2.0, tp=8.0),
            "parameter 'omega' must be finite",
        ),
        (
            lambda: jt.waves.check_frequency_grid(np.linspace(0.1, 3.0, 100), tp=0.0),
            "parameter 'tp' must be > 0",
        ),
        (
            lambda: jt.waves.mean_drift(np.linspace(0.1, 2.0, 10), np.ones(10), np.ones(9)),
            "parameter 'P' must have the frequency grid",
        ),
        (
            lambda: jt.waves.mean_drift_damping(
                np.linspace(0.1, 2.0, 10), np.ones(10), np.ones((9, 3, 3))
            ),
            "parameter 'B' must have the frequency grid",
        ),
        (
            lambda: jt.drift.wave_drift_damping(
                jt.presets.database("barge2"), omega=np.array([0.5, 0.9]), beta=0.0
            ),
            "parameter 'omega' must be a single value",
        ),
        (
            lambda: jt.drift.waterline(
                np.array([[0, 0], [1, 0], [1, 1], [0, 1.0], [0, 0]]), flare=np.ones(3), draft=1.0
            ),
            "parameter 'flare' must be one value or one per segment (4 segments)",
        ),
    ],
)
def test_bad_values_and_shapes_are_named(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value).startswith(message), str(e.value)


def test_a_waterline_file_with_a_word_names_the_file_and_the_line(tmp_path):
    f = tmp_path / "half.txt"
    f.write_text("# x y\n38.1 0\n38.1 12.2\nforty 12.2\n-38.1 0\n")
    with pytest.raises(ValueError, match=r"half.txt, line 4: expected numbers .* 'forty 12.2'"):
        jt.io.read_waterline(f, draft=5.0)


def test_jaxtow_drift_with_a_negative_hs_is_one_line(tmp_path, capsys):
    from jaxtow.cli import main

    with pytest.raises(SystemExit) as e:
        main(["drift", "--hs", "-1", "--out", str(tmp_path)])
    text = str(e.value.code) + capsys.readouterr().err
    assert "hs" in text and "Traceback" not in text


def test_a_half_wamit_table_reads_back_to_the_same_drift(tmp_path):
    """A table over jaxtow headings 0..180 written as WAMIT .8: read back with the default
    (a symmetric hull's half table completed to the full circle) it gives the same drift at
    every heading written, and with ``symmetry='none'`` the same table exactly."""
    w, b = np.linspace(0.2, 2.0, 10), np.radians(np.linspace(0.0, 180.0, 7))
    fy = np.sin(b)[None, :] * np.ones((10, 1))
    q = jt.drift.QTF(omega=w, beta=b, fx=np.ones((10, 7)), fy=fy, nz=0.5 * fy)
    f = tmp_path / "half.8"
    jt.io.write_wamit_drift(q, f)
    full, info = jt.io.read_qtf(f)
    assert "completed by port-starboard symmetry" in info["symmetry"]
    for k in range(7):
        np.testing.assert_allclose(
            np.asarray(full(w[3], b[k])), np.asarray(q(w[3], b[k])), rtol=1e-9, atol=1e-12
        )
    same, _ = jt.io.read_qtf(f, symmetry="none")
    np.testing.assert_allclose(np.asarray(same.beta), b, atol=1e-12)
    np.testing.assert_allclose(np.asarray(same.values), np.asarray(q.values), rtol=1e-9)
