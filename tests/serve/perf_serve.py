"""Issue 40 figures for docs/performance-serve.md (not a CTest: it measures,
it asserts nothing). Usage:
  /usr/bin/python3 tests/serve/perf_serve.py build/sreh-twin STATE_PARENT_DIR
1. state-write latency: 300 single ISDU writes (PUT 66.4, a new value each)
   answered only once fsync'd, against the same writes without --state-dir;
2. Modbus FC 3 round trips with 4 clients polling every 10 ms for 8 s, with
   normal scheduling and with --rt-priority 20."""
import os
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(__file__))
from harness import ModbusRaw, Serve, http_call  # noqa: E402

exe, parent = sys.argv[1], sys.argv[2]


def pct(v, q):
    v = sorted(v)
    return v[min(len(v) - 1, int(q * len(v)))] * 1000


def write_latency(*args):
    s = Serve(exe, "--ports", "1", *args)
    lat = []
    for i in range(300):
        t0 = time.monotonic()
        code, _ = http_call(s.ready["http"], "PUT", "/v1/ports/1/parameters/66/4", {"value": 1000 + i})
        lat.append(time.monotonic() - t0)
        assert code == 200
    s.stop()
    return lat


def modbus_4_clients(*args):
    s = Serve(exe, "--ports", "1", *args)
    lat, stop = [], threading.Event()

    def poll():
        m = ModbusRaw(s.modbus_port)
        while not stop.is_set():
            t0 = time.monotonic()
            m.read(1000, 5)
            lat.append(time.monotonic() - t0)
            time.sleep(max(0.0, 0.01 - (time.monotonic() - t0)))
        m.close()
    ts = [threading.Thread(target=poll) for _ in range(4)]
    for t in ts:
        t.start()
    time.sleep(8)
    stop.set()
    for t in ts:
        t.join()
    rt = http_call(s.ready["http"], "GET", "/v1/stats")[1]["realtime_scheduling"]
    s.stop()
    return lat, rt


print("load average %.1f" % os.getloadavg()[0])
state = tempfile.mkdtemp(dir=parent)
with_fsync = write_latency("--state-dir", state)
without = write_latency()
print("PUT 66.4 with --state-dir (fsync file + folder): p50 %.2f ms p99 %.2f ms max %.2f ms (n=%d)" %
      (pct(with_fsync, .5), pct(with_fsync, .99), max(with_fsync) * 1000, len(with_fsync)))
print("PUT 66.4 without --state-dir:                   p50 %.2f ms p99 %.2f ms max %.2f ms" %
      (pct(without, .5), pct(without, .99), max(without) * 1000))
for args in ((), ("--rt-priority", "20")):
    lat, rt = modbus_4_clients(*args)
    print("Modbus FC 3, 4 clients every 10 ms %s (SCHED_FIFO granted: %s): p50 %.3f ms p99 %.3f ms max %.2f ms (n=%d)" %
          (" ".join(args) or "normal scheduling", rt, pct(lat, .5), pct(lat, .99), max(lat) * 1000, len(lat)))
print("load average %.1f" % os.getloadavg()[0])
