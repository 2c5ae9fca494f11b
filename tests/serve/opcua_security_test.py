"""Issue 38 security (A-OPCUA-6, docs/opcua.md "Security"): on an address
other than loopback (0.0.0.0) serve offers only Basic256Sha256
Sign&Encrypt with user `sreh-twin` and the token as password, its server
certificate in --state-dir; a client's certificate is refused until moved to
the trusted folder. Security None is refused, so is an anonymous session; the
user may write. Usage: opcua_security_test.py SREH_TWIN CLIENT_JS OPCUA_DIR."""
import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile

from harness import Serve, check

exe, client_js, opcua_dir = sys.argv[1:4]
node = os.environ.get("SREH_TWIN_NODE", "node")
if shutil.which(node) is None:
    print("SKIP: no Node.js ('%s'); ./setup.sh installs Debian's nodejs" % node)
    sys.exit(77)
tmp = tempfile.mkdtemp()
token_file = os.path.join(tmp, "token")
with open(token_file, "w") as f:
    f.write("s3cret-token\n")
os.chmod(token_file, 0o600)
state = os.path.join(tmp, "state")
os.mkdir(state)
client_pki = os.path.join(tmp, "client-pki")
env = dict(os.environ, NODE_PATH=os.path.join(opcua_dir, "node_modules"))

args = ("--opcua", "0.0.0.0:0", "--token-file", token_file, "--state-dir", state)


def attempt(endpoint, *a):
    r = subprocess.run([node, client_js, endpoint, *a], capture_output=True, text=True, timeout=120, env=env)
    check(r.returncode == 0 and r.stdout.strip(), "client: %s" % r.stderr)
    return json.loads(r.stdout.strip().splitlines()[-1])


def local(s):
    return "opc.tcp://127.0.0.1:" + s.ready["opcua"].rsplit(":", 1)[1]


s = Serve(exe, *args)
try:
    check(glob.glob(os.path.join(state, "opcua-pki", "own", "certs", "*.pem")), "no server certificate in --state-dir")
    r = attempt(local(s), "none", client_pki)
    check(not r["ok"], "security None accepted on a non-loopback address: %s" % r)
    r = attempt(local(s), "secure", client_pki, "sreh-twin", "s3cret-token")
    check(not r["ok"], "an unknown client certificate was accepted: %s" % r)
    rejected = glob.glob(os.path.join(state, "opcua-pki", "rejected", "*"))
    check(len(rejected) == 1, "the client's certificate is not in rejected/: %s" % rejected)
finally:
    rc, err = s.stop(timeout=30)
    s.kill()
check(rc == 0, "exit %d: %s" % (rc, err))
# Trusting the client (docs/opcua.md): its certificate moved to trusted/, then the same serve command again.
trusted = os.path.join(state, "opcua-pki", "trusted", "certs")
shutil.move(rejected[0], os.path.join(trusted, os.path.basename(rejected[0])))
s = Serve(exe, *args)
try:
    r = attempt(local(s), "secure", client_pki)
    check(not r["ok"], "an anonymous session was accepted: %s" % r)
    r = attempt(local(s), "secure", client_pki, "sreh-twin", "wrong")
    check(not r["ok"], "a wrong password was accepted: %s" % r)
    r = attempt(local(s), "secure", client_pki, "sreh-twin", "s3cret-token")
    check(r["ok"] and r["call"] == "Good" and r["status"] == 0, "the user's write: %s" % r)
    check(s.get("/v1/ports/1/parameters/26/0")["value"] == "hall 3", "the write did not reach the device")
finally:
    rc, err = s.stop(timeout=30)
    s.kill()
check(rc == 0, "exit %d: %s" % (rc, err))
print("PASS")
