"""Benchmarks of the gam Python package, each a ratio measured in this run (docs/performance.md).

    python python/bench/bench.py            # after pip install ./python (a release build)

1. gam.transform_points on 10^6 rigid poses and points vs numpy's einsum of the (N, 4, 4)
   matrices with homogeneous points (given to numpy ready-made).
2. build(spec).sample(t) for 10^5 parameters vs the Rust sampler alone on the same t
   (gam._rust_sample_seconds: the same loop, without making the numpy arrays).
3. `import gam` in a fresh interpreter.
4. The Dask sweep (python/examples/dask_sweep.py) on a LocalCluster of 2 processes vs serial.
Times are the best of several runs (the machine may be shared).
"""

import pathlib
import subprocess
import sys
import time

import numpy as np

import gam

EXT = getattr(gam, "gam", gam)  # the extension module inside the package
SWEEP_SAMPLES = 20001


def best(f, repeat=5):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return min(times)


def random_rigid(n, rng):
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    w, x, y, z = q.T
    m = np.zeros((n, 4, 4))
    m[:, 0, :3] = np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], 1)
    m[:, 1, :3] = np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], 1)
    m[:, 2, :3] = np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], 1)
    m[:, :3, 3] = rng.normal(size=(n, 3))
    m[:, 3, 3] = 1
    return m


def bench_transform(n=10**6):
    rng = np.random.default_rng(1)
    m, p = random_rigid(n, rng), rng.normal(size=(n, 3))
    ph = np.hstack([p, np.ones((n, 1))])
    ours = best(lambda: gam.transform_points(m, p))
    einsum = best(lambda: np.einsum("nij,nj->ni", m, ph))
    assert np.allclose(gam.transform_points(m, p), np.einsum("nij,nj->ni", m, ph)[:, :3], atol=1e-12)
    print(f"transform_points, N = {n}: gam {ours * 1e3:.1f} ms, np.einsum {einsum * 1e3:.1f} ms, "
          f"ratio {ours / einsum:.2f}x")


SPEC = {"method": "ccm-additive",
        "poses": [{"position": [0, 0, 0]}, {"position": [1, 0, 0.5], "axis": [0, 0, 2], "angle": 1.2},
                  {"position": [1, 1, 0], "quaternion": [0.5, 0.5, -0.5, 0.5]},
                  {"position": [2, 1, 1], "axis": [1, 0, 0], "angle": 0.5}]}


def bench_sample(n=10**5):
    motion = gam.build(SPEC)
    t = np.linspace(0, 1, n)
    ours = best(lambda: motion.sample(t), 3)
    rust = min(EXT._rust_sample_seconds(motion, t) for _ in range(3))
    print(f"build(spec).sample(t), N = {n}: gam {ours * 1e3:.1f} ms ({ours / n * 1e6:.2f} us/sample), "
          f"Rust sampler {rust * 1e3:.1f} ms, ratio {ours / rust:.2f}x")


def bench_import():
    def run(code):
        return min(float(subprocess.check_output([sys.executable, "-c", code])) for _ in range(5))

    alone = run("import time; s = time.perf_counter(); import gam; print(time.perf_counter() - s)")
    both = run("import time; s = time.perf_counter(); import gam, numpy; print(time.perf_counter() - s)")
    print(f"import gam: {alone * 1e3:.0f} ms (numpy is imported on first array use); "
          f"import gam, numpy: {both * 1e3:.0f} ms")


def bench_dask():
    sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "examples"))
    import dask_sweep
    from dask.distributed import Client, LocalCluster

    specs = list(dask_sweep.variants(3))  # 36 variants of 20001 samples each
    start = time.perf_counter()
    serial = dask_sweep.sweep_serial(specs, SWEEP_SAMPLES)
    t_serial = time.perf_counter() - start
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            dask_sweep.sweep_dask(specs[:2], client)  # warm the workers (imports)
            start = time.perf_counter()
            dist = dask_sweep.sweep_dask(specs, client, SWEEP_SAMPLES)
            t_dask = time.perf_counter() - start
    same = all(np.array_equal(a["path"], b["path"]) for a, b in zip(serial, dist))
    print(f"dask sweep, {len(specs)} variants: serial {t_serial:.2f} s, LocalCluster(2 processes) "
          f"{t_dask:.2f} s, speed-up {t_serial / t_dask:.2f}x, results identical: {same}")


if __name__ == "__main__":
    if sys.argv[1:] == ["--dask-only"]:
        bench_dask()
        sys.exit()
    bench_transform()
    bench_sample()
    bench_import()
    bench_dask()
    # gam's sampling is itself parallel (rayon), so the serial loop above already uses both
    # cores; with one Rayon thread per process the comparison is one core against two:
    print("with RAYON_NUM_THREADS=1:", flush=True)
    import os

    subprocess.run([sys.executable, __file__, "--dask-only"], env=dict(os.environ, RAYON_NUM_THREADS="1"), check=True)
