"""run_scenario, size and sweep give what the CLI gives (`run --json`,
`size --json`, `sweep --csv`): the same C++ code paths (issue 19)."""
import csv
import math
import re

import numpy as np
import pytest

import sreh_twin
from conftest import SCENARIOS, cli, cli_json

SHIPPED = sorted(SCENARIOS.glob("*.yaml"))


@pytest.mark.parametrize("path", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_shipped_scenarios_pass(path):
    result = sreh_twin.run_scenario(path)
    assert result["passed"], result["failures"]
    assert result["checks"] and all(c["passed"] for c in result["checks"])


def without_timing(result):
    """`run --json` minus what is measured, not simulated (issue 25)."""
    assert result["wall_s"] > 0 and result["real_time_factor"] > 0
    return {k: v for k, v in result.items() if k not in ("wall_s", "real_time_factor")}


@pytest.mark.parametrize("name", ["t03_t05_t07_absolute_move", "error_114_5_tracking_blocked_flange",
                                  "store_origin_171_power_cycle", "load_mjcf_gripper"])
def test_run_scenario_is_run_json(name):
    path = SCENARIOS / f"{name}.yaml"
    assert without_timing(sreh_twin.run_scenario(str(path))) == without_timing(cli_json("run", path))


def test_failing_scenario_is_reported_like_the_cli(tmp_path):
    path = tmp_path / "fails.yaml"
    path.write_text("name: fails\nsteps:\n  - pd: {motor_on: 1}\n  - wait_until: {state: Done, within_s: 0.01}\n")
    result = sreh_twin.run_scenario(path)
    assert not result["passed"] and "step 2 (line 4)" in result["failures"][0]
    assert without_timing(result) == without_timing(cli_json("run", path, expect_exit=(1,)))


def test_bad_scenario_is_an_input_error(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("name: bad\nsteps:\n  - pd: {motor_on: 7}\n")
    with pytest.raises(sreh_twin.InputError, match="bad.yaml:3"):
        sreh_twin.run_scenario(path)
    with pytest.raises(sreh_twin.InputError, match="nope.yaml"):
        sreh_twin.run_scenario(tmp_path / "nope.yaml")


def test_size_is_size_json():
    py = sreh_twin.size(angle_deg=90, load_gcm2=2000, speed_dps=2000, accel_pct=80, dwell_s=0.1)
    assert py == cli_json("size", "--angle-deg", 90, "--load-gcm2", 2000, "--speed-dps", 2000, "--accel-pct", 80,
                          "--dwell-s", 0.1)
    assert py["feasible"] and py["mode"] == "evaluate"


def test_size_with_a_load_file_is_size_json():
    load = SCENARIOS / "load_disk.yaml"
    assert sreh_twin.size(angle_deg=45, load=load, speed_dps=1500) == cli_json(
        "size", "--angle-deg", 45, "--load", load, "--speed-dps", 1500)


def test_size_keywords_are_the_cli_options():
    help_text = cli("size", "--help").stdout
    # --quiet silences the CLI's progress lines on stderr (issue 39): Python prints none.
    cli_options = set(re.findall(r"--([a-zA-Z][\w-]*)", help_text)) - {"help", "json", "quiet"}
    assert {o.replace("-", "_") for o in cli_options} == set(sreh_twin.SIZE_OPTIONS)
    help_text = cli("sweep", "--help").stdout
    # --quiet silences the CLI's progress lines on stderr: Python prints none.
    cli_options = set(re.findall(r"--([a-zA-Z][\w-]*)", help_text)) - {"help", "quiet"}
    assert {o.replace("-", "_") for o in cli_options} == set(sreh_twin.SWEEP_OPTIONS)


def test_size_cycle(tmp_path):
    """size(cycle=...) is `size --cycle FILE --json`; the emitted scenario passes."""
    cycle = tmp_path / "cycle.yaml"
    cycle.write_text("load: {inertia_gcm2: 1000}\nsegments:\n  - {move_deg: 45, speed_dps: 1500}\n"
                     "  - {dwell_s: 0.1}\n  - {move_deg: 0, speed_dps: 1500}\n")
    scenario = tmp_path / "replay.yaml"
    py = sreh_twin.size(cycle=cycle, emit_scenario=scenario)
    assert py["feasible"] and [s["kind"] for s in py["segments"]] == ["move", "dwell", "move"]
    assert py == cli_json("size", "--cycle", cycle)
    assert sreh_twin.run_scenario(scenario)["passed"]


def test_size_refusals():
    with pytest.raises(sreh_twin.InputError, match=r"voltage_V 40 is outside 16 \.\. 32"):
        sreh_twin.size(angle_deg=90, load_gcm2=100, voltage_V=40)
    with pytest.raises(sreh_twin.InputError, match="load_gcm2 J or load"):
        sreh_twin.size(angle_deg=90)
    with pytest.raises(TypeError, match="unexpected keyword argument 'angle'"):
        sreh_twin.size(angle=90, load_gcm2=100)
    # angle_deg is required unless a cycle file is given (issue 17).
    with pytest.raises(sreh_twin.InputError, match="give the move with angle_deg A, or a cycle with cycle"):
        sreh_twin.size(load_gcm2=100)
    with pytest.raises(TypeError, match="wrong type"):
        sreh_twin.size(angle_deg=90, load_gcm2=100, cycles=1.5)


def test_sweep_columns_are_the_csv(tmp_path):
    out = tmp_path / "grid.csv"
    args = dict(loads_gcm2=[0, 14000], angles_deg=[30, 180], speeds_dps=[4300], threads=2)
    cols = sreh_twin.sweep(**args)
    cli("sweep", "--loads-gcm2", "0,14000", "--angles-deg", "30,180", "--speeds-dps", "4300", "--threads", 2,
        "--csv", out)
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    assert list(cols) == list(rows[0])
    assert all(len(c) == len(rows) == 4 for c in cols.values())
    assert cols["feasible"].dtype == np.bool_ and cols["simulations"].dtype == np.int64
    for name, column in cols.items():
        for value, row in zip(column, rows):
            text = row[name]
            if column.dtype == np.float64:
                assert (math.isnan(value) and text == "") or value == float(text), name
            elif column.dtype == np.bool_:
                assert int(value) == int(text), name
            else:
                assert str(value) == text, name
    assert list(cols["load_gcm2"]) == [0, 0, 14000, 14000] and list(cols["angle_deg"]) == [30, 180, 30, 180]


def test_sweep_writes_the_cli_csv_when_asked(tmp_path):
    ours, theirs = tmp_path / "py.csv", tmp_path / "cli.csv"
    sreh_twin.sweep(loads_gcm2=np.array([100.0]), angles_deg=90, speeds_dps=[3000], csv=ours)
    cli("sweep", "--loads-gcm2", 100, "--angles-deg", 90, "--speeds-dps", 3000, "--csv", theirs)
    assert ours.read_bytes() == theirs.read_bytes()
    with pytest.raises(sreh_twin.InputError, match="loads_gcm2: give at least one load"):
        sreh_twin.sweep(loads_gcm2=[], angles_deg=[90])


def test_stubs_name_every_keyword():
    """The .pyi stub's size / sweep signatures list exactly the CLI's options."""
    import ast
    import pathlib
    stub = ast.parse((pathlib.Path(sreh_twin.__file__).parent / "__init__.pyi").read_text())
    functions = {f.name: f for f in stub.body if isinstance(f, ast.FunctionDef)}
    for name, options in [("size", sreh_twin.SIZE_OPTIONS), ("sweep", sreh_twin.SWEEP_OPTIONS)]:
        assert [a.arg for a in functions[name].args.kwonlyargs] == list(options), name
