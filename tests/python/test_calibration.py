"""Issue 26 from Python: calibrate() is `sreh-twin calibrate --json`,
size(uncertainty=True) and sweep(uncertainty=True) give the CLI's bands."""
import re
import math

import pytest

import sreh_twin
from conftest import SCENARIOS, cli, cli_json


@pytest.fixture(scope="module")
def short_log(tmp_path_factory):
    """A master log of a short scenario, recorded by the twin (run --master-log)."""
    folder = tmp_path_factory.mktemp("calibration")
    log = folder / "log.csv"
    cli("run", SCENARIOS / "t03_t05_t07_absolute_move.yaml", "--master-log", log)
    return log


def test_master_log_has_one_row_per_cycle(short_log):
    lines = short_log.read_text().splitlines()
    assert lines[0] == "t_s,pd_out,pd_in,temperature_C"
    rows = [line.split(",") for line in lines[1:]]
    assert all(len(r) == 4 and len(r[1]) == 12 and len(r[2]) == 14 for r in rows)
    times = [float(r[0]) for r in rows]
    assert all(math.isclose(b - a, 0.002, abs_tol=1e-9) for a, b in zip(times, times[1:]))


def test_calibrate_is_the_cli(short_log, tmp_path):
    fit = ["coulomb_friction"]
    py = sreh_twin.calibrate(short_log, load_gcm2=2000, fit=fit, out=tmp_path / "py.yaml", report=tmp_path / "py_report",
                             max_iterations=3)
    js = cli_json("calibrate", short_log, "--load-gcm2", 2000, "--fit", ",".join(fit), "--out", tmp_path / "cli.yaml",
                  "--report", tmp_path / "cli_report", "--max-iterations", 3, expect_exit=(0, 1))
    model_yaml = py.pop("model_yaml")
    assert py == js
    assert (tmp_path / "py.yaml").read_text() == model_yaml == (tmp_path / "cli.yaml").read_text()
    # The same page, but for where it came from (issue 37: the provenance
    # block names the command line, or the library, and the version).
    def made_of(path):
        return re.sub(r'<section class="provenance".*?</section>', "", path.read_text(), flags=re.S)
    page = made_of(tmp_path / "py_report" / "index.html")
    assert 'class="provenance"' in (tmp_path / "py_report" / "index.html").read_text()
    assert page == made_of(tmp_path / "cli_report" / "index.html")
    assert "coulomb_friction" in page and page.count("<svg") == 2  # position and error of the one log
    c = py["constants"]["coulomb_friction"]
    assert c["ci95"][0] <= c["value"] <= c["ci95"][1]
    assert c["start"] == sreh_twin.model_card()["constants"]["coulomb_friction"]["value"]  # the card's


def test_calibrate_bad_log_names_file_and_line(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("t_s,pd_out,pd_in\n0.002,000000000001,00000000000002\n0.004,00000001,00000000000002\n")
    with pytest.raises(sreh_twin.InputError, match=r"bad.csv:3: pd_out"):
        sreh_twin.calibrate(bad, load_gcm2=0, out=tmp_path / "fit.yaml")


def test_calibrate_refuses_a_bad_output_before_the_fit(short_log, tmp_path):
    (tmp_path / "a_file").write_text("x")
    with pytest.raises(sreh_twin.InputError, match=r"report"):
        sreh_twin.calibrate(short_log, load_gcm2=0, report=tmp_path / "a_file")
    with pytest.raises(sreh_twin.InputError, match=r"out"):
        sreh_twin.calibrate(short_log, load_gcm2=0, out=short_log)  # would overwrite its own input


def test_size_uncertainty_brackets_the_nominal_and_repeats():
    options = dict(angle_deg=90, load_gcm2=2000, speed_dps=2000, tolerance_deg=0.0103, wait_ms=0, uncertainty=True,
                   samples=4, seed=3)
    a = sreh_twin.size(**options)
    assert a == sreh_twin.size(**options)
    lo, hi = a["positioning_s_range"]
    assert lo <= a["positioning_s"] <= hi and lo < hi
    lo, hi = a["peak_torque_Nm_range"]
    assert lo < hi and lo <= a["peak_torque_Nm"] <= hi
    assert a["uncertainty"]["samples"] == 4 and "torsional_stiffness" in a["uncertainty"]["sampled"]
    assert a == cli_json("size", "--angle-deg", 90, "--load-gcm2", 2000, "--speed-dps", 2000, "--tolerance-deg", 0.0103,
                         "--wait-ms", 0, "--uncertainty", "--samples", 4, "--seed", 3, expect_exit=(0, 1))


def test_sweep_uncertainty_adds_lo_hi_columns():
    s = sreh_twin.sweep(loads_gcm2=[2000], angles_deg=[90], speeds_dps=[2000], uncertainty=True, samples=3)
    assert s["positioning_s_lo"][0] <= s["positioning_s"][0] <= s["positioning_s_hi"][0]
    assert s["peak_torque_Nm_lo"][0] < s["peak_torque_Nm_hi"][0]
    assert "positioning_s_lo" not in sreh_twin.sweep(loads_gcm2=[2000], angles_deg=[90], speeds_dps=[2000])
