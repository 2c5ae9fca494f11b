"""sreh_twin.env.PositioningEnv: Gymnasium-shaped, deterministic under a seed."""
import numpy as np
import pytest

import sreh_twin
from sreh_twin.env import OBSERVATION_NAMES, PositioningEnv


def rollout(seed, steps=60):
    env = PositioningEnv(twin_options={"load_gcm2": 1000})
    obs, info = env.reset(seed=seed)
    env.action_space.seed(seed)
    out = [obs]
    rewards = []
    for i in range(steps):
        action = env.action_space.sample() if i % 20 == 0 else np.array([info["goal_deg"], 1.0, 1.0])
        obs, reward, terminated, truncated, info = env.step(action)
        out.append(obs)
        rewards.append(reward)
        if terminated or truncated:
            break
    return np.array(out), np.array(rewards), info


def test_spaces():
    env = PositioningEnv()
    assert env.action_space.shape == (3,) and env.action_space.dtype == np.float64
    assert env.observation_space.shape == (len(OBSERVATION_NAMES),)
    a = env.action_space.sample()
    assert a.shape == (3,) and a.dtype == np.float64
    assert np.all(a >= env.action_space.low) and np.all(a <= env.action_space.high)
    obs, info = env.reset(seed=1)
    assert obs.shape == env.observation_space.shape and obs.dtype == np.float64
    assert obs[OBSERVATION_NAMES.index("ready")] == 1.0 and info["state"] == "Ready"
    assert env.observation_space.low[1] <= obs[1] <= env.observation_space.high[1]


def test_same_seed_same_episode():
    obs_a, rew_a, _ = rollout(7)
    obs_b, rew_b, _ = rollout(7)
    assert np.array_equal(obs_a, obs_b) and np.array_equal(rew_a, rew_b)
    obs_c, _, _ = rollout(8)
    assert obs_c[0][1] != obs_a[0][1]  # another goal


def test_reaching_the_goal_terminates_with_success():
    env = PositioningEnv()
    obs, info = env.reset(options={"goal_deg": 60.0})
    total = 0.0
    for _ in range(100):
        obs, reward, terminated, truncated, info = env.step(np.array([60.0, 1.0, 1.0]))
        total += reward
        if terminated or truncated:
            break
    assert terminated and info["success"] and not truncated
    assert obs[OBSERVATION_NAMES.index("position_deg")] == pytest.approx(60.0, abs=0.5)
    assert 0.5 < total < 1.0  # +1 for success minus the time it took


def test_an_error_terminates_with_a_penalty():
    env = PositioningEnv()
    env.reset(options={"goal_deg": 90.0})
    env.twin.block_flange()
    for _ in range(200):
        obs, reward, terminated, truncated, info = env.step(np.array([90.0, 1.0, 1.0]))
        if terminated or truncated:
            break
    assert terminated and not info["success"] and reward < -1.0
    assert obs[OBSERVATION_NAMES.index("error_code")] == 8  # tracking error (manual 7.2 114.5)


def test_truncation_and_bad_actions():
    env = PositioningEnv(max_episode_s=0.05)
    env.reset(seed=0)
    truncated = False
    for _ in range(10):
        _, _, terminated, truncated, _ = env.step(np.zeros(3))
        if truncated:
            break
    assert truncated
    with pytest.raises(ValueError, match="shape"):
        env.step(np.zeros(2))
    with pytest.raises(RuntimeError):
        PositioningEnv().step(np.zeros(3))


def test_env_is_available_after_import():
    assert sreh_twin.env.PositioningEnv is PositioningEnv
