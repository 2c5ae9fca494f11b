"""examples/plc_client.py (the virtual-commissioning demo linked from the
README) runs against `serve` and completes its moves (exit 0)."""
import subprocess
import sys

from harness import Serve, check

exe, example = sys.argv[1], sys.argv[2]
s = Serve(exe)
try:
    out = subprocess.run([sys.executable, example, "--modbus", "127.0.0.1:%d" % s.modbus_port, "--cycles", "1"],
                         capture_output=True, text=True, timeout=60)
    check(out.returncode == 0, "plc_client exit %d:\n%s\n%s" % (out.returncode, out.stdout, out.stderr))
    check(out.stdout.count("Done at") == 3 and "90.0 deg/s" not in out.stdout, out.stdout)
    check(s.get("/v1/ports/1/parameters/66/1")["value"] == 9000, "parameter set 2 not written")
    pd = s.get("/v1/ports/1/processdata")
    check(abs(pd["in"]["position_deg"]) < 0.1 and not pd["out"]["motor_on"], "final state: %s" % pd)
finally:
    rc, err = s.stop()
    s.kill()
check(rc == 0, "exit %d: %s" % (rc, err))
print("PASS")
