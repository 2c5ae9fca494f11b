"""Twin.snapshot() / restore() (issue 13, A-TWIN-34..36): snapshot a
running twin mid-move, try something else, restore, and the continuation
is the same numpy trace, bit for bit."""
import numpy as np
import pytest

import sreh_twin

CONTINUE = 300  # 0.6 s of 2 ms cycles: the rest of the move and settling


def mid_move_twin(**kwargs):
    twin = sreh_twin.Twin(load_gcm2=4000, **kwargs)
    twin.run_cycles(15, sreh_twin.pd_out(motor_on=True))
    twin.run_cycles(40, sreh_twin.pd_out(120, parameter_set=1, motor_on=True, move=True))
    assert twin.state()["moving"]
    return twin


def tail(twin, n):
    """The last n rows of every trace column."""
    return {name: column[-n:] for name, column in twin.trace().items()}


def assert_bit_identical(a, b):
    assert a.keys() == b.keys()
    for name in a:
        assert a[name].dtype == b[name].dtype, name
        assert a[name].tobytes() == b[name].tobytes(), name  # bits, not approximately


def test_continue_restore_continue_gives_identical_traces():
    twin = mid_move_twin()
    snap = twin.snapshot()
    assert isinstance(snap, sreh_twin.TwinSnapshot)
    assert snap.cycles == 55 and "55" in repr(snap)
    twin.run_cycles(CONTINUE)
    first = tail(twin, CONTINUE)
    first_moves = twin.moves()

    # Something else: a torque on the flange, a voltage dip, a clamp, reset.
    twin.external_torque(0.4)
    twin.set_voltage(18.0)
    twin.block_flange()
    twin.run_cycles(100, sreh_twin.pd_out(-90, parameter_set=2, motor_on=True, move=True))
    twin.power_cycle()
    twin.run_cycles(10)

    twin.restore(snap)
    assert twin.cycles == 55 and twin.time_s == snap.time_s
    assert len(twin.trace()["t_s"]) == 55  # the kept trace is cut back (A-TWIN-36)
    twin.run_cycles(CONTINUE)
    second = tail(twin, CONTINUE)
    assert_bit_identical(first, second)
    assert twin.moves() == first_moves
    assert np.all(np.diff(twin.trace()["t_s"]) > 0)  # one run, no seam
    # The move really continued from mid-move: it ended at the target.
    assert first_moves[-1]["completed"]


def test_restore_into_another_twin_made_the_same_way():
    a = mid_move_twin()
    snap = a.snapshot()
    a.run_cycles(CONTINUE)
    b = sreh_twin.Twin(load_gcm2=4000)
    b.restore(snap)
    b.run_cycles(CONTINUE)
    assert_bit_identical(tail(a, CONTINUE), tail(b, CONTINUE))


def test_snapshot_of_another_world_is_refused_and_nothing_changes():
    snap = mid_move_twin().snapshot()
    other = sreh_twin.Twin(load_gcm2=4000, hard_stops_deg=[100.0])
    other.run_cycles(3)
    with pytest.raises(sreh_twin.InputError, match="hard_stops"):
        other.restore(snap)
    assert other.cycles == 3
    with pytest.raises(TypeError):
        other.restore("not a snapshot")
