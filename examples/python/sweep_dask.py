#!/usr/bin/env python3
"""Scale-out: a sizing sweep on a Dask cluster (issues 19, 31).

The grid is cut into --shards contiguous blocks, as `sreh-twin sweep --shard
i/N` cuts it; each block is one Dask task, sreh_twin.sweep(..., shard="i/N")
on a worker process, which sends its part CSV back. The client writes the
parts and joins them with `sreh-twin sweep merge`, so the result is the CLI's
`sweep` CSV byte for byte. Workers need the sreh_twin package and nothing
shared (no common folder). Needs Debian's python3-distributed.

A cluster of processes (what tests/scale_out/dask_check.sh runs):

  dask scheduler --host 127.0.0.1 --scheduler-file sched.json &
  PYTHONPATH=build/python dask worker --scheduler-file sched.json --nthreads 1 --no-nanny &   # as many as wanted, any machine
  PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_dask.py --scheduler-file sched.json \\
      --loads-gcm2 0,5000,15000 --angles-deg 30,90,180 --shards 4 --csv sweep.csv

Without --scheduler / --scheduler-file it starts a LocalCluster of --workers
processes on this machine.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time


def numbers(text):
    return [float(v) for v in text.split(",")]


def part_csv(shard, grid):
    """One block of the grid on a worker: the text of its part CSV, and who ran it."""
    import socket

    import sreh_twin

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "part.csv")
        sreh_twin.sweep(**grid, shard=shard, threads=1, csv=path)  # one thread: the worker's --nthreads 1
        with open(path, encoding="utf-8") as f:
            return f.read(), f"{socket.gethostname()}:{os.getpid()}"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scheduler", help="scheduler address, e.g. tcp://10.0.0.1:8786")
    p.add_argument("--scheduler-file", help="the file `dask scheduler --scheduler-file` wrote")
    p.add_argument("--workers", type=int, default=2, help="LocalCluster processes when no scheduler is given")
    p.add_argument("--loads-gcm2", type=numbers, required=True)
    p.add_argument("--angles-deg", type=numbers, required=True)
    p.add_argument("--voltages-V", type=numbers, default=[24.0])
    p.add_argument("--speeds-dps", type=numbers, default=[], help="evaluate these speeds (default: recommend a set)")
    p.add_argument("--cycles", type=int, default=2)
    p.add_argument("--shards", type=int, default=8, help="tasks, each one block of the grid")
    p.add_argument("--csv", required=True, help="the merged CSV")
    p.add_argument("--sreh-twin", default="sreh-twin", help="the CLI that merges the parts")
    a = p.parse_args()
    from dask.distributed import Client, LocalCluster

    grid = dict(loads_gcm2=a.loads_gcm2, angles_deg=a.angles_deg, voltages_V=a.voltages_V, cycles=a.cycles)
    if a.speeds_dps:
        grid["speeds_dps"] = a.speeds_dps
    t0 = time.perf_counter()
    cluster = None
    if a.scheduler or a.scheduler_file:
        client = Client(a.scheduler, scheduler_file=a.scheduler_file)
    else:  # processes, one thread each: every worker runs its own twins
        cluster = LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    try:
        shards = [f"{i}/{a.shards}" for i in range(1, a.shards + 1)]
        futures = client.map(part_csv, shards, grid=grid, pure=False)
        parts = client.gather(futures)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    with tempfile.TemporaryDirectory() as d:
        paths = []
        for i, (text, _) in enumerate(parts, 1):
            paths.append(os.path.join(d, f"part_{i}.csv"))
            with open(paths[-1], "w", encoding="utf-8") as f:
                f.write(text)
        subprocess.run([a.sreh_twin, "sweep", "merge", "--csv", a.csv, *paths], check=True, stdout=subprocess.DEVNULL)
    workers = sorted({who for _, who in parts})
    print(f"{a.shards} shards on {len(workers)} Dask workers ({', '.join(workers)}) in "
          f"{time.perf_counter() - t0:.1f} s: {a.csv}", file=sys.stderr)


if __name__ == "__main__":
    main()
