"""Issue 27 "Done when", HTTP: 100 event-stream clients opened and dropped,
and silent sockets, do not starve plain requests (a GET answers within 1 s);
the surplus streams get 503 at once; a wrong method is 405 with Allow; the
bearer scheme is case-insensitive; a world-writable token file is exit 2."""
import os
import socket
import subprocess
import sys
import tempfile
import time

from harness import Serve, check

exe = sys.argv[1]
tmp = tempfile.mkdtemp()
tok = os.path.join(tmp, "token")
with open(tok, "w") as f:
    f.write("s3cret\n")
os.chmod(tok, 0o600)
s = Serve(exe, "--ports", "1", "--token-file", tok)
HTTP = ("127.0.0.1", int(s.ready["http"].rsplit(":", 1)[1]))


def timed_get(path="/v1/ports/1"):
    t0 = time.monotonic()
    with socket.create_connection(HTTP, timeout=5) as c:
        c.sendall(("GET %s HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n" % path).encode())
        data = c.recv(4096)
    return time.monotonic() - t0, data


# ---- 100 event streams opened (and kept) ----
streams = []
answered_503 = 0
slowest_503 = 0.0
for i in range(100):
    c = socket.create_connection(HTTP, timeout=5)
    c.sendall(b"GET /v1/ports/1/events HTTP/1.1\r\nHost: x\r\nAccept: text/event-stream\r\n\r\n")
    streams.append((c, time.monotonic()))
for c, t0 in streams:
    head = c.recv(4096)
    if head.startswith(b"HTTP/1.1 503"):
        answered_503 += 1
        slowest_503 = max(slowest_503, time.monotonic() - t0)
    else:
        check(head.startswith(b"HTTP/1.1 200"), "event stream: %r" % head[:40])
dt, data = timed_get()
check(data.startswith(b"HTTP/1.1 200") and dt < 1.0, "GET next to 100 event streams: %.2f s %r" % (dt, data[:20]))
print("100 event streams: %d refused with 503 (slowest %.0f ms); a GET meanwhile %.0f ms" %
      (answered_503, slowest_503 * 1000, dt * 1000))
check(answered_503 >= 80 and slowest_503 < 5.0, "surplus streams not refused at once")
for c, _ in streams:
    c.close()
dt, data = timed_get()
check(data.startswith(b"HTTP/1.1 200") and dt < 1.0, "GET after dropping 100 streams: %.2f s" % dt)

# ---- 40 silent sockets ----
silent = [socket.create_connection(HTTP, timeout=5) for _ in range(40)]
time.sleep(0.2)
dt, data = timed_get()
check(data.startswith(b"HTTP/1.1 200") and dt < 1.0, "GET next to 40 silent sockets: %.2f s" % dt)
print("a GET next to 40 silent sockets: %.0f ms" % (dt * 1000))
for c in silent:  # the server closes them after its read timeout
    c.settimeout(5)
    check(c.recv(10) == b"", "a silent socket was not closed")
    c.close()

# ---- 405 for a wrong method, 404 for no such path ----
code, body = s.curl("DELETE", "/v1/ports/1")
check(code == 405 and "error" in body, "DELETE /v1/ports/1 -> %d %s" % (code, body))
out = subprocess.run(["curl", "-s", "-i", "-X", "POST", "-m", "10", "-H", "Content-Type: application/json",
                      "--data", "{}", s.http + "/v1/ports/1/processdata"],
                     capture_output=True, text=True, timeout=15).stdout
check(out.startswith("HTTP/1.1 405") and "Allow: GET" in out, "POST processdata: %s" % out[:200])
check(s.curl("GET", "/v1/nothing")[0] == 404, "unknown path: 404")

# ---- the live page shows the pacing figures of /v1/stats ----
code, js = s.curl("GET", "/assets/app.js")
check(code == 200 and "/v1/stats" in js and "late cycles" in js and "p99" in js, "live page without pacing figures")
stats = s.get("/v1/stats")
check(stats["jitter_max_us"] >= stats["jitter_p99_us"] >= stats["jitter_p50_us"] >= 0, "stats: %s" % stats)

# ---- bearer scheme case-insensitive ----
for scheme in ("Bearer", "bearer", "BEARER"):
    code, body = s.curl("PUT", "/v1/ports/1/processdata/out", {"motor_on": False},
                        headers=["Authorization: %s s3cret" % scheme])
    check(code == 200, "Authorization: %s -> %d %s" % (scheme, code, body))
check(s.curl("PUT", "/v1/ports/1/processdata/out", {"motor_on": False},
             headers=["Authorization: bearer S3CRET"])[0] == 403, "the token itself is case-sensitive")
rc, err = s.stop()
check(rc == 0, "exit %d: %s" % (rc, err))

# ---- a world-writable token file is refused ----
os.chmod(tok, 0o606)
p = subprocess.run([exe, "serve", "--modbus", "127.0.0.1:0", "--http", "127.0.0.1:0", "--token-file", tok],
                   capture_output=True, text=True, timeout=20)
check(p.returncode == 2 and tok in p.stderr and "writable" in p.stderr, "world-writable token: %d %s" % (p.returncode, p.stderr))
print("PASS")
