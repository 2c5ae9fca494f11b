"""Issue 39: pictures, videos and reports from Python as from the CLI.

run_scenario takes a path, YAML text or a dict and writes a video / frames /
report as `run --video / --frames / --report` does (the same renders/ code:
the frames' text log is byte-identical); Twin.render() and
PositioningEnv.render() return the module as an RGB array; size(report=)
writes the sizing report."""
import json

import numpy as np
import pytest
import yaml

import sreh_twin
from sreh_twin.env import PositioningEnv
from conftest import SCENARIOS, cli

SCENARIO = SCENARIOS / "t03_t05_t07_absolute_move.yaml"


def simulated(result, lines=True):
    """What the run simulated; a dict has no lines of its own, so its checks are compared without them."""
    checks = [c if lines else {k: v for k, v in c.items() if k != "line"} for c in result["checks"]]
    return {**{k: result[k] for k in ("passed", "moves", "final", "sim_time_s", "cycles")}, "checks": checks}


def test_run_scenario_takes_a_path_text_or_dict():
    text = SCENARIO.read_text()
    by_path = sreh_twin.run_scenario(SCENARIO)
    assert by_path["passed"]
    assert simulated(sreh_twin.run_scenario(str(SCENARIO))) == simulated(by_path)
    assert simulated(sreh_twin.run_scenario(text)) == simulated(by_path)
    assert simulated(sreh_twin.run_scenario(yaml.safe_load(text)), lines=False) == simulated(by_path, lines=False)


def test_scenario_text_errors_name_the_line():
    with pytest.raises(sreh_twin.InputError, match=r"<scenario text>:3:5: .*did you mean 'wait_until'"):
        sreh_twin.run_scenario("name: typo\nsteps:\n  - wait_untill: {state: Ready, within_s: 0.1}\n")
    with pytest.raises(TypeError):
        sreh_twin.run_scenario(42)


def test_video_frames_and_report_as_the_cli(tmp_path):
    opts = ["--size", "320x240", "--fps", "10"]
    cli("run", SCENARIO, "--frames", tmp_path / "cli_frames", "--quiet", *opts)
    result = sreh_twin.run_scenario(SCENARIO, video=tmp_path / "run.mp4", frames=tmp_path / "py_frames",
                                    report=tmp_path / "report", size="320x240", fps=10)
    assert result["passed"]
    py_log = (tmp_path / "py_frames" / "text.tsv").read_text()
    assert py_log == (tmp_path / "cli_frames" / "text.tsv").read_text()
    assert len(list((tmp_path / "py_frames").glob("frame_*.png"))) == len(list((tmp_path / "cli_frames").glob("frame_*.png")))
    assert "PASS: all" in py_log  # the closing card
    assert (tmp_path / "run.mp4").stat().st_size > 1000
    page = (tmp_path / "report" / "index.html").read_text()
    assert "video.mp4" in page and (tmp_path / "report" / "video.mp4").exists()


def test_bad_media_options_raise_before_the_run(tmp_path):
    with pytest.raises(sreh_twin.InputError, match=r"\.mp4, \.webm or \.gif"):
        sreh_twin.run_scenario(SCENARIO, video=tmp_path / "x.avi")
    with pytest.raises(sreh_twin.InputError, match=r"size 'big': expected WIDTHxHEIGHT"):
        sreh_twin.run_scenario(SCENARIO, video=tmp_path / "x.mp4", size="big")
    assert not list(tmp_path.iterdir())


def test_size_report_from_python(tmp_path):
    result = sreh_twin.size(angle_deg=90, load_gcm2=1000, report=tmp_path / "sizing")
    assert result["feasible"]
    assert "<html" in (tmp_path / "sizing" / "index.html").read_text().lower()
    assert result["request"]["mounting_tilt_deg"] == 0 and result["gravity_torque_max_Nm"] == 0


def test_twin_render_is_an_rgb_array(motor_on_twin):
    img = motor_on_twin.render(320, 240)
    assert img.shape == (240, 320, 3) and img.dtype == np.uint8
    bare = motor_on_twin.render(320, 240, overlay=False)
    # The overlay panel (top-left, dark) is the difference.
    assert np.abs(img[:60, :60].astype(int) - bare[:60, :60]).max() > 50
    with pytest.raises(sreh_twin.InputError, match="even"):
        motor_on_twin.render(321, 240)


def test_env_render_follows_the_flange():
    env = PositioningEnv(render_size=(320, 240))
    env.reset(seed=1, options={"goal_deg": 120.0})
    before = env.render()
    assert before.shape == (240, 320, 3) and before.dtype == np.uint8
    for _ in range(60):
        _, _, terminated, truncated, _ = env.step([120.0, 1, 1])
        if terminated or truncated:
            break
    after = env.render()
    module = (slice(40, 240), slice(110, 320))  # right of the overlay, below the banner
    changed = (np.abs(after[module].astype(int) - before[module]).max(axis=2) > 30).sum()
    assert changed > 200, changed
    assert PositioningEnv(render_mode=None).render() is None
