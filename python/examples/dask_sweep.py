"""A parameter sweep of GAM motions on a Dask cluster.

Every variant is a `gam interpolate` spec (a set of key poses x a shape factor x a gamma
pseudoscalar), built and sampled by GAM on a worker; what travels is the spec (a dict) to
the worker and the sampled arrays back (numpy: positions and speeds of the body point).

    python dask_sweep.py                          # a LocalCluster of 2 worker processes
    python dask_sweep.py --scheduler tcp://host:8786   # a running cluster (dask scheduler / dask worker)
    python dask_sweep.py --serial                  # the same sweep in one process

Each worker needs `gam` installed (pip install ./python) and the same Python and numpy.
"""

import argparse
import itertools
import time

import numpy as np

import gam


def key_pose_sets(count, seed=0):
    """`count` sets of four key poses (position, axis, angle), reproducible from `seed`."""
    rng = np.random.default_rng(seed)
    sets = []
    for _ in range(count):
        poses = [{"position": [0.0, 0.0, 0.0]}]
        for k in range(1, 4):
            poses.append({"position": (rng.normal(size=3) * 2 + [k, 0, 0]).tolist(),
                          "axis": rng.normal(size=3).tolist(), "angle": float(rng.uniform(0, 2))})
        sets.append(poses)
    return sets


def variants(n_sets=8, shapes=(0.5, 1.0, 2.0, 4.0), gammas=((0.0, 0.0), (0.5, 0.0), (0.0, 0.5))):
    """The sweep: every key-pose set x shape factor x gamma, as interpolate specs."""
    for poses, shape, gamma in itertools.product(key_pose_sets(n_sets), shapes, gammas):
        yield {"method": "ccm-additive", "poses": poses, "shape": shape, "gamma": list(gamma),
               "body_points": [[0.2, 0.1, 0.0]]}


def run_one(spec, samples=2001):
    """Builds and samples one variant: its path, speeds and the largest speed (plain arrays)."""
    t = np.linspace(0.0, 1.0, samples)
    s = gam.build(spec).sample(t)
    speed = np.linalg.norm(s["velocities"][:, 0, :], axis=1)
    return {"path": s["points"][:, 0, :], "speed": speed, "max_speed": float(speed.max()),
            "length": float(np.sum(np.linalg.norm(np.diff(s["points"][:, 0, :], axis=0), axis=1)))}


def sweep_serial(specs, samples=2001):
    return [run_one(s, samples) for s in specs]


def sweep_dask(specs, client, samples=2001):
    futures = client.map(run_one, specs, samples=samples, pure=False)
    return client.gather(futures)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    ap.add_argument("--sets", type=int, default=8, help="key-pose sets (default 8)")
    ap.add_argument("--samples", type=int, default=2001)
    ap.add_argument("--serial", action="store_true", help="run the loop in this process")
    a = ap.parse_args(argv)
    specs = list(variants(a.sets))
    start = time.perf_counter()
    if a.serial:
        results = sweep_serial(specs, a.samples)
    else:
        from dask.distributed import Client, LocalCluster

        if a.scheduler:
            client = Client(a.scheduler)
        else:
            client = Client(LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True))
        with client:
            results = sweep_dask(specs, client, a.samples)
    wall = time.perf_counter() - start
    best = min(range(len(specs)), key=lambda i: results[i]["max_speed"])
    print(f"{len(specs)} variants in {wall:.2f} s; smallest peak speed {results[best]['max_speed']:.4f} "
          f"(shape {specs[best]['shape']}, gamma {specs[best]['gamma']})")
    return results


if __name__ == "__main__":
    main()
