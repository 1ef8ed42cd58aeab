#!/usr/bin/env python3
"""The Python module's two speed figures (docs/python.md), not part of the tests:

1. overhead of a batched distance query: swept.distance() on 10k poses (poses converted from a
   (K, 7) array, results written into NumPy arrays) against the C++ swept::distance_batch() alone
   on the same poses, in the same process and threads (median of --runs alternating runs);
2. a 16-plan study (air-cleaner and cylinder-head at test scale, fitters inertia and pqp, four
   clearances) on a local Dask cluster of 2 worker processes against the same study run serially
   in one process; the tables are checked equal (volatile columns aside).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_python.py [--cli build/release/apps/swept/swept]
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time

import numpy as np

import swept
from swept import study as st


def sphere(radius, n_lat, n_lon):
    th = np.pi * np.arange(1, n_lat) / n_lat
    ph = 2 * np.pi * np.arange(n_lon) / n_lon
    ring = np.stack([np.outer(np.sin(th), np.cos(ph)), np.outer(np.sin(th), np.sin(ph)),
                     np.outer(np.cos(th), np.ones_like(ph))], axis=-1).reshape(-1, 3)
    v = np.concatenate([[[0, 0, 1]], ring, [[0, 0, -1]]]) * radius
    faces = []
    for j in range(n_lon):
        faces.append([0, 1 + j, 1 + (j + 1) % n_lon])
    for i in range(n_lat - 2):
        for j in range(n_lon):
            a, b = 1 + i * n_lon + j, 1 + i * n_lon + (j + 1) % n_lon
            faces += [[a, a + n_lon, b], [b, a + n_lon, b + n_lon]]
    last, base = len(v) - 1, 1 + (n_lat - 2) * n_lon
    for j in range(n_lon):
        faces.append([base + j, last, base + (j + 1) % n_lon])
    return v, np.array(faces, dtype=np.int64)


def bench_distance(poses_count: int, runs: int) -> None:
    v, f = sphere(10.0, 64, 128)  # 16 128 triangles
    vs, fs = sphere(5.0, 16, 32)  # 960 triangles
    box_v = np.array([[x, y, z] for z in (-4, 4) for y in (-2, 2) for x in (-3, 3)], dtype=float)
    box_f = np.array([[0, 2, 1], [1, 2, 3], [4, 5, 6], [5, 7, 6], [0, 1, 4], [1, 5, 4], [2, 6, 3], [3, 6, 7],
                      [0, 4, 2], [2, 4, 6], [1, 3, 5], [3, 7, 5]], dtype=np.int64)
    bench_distance_pair("spheres, 16128 x 960 triangles", (v, f), (vs, fs), poses_count, runs)
    bench_distance_pair("sphere and box, 960 x 12 triangles", (vs, fs), (box_v, box_f), poses_count, runs)


def bench_distance_pair(label, mesh_a, mesh_b, poses_count: int, runs: int) -> None:
    a = swept.BVH(swept.Mesh(*mesh_a))
    b = swept.BVH(swept.Mesh(*mesh_b))
    rng = np.random.default_rng(1)
    t = rng.uniform(-30, 30, size=(poses_count, 3))
    t[:, 0] += 40  # apart, at varying distance
    q = rng.normal(size=(poses_count, 4))
    poses = np.concatenate([t, q], axis=1)
    swept.distance(a, b, None, poses[:1000])  # warm up (threads, caches)
    py, cpp = [], []
    for _ in range(runs):
        t0 = time.perf_counter()
        r = swept.distance(a, b, None, poses)
        py.append((time.perf_counter() - t0) * 1e3)
        cpp.append(swept._swept._distance_batch_cpp_ms(a, b, poses))
    assert r.distance.shape == (poses_count,)
    mp, mc = statistics.median(py), statistics.median(cpp)
    print(f"distance, {label}, {poses_count} poses, {os.cpu_count()} cores, median of {runs}:")
    print(f"  swept.distance (Python, (K, 7) in, arrays out)  {mp:9.2f} ms")
    print(f"  swept::distance_batch (C++ alone)               {mc:9.2f} ms")
    print(f"  Python overhead                                 {100 * (mp - mc) / mc:+8.2f} %"
          f"   (runs: py {', '.join(f'{x:.1f}' for x in py)}; C++ {', '.join(f'{x:.1f}' for x in cpp)})")


def bench_study(cli: str, workers: int) -> None:
    with tempfile.TemporaryDirectory(prefix="swept-bench-study-") as d:
        for scene in ("air-cleaner", "cylinder-head"):
            subprocess.run([cli, "scene", scene, "--scale", "test", "-o", os.path.join(d, scene)], check=True,
                           stdout=subprocess.DEVNULL)
        path = os.path.join(d, "study.toml")
        with open(path, "w") as f:
            f.write(textwrap.dedent("""\
                [study]
                name = "bench"
                threads = 1
                [[problem]]
                file = "air-cleaner/problem.toml"
                [[problem]]
                file = "cylinder-head/problem.toml"
                [variants]
                fitter = ["inertia", "pqp"]
                clearance = [0.5, 0.75, 1.0, 1.25]
                time_limit = 120.0
                """))
        s = st.load_study(path)
        assert len(s.jobs) == 16
        load = os.getloadavg()[0]
        st.clear_cache()
        t0 = time.perf_counter()
        serial = st.run_study(s, serial=True, progress=False)
        t_serial = time.perf_counter() - t0
        st.clear_cache()
        from distributed import Client, LocalCluster
        t0 = time.perf_counter()
        with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                          dashboard_address=None) as lc, Client(lc) as client:
            t1 = time.perf_counter()
            cluster = st.run_study(s, client=client, progress=False)
            t2 = time.perf_counter()
        t_cluster, t_jobs = time.perf_counter() - t0, t2 - t1
        same = st.deterministic_rows(cluster) == st.deterministic_rows(serial)
        solved = sum(r["solved"] for r in serial)
        plan_s = sum(r["plan_ms"] or 0 for r in serial) / 1e3
        print(f"study, 16 plans ({solved} solved; planner time {plan_s:.1f} s serially), {os.cpu_count()} cores:")
        print(f"  serial, one process                   {t_serial:7.2f} s")
        print(f"  local Dask cluster, {workers} workers        {t_jobs:7.2f} s  jobs ({t_cluster:.2f} s with the cluster's start and stop)")
        print(f"  speed-up                              {t_serial / t_jobs:7.2f} x   ({t_serial / t_cluster:.2f} x with start and stop)"
              f"   tables equal: {same}")
        per_worker: dict[str, list[float]] = {}
        for r in cluster:
            w = per_worker.setdefault(r["worker"], [0.0, 0.0])
            w[0] += r["wall_ms"] / 1e3
            w[1] += r["cpu_ms"] / 1e3
        wall_s, cpu_s = sum(r["wall_ms"] for r in serial) / 1e3, sum(r["cpu_ms"] for r in serial) / 1e3
        # The CPU share is how much of a core a job got: below 1 when other programs shared the cores.
        print(f"  jobs' wall / CPU time: serial {wall_s:.1f} s / {cpu_s:.1f} s (CPU share {cpu_s / wall_s:.2f}); "
              + "; ".join(f"worker {i + 1} {w:.1f} s / {c:.1f} s (share {c / w:.2f})"
                          for i, (w, c) in enumerate(per_worker.values())))
        print(f"  load average before: {load:.1f}")
        if not same:
            sys.exit("the cluster's table differs from the serial one")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--cli", default=os.path.join(here, "..", "build", "release", "apps", "swept", "swept"))
    ap.add_argument("--poses", type=int, default=10000)
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--only", choices=["distance", "study"])
    args = ap.parse_args()
    if args.only in (None, "distance"):
        bench_distance(args.poses, args.runs)
    if args.only in (None, "study"):
        bench_study(args.cli, args.workers)


if __name__ == "__main__":
    main()
