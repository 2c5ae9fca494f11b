"""Issue 40, point 2: Data Storage at the master (iolink.md "Data Storage",
manual 8, A-SERVE-19), the same decision after SIGTERM and after SIGKILL
at any moment (docs/serve.md has the table):
  - no backup (new port, or the backup file deleted): upload;
  - the device asks for an upload (ParamDownloadStore): upload, before the
    answer to the store, so also when serve is killed right after it;
  - another module (replaced, also with the link down and serve stopped or
    killed right after; no memory file): the backup is downloaded into it;
  - the same module changed by the PLC's single writes: kept (acknowledged),
    not in the backup (a replacement does not get them).
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

# The PLC's single write is acknowledged, so it stays through SIGKILL; it is not in the
# backup (IO-Link: no upload request), so a module put in while serve is stopped
# (its memory file gone) gets the backup, not the single write.
code, j = http_call(s.ready["http"], "PUT", "/v1/ports/1/parameters/66/4", {"value": 2600})
check(code == 200 and param(s, 66, 4) == 2600, "single write: %d %s" % (code, j))
backup_checksum = ds(s)["checksum"]
kill(s)
s = Serve(exe, *args)
check(param(s, 66, 4) == 2600, "an acknowledged single write was lost to a restart: 66.4 = %s" % param(s, 66, 4))
check(ds(s)["checksum"] == backup_checksum and not in_step(s), "a single write went into the backup: %s" % ds(s))
s.stop()
os.remove(os.path.join(state, "port1.nvm"))
s = Serve(exe, *args)
check(param(s, 66, 4) == 2500 and in_step(s), "a new module while stopped: 66.4 = %s (backup 2500)" % param(s, 66, 4))

# Cleared backup: the device's set becomes the backup.
code, j = http_call(s.ready["http"], "PUT", "/v1/ports/1/parameters/66/4", {"value": 2700})
s.stop()
os.remove(os.path.join(state, "port1.ds.json"))
s = Serve(exe, *args)
check(param(s, 66, 4) == 2700 and ds(s)["backup"] and in_step(s), "cleared backup: %s" % ds(s))
rc, err = s.stop()
check(rc == 0, "exit %d %s" % (rc, err))
print("PASS")
