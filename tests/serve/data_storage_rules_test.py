"""Issue 40, point 2: Data Storage at the master as IO-Link specifies it
(iolink.md "Data Storage", manual 8), the same decision after SIGTERM and
after SIGKILL at any moment (docs/serve.md has the table):
  - no backup (new port, or the backup file deleted): upload;
  - the device asks for an upload (ParamDownloadStore): upload, also when
    serve was killed before its saver got to it;
  - the checksum differs without that request (a replaced module, a PLC's
    single writes): the backup is downloaded into the device.
Before: a replacement made while the link was down, then a restart, put the
factory-new module into the backup (66.4 = 2500 became 0)."""
import os
import signal
import sys
import tempfile
import time

from harness import Serve, check, http_call, param, store_block

exe = sys.argv[1]
state = tempfile.mkdtemp()
args = ("--ports", "1", "--state-dir", state)


def ds(s):
    return http_call(s.ready["http"], "GET", "/v1/ports/1/faults")[1]["data_storage"]


def in_step(s):
    """The backup matches the device (Parameter_Checksum, index 3.4)."""
    return ds(s)["checksum"] == param(s, 3, 4)


def kill(s):
    s.proc.send_signal(signal.SIGKILL)
    s.proc.communicate()


# New backup: a new port uploads at start.
s = Serve(exe, *args)
check(ds(s)["backup"] and in_step(s), "no first upload: %s" % ds(s))
# The device asks (ParamDownloadStore) and serve is killed at once: the request is in the
# module's memory, the restart serves it (upload), the device keeps its values.
check(store_block(s, [(66, 4, 2500)])[0] == 200, "store refused")
kill(s)
s = Serve(exe, *args)
check(param(s, 66, 4) == 2500 and in_step(s), "upload requested before a kill: 66.4 = %s, %s" % (param(s, 66, 4), ds(s)))

# A replacement while the link is down, then SIGTERM: the new module gets the backup at start-up.
for how in ("SIGTERM", "SIGKILL"):
    for body in ({"link_up": False}, {"replace_device": True}):
        code, j = http_call(s.ready["http"], "POST", "/v1/ports/1/faults", body)
        check(code == 200, "fault %s: %d %s" % (body, code, j))
    if how == "SIGTERM":
        s.stop()
    else:
        time.sleep(0.02)  # within 50 ms of the answer
        kill(s)
    s = Serve(exe, *args)
    check(param(s, 66, 4) == 2500, "replaced module after %s: 66.4 = %s, backup overwritten?" % (how, param(s, 66, 4)))
    check(in_step(s), "after %s: %s" % (how, ds(s)))
    print("replacement with the link down, then %s: backup downloaded (66.4 = 2500)" % how)

# The PLC's single write is not in the backup (IO-Link: no upload request): the next
# start-up downloads the backup over it, the same after SIGKILL.
code, j = http_call(s.ready["http"], "PUT", "/v1/ports/1/parameters/66/4", {"value": 2600})
check(code == 200 and param(s, 66, 4) == 2600, "single write: %d %s" % (code, j))
kill(s)
s = Serve(exe, *args)
check(param(s, 66, 4) == 2500 and in_step(s), "single write, restart: 66.4 = %s (backup 2500)" % param(s, 66, 4))

# Cleared backup: the device's set becomes the backup.
s.stop()
os.remove(os.path.join(state, "port1.ds.json"))
s = Serve(exe, *args)
check(param(s, 66, 4) == 2500 and ds(s)["backup"] and in_step(s), "cleared backup: %s" % ds(s))
rc, err = s.stop()
check(rc == 0, "exit %d %s" % (rc, err))
print("PASS")
