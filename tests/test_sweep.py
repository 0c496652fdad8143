"""Sweeps: vmapped kernels, chunking, sharding, datasets (NetCDF)."""

import json
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from helpers import model

import jaxtow as jt
from jaxtow.io import load_dataset, save_dataset


def test_sweep_dataset_is_labelled(barge_2a, tmp_path):
    grid = {"xp": np.linspace(0.1, 0.6, 6), "l0": np.array([0.5, 2.5])}
    ds = jt.sweep(model(barge_2a), grid, eigenvalues=True)
    assert ds["max_real"].dims == ("xp", "l0", "equilibrium")
    assert ds["eig_real"].dims == ("xp", "l0", "equilibrium", "mode")
    # by default a map holds max Re λ alone, from the pure-JAX spectral abscissa
    lean = jt.sweep(model(barge_2a), grid)
    assert "eig_real" not in lean and lean.attrs["eigenvalue_method"] == "routh"
    np.testing.assert_allclose(lean["max_real"], ds["max_real"], atol=1e-10)
    with pytest.raises(ValueError, match="eig_method"):
        jt.sweep_arrays(model(barge_2a), grid, jt.SweepSolver(eigenvalues=True, eig_method="routh"))
    assert ds["xp"].attrs["units"] == "1" and "attachment" in ds["xp"].attrs["long_name"]
    assert ds["psi"].attrs["units"] == "rad"
    assert "draft" in json.loads(ds.attrs["assumed_values"])
    assert "estimates" in ds.attrs["note"]
    # padding slots are NaN and marked not found; found slots are finite
    found = ds["found"].values
    assert np.isnan(ds["psi"].values[~found]).all() and np.isfinite(ds["psi"].values[found]).all()
    # NetCDF round trip is exact
    save_dataset(ds, tmp_path / "s.nc")
    back = load_dataset(tmp_path / "s.nc")
    for k in ds.data_vars:
        np.testing.assert_array_equal(back[k].values, ds[k].values)
        assert back[k].dtype == ds[k].dtype
    assert back.attrs == ds.attrs


@pytest.mark.slow
def test_chunked_equals_single_chunk(barge_2b):
    grid = {"xp": np.linspace(0.0, 0.6, 9), "l0": np.linspace(0.2, 2.5, 5)}
    a = jt.sweep_arrays(model(barge_2b), grid, execution=jt.SweepExecution(chunk_size=7))
    b = jt.sweep_arrays(model(barge_2b), grid, execution=jt.SweepExecution(chunk_size=4096))
    for k in a:
        if not k.startswith("_"):
            np.testing.assert_array_equal(a[k], b[k])


def test_analytic_and_numerical_sweeps_agree(barge_2a):
    grid = {"xp": np.linspace(0.05, 0.6, 12), "l0": np.array([0.4, 2.0])}
    num = jt.sweep_arrays(model(barge_2a), grid, jt.SweepSolver(method="numerical", max_roots=3))
    ana = jt.sweep_arrays(model(barge_2a), grid, jt.SweepSolver(method="analytic"))
    np.testing.assert_array_equal(num["n_equilibria"], ana["n_equilibria"])
    # slots are laid out differently (numerical: found roots first, by ψ; analytic: one
    # slot per branch), so compare the found roots in ψ order
    for key in ("psi", "max_real", "tension"):
        a = np.where(num["found"], num[key], np.inf)
        b = np.where(ana["found"], ana[key], np.inf)
        order_a = np.argsort(np.where(num["found"], num["psi"], np.inf), axis=-1)
        order_b = np.argsort(np.where(ana["found"], ana["psi"], np.inf), axis=-1)
        np.testing.assert_allclose(
            np.take_along_axis(a, order_a, -1), np.take_along_axis(b, order_b, -1), atol=1e-9
        )


@pytest.mark.parametrize(
    "grid, name",
    [
        ({"l0": [1.0, -1.0]}, "l0"),
        ({"EA": [0.0]}, "EA"),
        ({"xp": [0.5, 1.7]}, "xp"),
        ({"a22": [np.nan]}, "a22"),
        ({"nonsense": [1.0]}, "nonsense"),
    ],
)
def test_sweep_rejects_bad_grid(barge_2a, grid, name):
    with pytest.raises(ValueError, match=repr(name)):
        jt.sweep_arrays(model(barge_2a), grid)


def test_truncation_is_reported(barge_2b):
    a = jt.sweep_arrays(model(barge_2b), {"xp": np.array([0.5])}, jt.SweepSolver(max_roots=2))
    assert bool(a["truncated"][0]) and int(a["n_equilibria"][0]) == 3
    with pytest.raises(ValueError, match="max_roots"):
        jt.equilibria(model(barge_2b), max_roots=2)


@pytest.mark.parametrize("platform", ["gpu", "cuda", "rocm", "tpu", "METAL"])
def test_no_plan_off_the_cpu_picks_lapacks_eigensolver(barge_2b, platform):
    """On a GPU LAPACK's nonsymmetric eigensolver runs matrix by matrix (a 16,384-point chunk
    did not finish in 200 s on an H200): no default off the CPU picks it, whether the
    eigenvalues are wanted or only max Re λ, on one device or several."""
    from jaxtow._sweep import plan_sweep

    assert jt.default_eig_method(platform) == "polynomial"
    assert jt.default_eig_method("cpu") == "lapack"
    grid = {"xp": np.linspace(0.1, 0.5, 5)}
    for eigenvalues in (False, True):
        for ndev in (1, 4):
            plan = plan_sweep(
                model(barge_2b),
                grid,
                jt.SweepSolver(eigenvalues=eigenvalues),
                ndev=ndev,
                on_cpu=False,
            )
            assert plan.options["eig_method"] != "lapack", (eigenvalues, ndev)
    cpu = plan_sweep(model(barge_2b), grid, jt.SweepSolver(eigenvalues=True), ndev=1, on_cpu=True)
    assert cpu.options["eig_method"] == "lapack"


def test_the_backends_default_gives_the_same_eigenvalues(barge_2b):
    """The polynomial route (the default off the CPU) and LAPACK agree on the tow's spectra."""
    m = model(barge_2b)
    eqs = jt.equilibria(m)
    for y in np.asarray(eqs.state)[np.asarray(eqs.valid)]:

        def order(lam):  # by real part to 1e-6, then imaginary: conjugate pairs line up
            lam = np.asarray(lam)
            return lam[np.lexsort((lam.imag, np.round(lam.real, 6)))]

        a = order(jt.eigenvalues(m, y, "lapack"))
        b = order(jt.eigenvalues(m, y, "polynomial"))
        np.testing.assert_allclose(a, b, atol=1e-8)
        assert np.array_equal(
            np.asarray(jt.eigenvalues(m, y)), np.asarray(jt.eigenvalues(m, y, "lapack"))
        )


_SHARD_SCRIPT = textwrap.dedent("""
    import jax, numpy as np, jaxtow as jt
    assert len(jax.devices()) == 4, jax.devices()
    m = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())
    grid = {"xp": np.linspace(0.0, 0.6, 13), "l0": np.linspace(0.2, 2.5, 7)}
    a = jt.sweep_arrays(m, grid, *jt.sweep_options(chunk_size=32))                # 4 devices
    # the default pure-JAX spectral abscissa shards; compare like with like: the same
    # per-device program (8 points per device) must give bit-identical results
    b = jt.sweep_arrays(m, grid, *jt.sweep_options(chunk_size=8, devices=jax.devices()[:1], eig_method="routh"))
    c = jt.sweep_arrays(m, grid, *jt.sweep_options(chunk_size=32, devices=jax.devices()[:1], eig_method="lapack"))
    np.testing.assert_allclose(a["max_real"], c["max_real"], atol=1e-9)
    assert a["_eig_method"] == "routh"
    # with every eigenvalue wanted, several CPU devices select the LAPACK-free polynomial roots
    e = jt.sweep_arrays(m, grid, *jt.sweep_options(chunk_size=32, eigenvalues=True))
    assert e["_eig_method"] == "polynomial"
    np.testing.assert_allclose(e["max_real"], c["max_real"], atol=1e-8)
    # a large chunk over 4 CPU devices completes (LAPACK here deadlocked in OpenBLAS)
    big = {"xp": np.linspace(0.0, 0.6, 61), "l0": np.linspace(0.2, 2.5, 47)}
    jt.sweep_arrays(m, big)
    for k in a:
        if not k.startswith("_"):
            np.testing.assert_array_equal(a[k], b[k])
    # the chunk really is split across the 4 devices
    from jax.sharding import Mesh, NamedSharding, PartitionSpec as P
    from jaxtow._sweep import make_batched_kernel
    sh = NamedSharding(Mesh(np.array(jax.devices()), ("points",)), P("points"))
    k = make_batched_kernel(method="numerical", n_grid=2001, max_roots=4, psi_range=np.pi / 2,
                            routh_hurwitz=True, eig_method="polynomial")
    out = k(m, {"xp": jax.device_put(np.linspace(0.1, 0.5, 8), sh), "l0": jax.device_put(np.full(8, 2.0), sh)})
    assert len(out["psi"].sharding.device_set) == 4, out["psi"].sharding
    print("SHARDED_OK", a["max_real"].shape)
""")


@pytest.mark.slow
def test_sharded_sweep_identical_to_single_device():
    env = dict(
        os.environ, XLA_FLAGS="--xla_force_host_platform_device_count=4", JAX_PLATFORMS="cpu"
    )
    out = subprocess.run(
        [sys.executable, "-c", _SHARD_SCRIPT], env=env, capture_output=True, text=True, timeout=600
    )
    assert out.returncode == 0, out.stderr[-3000:]
    assert "SHARDED_OK" in out.stdout


_LARGE_SCRIPT = textwrap.dedent("""
    import numpy as np, jaxtow as jt
    m = jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())
    grid = {"xp": np.linspace(0.0, 0.6, 61), "l0": np.linspace(0.2, 2.5, 47)}
    for method in ("numerical", "analytic", "numerical"):
        a = jt.sweep_arrays(m, grid, jt.SweepSolver(method=method))
    print("LARGE_OK", int(a["n_equilibria"].sum()))
""")


@pytest.mark.slow
def test_large_batch_sweep_completes():
    """Regression: several batched LAPACK calls in one kernel (Hurwitz determinants via
    jnp.linalg.det) deadlocked XLA's CPU runtime on chunks of thousands of points. The
    sweep runs in a subprocess so that a hang fails the test instead of stalling the run."""
    out = subprocess.run(
        [sys.executable, "-c", _LARGE_SCRIPT],
        capture_output=True,
        text=True,
        timeout=300,
        env=dict(os.environ, JAX_PLATFORMS="cpu"),
    )
    assert out.returncode == 0, out.stderr[-3000:]
    assert "LARGE_OK" in out.stdout
