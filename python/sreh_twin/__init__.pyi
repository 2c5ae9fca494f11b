# Type stubs of sreh_twin (issue 19). The compiled parts live in _core.
import os
from typing import Any, Sequence, TypedDict

import numpy as np
import numpy.typing as npt

from . import env as env

_Bytes = bytes | bytearray | memoryview
_Path = str | os.PathLike[str]

STATES: tuple[str, ...]  # trace()["state"] indexes this: MotorOff, Ready, Busy, Done, ErrorOn, ErrorOff
LEDS: tuple[str, ...]    # trace()["led"] indexes this: off, green, yellow, blue, red, orange, white, violet
SIZE_OPTIONS: tuple[str, ...]
SWEEP_OPTIONS: tuple[str, ...]

class InputError(ValueError):
    """Bad input (a file, an option, a value); the CLI exits 2 for it."""

class IsduError(RuntimeError):
    """An ISDU request the device refused; code is the IO-Link error code, name its IO-Link name."""
    code: int
    name: str
    index: int
    subindex: int
    def __init__(self, code: int, index: int, subindex: int, message: str | None = ..., name: str | None = ...) -> None: ...

class State(TypedDict):
    time_s: float
    cycles: int
    position_deg: float
    setpoint_deg: float
    tracking_error_deg: float
    velocity_dps: float
    torque_Nm: float
    external_torque_Nm: float
    supply_V: float
    temperature_C: float
    state: str
    error_code: int
    warning_code: int
    led: str
    moving: bool
    settling: bool
    flange_blocked: bool

class PdIn(TypedDict):
    position_raw: int
    position_deg: float
    error_code: int
    warning_code: int
    error: bool
    warning: bool
    done: bool
    busy: bool
    ready: bool
    motor_off: bool

class PdOut(TypedDict):
    target_raw: int
    target_deg: float
    parameter_set: int
    shortest_path: bool
    relative: bool
    set_origin: bool
    reset_error: bool
    stop: bool
    move: bool
    motor_on: bool

class Move(TypedDict):
    start_s: float
    target_deg: float
    travel_s: float
    settling_s: float | None
    positioning_s: float | None
    max_tracking_error_deg: float
    overshoot_deg: float
    in_window_s: float | None
    completed: bool

IsduValue = int | str | bytes | list[int]

class TwinSnapshot:
    """A running Twin at one cycle (Twin.snapshot()); opaque, for Twin.restore()."""
    @property
    def cycles(self) -> int: ...
    @property
    def time_s(self) -> float: ...

class Twin:
    """One SREH-50-IOL on a simulated IO-Link master. Not thread-safe."""
    def __init__(self, *, load_gcm2: float | None = ..., load_file: _Path | None = ..., voltage_V: float = ...,
                 ambient_C: float = ..., master_cycle_ms: float = ..., configure_load: bool = ...,
                 record_trace: bool = ..., hard_stops_deg: Sequence[float] = ..., nvm: bytes | None = ...,
                 model: _Path | None = ..., mounting_tilt_deg: float | None = ...) -> None: ...
    def exchange(self, pd_out: _Bytes) -> bytes: ...
    def run_cycles(self, n: int, pd_out: _Bytes | None = ...) -> bytes: ...
    def set_pd_out(self, pd_out: _Bytes) -> None: ...
    @property
    def pd_out(self) -> bytes: ...
    @property
    def pd_in(self) -> bytes: ...
    def set_outputs_valid(self, valid: bool) -> None: ...
    def isdu_read(self, index: int, subindex: int = ..., *, raw: bool = ...) -> IsduValue: ...
    def isdu_write(self, index: int, subindex: int, value: IsduValue | bytearray) -> None: ...
    def system_command(self, code: int) -> None: ...
    def power_cycle(self) -> None: ...
    def firmware_update(self, image: _Bytes) -> None: ...
    def link_down(self, down: bool = ...) -> None: ...
    def set_voltage(self, voltage_V: float) -> None: ...
    def external_torque(self, torque_Nm: float) -> None: ...
    def block_flange(self, blocked: bool = ...) -> None: ...
    def set_ambient(self, ambient_C: float) -> None: ...
    def state(self) -> State: ...
    def trace(self) -> dict[str, npt.NDArray[Any]]: ...
    def trace_csv(self, path: _Path | None = ...) -> str: ...
    def moves(self) -> list[Move]: ...
    def render(self, width: int = 640, height: int = 480, *, overlay: bool = True) -> npt.NDArray[np.uint8]: ...
    def save_nvm(self) -> bytes: ...
    def snapshot(self) -> TwinSnapshot: ...
    def restore(self, snapshot: TwinSnapshot) -> None: ...
    @property
    def time_s(self) -> float: ...
    @property
    def cycles(self) -> int: ...
    @property
    def load_inertia_gcm2(self) -> float: ...

def pd_out(target_deg: float = ..., *, target_raw: int | None = ..., target_counts: int | None = ..., parameter_set: int = ...,
           shortest_path: bool = ..., relative: bool = ..., set_origin: bool = ..., reset_error: bool = ...,
           stop: bool = ..., move: bool = ..., motor_on: bool = ...) -> bytes: ...
def decode_pd_in(frame: _Bytes) -> PdIn: ...
def decode_pd_out(frame: _Bytes) -> PdOut: ...
def models_dir() -> str: ...

__version__: str
def model_card(model: _Path | None = ...) -> dict[str, Any]: ...
def run_scenario(scenario: _Path | str | dict[str, Any], *, video: _Path | None = None, report: _Path | None = None,
                 frames: _Path | None = None, size: str = "1280x720", fps: int = 30,
                 slowmo: float | None = None) -> dict[str, Any]: ...
def size(*, angle_deg: float | None = ..., load_gcm2: float | None = ..., load: _Path | None = ..., voltage_V: float = ...,
         dwell_s: float = ..., tolerance_deg: float = ..., wait_ms: float = ..., timeout_ms: float | None = ...,
         ambient_C: float = ..., speed_dps: float | None = ..., accel_pct: float | None = ...,
         jerk_pct: float | None = ..., parameter_set: int = ..., cycles: int = ...,
         thermal_margin_K: float = ..., max_positioning_ms: float | None = ...,
         max_cycle_ms: float | None = ..., source_resistance_ohm: float = ...,
         bus_capacitance_F: float = ..., handshake_cycles: int = ...,
         mounting_tilt_deg: float | None = ...,
         model: _Path | None = ...,
         report: _Path | None = ..., uncertainty: bool = ..., samples: int = ..., seed: int = ...,
         settling_spread_counts: int = ..., cycle: _Path | None = ...,
         emit_scenario: _Path | None = ..., csv: _Path | None = ...) -> dict[str, Any]: ...
def calibrate(logs: _Path | Sequence[_Path], *, load_gcm2: float | None = ..., load: _Path | None = ...,
              setup: _Path | None = ..., model: _Path | None = ..., fit: Sequence[str] = ...,
              out: _Path | None = ..., report: _Path | None = ..., threads: int | None = ...,
              max_iterations: int = ...) -> dict[str, Any]: ...
_Floats = float | Sequence[float] | npt.NDArray[np.floating[Any]]
def sweep(*, loads_gcm2: _Floats, angles_deg: _Floats, voltages_V: _Floats = ..., speeds_dps: _Floats = ...,
          accel_pct: float = ..., jerk_pct: float = ..., dwell_s: float = ..., tolerance_deg: float = ...,
          wait_ms: float = ..., timeout_ms: float | None = ..., ambient_C: float = ..., cycles: int = ...,
          threads: int = ..., csv: _Path | None = ..., report: _Path | None = ...,
          model: _Path | None = ..., shard: str | None = ..., targets_s: _Floats = ..., uncertainty: bool = ...,
          samples: int = ..., seed: int = ...) -> dict[str, npt.NDArray[Any]]: ...
