"""The Dask sweep (python/examples/dask_sweep.py) on a LocalCluster of two worker processes
gives exactly the serial loop's results."""

import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "examples"))

import dask_sweep  # noqa: E402


def test_dask_sweep_equals_serial():
    from dask.distributed import Client, LocalCluster

    specs = list(dask_sweep.variants(n_sets=3, shapes=(1.0, 2.0), gammas=((0.0, 0.0), (0.5, 0.0))))
    assert len(specs) == 12
    serial = dask_sweep.sweep_serial(specs, samples=201)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == 2
            distributed = dask_sweep.sweep_dask(specs, client, samples=201)
    assert len(distributed) == len(serial)
    for a, b in zip(serial, distributed):
        assert a["max_speed"] == b["max_speed"] and a["length"] == b["length"]
        assert np.array_equal(a["path"], b["path"]) and np.array_equal(a["speed"], b["speed"])
    # the variants differ: the sweep is not the same motion twelve times
    assert len({r["max_speed"] for r in serial}) == len(specs)
