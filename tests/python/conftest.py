"""Shared fixtures of the Python API tests (issue 19).

Run by CTest (label `python`) with PYTHONPATH=<build>/python and SREH_CLI
set; by hand: PYTHONPATH=build/python /usr/bin/python3 -m pytest tests/python
from the source tree (the CLI is then looked for in build/).
"""
import json
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("SREH_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BUILD_DIR = pathlib.Path(os.environ.get("SREH_BUILD_DIR", SOURCE_DIR / "build"))
CLI = pathlib.Path(os.environ.get("SREH_CLI", BUILD_DIR / "sreh-twin"))
SCENARIOS = SOURCE_DIR / "scenarios"


def cli(*args, expect_exit=(0,)):
    """Runs sreh-twin; returns the CompletedProcess (text)."""
    done = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True, check=False)
    assert done.returncode in expect_exit, f"sreh-twin {' '.join(map(str, args))}: exit {done.returncode}\n{done.stderr}"
    return done


def cli_json(*args, expect_exit=(0,)):
    return json.loads(cli(*args, "--json", expect_exit=expect_exit).stdout)


@pytest.fixture
def motor_on_twin():
    """A factory-new module with 2000 g cm^2, motor on and Ready (manual 3.2 T1)."""
    import sreh_twin
    twin = sreh_twin.Twin(load_gcm2=2000)
    frame = sreh_twin.pd_out(motor_on=True, parameter_set=1)
    for _ in range(20):
        if sreh_twin.decode_pd_in(twin.exchange(frame))["ready"]:
            return twin
    raise AssertionError("motor on: never Ready")
