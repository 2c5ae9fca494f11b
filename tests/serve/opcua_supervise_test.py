"""Issue 38: serve starts, supervises and stops its OPC UA front. A used
address or a non-loopback address without --token-file: exit 2, one line,
nothing left running. A front killed while serve runs is reported and
restarted on the same port, and a client browses it again. SIGTERM stops the
front with serve; SIGKILL of serve takes the front with it (no orphan).
Usage: opcua_supervise_test.py SREH_TWIN CLIENT_JS OPCUA_DIR."""
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time

from harness import check

exe, client_js, opcua_dir = sys.argv[1:4]
node = os.environ.get("SREH_TWIN_NODE", "node")
if shutil.which(node) is None:
    print("SKIP: no Node.js ('%s'); ./setup.sh installs Debian's nodejs" % node)
    sys.exit(77)
base = [exe, "serve", "--modbus", "127.0.0.1:0", "--http", "127.0.0.1:0"]


def children(pid):
    out = []
    for task in os.listdir("/proc/%d/task" % pid):
        with open("/proc/%d/task/%s/children" % (pid, task)) as f:
            out += [int(x) for x in f.read().split()]
    return out


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    with open("/proc/%d/stat" % pid) as f:
        return f.read().split(")")[-1].split()[0] != "Z"


def wait_gone(pid, what, timeout_s=10):
    end = time.monotonic() + timeout_s
    while alive(pid) and time.monotonic() < end:
        time.sleep(0.05)
    check(not alive(pid), what)


# 1. Bad input: exit 2, one line naming the problem.
busy = socket.socket()
busy.bind(("127.0.0.1", 0))
busy.listen(1)
r = subprocess.run(base + ["--opcua", "127.0.0.1:%d" % busy.getsockname()[1]], capture_output=True, text=True,
                   timeout=240)
check(r.returncode == 2 and "address in use" in r.stderr and r.stderr.count("\n") == 1,
      "a used OPC UA address: exit %d, %r" % (r.returncode, r.stderr))
busy.close()
r = subprocess.run(base + ["--opcua", "0.0.0.0:0"], capture_output=True, text=True, timeout=60)
check(r.returncode == 2 and "--token-file" in r.stderr, "non-loopback without a token: %d %r" % (r.returncode, r.stderr))

# 2. A killed front is reported and restarted on the same port.
proc = subprocess.Popen(base + ["--ports", "2", "--opcua", "127.0.0.1:0"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                        text=True)
lines = []
threading.Thread(target=lambda: lines.extend(iter(proc.stderr.readline, "")), daemon=True).start()
try:
    ready = json.loads(proc.stdout.readline())
    env = dict(os.environ, NODE_PATH=os.path.join(opcua_dir, "node_modules"))
    browse = [node, client_js, "opc.tcp://" + ready["opcua"], "http://" + ready["http"], "--browse-only"]
    front = children(proc.pid)
    check(len(front) == 1, "serve has %d child processes, expected the front" % len(front))
    os.kill(front[0], signal.SIGKILL)
    end = time.monotonic() + 240
    while not any("is back on" in l for l in lines) and time.monotonic() < end and proc.poll() is None:
        time.sleep(0.1)
    text = "".join(lines)
    check("the OPC UA front stopped (signal 9" in text and "is back on " + ready["opcua"] in text,
          "restart not reported: %r" % text)
    again = children(proc.pid)
    check(len(again) == 1 and again[0] != front[0], "no new front: %s" % again)
    b = subprocess.run(browse, capture_output=True, text=True, timeout=120, env=env)
    check(b.returncode == 0, "browse after the restart: %s" % b.stderr)
    # 3. SIGTERM: serve stops, the front with it.
    proc.send_signal(signal.SIGTERM)
    proc.wait(timeout=30)
    check(proc.returncode == 0, "exit %d after SIGTERM: %s" % (proc.returncode, "".join(lines)))
    wait_gone(again[0], "the front outlived serve's SIGTERM")
finally:
    if proc.poll() is None:
        proc.kill()

# 4. SIGKILL of serve: the front goes too (parent-death signal), even while it is still starting.
proc = subprocess.Popen(base + ["--opcua", "127.0.0.1:0"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
try:
    end = time.monotonic() + 60
    front = []
    while not front and time.monotonic() < end:
        front = children(proc.pid)
        time.sleep(0.05)
    check(len(front) == 1, "no front started")
    proc.kill()
    proc.wait(timeout=10)
    wait_gone(front[0], "the front outlived a SIGKILLed serve")
finally:
    if proc.poll() is None:
        proc.kill()
print("PASS")
