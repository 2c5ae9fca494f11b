#!/usr/bin/env python3
"""Parameter identification: estimate the load inertia from a trace (issue 19).

A module carries a load we pretend not to know (an MJCF gripper by
default). We move it back and forth through process data, as a PLC would,
record the trace and fit the flange dynamics

    torque = J_total * alpha + b * omega + c * sign(omega)

by least squares on the samples (alpha from the velocity by central
differences). J_load = J_total - J_intern (manual 3.5.6: 0.115 kg cm^2
= 1150 g cm^2 inside the module). The answer is compared with the inertia
MuJoCo computes for the mounted load, and written into the configured load
of set 1 (index 65.4, manual 6.2) as a commissioning tool would.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/identify_load.py [--load-file models/loads/gripper.xml]
"""
import argparse
import math

import numpy as np

import sreh_twin

J_INTERN_GCM2 = 1150.0


def excite(twin, angles_deg, frames_per_move=400):
    """Moves between the angles with the handshake (manual 3.2 T3, T5, T7)."""
    for target in angles_deg:
        move = sreh_twin.pd_out(target, parameter_set=1, motor_on=True, move=True)
        for _ in range(frames_per_move):
            if sreh_twin.decode_pd_in(twin.exchange(move))["done"]:
                break
        twin.run_cycles(5, sreh_twin.pd_out(target, parameter_set=1, motor_on=True))  # Move released: Ready


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--load-file", default="models/loads/gripper.xml")
    a = p.parse_args()

    # configure_load=False: the device is told nothing about the load (its
    # factory-configured load is used), as on a first commissioning.
    twin = sreh_twin.Twin(load_file=a.load_file, configure_load=False, master_cycle_ms=2)
    twin.run_cycles(10, sreh_twin.pd_out(motor_on=True))
    # A gentle identification set (manual 6.2, index 65): the device plans
    # its ramps for the configured load, which is still the factory value, so
    # full acceleration would overload the motor (tracking error 114.5).
    twin.isdu_write(65, 1, 15000)  # 1500 deg/s
    twin.isdu_write(65, 2, 150)    # 15 % acceleration
    excite(twin, [120, -60, 200, 0, 90, -90])
    if twin.state()["error_code"]:
        raise SystemExit(f"identification run failed: {twin.state()}")

    tr = twin.trace()
    dt = np.diff(tr["t_s"]).mean()
    omega = np.deg2rad(tr["velocity_dps"])  # process-data direction = clockwise (index 82 factory setting)
    alpha = np.gradient(omega, dt)
    tau = tr["torque_Nm"]
    moving = np.abs(omega) > 0.05
    A = np.column_stack([alpha, omega, np.sign(omega)])[moving]
    (j_total, b, c), *_ = np.linalg.lstsq(A, tau[moving], rcond=None)
    j_total_gcm2 = j_total * 1e7
    estimate = j_total_gcm2 - J_INTERN_GCM2
    truth = twin.load_inertia_gcm2
    fit = A @ np.array([j_total, b, c])
    r2 = 1 - np.sum((tau[moving] - fit) ** 2) / np.sum((tau[moving] - tau[moving].mean()) ** 2)
    print(f"samples: {moving.sum()} moving of {len(tau)} ({twin.time_s:.2f} s, {len(twin.moves())} moves)")
    print(f"fit: J_total {j_total_gcm2:.0f} g cm^2, viscous {b * 1e3:.3f} mN m s/rad, "
          f"Coulomb {c * 1e3:.2f} mN m, R^2 {r2:.4f}")
    print(f"load inertia estimate {estimate:.0f} g cm^2, MuJoCo's {truth:.0f} g cm^2 "
          f"({(estimate - truth) / truth * 100:+.1f} %)")
    twin.isdu_write(65, 4, int(round(max(0.0, estimate))))
    print(f"configured load of set 1 (index 65.4) now {twin.isdu_read(65, 4)} g cm^2")
    return 0 if math.isfinite(estimate) else 1


if __name__ == "__main__":
    raise SystemExit(main())
