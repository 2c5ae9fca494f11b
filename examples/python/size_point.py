#!/usr/bin/env python3
"""One sizing point as a CSV row: LOAD_GCM2 ANGLE_DEG -> load,angle,speed,positioning_s,feasible.

The unit of work of sweep_parallel.sh.
"""
import sys

import sreh_twin


def size_point(load_gcm2, angle_deg):
    r = sreh_twin.size(angle_deg=angle_deg, load_gcm2=load_gcm2)
    return (load_gcm2, angle_deg, r["recommended"]["speed_dps"], r["positioning_s"], r["feasible"])


def csv_row(point):
    load, angle, speed, positioning, feasible = point
    return f"{load:g},{angle:g},{speed:g},{positioning!r},{int(feasible)}"


if __name__ == "__main__":
    print(csv_row(size_point(float(sys.argv[1]), float(sys.argv[2]))))
