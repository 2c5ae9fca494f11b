"""ISDU from Python (manual chapter 6): round trips with the parameter
table's types, refusals carrying the IO-Link code, the device unchanged."""
import pytest

import sreh_twin
from conftest import cli


def test_numeric_round_trip_and_factory_default():
    twin = sreh_twin.Twin()
    assert twin.isdu_read(65, 1) == 30000  # manual 6.2: 3000 deg/s factory default, raw 0.1 deg/s
    twin.isdu_write(65, 1, 12345)
    assert twin.isdu_read(65, 1) == 12345
    assert twin.isdu_read(65, 1, raw=True) == bytes([0x30, 0x39])  # uint16 big-endian


def test_whole_record_read_and_write():
    twin = sreh_twin.Twin()
    record = twin.isdu_read(66)  # parameter set 2 (manual 6.2): 8 members
    assert isinstance(record, list) and len(record) == 8
    changed = list(record)
    changed[0] = 20000
    twin.isdu_write(66, 0, changed)
    assert twin.isdu_read(66) == changed
    assert twin.isdu_read(66, 1) == 20000


def test_text_round_trip():
    twin = sreh_twin.Twin()
    assert twin.isdu_read(16) == "Afag"  # vendor name (manual 6.5)
    twin.isdu_write(24, 0, "station 7")  # application specific tag
    assert twin.isdu_read(24) == "station 7"


def test_load_given_to_twin_is_configured_in_every_set():
    twin = sreh_twin.Twin(load_gcm2=1234.4)
    assert [twin.isdu_read(i, 4) for i in range(64, 72)] == [1234] * 8
    assert twin.load_inertia_gcm2 == pytest.approx(1234.4, rel=1e-9)
    untouched = sreh_twin.Twin(load_gcm2=1234.4, configure_load=False)
    assert untouched.isdu_read(64, 4) != 1234


@pytest.mark.parametrize("index, subindex, value, code", [
    (112, 0, 50, 0x8023),      # temperature is read only
    (64, 1, 50000, 0x8030),    # above 4300 deg/s
    (64, 4, 15001, 0x8030),    # above 15000 g cm^2
    (82, 0, b"\x00\x01", 0x8033),  # two octets for a uint8
    (65, 1, b"\x01", 0x8034),  # one octet for a uint16
    (4711, 0, 1, 0x8011),      # index not available
])
def test_refused_writes_carry_the_code_and_change_nothing(index, subindex, value, code):
    twin = sreh_twin.Twin()
    before = twin.save_nvm()
    with pytest.raises(sreh_twin.IsduError) as refused:
        twin.isdu_write(index, subindex, value)
    assert refused.value.code == code
    assert (refused.value.index, refused.value.subindex) == (index, subindex)
    assert f"0x{code:04X}" in str(refused.value)
    assert twin.save_nvm() == before


def test_refused_reads():
    twin = sreh_twin.Twin()
    with pytest.raises(sreh_twin.IsduError) as e:
        twin.isdu_read(64, 9)
    assert e.value.code == 0x8012  # subindex not available
    with pytest.raises(sreh_twin.IsduError) as e:
        twin.isdu_read(2)
    assert e.value.code == 0x8023  # system command is write-only


def test_system_commands():
    twin = sreh_twin.Twin()
    with pytest.raises(sreh_twin.IsduError) as e:
        twin.system_command(99)
    assert e.value.code == 0x8035  # unknown command (manual 6.6)
    twin.isdu_write(65, 1, 12345)
    twin.system_command(129)  # application reset: configuration to factory settings
    assert twin.isdu_read(65, 1) == 30000


def test_configuration_survives_a_power_cycle_and_a_saved_image():
    twin = sreh_twin.Twin()
    twin.isdu_write(65, 1, 12345)
    twin.power_cycle()
    assert twin.isdu_read(65, 1) == 12345
    again = sreh_twin.Twin(nvm=twin.save_nvm())
    assert again.isdu_read(65, 1) == 12345


def test_bad_values_are_input_errors_not_device_answers():
    twin = sreh_twin.Twin()
    with pytest.raises(sreh_twin.InputError, match="out of range"):
        twin.isdu_write(65, 1, 1 << 20)  # does not fit the uint16 on the wire
    with pytest.raises(sreh_twin.InputError):
        twin.isdu_read(70000)
    with pytest.raises(TypeError):
        twin.isdu_write(65, 1, 1.5)
    assert issubclass(sreh_twin.InputError, ValueError)


def test_isdu_error_carries_the_io_link_name():
    """Issue 29: a refusal names its code the IO-Link way (iolink.md)."""
    twin = sreh_twin.Twin()
    with pytest.raises(sreh_twin.IsduError) as refused:
        twin.isdu_write(65, 1, 60000)  # above 43000 (4300 deg/s)
    assert refused.value.code == 0x8030
    assert refused.value.name == "Parameter value out of range"
    assert "0x8030 (Parameter value out of range)" in str(refused.value)
    # Issue 39: and what to do, from the one table of codes (docs/errors.md).
    assert "inside the range" in refused.value.remedy


def test_version_is_the_command_lines():
    assert cli("--version").stdout.split()[1] == sreh_twin.__version__
