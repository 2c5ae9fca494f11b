"""A Gymnasium-shaped positioning environment over the twin (issue 19).

Works without Gymnasium; if it is installed, the environment is a
``gymnasium.Env`` with ``gymnasium.spaces.Box`` spaces and is registered as
``sreh_twin/Positioning-v0``.

Task: bring the flange to a goal angle fast, without an error. The agent
drives the module as a PLC would, through process data (manual 2.2):

* action (float64, shape (3,)): ``[target_deg, parameter_set, start]``.
  target_deg is the target position (rounded to the wire's 2^16 counts per
  revolution), parameter_set is rounded to 0..7, start >= 0.5 sets the Move
  bit. Motor on is held by the environment. The device's handshake applies
  (manual 3.2): a new Move needs the bit released first (Done -> Ready).
* observation (float64, shape (11,)): the decoded input process data
  (manual 2.3) plus time and goal: ``[time_s, goal_deg, position_deg,
  ready, busy, done, error, warning, motor_off, error_code, warning_code]``.
* reward per step of ``dt_s = cycles_per_step`` IO-Link cycles:
  ``-dt_s * (1 + |goal_deg - position_deg| / 180)`` (time costs, more so
  when far away), ``+1`` when the module reports Done within
  ``tolerance_deg`` of the goal (terminated, success), ``-1`` when it reports
  an error (terminated). Truncated after ``max_episode_s`` of simulated time.
* ``render()`` (render_mode "rgb_array", the default): the module as a
  video frame of ``sreh-twin run --video`` shows it, an RGB uint8 array of
  shape (height, width, 3) for ``render_size=(width, height)``.
"""
import numpy as np

from . import _core

try:  # optional: the real thing when installed
    import gymnasium as _gym
except ImportError:  # pragma: no cover - Gymnasium is not a dependency
    _gym = None

OBSERVATION_NAMES = ("time_s", "goal_deg", "position_deg", "ready", "busy", "done", "error", "warning",
                     "motor_off", "error_code", "warning_code")
ACTION_NAMES = ("target_deg", "parameter_set", "start")


class Box:
    """A box in R^n as gymnasium.spaces.Box: shape, dtype, low, high, sample()."""

    def __init__(self, low, high, dtype=np.float64, seed=None):
        self.dtype = np.dtype(dtype)
        self.low = np.asarray(low, dtype=self.dtype)
        self.high = np.asarray(high, dtype=self.dtype)
        self.shape = self.low.shape
        self._rng = np.random.default_rng(seed)

    def seed(self, seed=None):
        self._rng = np.random.default_rng(seed)
        return [seed]

    def sample(self):
        low = np.where(np.isfinite(self.low), self.low, -1e3)
        high = np.where(np.isfinite(self.high), self.high, 1e3)
        return self._rng.uniform(low, high).astype(self.dtype)

    def contains(self, x):
        x = np.asarray(x)
        return x.shape == self.shape and bool(np.all(x >= self.low) and np.all(x <= self.high))

    __contains__ = contains

    def __repr__(self):
        return f"Box({self.low}, {self.high}, {self.shape}, {self.dtype})"


def _box(low, high):
    if _gym is not None:
        return _gym.spaces.Box(np.asarray(low, np.float64), np.asarray(high, np.float64), dtype=np.float64)
    return Box(low, high)


_Base = _gym.Env if _gym is not None else object


class PositioningEnv(_Base):
    """Reach a goal angle fast without error; see the module docstring.

    goal_range_deg: goals are drawn uniformly from it at reset (or given as
    ``reset(options={"goal_deg": ...})``). tolerance_deg: how close Done must
    be. cycles_per_step: IO-Link cycles per step (2 ms each by default).
    twin_options: keywords for sreh_twin.Twin (load_gcm2, voltage_V, ...);
    the trace is off unless twin_options says record_trace=True.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 30}

    def __init__(self, goal_range_deg=(-180.0, 180.0), tolerance_deg=0.5, max_episode_s=2.0, cycles_per_step=5,
                 twin_options=None, render_mode="rgb_array", render_size=(640, 480)):
        if not goal_range_deg[0] <= goal_range_deg[1]:
            raise ValueError(f"goal_range_deg {goal_range_deg}: low must not exceed high")
        if cycles_per_step < 1:
            raise ValueError(f"cycles_per_step {cycles_per_step}: at least 1")
        self.goal_range_deg = (float(goal_range_deg[0]), float(goal_range_deg[1]))
        self.tolerance_deg = float(tolerance_deg)
        self.max_episode_s = float(max_episode_s)
        self.cycles_per_step = int(cycles_per_step)
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode {render_mode!r}: expected 'rgb_array' or None")
        self.render_mode = render_mode
        self.render_size = (int(render_size[0]), int(render_size[1]))
        self.twin_options = {"record_trace": False, **(twin_options or {})}
        self.action_space = _box([-360.0, 0.0, 0.0], [360.0, 7.0, 1.0])
        inf = np.inf
        self.observation_space = _box(
            [0.0, -360.0, -inf, 0, 0, 0, 0, 0, 0, 0, 0],
            [inf, 360.0, inf, 1, 1, 1, 1, 1, 1, 255, 255])
        self.twin = None
        self.goal_deg = 0.0
        self._rng = np.random.default_rng()
        self._pd_in = None

    def reset(self, seed=None, options=None):
        """A factory-new module with the motor on (Ready); returns (obs, info).

        seed reseeds the goal generator and action_space; options may give
        "goal_deg" and any sreh_twin.Twin keyword (e.g. "load_gcm2") for
        this episode."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
            self.action_space.seed(seed)
        options = dict(options or {})
        if "goal_deg" in options:
            self.goal_deg = float(options.pop("goal_deg"))
        else:
            self.goal_deg = float(self._rng.uniform(*self.goal_range_deg))
        self.twin = _core.Twin(**{**self.twin_options, **options})
        motor_on = _core.pd_out(0.0, parameter_set=1, motor_on=True)
        for _ in range(100):  # manual 3.2 T1: Ready within a few cycles
            self._pd_in = self.twin.exchange(motor_on)
            if _core.decode_pd_in(self._pd_in)["ready"]:
                break
        return self._observation(), self._info(False)

    def step(self, action):
        """One step of cycles_per_step IO-Link cycles with this action."""
        if self.twin is None:
            raise RuntimeError("PositioningEnv.step before reset")
        a = np.asarray(action, dtype=np.float64)
        if a.shape != self.action_space.shape:
            raise ValueError(f"action: expected shape {self.action_space.shape}, got {a.shape}")
        if not np.all(np.isfinite(a)):
            raise ValueError("action: values must be finite")
        a = np.clip(a, self.action_space.low, self.action_space.high)
        frame = _core.pd_out(float(a[0]), parameter_set=int(round(a[1])), move=bool(a[2] >= 0.5), motor_on=True)
        t0 = self.twin.time_s
        self._pd_in = self.twin.run_cycles(self.cycles_per_step, frame)
        dt = self.twin.time_s - t0
        pd = _core.decode_pd_in(self._pd_in)
        distance = abs(self.goal_deg - pd["position_deg"])
        success = bool(pd["done"] and distance <= self.tolerance_deg)
        reward = -dt * (1.0 + distance / 180.0)
        if success:
            reward += 1.0
        if pd["error"]:
            reward -= 1.0
        terminated = success or bool(pd["error"])
        truncated = not terminated and self.twin.time_s >= self.max_episode_s
        return self._observation(), float(reward), terminated, truncated, self._info(success)

    def render(self):
        """The module now, as a video frame shows it (the overlay with time,
        state, positions and codes): a numpy uint8 array (height, width, 3),
        RGB, of render_size (width, height). None with render_mode=None."""
        if self.render_mode is None:
            return None
        if self.twin is None:
            raise RuntimeError("PositioningEnv.render before reset")
        return self.twin.render(*self.render_size)

    def close(self):
        self.twin = None

    def _observation(self):
        pd = _core.decode_pd_in(self._pd_in)
        return np.array([self.twin.time_s, self.goal_deg, pd["position_deg"], pd["ready"], pd["busy"], pd["done"],
                         pd["error"], pd["warning"], pd["motor_off"], pd["error_code"], pd["warning_code"]],
                        dtype=np.float64)

    def _info(self, success):
        s = self.twin.state()
        return {"success": success, "goal_deg": self.goal_deg, "state": s["state"],
                "error_code": s["error_code"], "warning_code": s["warning_code"]}


if _gym is not None:  # pragma: no cover - only with Gymnasium installed
    try:
        _gym.register(id="sreh_twin/Positioning-v0", entry_point="sreh_twin.env:PositioningEnv")
    except Exception:  # already registered (module reloaded)
        pass
