#!/usr/bin/python3
"""Virtual commissioning demo (issue 18): a small PLC program that drives the
SREH-50-IOL twin through `sreh-twin serve` over Modbus TCP, exactly as it
would drive the real module through an IO-Link master's Modbus map
(docs/modbus-map.md):

  1. parameterises motion parameter set 2 over the ISDU channel (manual 6.2),
  2. switches the motor on and waits for Ready (manual 3.2, T1),
  3. moves between positions by handshake: Move set -> Done (T5) -> Move
     released -> Ready (T7),
  4. reads status: position, device status (index 36), temperature (112).

Run (Debian's pymodbus, hence /usr/bin/python3, not a pyenv python3):
  ./build/sreh-twin serve --modbus 127.0.0.1:5020 --http 127.0.0.1:8080 &
  /usr/bin/python3 examples/plc_client.py --modbus 127.0.0.1:5020
and watch it on http://127.0.0.1:8080/ . Exit 0 when every move completed.
"""
import argparse
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
# Register offsets inside a port's block (port p at p * 1000), docs/modbus-map.md.
PD_IN, PD_OUT, STATE = 1, 10, 20
ISDU_CMD, ISDU_SEQ = 100, 300
DEVICE_STATUS = 500


class Module:
    """One SREH-50-IOL on master port `port`."""

    def __init__(self, client, port):
        self.c = client
        self.base = port * 1000
        self.target_raw = 0
        self.parameter_set = 0

    def read(self, offset, count):
        r = self.c.read_holding_registers(self.base + offset, count, slave=1)
        if r.isError():
            raise RuntimeError("Modbus read at %d: %s" % (self.base + offset, r))
        return r.registers

    def write(self, offset, values):
        r = self.c.write_registers(self.base + offset, values, slave=1)
        if r.isError():
            raise RuntimeError("Modbus write at %d: %s" % (self.base + offset, r))

    # ---- process data (manual 2.2, 2.3) ----
    def outputs(self, motor_on=1, move=0, stop=0, reset_error=0):
        t = self.target_raw & 0xFFFFFFFF
        bits = motor_on | (move << 1) | (stop << 2) | (reset_error << 3)
        self.write(PD_OUT, [t >> 16, t & 0xFFFF, (self.parameter_set << 8) | bits])

    def inputs(self):
        r = self.read(PD_IN, 4)
        octets = b"".join(x.to_bytes(2, "big") for x in r)[:7]
        pos = int.from_bytes(octets[0:4], "big", signed=True)
        status = octets[6]
        return {"position_deg": pos * 360.0 / 65536, "error_code": octets[4], "warning_code": octets[5],
                "error": bool(status & 0x20), "done": bool(status & 0x08), "busy": bool(status & 0x04),
                "ready": bool(status & 0x02), "motor_off": bool(status & 0x01)}

    def wait(self, what, pred, timeout_s=5.0):
        end = time.monotonic() + timeout_s
        while time.monotonic() < end:
            pd = self.inputs()
            if pd["error"]:
                raise RuntimeError("module reports an error (error code 0x%02X) while waiting for %s"
                                   % (pd["error_code"], what))
            if pred(pd):
                return pd
            time.sleep(0.004)  # a PLC task of a few ms
        raise RuntimeError("timeout waiting for " + what)

    # ---- acyclic parameters (ISDU channel) ----
    def isdu(self, command, index, subindex, data=b""):
        seq = self.read(ISDU_SEQ, 1)[0]
        words = [(data[i] << 8) | (data[i + 1] if i + 1 < len(data) else 0) for i in range(0, len(data), 2)]
        self.write(ISDU_CMD, [command, index, subindex, len(data)] + words)
        seq2, status, error, length = self.read(ISDU_SEQ, 4)
        if seq2 != (seq + 1) & 0xFFFF:
            raise RuntimeError("ISDU request not executed")
        if status != 1:
            raise RuntimeError("ISDU %d.%d refused: IO-Link error 0x%04X" % (index, subindex, error))
        regs = self.read(ISDU_SEQ + 4, (length + 1) // 2) if length else []
        return b"".join(x.to_bytes(2, "big") for x in regs)[:length]

    def set_u16(self, index, subindex, value):
        self.isdu(2, index, subindex, value.to_bytes(2, "big"))

    def get_uint(self, index, subindex=0):
        return int.from_bytes(self.isdu(1, index, subindex), "big")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--modbus", default="127.0.0.1:5020", help="HOST:PORT of sreh-twin serve's Modbus TCP")
    ap.add_argument("--port", type=int, default=1, help="IO-Link master port of the module")
    ap.add_argument("--positions", default="90,180,0", help="positions to visit, deg")
    ap.add_argument("--cycles", type=int, default=2, help="how often to visit them")
    ap.add_argument("--speed-dps", type=float, default=900.0, help="maximum speed of parameter set 2")
    a = ap.parse_args()
    host, port = a.modbus.rsplit(":", 1)
    client = ModbusTcpClient(host, port=int(port), timeout=3)
    if not client.connect():
        print("plc_client: cannot connect to %s" % a.modbus, file=sys.stderr)
        return 2
    m = Module(client, a.port)
    try:
        # 1. Parameter set 2 (index 66, manual 6.2): speed, 50 % acceleration, no load.
        m.set_u16(66, 1, int(round(a.speed_dps * 10)))
        m.set_u16(66, 2, 500)
        m.set_u16(66, 4, 0)
        print("parameter set 2: %.1f deg/s, acceleration %.1f %%" % (m.get_uint(66, 1) / 10, m.get_uint(66, 2) / 10))
        # 2. Motor on.
        m.parameter_set = 2
        m.outputs(motor_on=1)
        m.wait("Ready", lambda pd: pd["ready"])
        print("motor on: Ready")
        # 3. Moves by handshake.
        for cycle in range(a.cycles):
            for target in (float(x) for x in a.positions.split(",")):
                m.target_raw = int(round(target * 65536 / 360))
                t0 = time.monotonic()
                m.outputs(motor_on=1, move=1)
                pd = m.wait("Done at %g deg" % target, lambda pd: pd["done"])
                took = time.monotonic() - t0
                m.outputs(motor_on=1, move=0)
                m.wait("Ready", lambda pd: pd["ready"])
                print("cycle %d: Done at %8.3f deg (target %g) after %.3f s" % (cycle + 1, pd["position_deg"], target, took))
        # 4. Status.
        print("state %s, device status %d, temperature %.1f degC" % (
            STATES[m.read(STATE, 1)[0]], m.read(DEVICE_STATUS, 1)[0], m.get_uint(112) * 0.5))
        m.outputs(motor_on=0)
        return 0
    except RuntimeError as e:
        print("plc_client: %s" % e, file=sys.stderr)
        return 1
    finally:
        client.close()


if __name__ == "__main__":
    sys.exit(main())
