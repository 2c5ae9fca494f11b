#!/usr/bin/env python3
"""Scale-out: a sizing sweep over a Dask LocalCluster (issue 19).

Every grid point is one sreh_twin.size() call on a worker process; the
result is the same CSV as sweep_parallel.sh (GNU parallel) prints, row for
row, since every point is deterministic. Needs Debian python3-distributed
(`SREH_WITH_EXAMPLES=1 ./setup.sh`). Workers inherit PYTHONPATH.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/sweep_dask.py [--workers 2] > dask.csv
"""
import argparse
import itertools
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from size_point import csv_row, size_point  # noqa: E402

LOADS = [0, 2000, 5000, 10000, 15000]
ANGLES = [45, 90, 180]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--workers", type=int, default=2)
    a = p.parse_args()
    from dask.distributed import Client, LocalCluster

    t0 = time.perf_counter()
    # Processes, one thread each: every worker runs its own twins.
    with LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        grid = list(itertools.product(LOADS, ANGLES))
        futures = client.map(size_point, [float(l) for l, _ in grid], [float(g) for _, g in grid])
        points = client.gather(futures)
    for point in points:
        print(csv_row(point))
    print(f"{len(points)} points on {a.workers} Dask workers in {time.perf_counter() - t0:.1f} s", file=sys.stderr)


if __name__ == "__main__":
    main()
