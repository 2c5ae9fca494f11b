"""Issue 38 "Done when": `serve --ports 2 --opcua` driven by a real OPC UA
client (opcua_client.js, node-opcua-client): browse by the OPC 30120 types,
identification, WriteISDU/ReadISDU (0x8030 + Status -3), motor on and a move
on both ports at once through ProcessDataOutput/ProcessDataInput (manual
3.2), a blocked move's IO-Link event (30120 9.8). Afterwards the state the
OPC UA client saw matches Modbus and HTTP. Usage: opcua_test.py SREH_TWIN
CLIENT_JS OPCUA_DIR (serve/opcua, whose node_modules the client uses)."""
import json
import os
import shutil
import subprocess
import sys

from harness import Serve, check, pd_in_registers_to_hex

exe, client_js, opcua_dir = sys.argv[1:4]
node = os.environ.get("SREH_TWIN_NODE", "node")
if shutil.which(node) is None:
    print("SKIP: no Node.js ('%s'); ./setup.sh installs Debian's nodejs" % node)
    sys.exit(77)
check(os.path.isdir(os.path.join(opcua_dir, "node_modules", "node-opcua")),
      "%s/node_modules is missing: run `npm ci` there (./setup.sh does)" % opcua_dir)

mb_map = json.loads(subprocess.run([exe, "serve", "--ports", "2", "--print-modbus-map", "--json"], capture_output=True,
                                   text=True, check=True).stdout)

s = Serve(exe, "--ports", "2", "--opcua", "127.0.0.1:0")
try:
    endpoint = "opc.tcp://" + s.ready["opcua"]
    env = dict(os.environ, NODE_PATH=os.path.join(opcua_dir, "node_modules"))
    r = subprocess.run([node, client_js, endpoint, s.http], capture_output=True, text=True, timeout=240, env=env)
    sys.stderr.write(r.stderr)
    check(r.returncode == 0, "the OPC UA client failed (exit %d)" % r.returncode)
    seen = json.loads(r.stdout.strip().splitlines()[-1])

    mb = s.pymodbus()
    for p, opc in enumerate(seen["ports"], start=1):
        regs = {k: v["register"] for k, v in mb_map["ports"][p - 1].items() if isinstance(v, dict)}
        http = s.get("/v1/ports/%d/processdata" % p)
        modbus_in = pd_in_registers_to_hex(mb.read_holding_registers(regs["pd_in"], 4, slave=1).registers)
        modbus_out = "".join("%04X" % v for v in mb.read_holding_registers(regs["pd_out"], 3, slave=1).registers)
        # Process data out is what the OPC UA client wrote last: the same on every door.
        check(opc["pd_out"] == http["out"]["raw"] == modbus_out,
              "port %d PD out: OPC UA %s, HTTP %s, Modbus %s" % (p, opc["pd_out"], http["out"]["raw"], modbus_out))
        # Process data in: the module holds its position (a count of dither allowed, manual 3.5.7's window).
        for name, raw in (("HTTP", http["in"]["raw"]), ("Modbus", modbus_in)):
            pos = lambda h: int.from_bytes(bytes.fromhex(h[:8]), "big", signed=True)
            check(abs(pos(raw) - pos(opc["pd_in"])) <= 18 and raw[8:] == opc["pd_in"][8:],
                  "port %d PD in: OPC UA %s, %s %s" % (p, opc["pd_in"], name, raw))
        check(http["in"]["state"] == "Ready", "port %d state %s after the client" % (p, http["in"]["state"]))
        check(s.get("/v1/ports/%d/parameters/65/1" % p)["value"] == opc["speed_65_1"], "port %d 65.1" % p)
        # Motor Off -> Ready -> Busy/Done -> Done -> Ready: each seen as a notification (how many more: load-dependent).
        check(opc["changes"] >= 4, "port %d: only %d ProcessDataInput notifications" % (p, opc["changes"]))
    mb.close()
finally:
    rc, err = s.stop(timeout=30)
    s.kill()
check(rc == 0, "exit %d after SIGTERM: %s" % (rc, err))
print("PASS")
