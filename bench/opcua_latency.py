#!/usr/bin/python3
"""Issue 38's measurement (docs/performance-serve.md, "OPC UA front"):
`serve --ports 1` with the port kept moving 0 <-> 90 deg by a Modbus PLC
thread (manual 3.2 handshake, polling every 4 ms) while a second Modbus
client measures FC 3 round trips; once with --opcua and an OPC UA client
subscribed to ProcessDataInput (sampling 10 ms), once without. Prints the
ProcessDataInput latency, Modbus round trips and the master cycle jitter of
both runs. $SERVE_ARGS adds options to both serve runs (e.g. "--rt-priority 20").
Usage: bench/opcua_latency.py BUILD/sreh-twin [SECONDS=60] [PUBLISHING_MS=5]"""
import json
import os
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "serve"))
from harness import Serve, pd_out_registers  # noqa: E402

exe = sys.argv[1]
seconds = float(sys.argv[2]) if len(sys.argv) > 2 else 60
publishing_ms = sys.argv[3] if len(sys.argv) > 3 else "5"
here = os.path.dirname(os.path.abspath(__file__))
opcua_dir = os.path.join(here, "..", "serve", "opcua")
node = os.environ.get("SREH_TWIN_NODE", "node")


def quantiles(xs):
    xs = sorted(xs)
    q = lambda f: xs[min(len(xs) - 1, max(0, int(f * len(xs) + 0.5) - 1))] if xs else float("nan")
    return {"n": len(xs), "p50_us": q(0.5), "p99_us": q(0.99), "max_us": xs[-1] if xs else float("nan")}


def run(with_opcua):
    args = ["--ports", "1"] + os.environ.get("SERVE_ARGS", "").split() + (["--opcua", "127.0.0.1:0"] if with_opcua else [])
    s = Serve(exe, *args)
    stop = threading.Event()
    plc, probe = s.pymodbus(), s.pymodbus()

    def mover():  # manual 3.2: Move held until Done, released until Ready
        plc.write_registers(1010, pd_out_registers(motor_on=1), slave=1)
        # Ready before the first Move (manual 3.2 T1): a Move in MotorOff is
        # an error (114.6.4) and the port would never move at all.
        while not stop.is_set() and not plc.read_holding_registers(1001, 4, slave=1).registers[3] >> 8 & 2:
            time.sleep(0.004)
        target = 0
        while not stop.is_set():
            target = 16384 if target == 0 else 0
            plc.write_registers(1010, pd_out_registers(target, 1, motor_on=1, move=1), slave=1)
            while not stop.is_set() and not plc.read_holding_registers(1001, 4, slave=1).registers[3] >> 8 & 8:
                time.sleep(0.004)
            plc.write_registers(1010, pd_out_registers(target, 1, motor_on=1), slave=1)
            while not stop.is_set() and not plc.read_holding_registers(1001, 4, slave=1).registers[3] >> 8 & 2:
                time.sleep(0.004)

    rtts = []

    def prober():
        while not stop.is_set():
            t0 = time.perf_counter()
            probe.read_holding_registers(1001, 4, slave=1)
            rtts.append((time.perf_counter() - t0) * 1e6)
            time.sleep(0.002)

    threads = [threading.Thread(target=mover), threading.Thread(target=prober)]
    for t in threads:
        t.start()
    latency = None
    try:
        if with_opcua:
            env = dict(os.environ, NODE_PATH=os.path.join(opcua_dir, "node_modules"))
            r = subprocess.run([node, os.path.join(here, "opcua_latency_client.js"), "opc.tcp://" + s.ready["opcua"],
                                "10", publishing_ms, str(seconds)], capture_output=True, text=True, env=env,
                               timeout=seconds + 120)
            if r.returncode != 0:
                raise SystemExit("latency client failed: " + r.stderr)
            latency = json.loads(r.stdout.strip().splitlines()[-1])
        else:
            time.sleep(seconds)
        stats = s.get("/v1/stats")
    finally:
        stop.set()
        for t in threads:
            t.join()
        s.stop(timeout=30)
        s.kill()
    return latency, quantiles(rtts), stats


load = os.getloadavg()[0]
for with_opcua in (True, False):
    latency, rtt, stats = run(with_opcua)
    print(json.dumps({"opcua": with_opcua, "seconds": seconds, "serve_args": os.environ.get("SERVE_ARGS", ""),
                      "nice": os.nice(0), "load_avg_1min_at_start": round(load, 1),
                      "pd_in_latency": latency, "modbus_rtt": rtt,
                      "jitter": {k: stats[k] for k in ("cycles", "late_cycles", "jitter_p50_us", "jitter_p99_us",
                                                       "jitter_max_us", "busy_fraction")}}), flush=True)
