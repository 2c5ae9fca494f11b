"""Issue 27 "Done when", Modbus: one client cannot stall the others. A
client sending 1 byte every 150 ms and 32 idle sockets: another client's 20
reads each answer within 100 ms and it connects within 2 s (the limit evicts
the longest-idle connection). Two clients hammering one port's ISDU channel
get zero crossed answers. A bad MBAP header gets no answer and the
connection closes; exceptions carry FC | 0x80; FC 23 works; the idle timeout
disconnects a silent client; with a token, ISDU reads work and writes need
--modbus-writers."""
import os
import socket
import struct
import sys
import tempfile
import threading
import time

from harness import Serve, check

exe = sys.argv[1]
s = Serve(exe, "--ports", "1", "--modbus-idle-timeout-s", "3")
MB = ("127.0.0.1", s.modbus_port)


def mbap(pdu, tid=1, protocol=0, length=None):
    return struct.pack(">HHHB", tid, protocol, len(pdu) + 1 if length is None else length, 1) + pdu


def recv_exact(c, n):
    data = b""
    while len(data) < n:
        chunk = c.recv(n - len(data))
        if not chunk:
            break
        data += chunk
    return data


def request(c, pdu, tid=1):
    c.sendall(mbap(pdu, tid))
    head = recv_exact(c, 7)
    check(len(head) == 7, "no answer to %r" % pdu)
    t, proto, length, unit = struct.unpack(">HHHB", head)
    check(t == tid and proto == 0, "answer header %r" % head)
    return recv_exact(c, length - 1)


def read_regs(c, addr, count, tid=1):
    a = request(c, struct.pack(">BHH", 3, addr, count), tid)
    check(a[0] == 3 and a[1] == 2 * count, "read %d: %r" % (addr, a))
    return list(struct.unpack(">%dH" % count, a[2:]))


def connect():
    c = socket.create_connection(MB, timeout=5)
    c.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    return c


def closed_without_answer(c, timeout=3):
    c.settimeout(timeout)
    try:
        return c.recv(100) == b""
    except ConnectionResetError:
        return True
    except socket.timeout:
        return False


# ---- a slow client and 32 idle sockets ----
stop = threading.Event()


def slow_client():
    frame = mbap(struct.pack(">BHH", 3, 1001, 4))
    while not stop.is_set():
        try:
            with connect() as c:
                for b in frame:
                    c.sendall(bytes([b]))
                    if stop.wait(0.15):
                        return
        except OSError:
            pass


t = threading.Thread(target=slow_client)
t.start()
idle = [connect() for _ in range(32)]
time.sleep(0.3)
t0 = time.monotonic()
c = connect()
worst = 0.0
for i in range(20):
    a = time.monotonic()
    read_regs(c, 1001, 4, tid=i)
    worst = max(worst, time.monotonic() - a)
check(time.monotonic() - t0 < 2.0, "connect + 20 reads took %.2f s" % (time.monotonic() - t0))
check(worst < 0.1, "a read took %.0f ms with a slow client and 32 idle sockets" % (worst * 1000))
print("slowest of 20 reads next to a slow client and 32 idle sockets: %.1f ms" % (worst * 1000))
stop.set()
t.join()
for x in idle:
    x.close()
c.close()

# ---- two clients hammering the ISDU channel: zero crossed answers ----
# A reads 64.1 (300), B the vendor name (16.0): each answer must be its own.
crossed = [0, 0]
done = [0, 0]
reference = [None, None]


def hammer(k, index, sub):
    with connect() as c:
        end = time.monotonic() + 5
        tid = 0
        while time.monotonic() < end:
            tid = (tid + 1) & 0xFFFF
            request(c, struct.pack(">BHHB4H", 16, 1100, 4, 8, 1, index, sub, 0), tid)
            regs = read_regs(c, 1300, 5, tid)[1:]  # status, error, length, first data word
            if reference[k] is None:
                reference[k] = regs
            if regs != reference[k] or read_regs(c, 1101, 1, tid)[0] != index:
                crossed[k] += 1
            done[k] += 1


threads = [threading.Thread(target=hammer, args=(0, 64, 1)), threading.Thread(target=hammer, args=(1, 16, 0))]
for x in threads:
    x.start()
for x in threads:
    x.join()
print("ISDU hammering: %d + %d requests, %d + %d crossed" % (done[0], done[1], crossed[0], crossed[1]))
check(reference[0] != reference[1] and reference[0][0] == 1 and reference[1][0] == 1,
      "the two answers must differ: %s" % reference)
check(done[0] > 50 and done[1] > 50, "too few requests: %s" % done)
check(crossed == [0, 0], "crossed answers: %s" % crossed)

# ---- FC 23: request and answer in one transaction ----
with connect() as c:
    a = request(c, struct.pack(">BHHHHB4H", 23, 1300, 5, 1100, 4, 8, 1, 64, 1, 0))
    regs = list(struct.unpack(">5H", a[2:]))
    check(a[0] == 23 and regs[1] == 1 and regs[3] == 2, "FC 23: %r" % regs)
    check(read_regs(c, 1304, 1)[0] == 300, "FC 23 answer data")
    # exceptions: FC | 0x80, also for function codes at or above 0x80
    for fc in (4, 0x2B, 0x80, 0xFF):
        a = request(c, bytes([fc, 0, 0]))
        check(a == bytes([fc | 0x80, 1]), "exception to FC 0x%02X: %r" % (fc, a))
    # registers inside the map but unlisted read 0; outside: exception 02
    check(read_regs(c, 3, 2) == [0, 0], "global block past 2 reads 0")
    check(request(c, struct.pack(">BHH", 3, 1995, 10)) == bytes([0x83, 2]), "outside the map: exception 02")

# ---- FC 23 from a real client (pymodbus), as docs/modbus-map.md shows it ----
pm = s.pymodbus()
r = pm.readwrite_registers(read_address=1300, read_count=5, write_address=1100, write_registers=[1, 64, 1, 0], slave=1)
check(not r.isError() and r.registers[1:] == [1, 0, 2, 300], "pymodbus FC 23: %s" % r)
pm.close()

# ---- bad MBAP: no answer, connection closed ----
for bad in (mbap(struct.pack(">BHH", 3, 1001, 4), protocol=1),        # protocol id
            mbap(struct.pack(">BHH", 3, 1001, 4), length=261) + b"\0" * 300,  # length over 254
            mbap(b"\x03", length=1),                                    # length under 2
            mbap(struct.pack(">BHHH", 3, 1001, 4, 0)),                  # PDU longer than FC 3's
            bytes(range(256)) * 40):                                    # 10 KB of garbage
    c = connect()
    c.sendall(bad)
    check(closed_without_answer(c), "bad frame %r... answered or left open" % bad[:12])
    c.close()
with connect() as c:
    check(read_regs(c, 1001, 4) is not None, "server still serves")

# ---- idle timeout (3 s here) ----
c = connect()
read_regs(c, 1001, 1)
t0 = time.monotonic()
check(closed_without_answer(c, timeout=6), "idle client not disconnected")
waited = time.monotonic() - t0
check(2.5 < waited < 4.5, "idle timeout after %.1f s, expected 3" % waited)
c.close()
rc, err = s.stop()
check(rc == 0, "exit %d: %s" % (rc, err))

# ---- with a token: ISDU reads work, writes only from --modbus-writers ----
tmp = tempfile.mkdtemp()
tok = os.path.join(tmp, "token")
with open(tok, "w") as f:
    f.write("s3cret\n")
os.chmod(tok, 0o600)
for writers, may_write in (((), False), (("--modbus-writers", "10.0.0.9,127.0.0.1"), True)):
    s = Serve(exe, "--ports", "1", "--token-file", tok, *writers)
    MB = ("127.0.0.1", s.modbus_port)
    with connect() as c:
        a = request(c, struct.pack(">BHHB4H", 16, 1100, 4, 8, 1, 64, 1, 0))
        check(a[0] == 16, "ISDU read request with a token: %r" % a)
        check(read_regs(c, 1301, 4) == [1, 0, 2, 300], "ISDU read with a token")
        a = request(c, struct.pack(">BHH", 6, 1012, 1))
        check((a[0] == 6) == may_write, "PD out write with writers %s: %r" % (writers, a))
        if not may_write:
            check(a == bytes([0x86, 1]), "refused write: exception 01, got %r" % a)
    s.stop()
os.chmod(tok, 0o622)
import subprocess  # noqa: E402
p = subprocess.run([exe, "serve", "--modbus", "127.0.0.1:0", "--http", "127.0.0.1:0", "--token-file", tok],
                   capture_output=True, text=True, timeout=20)
check(p.returncode == 2 and "writable" in p.stderr, "group-writable token file: exit %d %s" % (p.returncode, p.stderr))
print("PASS")
