"""Issue 40, point 1 ("durable or refused") and the stale temporaries of
point 10: with the state folder full, an ISDU write is not acknowledged
(HTTP 503 + IO-Link 0x8082, Modbus ISDU status 2 / 0x8082), the device
keeps its old value, the failure shows in the port summary, /v1/stats and
stderr, and SIGTERM exits 4; once there is room again an acknowledged
write survives SIGKILL, and temporaries of a killed run are removed at start.

The full disk is a 64 KiB tmpfs where the test may mount one (root), else
the test hook SREH_SERVE_TEST_FAIL_STATE_WRITES_WHILE (docs/serve.md)."""
import os
import signal
import subprocess
import sys
import tempfile

from harness import ModbusRaw, Serve, check, http_call, param, store_block, wait_until

exe = sys.argv[1]
top = tempfile.mkdtemp()
state = os.path.join(top, "state")
os.mkdir(state)
mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", state], capture_output=True).returncode == 0
flag = os.path.join(top, "disk-full")
if not mounted:
    os.environ["SREH_SERVE_TEST_FAIL_STATE_WRITES_WHILE"] = flag
filler = os.path.join(state, "filler")


def fill_disk():
    if not mounted:
        open(flag, "w").close()
        return
    with open(filler, "wb", buffering=0) as f:  # until ENOSPC
        try:
            while True:
                f.write(b"\0" * 4096)
        except OSError:
            pass


def free_disk():
    for f in (filler, flag):
        if os.path.exists(f):
            os.remove(f)


try:
    s = Serve(exe, "--ports", "1", "--state-dir", state)
    # Commissioned as IO-Link wants it (a block ending with ParamDownloadStore): 66.4 = 1111.
    check(store_block(s, [(66, 4, 1111)])[0] == 200, "commissioning refused")
    check(param(s, 66, 4) == 1111, "66.4 not written")

    fill_disk()
    code, body = http_call(s.ready["http"], "PUT", "/v1/ports/1/parameters/66/4", {"value": 2222})
    check(code == 503 and body.get("iolink_error") == "0x8082",
          "a write the full disk could not take was answered %d %s" % (code, body))
    check(param(s, 66, 4) == 1111, "the refused write changed the device (no roll back)")
    summary = http_call(s.ready["http"], "GET", "/v1/ports/1")[1]
    check(summary.get("state_write_error"), "the port summary does not show the failed write: %s" % summary)
    stats = http_call(s.ready["http"], "GET", "/v1/stats")[1]
    check(stats.get("state_write_failures", 0) >= 1 and "1" in stats.get("state_write_errors", {}),
          "/v1/stats does not show the failed write: %s" % stats)
    # Modbus: the same ISDU write through the register window is refused with the same code.
    m = ModbusRaw(s.modbus_port)
    check(m.write(1100, [2, 66, 4, 2, 2222]) == "ok", "modbus ISDU request not taken")
    status, error = m.read(1301, 2)
    check(status == 2 and error == 0x8082, "modbus ISDU write on a full disk: status %d error 0x%04X" % (status, error))
    check(param(s, 66, 4) == 1111, "the refused Modbus write changed the device")
    m.close()
    rc, err = s.stop()
    check(rc == 4 and "not saved" in err, "SIGTERM with a full state folder: exit %d\n%s" % (rc, err))
    print("full disk: refused with 0x8082 over HTTP and Modbus, rolled back, exit %d" % rc)

    # Room again; a temporary of a killed run is removed at start; acknowledged = kept through SIGKILL.
    free_disk()
    stale = os.path.join(state, ".port1.nvm.99999-3.tmp")
    open(stale, "w").write("half")
    s = Serve(exe, "--ports", "1", "--state-dir", state)
    check(not os.path.exists(stale), "a stale temporary survived the start")
    check(param(s, 66, 4) == 1111, "after the restart 66.4 = %s, expected 1111" % param(s, 66, 4))
    check(http_call(s.ready["http"], "GET", "/v1/ports/1")[1]["state_write_error"] is None, "a stale error shows")
    check(store_block(s, [(66, 4, 3333)])[0] == 200, "write refused with room on disk")
    s.proc.send_signal(signal.SIGKILL)  # right after the answer
    s.proc.communicate()
    s = Serve(exe, "--ports", "1", "--state-dir", state)
    check(param(s, 66, 4) == 3333, "an acknowledged write was lost to SIGKILL: 66.4 = %s" % param(s, 66, 4))
    rc, err = s.stop()
    check(rc == 0, "clean stop: exit %d %s" % (rc, err))
    print("room again: stale temporary removed, acknowledged write kept through SIGKILL (%s)" %
          ("tmpfs" if mounted else "injected ENOSPC"))
finally:
    free_disk()
    if mounted:
        subprocess.run(["umount", "-l", state], capture_output=True)
print("PASS")
