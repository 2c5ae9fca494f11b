"""A move via process data from Python matches the CLI's trace bit for bit
(the same twin, the same frames, the same cycles), and the trace comes as
numpy columns (no per-sample Python objects)."""
import numpy as np
import pytest

import sreh_twin
from conftest import cli

# The same PLC program as a scenario (scenarios/README.md): a pd step lasts
# one cycle, wait_s rounds up to whole 2 ms cycles.
SCENARIO = """\
name: "python: a 90 deg move for the bit-for-bit comparison"
load: {inertia_gcm2: 2000}
device:
  isdu:
    - {index: 65, subindex: 4, value: 2000}
steps:
  - pd: {motor_on: 1}
  - wait_s: 0.02
  - pd: {target_deg: 90, parameter_set: 1, move: 1}
  - wait_s: 0.3
  - pd: {move: 0}
  - wait_s: 0.02
"""


def python_run():
    twin = sreh_twin.Twin(load_gcm2=2000, configure_load=False)
    twin.isdu_write(65, 4, 2000)
    program = [(sreh_twin.pd_out(motor_on=True), 1 + 10),
               (sreh_twin.pd_out(90, parameter_set=1, motor_on=True, move=True), 1 + 150),
               (sreh_twin.pd_out(90, parameter_set=1, motor_on=True), 1 + 10)]
    received = []
    for frame, cycles in program:
        for _ in range(cycles):
            received.append(twin.exchange(frame))
    return twin, received


def test_move_matches_the_cli_trace_bit_for_bit(tmp_path):
    scenario = tmp_path / "move.yaml"
    scenario.write_text(SCENARIO)
    csv = tmp_path / "trace.csv"
    cli("run", scenario, "--trace", csv)
    twin, received = python_run()
    assert twin.trace_csv() == csv.read_text()
    rows = csv.read_text().splitlines()[1:]
    assert len(rows) == len(received) == 1 + 10 + 1 + 150 + 1 + 10
    header = csv.read_text().splitlines()[0].split(",")
    pd_in_hex = header.index("pd_in_hex")
    assert [r.split(",")[pd_in_hex] for r in rows] == [f.hex().upper() for f in received]
    # The numeric columns are the values the CSV prints (to its precision).
    trace = twin.trace()
    printed = np.array([float(r.split(",")[header.index("position_deg")]) for r in rows])
    assert np.all(np.abs(trace["position_deg"] - printed) <= 5e-7)
    assert twin.moves()[0]["completed"] and twin.state()["position_deg"] == pytest.approx(90, abs=0.1)


def test_run_cycles_equals_exchange_per_cycle():
    a, b = sreh_twin.Twin(load_gcm2=500), sreh_twin.Twin(load_gcm2=500)
    frame = sreh_twin.pd_out(-45, parameter_set=1, motor_on=True, move=True)
    last = a.run_cycles(120, frame)
    for _ in range(120):
        last_b = b.exchange(frame)
    assert last == last_b == a.pd_in
    for name, column in a.trace().items():
        assert np.array_equal(column, b.trace()[name]), name


def test_trace_columns_are_numpy_arrays_with_fixed_dtypes():
    twin, _ = python_run()
    trace = twin.trace()
    n = twin.cycles
    floats = ["t_s", "setpoint_deg", "position_deg", "tracking_error_deg", "velocity_dps", "torque_Nm", "supply_V",
              "temperature_C", "torque_limit_Nm", "external_torque_Nm"]
    for name in floats:
        assert trace[name].dtype == np.float64 and trace[name].shape == (n,), name
    for name in ["state", "error_code", "warning_code", "led"]:
        assert trace[name].dtype == np.uint8 and trace[name].shape == (n,), name
    for name in ["pd_out", "pd_in"]:
        assert trace[name].dtype == np.uint64 and trace[name].shape == (n,), name
    assert set(trace) == set(floats) | {"state", "error_code", "warning_code", "led", "pd_out", "pd_in"}
    # Frames as integers in the manual's bit numbering (2.3): bits 55..24
    # actual position, bit 3 Done.
    position = (trace["pd_in"] >> np.uint64(24)).astype(np.uint32).view(np.int32)
    # Within one wire count (0.0055 deg): friction can hold the rotor an
    # encoder count short of the target for a while (A-CTRL-7, A-TWIN-22).
    assert abs(int(position[-1]) - round(90 * 65536 / 360)) <= 1
    done = (trace["pd_in"] >> np.uint64(3)) & np.uint64(1)
    states = np.array(sreh_twin.STATES)[trace["state"]]
    # The frame of a row is the device's answer at the cycle's start: Done
    # shows from the row after the state became Done, until the row where
    # releasing Move ends it (T7 happens in that exchange).
    in_done = np.flatnonzero(states == "Done")
    assert np.array_equal(np.flatnonzero(done == 1), np.arange(in_done[0] + 1, in_done[-1] + 1))
    assert sreh_twin.LEDS[trace["led"][-1]] == "green"


def test_trace_off():
    twin = sreh_twin.Twin(record_trace=False)
    twin.run_cycles(10)
    assert all(len(c) == 0 for c in twin.trace().values())


def test_process_data_codec():
    frame = sreh_twin.pd_out(90, parameter_set=3, motor_on=True, move=True)
    assert len(frame) == 6
    fields = sreh_twin.decode_pd_out(frame)
    assert fields["target_raw"] == 16384 and fields["parameter_set"] == 3  # manual 2.5: 2^16 per rev
    assert fields["target_deg"] == 90.0
    assert fields["motor_on"] and fields["move"] and not fields["stop"]
    assert sreh_twin.decode_pd_out(sreh_twin.pd_out(target_raw=-1))["target_raw"] == -1
    position = sreh_twin.decode_pd_in(bytes([0xFF, 0xFF, 0xC0, 0x00, 0, 0, 0x02]))  # -16384 counts, Ready
    assert position["position_raw"] == -16384 and position["position_deg"] == -90.0 and position["ready"]
    with pytest.raises(sreh_twin.InputError, match="6 bytes"):
        sreh_twin.decode_pd_out(b"\x00")
    with pytest.raises(sreh_twin.InputError):
        sreh_twin.Twin().exchange(b"\x00" * 7)
    with pytest.raises(TypeError):
        sreh_twin.Twin().exchange("abcdef")


def test_process_data_old_names_are_deprecated_aliases():
    # Issue 30: one vocabulary (target_raw, position_raw); the old names
    # still work for one release and say so.
    with pytest.warns(DeprecationWarning, match="target_raw"):
        frame = sreh_twin.pd_out(target_counts=-1)
    with pytest.warns(DeprecationWarning, match="target_raw"):
        assert sreh_twin.decode_pd_out(frame)["target_position"] == -1
    with pytest.warns(DeprecationWarning, match="position_raw"):
        assert sreh_twin.decode_pd_in(bytes(7))["actual_position"] == 0
    with pytest.raises(KeyError):
        sreh_twin.decode_pd_in(bytes(7))["no_such_field"]
