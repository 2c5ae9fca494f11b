#!/usr/bin/env python3
"""The Python API's costs (issue 19), figures in docs/performance-python.md.

  PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py [--build build] [--rounds 5] [--callgrind]

1. run_cycles(n) from Python against the C++ twin on the same workload
   (bench/twin_bench.cpp BM_TwinRunCycles: 2000 g cm^2, constant frame,
   trace off), alternating rounds, thread CPU time, medians.
2. The overhead of one exchange() call: n exchange() calls against one
   run_cycles(n) on identical twins, interleaved in this process; the
   difference per cycle is what a Python call adds to the C++ cycle.
3. --callgrind: the same as instruction counts (load-independent): the
   instructions per cycle of whole Python processes, from the difference of
   a long and a short run, against those inside Twin::run_cycle.
"""
import argparse
import json
import os
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile
import time

import sreh_twin

FRAME = sreh_twin.pd_out(90, parameter_set=1, motor_on=True, move=True)


def make_twin():
    return sreh_twin.Twin(load_gcm2=2000, record_trace=False)


def python_run_cycles_us(n=20000):
    twin = make_twin()
    twin.run_cycles(500, FRAME)  # warm
    t0 = time.thread_time()
    twin.run_cycles(n, FRAME)
    return 1e6 * (time.thread_time() - t0) / n


def cpp_run_cycles_us(build):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([str(build / "bench" / "twin_bench"), "--benchmark_filter=BM_TwinRunCycles$",
                        "--benchmark_min_time=1", f"--benchmark_out={out.name}", "--benchmark_out_format=json"],
                       capture_output=True, check=True)
        [run] = json.load(open(out.name))["benchmarks"]
    return run["cpu_time"]  # us per iteration (one cycle)


def exchange_overhead_us(n=2000, chunks=40):
    a, b = make_twin(), make_twin()
    a.run_cycles(500, FRAME)
    b.run_cycles(500, FRAME)
    ex, rc = [], []
    for _ in range(chunks):
        t0 = time.thread_time()
        for _ in range(n):
            a.exchange(FRAME)
        t1 = time.thread_time()
        b.run_cycles(n, FRAME)
        t2 = time.thread_time()
        ex.append(1e6 * (t1 - t0) / n)
        rc.append(1e6 * (t2 - t1) / n)
    diffs = [e - r for e, r in zip(ex, rc)]
    return statistics.median(ex), statistics.median(rc), statistics.median(diffs), min(diffs), max(diffs)


CALLGRIND_SCRIPT = """
import sreh_twin, sys
mode, n = sys.argv[1], int(sys.argv[2])
twin = sreh_twin.Twin(load_gcm2=2000, record_trace=False)
frame = sreh_twin.pd_out(90, parameter_set=1, motor_on=True, move=True)
if mode == "exchange":
    for _ in range(n):
        twin.exchange(frame)
else:
    twin.run_cycles(n, frame)
"""


def instructions(mode, n, toggle=None):
    args = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"]
    if toggle:
        args += ["--collect-atstart=no", f"--toggle-collect={toggle}"]
    done = subprocess.run(args + [sys.executable, "-c", CALLGRIND_SCRIPT, mode, str(n)],
                          capture_output=True, text=True, check=True)
    return int(re.search(r"Collected : (\d+)", done.stderr).group(1))


def callgrind_per_cycle(short=200, long=1200):
    out = {}
    for mode in ("exchange", "run_cycles"):
        total = (instructions(mode, long) - instructions(mode, short)) / (long - short)
        inside = instructions(mode, long, "sreh::Twin::run_cycle()") / long
        out[mode] = (total, inside)
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default="build", type=pathlib.Path)
    p.add_argument("--rounds", default=5, type=int)
    p.add_argument("--callgrind", action="store_true")
    a = p.parse_args()
    print(f"load average {os.getloadavg()[0]:.1f}")
    py, cpp = [], []
    for _ in range(a.rounds):
        py.append(python_run_cycles_us())
        cpp.append(cpp_run_cycles_us(a.build))
    mp, mc = statistics.median(py), statistics.median(cpp)
    print(f"run_cycles from Python: {mp:.2f} us/cycle (rounds {min(py):.2f} .. {max(py):.2f})")
    print(f"C++ Twin::run_cycle:    {mc:.2f} us/cycle (rounds {min(cpp):.2f} .. {max(cpp):.2f})")
    print(f"ratio Python / C++:     {mp / mc:.3f}")
    ex, rc, d, lo, hi = exchange_overhead_us()
    print(f"exchange() per call:    {ex:.2f} us; run_cycles per cycle {rc:.2f} us; "
          f"overhead {d:.2f} us (chunks {lo:.2f} .. {hi:.2f})")
    if a.callgrind:
        for mode, (total, inside) in callgrind_per_cycle().items():
            print(f"callgrind {mode:10s}: {total:,.0f} instructions per cycle, {inside:,.0f} inside Twin::run_cycle, "
                  f"{total - inside:,.0f} outside ({(total - inside) / inside * 100:.2f} %)")


if __name__ == "__main__":
    main()
