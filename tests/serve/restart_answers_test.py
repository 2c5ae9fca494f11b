"""Issue 40, points 6, 7, 9 and 10 (wrong answers after a restart, strict requests):
 7. after a restart the process data says valid only once the module has
    started up and read its multiturn encoder (manual 4.1): never a valid
    frame with the position of before the power-on (checked at --speed 0.01,
    where start-up takes 0.6 s of wall time);
 9. event ids carry the run: a client resuming with an id of another run
    gets the hello and every new event (the live page no longer freezes);
 6. one client watches 16 ports with one stream (GET /v1/events), a second
    viewer gets its own;
10. Modbus FC 23 checks both parts before doing either; FC 6 to +102/+103
    answers exception 03 as docs/modbus-map.md promises; /v1/ports/01 is no port."""
import json
import os
import socket
import sys
import tempfile
import time

from harness import ModbusRaw, Serve, check, http_call

exe = sys.argv[1]


def sse(http, path, last_id=None, want=lambda events: False, timeout=3.0):
    """Reads an event stream until want(events) or timeout; returns [(event, id, data)]."""
    host, port = http.rsplit(":", 1)
    c = socket.create_connection((host, int(port)), timeout=timeout)
    head = "GET %s HTTP/1.1\r\nHost: x\r\nAccept: text/event-stream\r\n" % path
    if last_id:
        head += "Last-Event-ID: %s\r\n" % last_id
    c.sendall((head + "\r\n").encode())
    buf, events, end = b"", [], time.monotonic() + timeout
    while time.monotonic() < end and not want(events):
        c.settimeout(max(0.01, end - time.monotonic()))
        try:
            chunk = c.recv(65536)
        except socket.timeout:
            break
        if not chunk:
            break
        buf += chunk
        while b"\n\n" in buf:
            block, buf = buf.split(b"\n\n", 1)
            ev, eid, data = None, None, None
            for line in block.decode(errors="replace").split("\n"):
                if line.startswith("event: "):
                    ev = line[7:]
                elif line.startswith("id: "):
                    eid = line[4:]
                elif line.startswith("data: "):
                    data = json.loads(line[6:])
            if ev:
                events.append((ev, eid, data))
    c.close()
    return events


# ---- 7: valid only with the restored position ----
state = tempfile.mkdtemp()
with open(os.path.join(state, "port1.flange.json"), "w") as f:
    json.dump({"flange_angle_deg": 450.0}, f)  # where the flange was when serve stopped
s = Serve(exe, "--ports", "1", "--state-dir", state, "--speed", "0.01")
m = ModbusRaw(s.modbus_port)
valid_reads, end = 0, time.monotonic() + 1.5
while time.monotonic() < end:
    status, hi, lo = m.read(1000, 3)
    pos_deg = ((hi << 16 | lo) - (1 << 32) if hi & 0x8000 else (hi << 16 | lo)) * 360.0 / 16384 / 4
    if status & 1:
        valid_reads += 1
        check(abs(pos_deg - 450.0) < 1.0, "process data valid with position %.1f deg (the flange is at 450)" % pos_deg)
    pd = http_call(s.ready["http"], "GET", "/v1/ports/1/processdata")[1]["in"]
    if pd["valid"]:
        check(abs(pd["position_deg"] - 450.0) < 1.0, "HTTP: valid with position %.1f deg" % pd["position_deg"])
check(valid_reads > 0, "the process data never became valid")
m.close()
s.stop()
print("restart: %d valid Modbus reads, every one at 450 deg" % valid_reads)

# ---- 9 and 6: run ids, one stream for 16 ports ----
s = Serve(exe, "--ports", "16")
first = sse(s.ready["http"], "/v1/ports/1/events", want=lambda e: any(x[1] for x in e))
old_id = next(x[1] for x in first if x[1])
run = old_id.rsplit("-", 1)[0]
s.stop()
s = Serve(exe, "--ports", "16")
again = sse(s.ready["http"], "/v1/ports/1/events", last_id=old_id, want=lambda e: any(x[1] for x in e))
check(again and again[0][0] == "hello", "a client of the last run gets no hello: %s" % again[:2])
new_ids = [x[1] for x in again if x[1]]
check(new_ids and not new_ids[0].startswith(run + "-"), "no new events after a restart (old id %s): %s" % (old_id, again[:3]))
# Resuming within the run: what came after the id, nothing twice.
seen = sse(s.ready["http"], "/v1/events?ports=1", want=lambda e: sum(1 for x in e if x[1]) >= 3)
ids = [x[1] for x in seen if x[1]]
resumed = sse(s.ready["http"], "/v1/events?ports=1", last_id=ids[0], want=lambda e: sum(1 for x in e if x[1]) >= 2)
rids = [x[1] for x in resumed if x[1]]
check(rids and rids[0] == ids[1], "resume after %s: first id %s, expected %s" % (ids[0], rids[:1], ids[1]))
# One stream for every port, a second viewer too: every event says its port.
views = [sse(s.ready["http"], "/v1/events", want=lambda e: {x[2]["port"] for x in e if x[0] == "sample"} >= set(range(1, 17)))
         for _ in range(2)]
for v in views:
    hellos = {x[2]["port"] for x in v if x[0] == "hello"}
    check(hellos == set(range(1, 17)), "hello for ports %s" % sorted(hellos))
    check(all("port" in x[2] for x in v), "an event without its port")
    check({x[2]["port"] for x in v if x[0] == "sample"} == set(range(1, 17)), "samples not from every port")
code, _ = http_call(s.ready["http"], "GET", "/v1/events?ports=17")
check(code == 404, "/v1/events?ports=17 -> %d" % code)
print("event ids carry the run; one stream shows 16 ports, two viewers at once")

# ---- 10: strict requests ----
m = ModbusRaw(s.modbus_port)
before = m.read(1010, 3)
r = m.read_write(99000 % 65536, 2, 1010, [0, 0, 1])  # read part outside the map, write part valid (Motor On)
check(r == ("exc", 2), "FC 23 with a read outside the map: %s" % (r,))
check(m.read(1010, 3) == before, "FC 23 refused but its write part was done: %s" % m.read(1010, 3))
check(m.write1(1102, 256) == ("exc", 3), "FC 6 +102 = 256 accepted")
check(m.write1(1103, 233) == ("exc", 3), "FC 6 +103 = 233 accepted")
check(m.write1(1102, 255) == "ok" and m.write1(1103, 232) == "ok", "FC 6 valid values refused")
m.close()
for path in ("/v1/ports/01", "/v1/ports/001/processdata", "/v1/ports/+1"):
    code, _ = http_call(s.ready["http"], "GET", path)
    check(code == 404, "GET %s -> %d" % (path, code))
rc, err = s.stop()
check(rc == 0, "exit %d %s" % (rc, err))
print("PASS")
