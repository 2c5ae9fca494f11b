"""Issue 18: malformed Modbus frames and HTTP requests (a bounded, seeded
set, loopback only) get an error or a closed connection, never stop the
server and never touch the twin; afterwards it still serves both protocols."""
import json
import random
import socket
import struct
import sys
import time

from harness import Serve, check

exe = sys.argv[1]
rng = random.Random(18)  # deterministic
s = Serve(exe, "--ports", "1")
MB = ("127.0.0.1", s.modbus_port)
HTTP = ("127.0.0.1", int(s.ready["http"].rsplit(":", 1)[1]))
deadline = time.monotonic() + 40  # hard bound on the whole test


def exchange(addr, payload, read=True, timeout=5.0):
    """Sends raw bytes, returns whatever comes back before close/timeout."""
    with socket.create_connection(addr, timeout=timeout) as c:
        try:
            c.sendall(payload)
            if not read:
                return b""
            data = b""
            while len(data) < 1 << 20:
                chunk = c.recv(65536)
                if not chunk:
                    break
                data += chunk
                if addr == MB and len(data) >= 9:
                    break
        except (socket.timeout, ConnectionResetError, BrokenPipeError):
            return b""
        return data


def mbap(pdu, unit=1, tid=1, length=None):
    return struct.pack(">HHHB", tid, 0, len(pdu) + 1 if length is None else length, unit) + pdu


def modbus_serves():
    r = exchange(MB, mbap(struct.pack(">BHH", 3, 1001, 4)))
    return len(r) == 9 + 8 and r[7] == 3


def http_serves():
    r = exchange(HTTP, b"GET /v1/ports HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n")
    return r.startswith(b"HTTP/1.1 200")


# ---- Modbus: garbage, wrong lengths, unknown functions, read-only writes ----
frames = [
    b"", b"\x00", b"\xff" * 7, b"\xff" * 300, b"GET / HTTP/1.0\r\n\r\n",
    mbap(b"", length=0), mbap(b"\x03", length=200), mbap(b"\x03\x00"), mbap(struct.pack(">BHH", 3, 0, 0)),
    mbap(struct.pack(">BHH", 3, 0, 126)), mbap(struct.pack(">BHH", 3, 65500, 100)),
    mbap(struct.pack(">BHH", 3, 1990, 20), unit=0), mbap(struct.pack(">BHH", 3, 1001, 4), unit=255),
    mbap(struct.pack(">BHH", 6, 1001, 7)),              # write to PD in (read-only)
    mbap(struct.pack(">BHH", 6, 1013, 7)),              # PD out valid takes 0/1
    mbap(struct.pack(">BHH", 6, 1100, 9)),              # ISDU command takes 1/2
    mbap(struct.pack(">BHHB", 16, 1010, 3, 5) + b"\x00" * 5),  # byte count mismatch
    mbap(struct.pack(">BHHB", 16, 1010, 200, 255) + b"\x00" * 255),
    mbap(struct.pack(">BHHB", 16, 5010, 3, 6) + b"\x00" * 6),  # no port 5
    mbap(struct.pack(">BHH", 1, 0, 8)), mbap(struct.pack(">BHH", 4, 1001, 4)), mbap(struct.pack(">BHH", 5, 0, 0xFF00)),
    mbap(b"\x2b\x0e\x01\x00"), mbap(b"\x17" + b"\x00" * 9), mbap(b"\x80\x00"),
    mbap(struct.pack(">BHH", 3, 1001, 4), tid=0xFFFF)[:-2],  # truncated, then silence
]
for _ in range(120):  # random frames, some with a plausible header
    body = bytes(rng.randrange(256) for _ in range(rng.randrange(0, 40)))
    frames.append(mbap(body, unit=rng.randrange(256), length=rng.choice([None, rng.randrange(65536)]))
                  if rng.random() < 0.6 else body)
for i, f in enumerate(frames):
    check(time.monotonic() < deadline, "robustness test over its time bound")
    exchange(MB, f, timeout=0.1)
    if i % 25 == 0:
        check(modbus_serves(), "Modbus stopped serving after frame %d: %r" % (i, f[:20]))

# Exceptions, not silence, for well-formed but wrong requests.
r = exchange(MB, mbap(struct.pack(">BHH", 6, 1001, 7)))
check(len(r) >= 9 and r[7] == 0x86 and r[8] == 2, "write to read-only register: exception 02, got %r" % r)
r = exchange(MB, mbap(struct.pack(">BHH", 4, 1001, 4)))
check(len(r) >= 9 and r[7] == 0x84 and r[8] == 1, "unsupported function: exception 01, got %r" % r)

# ---- HTTP: malformed JSON, wrong lengths, unknown index, oversized bodies ----
def put(path, body):
    return s.curl("PUT", path, body)

cases = [
    (put, "/v1/ports/1/processdata/out", "{not json", 400),
    (put, "/v1/ports/1/processdata/out", "[1,2]", 400),
    (put, "/v1/ports/1/processdata/out", {"raw": "0011"}, 400),
    (put, "/v1/ports/1/processdata/out", {"raw": "00112233445566"}, 400),
    (put, "/v1/ports/1/processdata/out", {"raw": "zz0000000001"}, 400),
    (put, "/v1/ports/1/processdata/out", {"motor_on": "yes"}, 400),
    (put, "/v1/ports/1/processdata/out", {"motor_on": True, "bogus": 1}, 400),
    (put, "/v1/ports/1/processdata/out", {"target_deg": 1e300}, 400),
    (put, "/v1/ports/1/processdata/out", {"motor_on": True, "raw": "000000000001"}, 400),
    (put, "/v1/ports/9/processdata/out", {"motor_on": True}, 404),
    (put, "/v1/ports/1/parameters/64/1", {"value": "fast"}, 400),
    (put, "/v1/ports/1/parameters/64/1", {"value": 1 << 40}, 400),
    (put, "/v1/ports/1/parameters/64/1", {}, 400),
    (put, "/v1/ports/1/parameters/99999/1", {"value": 1}, 400),
    (put, "/v1/ports/1/parameters/64/1", {"raw": "0"}, 400),
    (lambda p, b: s.curl("POST", p, b), "/v1/ports/1/faults", {"supply_V": -5}, 400),
    (lambda p, b: s.curl("POST", p, b), "/v1/ports/1/faults", {"meteor": True}, 400),
    (lambda p, b: s.curl("POST", p, b), "/v1/ports/1/faults", "{}", 400),
    (lambda p, b: s.curl("GET", p), "/v1/ports/1/parameters/4242/0", None, 404),
    (lambda p, b: s.curl("GET", p), "/v1/ports/1/parameters/64/77", None, 404),
    (lambda p, b: s.curl("GET", p), "/v1/nothing", None, 404),
    (lambda p, b: s.curl("DELETE", p), "/v1/ports/1", None, 405),
    (put, "/v1/ports/1/processdata/out", json.dumps({"motor_on": True, "pad": "x" * 200000}), 413),
]
for fn, path, body, want in cases:
    code, payload = fn(path, body)
    check(code == want, "%s %r -> %d %s (want %d)" % (path, str(body)[:60], code, payload, want))
    check(isinstance(payload, dict) and ("error" in payload or "iolink_error" in payload),
          "%s: no JSON error body: %r" % (path, payload))

raw_http = [b"\x00\x01\x02garbage\r\n\r\n", b"GET " + b"/a" * 5000 + b" HTTP/1.1\r\n\r\n",
            b"GET / HTTP/1.1\r\n" + b"X: y\r\n" * 2000 + b"\r\n", b"PUT /v1/ports/1/processdata/out HTTP/1.1\r\n"
            b"Content-Length: 999999999\r\n\r\n{", b"POST /v1/ports/1/faults HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\nzz\r\n",
            b"GET /v1/ports HTTP/1.1\r\n"]  # never finished
for _ in range(40):
    raw_http.append(bytes(rng.randrange(256) for _ in range(rng.randrange(1, 200))) + b"\r\n\r\n")
for i, f in enumerate(raw_http):
    check(time.monotonic() < deadline, "robustness test over its time bound")
    exchange(HTTP, f, timeout=0.1)
    if i % 10 == 0:
        check(http_serves(), "HTTP stopped serving after request %d" % i)

# Nothing reached the twin: outputs as from start-up, parameters at their defaults.
check(modbus_serves() and http_serves(), "server no longer serves")
pd = s.get("/v1/ports/1/processdata")
check(pd["out"]["raw"] == "000000000000" and pd["out"]["valid"], "bad requests changed PD out: %s" % pd["out"])
check(s.get("/v1/ports/1/parameters/64/1")["value"] == 300, "bad requests changed 64.1")
check(s.get("/v1/ports/1/faults")["supply_V"] == 24, "bad requests changed the faults")
rc, err = s.stop()
check(rc == 0, "exit %d: %s" % (rc, err))
print("PASS")
