"""Sweeps and batches of runs on a Dask cluster equal the single-process ones (the cluster
tests, about a minute of worker start-up and compilation, run with the slow suite)."""

import numpy as np
import pytest

import jaxtow as jt

distributed = pytest.importorskip("distributed", reason="the Dask extra is not installed")


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
    )
    with cluster, distributed.Client(cluster) as c:
        yield c


@pytest.fixture(scope="module")
def model():
    return jt.TowModel(vessel=jt.presets.barge_2a(), towline=jt.presets.default_towline())


@pytest.mark.slow
def test_sweep_on_two_workers_equals_one_process_bitwise(client, model):
    # 96 points in chunks of 32: three tasks over two worker processes
    grid = {"xp": np.linspace(0.1, 0.9, 8), "l0": np.linspace(1.0, 4.0, 12)}
    ref = jt.sweep(model, grid, chunk_size=32)
    warmed = jt.distributed.compile_on_workers(client, model, grid, chunk_size=32)
    assert len(warmed) == 2 and all(t > 0 for t in warmed.values())
    lazy = jt.distributed.sweep(model, grid, client=client, chunk_size=32)
    assert lazy["max_real"].chunks is not None  # dask-backed until computed
    ds = lazy.compute()
    assert set(ds.data_vars) == set(ref.data_vars)
    assert ds.sizes == ref.sizes
    for k in ref.data_vars:
        np.testing.assert_array_equal(ds[k].values, ref[k].values, err_msg=k)
    # a fishtailing and a following part of the map: not a uniform answer
    assert 0 < int((ds["stability"] == 1).sum()) < ds["stability"].size
    assert ds.attrs["scheduler"] == "dask"
    assert {k: v for k, v in ds.attrs.items() if k != "scheduler"} == ref.attrs


@pytest.mark.slow
def test_batch_of_runs_on_two_workers_equals_one_process(client, model):
    # runs_per_task a multiple of batch_size: every run is integrated in a vmapped group of
    # the same width as in one process, so the results are bitwise equal (groups of other
    # widths round differently, and a fishtailing tow amplifies that)
    y0s = np.array([jt.initial_state(model, psi0=0.0, y0=y) for y in (0.1, 0.2, 0.3, 0.4)])
    params = {"xp": np.array([0.3, 0.4, 0.5, 0.45])}
    opts = dict(t1=20.0, params=params, n_save=51, batch_size=2)
    ref = jt.simulate_batch(model, y0s, **opts)
    got = jt.distributed.simulate_batch(model, y0s, client=client, runs_per_task=2, **opts)
    assert got.ys.shape == (4, 51, 6)
    np.testing.assert_array_equal(got.ys, np.asarray(ref.ys))
    np.testing.assert_array_equal(got.success, np.asarray(ref.success))
    assert np.all(got.success)


def test_inputs_checked_before_any_task(model):
    # no cluster is needed to refuse them: nothing is sent
    with pytest.raises(ValueError, match="'l0'"):
        jt.distributed.sweep(model, {"l0": [-1.0, 2.0]})
    with pytest.raises(TypeError, match="'checkpoint'"):
        jt.distributed.sweep(model, {"l0": [2.0]}, checkpoint="x")
    with pytest.raises(ValueError, match="runs_per_task"):
        jt.distributed.simulate_batch(model, np.zeros((1, 6)), client=None, runs_per_task=0)


@pytest.mark.slow
def test_lazy_sweep_without_a_cluster_equals_one_process(model):
    """Without a client the Dataset stays lazy (shapes from tracing, nothing computed) and
    is computed by whichever scheduler is active: here Dask's synchronous one."""
    grid = {"l0": np.linspace(1.0, 4.0, 10)}
    ref = jt.sweep(model, grid, chunk_size=4)
    lazy = jt.distributed.sweep(model, grid, chunk_size=4)
    assert lazy["max_real"].chunks is not None
    ds = lazy.compute(scheduler="synchronous")
    for k in ref.data_vars:
        np.testing.assert_array_equal(ds[k].values, ref[k].values, err_msg=k)
