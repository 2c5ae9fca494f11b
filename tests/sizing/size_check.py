"""Shared by the sizing check scripts (spread_check.py, verdict_check.py):
a failed check, and `sreh-twin size` run with its exit code checked."""
import subprocess
import sys


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def run_size(twin, args):
    """`twin size ARGS`; exit 0 or 1 (feasible or not), anything else fails the check."""
    p = subprocess.run([twin, "size"] + args, capture_output=True, text=True)
    if p.returncode not in (0, 1):
        fail(f"size {' '.join(args)}: exit {p.returncode}: {p.stderr}")
    return p
