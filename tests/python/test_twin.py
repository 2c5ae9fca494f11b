"""Twin() arguments: loads, supply, clocks, bad input (issue 19)."""
import pytest

import sreh_twin
from conftest import SCENARIOS


def test_master_cycle_sets_the_io_link_clock():
    twin = sreh_twin.Twin(master_cycle_ms=4)
    twin.run_cycles(10)
    assert twin.cycles == 10 and twin.time_s == pytest.approx(0.04)
    assert list(twin.trace()["t_s"][:2]) == pytest.approx([0.004, 0.008])


def test_load_file_yaml_and_mjcf():
    disk = sreh_twin.Twin(load_file=SCENARIOS / "load_disk.yaml")
    assert disk.load_inertia_gcm2 == pytest.approx(5400, rel=1e-6)  # 0.3 kg disk, r 6 cm: m r^2 / 2
    assert disk.isdu_read(64, 4) == round(disk.load_inertia_gcm2)
    gripper = sreh_twin.Twin(load_file="models/loads/gripper.xml")  # found in the models folder
    assert gripper.load_inertia_gcm2 > 0


def test_supply_and_ambient_arguments():
    twin = sreh_twin.Twin(voltage_V=30.0, ambient_C=40.0)
    state = twin.state()
    assert state["supply_V"] == 30.0 and state["temperature_C"] == 40.0


def test_hard_stop_stops_the_load():
    twin = sreh_twin.Twin(load_gcm2=500, hard_stops_deg=[30.0])
    move = sreh_twin.pd_out(60, parameter_set=1, motor_on=True, move=True)
    twin.run_cycles(10, sreh_twin.pd_out(motor_on=True))
    twin.run_cycles(200, move)
    assert twin.state()["position_deg"] < 31.0


@pytest.mark.parametrize("kwargs, message", [
    (dict(load_gcm2=20000), "15000"),
    (dict(load_gcm2=10, load_file="x.yaml"), "not both"),
    (dict(load_file="does/not/exist.yaml"), "exist.yaml"),
    (dict(master_cycle_ms=2.05), "integer multiple"),
    (dict(master_cycle_ms=1), "2 .. 1000"),
    (dict(voltage_V=float("nan")), "finite"),
])
def test_bad_arguments(kwargs, message):
    with pytest.raises(sreh_twin.InputError, match=message):
        sreh_twin.Twin(**kwargs)


def test_only_keywords():
    with pytest.raises(TypeError):
        sreh_twin.Twin(2000)


def test_model_card_and_a_model_file(tmp_path):
    """Issue 25: model_card() is `model show --json`; Twin(model=...) takes a
    model file that overrides constants of the card (here the bearing
    friction: three times the card's holds the free flange against a torque
    that turns the card's module, manual 3.1). The card's breakaway is
    Coulomb + Stribeck excess (0.012 N m) with cogging up to 0.005 N m on
    top: 0.02 N m turns it; tripled Coulomb (0.024, outside the card's
    range, so the file gives a range) holds."""
    card = sreh_twin.model_card()["constants"]
    assert card["coulomb_friction"]["unit"] == "N m"
    lo, hi = card["coulomb_friction"]["range"]
    assert lo <= card["coulomb_friction"]["value"] <= hi
    stiff = tmp_path / "stiff_bearing.yaml"
    stiff.write_text("constants:\n  coulomb_friction: {value: 0.024, range: [0.005, 0.03]}\n")
    assert sreh_twin.model_card(stiff)["constants"]["coulomb_friction"]["value"] == 0.024
    turned = {}
    for name, model in (("card", None), ("stiff", stiff)):
        twin = sreh_twin.Twin(model=model)
        twin.external_torque(0.02)
        twin.run_cycles(50)
        turned[name] = abs(twin.state()["position_deg"])
    assert turned["card"] > 1.0 and turned["stiff"] < 0.01
    typo = tmp_path / "typo.yaml"
    typo.write_text("constants:\n  coulomb_frition: 0.012\n")
    with pytest.raises(sreh_twin.InputError, match="typo.yaml:2:3: unknown constant 'coulomb_frition'"):
        sreh_twin.Twin(model=typo)
