"""sreh_twin: the Afag SREH-50-IOL digital twin from Python (issue 19).

The device is reached as from a PLC: ``Twin.exchange()`` sends the 6-byte
output process data and returns the 7-byte input frame (manual 2.2, 2.3),
``Twin.isdu_read()`` / ``isdu_write()`` are its parameters (manual 6).
``run_scenario``, ``size`` and ``sweep`` are the CLI's ``run --json``,
``size --json`` and ``sweep`` on the same C++ code paths, writing the same
videos and reports (``run_scenario(..., video=, report=)``,
``size(..., report=)``); ``Twin.render()`` draws the module as an RGB array. ``sreh_twin.env``
holds a Gymnasium-shaped positioning environment.
"""
import json as _json
import os as _os
import re as _re
import warnings as _warnings

from . import _core

# An installed package carries its own copy of the models (cmake --install)
# and points the twin at it, unless the user chose a folder
# (twin/models_dir.hpp); in the build tree the usual search applies.
_models = _os.path.join(_os.path.dirname(__file__), "models")
if _os.path.isfile(_os.path.join(_models, "sreh50.xml")):
    _os.environ.setdefault("SREH_TWIN_MODELS_DIR", _models)

from ._core import (  # noqa: E402
    IsduError,
    InputError,
    Twin,
    TwinSnapshot,
    pd_out,
    STATES,
    LEDS,
    SIZE_OPTIONS,
    SWEEP_OPTIONS,
    models_dir,
    model_card,
    __version__,
)

__all__ = [
    "Twin", "TwinSnapshot", "IsduError", "InputError", "run_scenario", "size", "sweep", "calibrate", "pd_out", "decode_pd_in",
    "decode_pd_out", "PdFields", "STATES", "LEDS", "SIZE_OPTIONS", "SWEEP_OPTIONS", "models_dir", "model_card", "env",
]


class PdFields(dict):
    """A decoded process-data frame: the field names of the layout table,
    as scenarios and serve use them (``position_raw``, ``position_deg``,
    ``target_raw``, ``target_deg``, ...). The names before issue 30 still
    read, with a DeprecationWarning, for one release."""

    _OLD_NAMES = {"actual_position": "position_raw", "target_position": "target_raw"}

    def __missing__(self, key):
        new = self._OLD_NAMES.get(key)
        if new is None or new not in self:
            raise KeyError(key)
        _warnings.warn(f"process data field '{key}' is deprecated: use '{new}'", DeprecationWarning, stacklevel=2)
        return self[new]


def decode_pd_in(frame):
    """The fields of a 7-byte input frame (manual 2.3): position_raw
    (counts), position_deg, error_code, warning_code and the status bits."""
    return PdFields(_core.decode_pd_in(frame))


def decode_pd_out(frame):
    """The fields of a 6-byte output frame (manual 2.2): target_raw
    (counts), target_deg, parameter_set and the command bits."""
    return PdFields(_core.decode_pd_out(frame))


def _python_names(error):
    """The CLI's messages name options (--angle-deg); here they are keywords (angle_deg)."""
    text = _re.sub(r"--([A-Za-z][A-Za-z0-9-]*)", lambda m: m.group(1).replace("-", "_"), str(error))
    return InputError(text)


def run_scenario(scenario, *, video=None, report=None, frames=None, size="1280x720", fps=30, slowmo=None):
    """Run a scenario (scenarios/README.md) and return the dict of
    ``sreh-twin run --json``: name, passed, failures, stopped_early, moves,
    final, checks, sim_time_s, cycles and the run's extremes.

    ``scenario`` is a file path, the scenario's YAML text, or a dict of the
    same keys (e.g. ``{"name": "one move", "steps": [{"pd": {"motor_on": 1}},
    ...]}``); relative files in text or a dict resolve from the current
    directory. ``video`` (.mp4, .webm or .gif), ``frames`` (a folder of PNG
    frames with text.tsv) and ``report`` (an HTML report folder) write what
    ``run --video``, ``--frames`` and ``--report`` write; ``size``
    ("WIDTHxHEIGHT"), ``fps`` and ``slowmo`` (one factor for the whole
    video; default automatic) as the CLI's options. A failed check gives
    ``passed == False``; a bad scenario or option raises InputError."""
    text = None
    if isinstance(scenario, dict):
        text = _json.dumps(scenario)  # JSON is YAML
    elif isinstance(scenario, str) and not _os.path.exists(scenario) and ("\n" in scenario or ":" in scenario):
        text = scenario
    elif not isinstance(scenario, (str, _os.PathLike)):
        raise TypeError(f"run_scenario: expected a path, YAML text or a dict, got {type(scenario).__name__}")
    source = text if text is not None else _os.fspath(scenario)
    paths = {k: None if v is None else _os.fspath(v) for k, v in {"video": video, "frames": frames, "report": report}.items()}
    try:
        return _core.run_scenario(source, is_text=text is not None, base_dir=_os.getcwd(), size=size, fps=fps,
                                  slowmo=slowmo, **paths)
    except InputError as e:
        raise _python_names(e) from None


def size(**options):
    """PerfectCycle-style sizing, the dict of ``sreh-twin size --json``.

    Keywords are the CLI's long options with '-' as '_' (SIZE_OPTIONS):
    angle_deg (required unless cycle), load_gcm2 or load (a YAML load file),
    voltage_V, dwell_s, tolerance_deg, wait_ms, timeout_ms, ambient_C,
    speed_dps, accel_pct, jerk_pct (evaluate this set instead of
    recommending one), parameter_set, cycles, report (an HTML report
    folder), cycle (a multi-segment cycle file; it holds load, supply, ...),
    emit_scenario (write a scenario replaying the sized cycle),
    uncertainty=True (with samples, seed: the *_range bands over the model
    card's ranges and feasible_worst_case, issue 26).
    Bad values raise InputError naming the keyword."""
    try:
        return _core.size(**options)
    except InputError as e:
        raise _python_names(e) from None


def calibrate(logs, *, load_gcm2=None, load=None, setup=None, model=None, fit=(), out=None, report=None,
              threads=None, max_iterations=25):
    """Fit model-card constants to master logs (``sreh-twin calibrate --json``,
    docs/calibration.md): a dict with constants {NAME: {value, start, ci95,
    unit, identified}}, rms_residual_deg, iterations, converged, and
    model_yaml (the fitted model file, also written to ``out`` when given);
    ``report`` names a folder for the HTML report (``calibrate --report``).
    ``logs`` is one path or a list; ``fit`` a list of constant names. A bad
    log raises InputError naming file:line."""
    if isinstance(logs, (str, bytes)) or hasattr(logs, "__fspath__"):
        logs = [logs]
    try:
        return _core.calibrate([_os.fspath(p) for p in logs], load_gcm2=load_gcm2,
                               load=None if load is None else _os.fspath(load),
                               setup=None if setup is None else _os.fspath(setup),
                               model=None if model is None else _os.fspath(model), fit=list(fit),
                               out=None if out is None else _os.fspath(out),
                               report=None if report is None else _os.fspath(report), threads=threads,
                               max_iterations=max_iterations)
    except InputError as e:
        raise _python_names(e) from None


def sweep(**options):
    """Sizing over a grid (``sreh-twin sweep``): a dict of the CSV's columns
    as 1-D numpy arrays, one entry per grid point in grid order (loads
    outermost, then angles, voltages, speeds). Times of runs whose moves did
    not complete are NaN; mode and reason are str arrays.

    Keywords (SWEEP_OPTIONS): loads_gcm2, angles_deg (required), voltages_V,
    speeds_dps (lists or arrays), accel_pct, jerk_pct, dwell_s,
    tolerance_deg, wait_ms, timeout_ms, ambient_C, cycles, threads, and
    optionally csv / report / targets_s to also write the CLI's files."""
    try:
        return _core.sweep(**options)
    except InputError as e:
        raise _python_names(e) from None


from . import env  # noqa: E402  (sreh_twin.env is available after import sreh_twin)
