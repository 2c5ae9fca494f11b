"""Shared helpers of the serve tests (issue 18): start `sreh-twin serve` on
loopback ports the OS picks, talk to it with curl, mbpoll and pymodbus, stop it
with SIGTERM. Everything is bounded in time: a hung server fails the test."""
import atexit
import json
import os
import signal
import subprocess
import sys
import time
import types

# Debian's python3-pymodbus only recommends python3-serial(-asyncio), which its
# client package imports even for TCP: empty stand-ins when they are missing.
for _name in ("serial", "serial_asyncio"):
    try:
        __import__(_name)
    except ImportError:
        _stub = types.ModuleType(_name)
        _stub.create_serial_connection = None
        sys.modules[_name] = _stub
from pymodbus.client import ModbusTcpClient  # noqa: E402

STATES = ["MotorOff", "Ready", "Busy", "Done", "ErrorOn", "ErrorOff"]


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)


class Serve:
    """`sreh-twin serve` with --modbus/--http on port 0; `.http` and `.modbus_port` from its ready line."""

    def __init__(self, exe, *args):
        self.proc = subprocess.Popen([exe, "serve", "--modbus", "127.0.0.1:0", "--http", "127.0.0.1:0", *args],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        # A failed check exits the test (sys.exit): the server goes with it
        # instead of running on after CTest (a stray serve was found spinning).
        atexit.register(self.kill)
        line = self.proc.stdout.readline()
        if not line:
            fail("serve did not start: " + self.proc.stderr.read())
        self.ready = json.loads(line)
        self.http = "http://" + self.ready["http"]
        self.modbus_port = int(self.ready["modbus"].rsplit(":", 1)[1])

    def stop(self, timeout=15):
        """SIGTERM; returns (exit code, stderr)."""
        self.proc.send_signal(signal.SIGTERM)
        try:
            _, err = self.proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            stacks = ""
            if os.path.exists("/usr/bin/gdb"):  # where it hangs, for the log
                stacks = subprocess.run(["gdb", "-p", str(self.proc.pid), "-batch", "-ex", "thread apply all bt 12"],
                                        capture_output=True, text=True, timeout=60).stdout
            self.proc.kill()
            fail("serve did not stop within %d s of SIGTERM\n%s" % (timeout, stacks))
        return self.proc.returncode, err

    def kill(self):
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.communicate()

    # ---- HTTP through curl (a real client, as in the issue) ----
    def curl(self, method, path, body=None, headers=()):
        cmd = ["curl", "-s", "-m", "15", "-X", method, "-w", "\n%{http_code}", self.http + path]
        for h in headers:
            cmd += ["-H", h]
        data = None
        if body is not None:
            cmd += ["-H", "Content-Type: application/json", "--data-binary", "@-"]
            data = body if isinstance(body, str) else json.dumps(body)
        out = subprocess.run(cmd, input=data, capture_output=True, text=True, timeout=20).stdout
        text, _, code = out.rpartition("\n")
        try:
            payload = json.loads(text) if text else None
        except json.JSONDecodeError:
            payload = text
        return int(code or 0), payload

    def get(self, path):
        code, payload = self.curl("GET", path)
        check(code == 200, "GET %s -> %d %s" % (path, code, payload))
        return payload

    # ---- Modbus through mbpoll (0-based registers, any unit id) ----
    def mbpoll_read(self, reg, count, unit=1):
        out = subprocess.run(["mbpoll", "-m", "tcp", "-p", str(self.modbus_port), "-a", str(unit), "-0", "-1",
                              "-t", "4", "-r", str(reg), "-c", str(count), "-o", "10", "127.0.0.1"],
                             capture_output=True, text=True, timeout=15)
        check(out.returncode == 0, "mbpoll read %d: %s %s" % (reg, out.stdout, out.stderr))
        values = []
        for line in out.stdout.splitlines():
            if line.startswith("["):
                values.append(int(line.split(":")[1].split()[0]))
        check(len(values) == count, "mbpoll read %d: %s" % (reg, out.stdout))
        return values

    def mbpoll_write(self, reg, values, unit=1, expect_ok=True):
        out = subprocess.run(["mbpoll", "-m", "tcp", "-p", str(self.modbus_port), "-a", str(unit), "-0", "-1",
                              "-t", "4", "-r", str(reg), "-o", "10", "127.0.0.1", "--", *[str(v) for v in values]],
                             capture_output=True, text=True, timeout=15)
        if expect_ok:
            check(out.returncode == 0, "mbpoll write %d %s: %s %s" % (reg, values, out.stdout, out.stderr))
        return out.returncode

    def pymodbus(self):
        c = ModbusTcpClient("127.0.0.1", port=self.modbus_port, timeout=10)
        check(c.connect(), "pymodbus: cannot connect")
        return c


def wait_until(pred, what, timeout_s=15):
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        if pred():
            return
        time.sleep(0.02)
    fail("timed out waiting for " + what)


def pd_in_registers_to_hex(regs):
    """4 registers (big-endian) -> the 7 octets of process data in, as hex."""
    return "".join("%04X" % r for r in regs)[:14]


def pd_out_registers(target_raw=0, parameter_set=0, motor_on=0, move=0, stop=0, reset_error=0):
    """Manual 2.2: target int32 (bits 47..16), parameter set (15..8), control bits (7..0)."""
    t = target_raw & 0xFFFFFFFF
    bits = motor_on | (move << 1) | (stop << 2) | (reset_error << 3)
    return [t >> 16, t & 0xFFFF, (parameter_set << 8) | bits]


# ---- issue 40: fast clients for the fault tests ----
import http.client  # noqa: E402
import socket  # noqa: E402
import struct  # noqa: E402


def http_call(host_port, method, path, body=None, headers=None, timeout=5):
    """One request on a fresh connection (http.client); returns (status, parsed JSON or text)."""
    host, port = host_port.rsplit(":", 1)
    c = http.client.HTTPConnection(host, int(port), timeout=timeout)
    try:
        data = None if body is None else json.dumps(body)
        h = dict(headers or {})
        if data is not None:
            h["Content-Type"] = "application/json"
        c.request(method, path, body=data, headers=h)
        r = c.getresponse()
        text = r.read().decode()
        try:
            return r.status, json.loads(text)
        except json.JSONDecodeError:
            return r.status, text
    finally:
        c.close()


def param(s, index, sub):
    code, j = http_call(s.ready["http"], "GET", "/v1/ports/1/parameters/%d/%d" % (index, sub))
    check(code == 200, "GET parameter %d.%d -> %d %s" % (index, sub, code, j))
    return j["value"]


def store_block(s, writes, port=1):
    """A parameterisation as IO-Link wants it to survive a replacement: ParamDownloadStart (3), the
    writes, ParamDownloadStore (5). Returns the status of the last answer (200: acknowledged)."""
    base = "/v1/ports/%d/parameters/" % port
    for path, body in [("2/0", {"value": 3})] + [("%d/%d" % (i, sb), {"value": v}) for i, sb, v in writes] + \
            [("2/0", {"value": 5})]:
        code, j = http_call(s.ready["http"], "PUT", base + path, body)
        if code != 200:
            return code, j
    return 200, j


class ModbusRaw:
    """A bare Modbus TCP client (one socket, FC 3/6/16/23): exceptions come back as ("exc", code)."""

    def __init__(self, port, timeout=5):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=timeout)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.tid = 0

    def close(self):
        self.sock.close()

    def call(self, pdu):
        self.tid = (self.tid + 1) & 0xFFFF
        self.sock.sendall(struct.pack(">HHHB", self.tid, 0, len(pdu) + 1, 1) + pdu)
        head = self._recv(7)
        tid, _, length, _ = struct.unpack(">HHHB", head)
        body = self._recv(length - 1)
        check(tid == self.tid, "modbus: transaction %d answered as %d" % (self.tid, tid))
        if body[0] & 0x80:
            return ("exc", body[1])
        return body

    def _recv(self, n):
        out = b""
        while len(out) < n:
            chunk = self.sock.recv(n - len(out))
            if not chunk:
                raise ConnectionError("modbus: connection closed")
            out += chunk
        return out

    def read(self, reg, count):
        r = self.call(struct.pack(">BHH", 3, reg, count))
        return r if isinstance(r, tuple) else list(struct.unpack(">%dH" % count, r[2:]))

    def write1(self, reg, value):
        r = self.call(struct.pack(">BHH", 6, reg, value))
        return r if isinstance(r, tuple) else "ok"

    def write(self, reg, values):
        r = self.call(struct.pack(">BHHB", 16, reg, len(values), 2 * len(values)) + struct.pack(">%dH" % len(values), *values))
        return r if isinstance(r, tuple) else "ok"

    def read_write(self, read_reg, read_count, write_reg, values):
        r = self.call(struct.pack(">BHHHHB", 23, read_reg, read_count, write_reg, len(values), 2 * len(values)) +
                      struct.pack(">%dH" % len(values), *values))
        return r if isinstance(r, tuple) else list(struct.unpack(">%dH" % read_count, r[2:]))
