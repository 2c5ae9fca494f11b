"""Issue 27, manual 8 "Device exchange": the master keeps each port's Data
Storage backup (in --state-dir), uploads when the device asks (after
ParamDownloadStore), and restores it into a replacement module (fault
`replace_device`): the PLC program runs on without re-parameterising. A
single ISDU write (not stored) is not in the backup, as IO-Link says."""
import json
import os
import sys
import tempfile
import time

from harness import Serve, check, wait_until

exe = sys.argv[1]
state = tempfile.mkdtemp()
args = ("--ports", "1", "--state-dir", state)


def param(s, index, sub):
    return s.get("/v1/ports/1/parameters/%d/%d" % (index, sub))["value"]


def write(s, index, sub, value):
    code, body = s.curl("PUT", "/v1/ports/1/parameters/%d/%d" % (index, sub), {"value": value})
    check(code == 200, "PUT %d.%d = %s -> %d %s" % (index, sub, value, code, body))


def faults(s):
    return s.get("/v1/ports/1/faults")


s = Serve(exe, *args)
ds0 = faults(s)["data_storage"]
check(ds0["backup"], "no first upload at start: %s" % ds0)
# Block parameterisation ending in ParamDownloadStore (iolink.md: system commands 3 .. 5).
write(s, 2, 0, 3)
write(s, 66, 4, 6000)
write(s, 86, 0, 1000)
write(s, 2, 0, 5)
wait_until(lambda: faults(s)["data_storage"]["checksum"] != ds0["checksum"], "the master's upload after the store")
write(s, 65, 4, 4000)  # a single write: not in the backup
pos = s.get("/v1/ports/1/processdata")["in"]["position_deg"]

code, body = s.curl("POST", "/v1/ports/1/faults", {"replace_device": True})
check(code == 200 and body["device_replacements"] == 1, "replace_device: %d %s" % (code, body))
wait_until(lambda: param(s, 66, 4) == 6000, "66.4 restored into the new module")
check(param(s, 86, 0) == 1000, "zero offset restored: %s" % param(s, 86, 0))
check(param(s, 65, 4) == 0, "a value never stored came back: 65.4 = %s" % param(s, 65, 4))
check(faults(s)["data_storage_error"] is None, "download refused: %s" % faults(s))
wait_until(lambda: s.get("/v1/ports/1/processdata")["in"]["valid"], "the new module communicates")
now = s.get("/v1/ports/1/processdata")["in"]["position_deg"]
check(abs(now - pos) < 0.1, "position after replacement %.3f, before %.3f (same flange, same zero)" % (now, pos))
rc, err = s.stop()
check(rc == 0, "exit %d %s" % (rc, err))
backup = json.load(open(os.path.join(state, "port1.ds.json")))
# records are backed up whole (subindex 0): 66.4 is octets 6..7 of record 66
check(any(v["index"] == 66 and v["subindex"] == 0 and v["raw"][12:16] == "1770" for v in backup["values"]),
      "port1.ds.json lacks 66.4 = 6000")

# The backup outlives a restart: a replacement after it is restored too.
s = Serve(exe, *args)
check(param(s, 66, 4) == 6000, "66.4 after restart")
s.curl("POST", "/v1/ports/1/faults", {"replace_device": True})
time.sleep(0.1)
wait_until(lambda: param(s, 66, 4) == 6000 and param(s, 86, 0) == 1000, "restored after a restart")
rc, err = s.stop()
check(rc == 0, "exit %d %s" % (rc, err))
print("PASS")
