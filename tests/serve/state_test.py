"""Issue 27 "Done when": `serve --state-dir` keeps what a module keeps
through a power cycle (manual 4.1, 4.3, 6.2): set 2's load (66.4), a stored
origin (Set Origin + system command 171) and the flange's position come back
after SIGTERM and after SIGKILL 0.5 s after an answered write, with the same
command line. A corrupt file is exit 2 naming it and is left alone; a second
serve on the same state folder or on a used HTTP or Modbus port is exit 2."""
import os
import signal
import subprocess
import sys
import tempfile
import time

from harness import Serve, check, wait_until

exe = sys.argv[1]
tmp = tempfile.mkdtemp()
state = os.path.join(tmp, "state")
os.mkdir(state)
args = ("--ports", "1", "--state-dir", state)


def pd(s):
    return s.get("/v1/ports/1/processdata")


def put_pd(s, **fields):
    code, body = s.curl("PUT", "/v1/ports/1/processdata/out", fields)
    check(code == 200, "PUT processdata/out %s -> %d %s" % (fields, code, body))


def param(s, index, sub):
    return s.get("/v1/ports/1/parameters/%d/%d" % (index, sub))["value"]


def write_param(s, index, sub, value):
    code, body = s.curl("PUT", "/v1/ports/1/parameters/%d/%d" % (index, sub), {"value": value})
    check(code == 200, "PUT %d.%d = %s -> %d %s" % (index, sub, value, code, body))


def wait_state(s, name):
    wait_until(lambda: pd(s)["in"]["state"] == name, "state " + name)


# ---- first run: factory-new (no files yet), commission ----
s = Serve(exe, *args)
check(param(s, 66, 4) != 6000, "66.4 is not factory-new")
put_pd(s, motor_on=True)
wait_state(s, "Ready")
put_pd(s, motor_on=True, target_deg=300, parameter_set=1, move=True)
wait_state(s, "Done")
put_pd(s, motor_on=True, target_deg=300, parameter_set=1, move=False)
wait_state(s, "Ready")
put_pd(s, motor_on=True, set_origin=True)  # manual 4.3.2: here is 0 ...
wait_until(lambda: abs(pd(s)["in"]["position_deg"]) < 0.05, "Set Origin")
put_pd(s, motor_on=True, set_origin=False)
write_param(s, 2, 0, 171)                   # ... kept: Save position zero persistently (manual 6.6)
zero = param(s, 86, 0)
write_param(s, 66, 4, 6000)                 # set 2's load
put_pd(s, motor_on=False)
rc, err = s.stop()
check(rc == 0, "exit %d: %s" % (rc, err))
check(os.path.exists(os.path.join(state, "port1.nvm")), "no port1.nvm after stop")

# ---- second run, same command line: a power cycle ----
s = Serve(exe, *args)
check(param(s, 66, 4) == 6000, "66.4 lost across SIGTERM: %s" % param(s, 66, 4))
check(param(s, 86, 0) == zero, "stored origin lost: 86 = %s, was %s" % (param(s, 86, 0), zero))
wait_until(lambda: pd(s)["in"]["valid"], "PD in valid after start-up")
pos = pd(s)["in"]["position_deg"]
check(abs(pos) < 0.1, "flange not where it was: position %.3f deg, expected 0 (origin at the flange)" % pos)

# ---- SIGKILL 0.5 s after an answered write (HTTP and Modbus) ----
write_param(s, 66, 4, 7000)
mb = s.pymodbus()
r = mb.write_registers(1100, [2, 67, 4, 2, 5000], slave=1)  # ISDU write 67.4 = 5000 over Modbus
check(not r.isError() and mb.read_holding_registers(1301, 2, slave=1).registers == [1, 0], "Modbus ISDU write")
mb.close()
time.sleep(0.5)
s.proc.send_signal(signal.SIGKILL)
s.proc.communicate(timeout=10)

s = Serve(exe, *args)
check(param(s, 66, 4) == 7000, "66.4 lost across SIGKILL: %s" % param(s, 66, 4))
check(param(s, 67, 4) == 5000, "67.4 (written over Modbus) lost across SIGKILL: %s" % param(s, 67, 4))
check(param(s, 86, 0) == zero, "stored origin lost across SIGKILL")
wait_until(lambda: pd(s)["in"]["valid"], "PD in valid")
check(abs(pd(s)["in"]["position_deg"]) < 0.1, "flange moved across SIGKILL: %s" % pd(s)["in"]["position_deg"])

# ---- one serve per state folder; a used HTTP or Modbus port ----
def second(*extra):
    p = subprocess.run([exe, "serve", *extra], capture_output=True, text=True, timeout=20)
    return p.returncode, p.stderr

rc, err = second("--modbus", "127.0.0.1:0", "--http", "127.0.0.1:0", *args)
check(rc == 2 and "in use" in err, "second serve on one state folder: exit %d %s" % (rc, err))
rc, err = second("--modbus", "127.0.0.1:0", "--http", s.ready["http"], "--duration-s", "1")
check(rc == 2 and "address in use" in err, "second serve on a used HTTP port: exit %d %s" % (rc, err))
fresh = os.path.join(tmp, "fresh")
os.mkdir(fresh)
rc, err = second("--modbus", s.ready["modbus"], "--http", "127.0.0.1:0", "--duration-s", "1", "--state-dir", fresh)
check(rc == 2 and "address in use" in err, "second serve on a used Modbus port: exit %d %s" % (rc, err))
check(not [f for f in os.listdir(fresh) if not f.startswith(".")], "exit 2 wrote the state folder: %s" % os.listdir(fresh))
rc, err = s.stop()
check(rc == 0, "exit %d: %s" % (rc, err))

# ---- a corrupt image: exit 2 naming it, the file untouched ----
nvm = os.path.join(state, "port1.nvm")
with open(nvm, "r+b") as f:
    data = bytearray(f.read())
    data[len(data) // 2] ^= 0x55
    f.seek(0)
    f.write(data)
before = open(nvm, "rb").read()
rc, err = second("--modbus", "127.0.0.1:0", "--http", "127.0.0.1:0", *args)
check(rc == 2 and "port1.nvm" in err and err.count("\n") == 1, "corrupt image: exit %d %r" % (rc, err))
check(open(nvm, "rb").read() == before, "the corrupt image was overwritten")
print("PASS")
