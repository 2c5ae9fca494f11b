#!/usr/bin/env python3
"""Sizing study: positioning time vs load for a few move angles (issue 19).

For every load and angle the fastest feasible parameter set is recommended
(PerfectCycle-style, as `sreh-twin sweep`), and its simulated positioning
time is plotted against the load. Needs matplotlib (Debian python3-matplotlib,
`SREH_WITH_EXAMPLES=1 ./setup.sh`).

  PYTHONPATH=build/python /usr/bin/python3 examples/python/sizing_study.py [--out positioning_vs_load.png]
"""
import argparse

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import sreh_twin  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default="positioning_vs_load.png")
    p.add_argument("--loads", default="0,1000,2500,5000,7500,10000,15000", help="g cm^2, comma separated")
    p.add_argument("--angles", default="45,90,180", help="deg, comma separated")
    a = p.parse_args()
    loads = [float(x) for x in a.loads.split(",")]
    angles = [float(x) for x in a.angles.split(",")]

    cols = sreh_twin.sweep(loads_gcm2=loads, angles_deg=angles)  # one column per CSV column, grid order
    fig, ax = plt.subplots(figsize=(7, 4.5))
    print(f"{'angle':>6} {'load g cm^2':>12} {'speed deg/s':>12} {'positioning s':>14} feasible")
    for angle in angles:
        at = cols["angle_deg"] == angle
        ok = at & cols["feasible"]
        ax.plot(cols["load_gcm2"][ok], 1e3 * cols["positioning_s"][ok], "o-", label=f"{angle:g} deg")
        for i in np.flatnonzero(at):
            print(f"{angle:6g} {cols['load_gcm2'][i]:12g} {cols['speed_dps'][i]:12g} "
                  f"{cols['positioning_s'][i]:14.4f} {bool(cols['feasible'][i])}")
    ax.set_xlabel("load inertia [g cm^2]")
    ax.set_ylabel("positioning time [ms]")
    ax.set_title("SREH-50-IOL: recommended set per point, 24 V")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(f"plot: {a.out}")


if __name__ == "__main__":
    main()
