// Issue 38 "Done when", the OPC UA side: a real client (node-opcua-client)
// against `serve --ports 2 --opcua`. Browses to both ports' devices by their
// OPC 30120 type definitions, reads identification, WriteISDU/ReadISDU set 1
// (manual 6.2, index 65), 0x8030 with Status -3 out of range (30120 7.1.4.1),
// a parameter variable in engineering units, motor on and a move through
// ProcessDataOutput watched on ProcessDataInput through a subscription
// (manual 3.2 handshake, 2.2/2.3 layout), on both ports at once; then a
// blocked move on both ports at once (serve's fault injection) and its IO-Link
// event as an IOLinkDeviceAlarmType (30120 9.8). Prints one JSON line with what it saw
// last, for opcua_test.py to compare with Modbus and HTTP.
// Usage: node opcua_client.js opc.tcp://HOST:PORT http://HOST:PORT [--browse-only]
"use strict";
for (const k of ["log", "info", "warn", "debug"]) console[k] = console.error; // stdout carries the result only
const opcua = require("node-opcua");
const { OPCUAClient, AttributeIds, BrowseDirection, DataType, VariantArrayType, TimestampsToReturn, StatusCodes } = opcua;

const [endpoint, http, mode] = process.argv.slice(2);
const IOL = "http://opcfoundation.org/UA/IOLink/";
const kTimeoutMs = 20000;

function check(cond, message) {
  if (!cond) throw new Error(message);
}

function log(message) {
  process.stderr.write(`opcua_client: ${message}\n`);
}

async function httpJson(method, path, body) {
  const r = await fetch(http + path, {
    method,
    headers: body ? { "Content-Type": "application/json" } : {},
    body: body ? JSON.stringify(body) : undefined,
  });
  check(r.ok, `${method} ${path}: HTTP ${r.status}`);
  return r.json();
}

async function browse(session, nodeId) {
  const r = await session.browse({
    nodeId,
    referenceTypeId: "HierarchicalReferences",
    browseDirection: BrowseDirection.Forward,
    includeSubtypes: true,
    resultMask: 63,
  });
  check(r.statusCode === StatusCodes.Good, `browse ${nodeId}: ${r.statusCode.toString()}`);
  return r.references;
}

// Children whose type definition is `type` (a NodeId string).
async function childrenOfType(session, nodeId, type) {
  return (await browse(session, nodeId)).filter((ref) => ref.typeDefinition.toString() === type);
}

async function child(session, nodeId, name) {
  const ref = (await browse(session, nodeId)).find((r) => r.browseName.name === name);
  check(ref, `${nodeId}: no child ${name}`);
  return ref.nodeId.toString();
}

async function read(session, nodeId) {
  const dv = await session.read({ nodeId, attributeId: AttributeIds.Value });
  return dv;
}

// PD in fields (manual 2.3): position int32 big-endian, then error, warning, status bits.
function pdIn(buf) {
  const b = Buffer.from(buf);
  return { position: b.readInt32BE(0), error: b[4], warning: b[5], bits: b[6] };
}
const kMotorOff = 1, kReady = 2, kBusy = 4, kDone = 8, kError = 32;

// PD out (manual 2.2): target int32, motion parameter set, control bits.
function pdOut(target, set, bits) {
  const b = Buffer.alloc(6);
  b.writeInt32BE(target, 0);
  b[4] = set;
  b[5] = bits;
  return b;
}
const kMotorOn = 1, kMove = 2, kResetError = 8;

class Device {
  constructor(session, port, nodes) {
    this.session = session;
    this.port = port;
    Object.assign(this, nodes);
    this.last = null;
    this.waiters = [];
    this.changes = 0;
  }

  async call(method, args) {
    const methodId = await child(this.session, this.methodSet, method);
    const r = await this.session.call({ objectId: this.methodSet, methodId, inputArguments: args });
    check(r.statusCode === StatusCodes.Good, `Port${this.port} ${method}: ${r.statusCode.toString()}`);
    return r.outputArguments.map((v) => v.value);
  }

  readIsdu(index, sub) {
    return this.call("ReadISDU", [{ dataType: DataType.UInt16, value: index }, { dataType: DataType.Byte, value: sub }]);
  }

  writeIsdu(index, sub, bytes) {
    return this.call("WriteISDU", [{ dataType: DataType.UInt16, value: index }, { dataType: DataType.Byte, value: sub },
      { dataType: DataType.Byte, arrayType: VariantArrayType.Array, value: Buffer.from(bytes) }]);
  }

  async writePdOut(buf) {
    const s = await this.session.write({ nodeId: this.pdOutNode, attributeId: AttributeIds.Value,
      value: { value: { dataType: DataType.Byte, arrayType: VariantArrayType.Array, value: buf } } });
    check(s === StatusCodes.Good, `Port${this.port} write ProcessDataOutput: ${s.toString()}`);
  }

  async subscribe(subscription) {
    const item = opcua.ClientMonitoredItem.create(subscription, { nodeId: this.pdInNode, attributeId: AttributeIds.Value },
      { samplingInterval: 10, discardOldest: true, queueSize: 100 }, TimestampsToReturn.Both);
    item.on("changed", (dv) => {
      if (!dv.statusCode.isGood()) return;
      ++this.changes;
      this.seen(pdIn(dv.value.value));
    });
  }

  seen(state) {
    this.last = state;
    this.waiters = this.waiters.filter((w) => !w.pred(this.last) || (w.resolve(this.last), false));
  }

  // Resolves when a ProcessDataInput notification satisfies pred.
  until(pred, what) {
    if (this.last && pred(this.last)) return Promise.resolve(this.last);
    return new Promise((resolve, reject) => {
      // The subscription delivers the states; a read every second as well, so that a
      // notification lost to a publish timeout on a starved machine does not hang the test.
      const poll = setInterval(() => read(this.session, this.pdInNode).then((dv) => {
        if (dv.statusCode.isGood()) this.seen(pdIn(dv.value.value));
      }).catch(() => {}), 1000);
      const timer = setTimeout(() => (clearInterval(poll), reject(new Error(`Port${this.port}: ${what} not seen in ` +
        `${kTimeoutMs} ms (last PD in ${JSON.stringify(this.last)})`))), kTimeoutMs);
      this.waiters.push({ pred, resolve: (v) => (clearTimeout(timer), clearInterval(poll), resolve(v)) });
    });
  }

  // Manual 3.2: Move held until Done (T5), released -> Ready (T7).
  async move(target, set) {
    await this.writePdOut(pdOut(target, set, kMotorOn | kMove));
    await this.until((s) => s.bits & (kBusy | kDone), "Busy after Move");
    const done = await this.until((s) => s.bits & kDone, "Done");
    check(Math.abs(done.position - target) <= 18, `Port${this.port}: Done at ${done.position}, target ${target}`);
    await this.writePdOut(pdOut(target, set, kMotorOn));
    await this.until((s) => s.bits & kReady, "Ready after Move released");
    return done;
  }
}

// Step 1: browse by type definitions (30120 8.4: IOLinkMasterSet; 7.2 ports; 7.1 devices).
async function findDevices(session, iol) {
  const t = (i) => `ns=${iol};i=${i}`;
  const masterSet = await child(session, "ns=0;i=85", "IOLinkMasterSet");
  const masters = await childrenOfType(session, masterSet, t(1014)); // IOLinkMasterType
  check(masters.length === 1, `IOLinkMasterSet holds ${masters.length} masters`);
  const ports = await childrenOfType(session, masters[0].nodeId.toString(), t(1015)); // IOLinkPortType
  check(ports.length === 2, `master has ${ports.length} ports, expected 2`);
  const devices = [];
  for (const port of ports.sort((a, b) => a.browseName.name.localeCompare(b.browseName.name))) {
    const devs = await childrenOfType(session, port.nodeId.toString(), t(1002)); // IOLinkDeviceType
    check(devs.length === 1, `${port.browseName.name}: ${devs.length} devices`);
    const device = devs[0].nodeId.toString();
    const ps = await child(session, device, "ParameterSet");
    const pdInRefs = await childrenOfType(session, ps, t(2002)); // ProcessDataVariableType
    check(pdInRefs.length === 2, `${port.browseName.name}: ${pdInRefs.length} process data variables`);
    devices.push({
      device,
      parameterSet: ps,
      methodSet: await child(session, device, "MethodSet"),
      pdInNode: await child(session, ps, "ProcessDataInput"),
      pdOutNode: await child(session, ps, "ProcessDataOutput"),
    });
  }
  return devices;
}

// Step 2: identification against the device's own answers over HTTP (manual 6.5).
async function checkIdentification(d) {
  const value = async (name) => (await read(d.session, await child(d.session, d.device, name))).value.value;
  const manufacturer = (await value("Manufacturer")).text;
  const http16 = (await httpJson("GET", `/v1/ports/${d.port}/parameters/16/0`)).value;
  check(manufacturer === http16, `Manufacturer ${manufacturer} vs HTTP ${http16}`);
  const model = (await value("Model")).text;
  const http18 = (await httpJson("GET", `/v1/ports/${d.port}/parameters/18/0`)).value;
  check(model === http18, `Model ${model} vs HTTP ${http18}`);
  check((await value("MinCycleTime")) === 2, "MinCycleTime is not 2 ms (manual 1)");
  check((await value("VendorID")) === 0 && (await value("DeviceID")) === 0, "Vendor/Device ID (A-IODD-1: 0)");
  const serial = await value("SerialNumber");
  check(serial === (await httpJson("GET", `/v1/ports/${d.port}/parameters/21/0`)).value, "SerialNumber vs HTTP");
  const lengthNode = await child(d.session, d.pdInNode, "ProcessDataLength");
  check((await read(d.session, lengthNode)).value.value === 56, "ProcessDataInput length is not 56 bits (manual 2.3)");
}

// Step 3: ISDU through the MethodSet (30120 7.1.4.1/2), set 1 = index 65 (manual 6.2).
async function checkIsdu(d, speedRaw) {
  const hi = speedRaw >> 8, lo = speedRaw & 0xff;
  let [err, status] = await d.writeIsdu(65, 1, [hi, lo]);
  check(status === 0 && err === 0, `Port${d.port} WriteISDU 65.1: status ${status}, error 0x${err.toString(16)}`);
  let [result, err2, status2] = await d.readIsdu(65, 1);
  check(status2 === 0 && err2 === 0 && Buffer.from(result).equals(Buffer.from([hi, lo])),
    `Port${d.port} ReadISDU 65.1 = ${Buffer.from(result || []).toString("hex")} status ${status2}`);
  const http = await httpJson("GET", `/v1/ports/${d.port}/parameters/65/1`);
  check(http.value === speedRaw, `HTTP 65.1 = ${http.value}, OPC UA wrote ${speedRaw}`);
  [err, status] = await d.writeIsdu(65, 1, [0xc3, 0x50]); // 50000 = 5000 deg/s > 4300 deg/s
  check(status === -3 && err === 0x8030, `Port${d.port} out of range: status ${status}, error 0x${err.toString(16)}`);
  [result] = await d.readIsdu(65, 1);
  check(Buffer.from(result).readUInt16BE(0) === speedRaw, "a refused write changed 65.1");
  // The same parameter as a variable in engineering units (deg/s, AnalogItemType).
  const record = await child(d.session, d.parameterSet, "Motion parameter set 1");
  const speedNode = await child(d.session, record, "Maximum speed");
  check(speedNode === `ns=1;s=Port${d.port}.65.1`, `parameter node id ${speedNode} (docs/opcua.md)`);
  check(d.device === `ns=1;s=IOLinkMaster-Port${d.port}-Device`, `device node id ${d.device} (docs/opcua.md)`);
  const dv = await read(d.session, speedNode);
  check(Math.abs(dv.value.value - speedRaw / 10) < 1e-9, `Maximum speed variable ${dv.value.value} deg/s`);
  const bad = await d.session.write({ nodeId: speedNode, attributeId: AttributeIds.Value,
    value: { value: { dataType: DataType.Double, value: 5000 } } });
  check(bad.isNotGood(), `writing 5000 deg/s was accepted: ${bad.toString()}`);
}

// A blocked move (docs/serve.md faults: flange_blocked) half a turn from
// `at`: a tracking error, its event from this device (30120 9.8, ActiveState
// true), then release and reset; the event disappears (ActiveState false).
async function blockedMove(d, at, events, alarmType) {
  const until = (pred, what) => {
    const deadline = Date.now() + kTimeoutMs;
    return (async () => {
      let e;
      while (!(e = events.find(pred)) && Date.now() < deadline) await new Promise((r) => setTimeout(r, 50));
      check(e, `Port${d.port}: ${what}; events: ${JSON.stringify(events)}`);
      return e;
    })();
  };
  await httpJson("POST", `/v1/ports/${d.port}/faults`, { flange_blocked: true });
  await d.writePdOut(pdOut(at + 32768, 1, kMotorOn | kMove));
  const err = await d.until((s) => s.bits & kError, "Error after a blocked move");
  const ev = await until((e) => e[0].toString() === alarmType && e[1].toString() === d.device && e[4] === true,
    "no IOLinkDeviceAlarmType event from its device");
  check(ev[3] === 700 && /^IO-Link EventCode: 0x[0-9A-F]{4}$/.test(ev[2].text), `event ${JSON.stringify(ev)}`);
  log(`Port${d.port} blocked move: error 0x${err.error.toString(16)}, event ${ev[2].text} severity ${ev[3]}`);
  // The tracking error switched the motor off (manual 2.4), so the error is
  // reset with Motor On = 0 (3.3, transition 10.2), then the motor goes on (T1).
  check(err.bits & kMotorOff, `Port${d.port}: the motor is still on after the tracking error (${JSON.stringify(err)})`);
  await httpJson("POST", `/v1/ports/${d.port}/faults`, { flange_blocked: false });
  await d.writePdOut(pdOut(at, 1, kResetError));
  await d.until((s) => !(s.bits & kError), "error reset");
  await d.writePdOut(pdOut(at, 1, 0));
  await d.writePdOut(pdOut(at, 1, kMotorOn));
  await d.until((s) => s.bits & kReady, "Ready after the reset");
  const code = ev[5];
  await until((e) => e[0].toString() === alarmType && e[1].toString() === d.device && e[5] === code && e[4] === false,
    `event 0x${code.toString(16)} did not disappear`);
  log(`Port${d.port}: the event disappeared after the reset`);
}

async function main() {
  const client = OPCUAClient.create({ endpointMustExist: false, connectionStrategy: { maxRetry: 2, initialDelay: 200 } });
  await client.connect(endpoint);
  const session = await client.createSession();
  try {
    const iol = (await session.readNamespaceArray()).indexOf(IOL);
    check(iol > 0, "the IO-Link namespace is not served");
    const nodes = await findDevices(session, iol);
    const devices = nodes.map((n, i) => new Device(session, i + 1, n));
    log("browsed: 1 master, 2 ports, 2 devices by their 30120 types");
    if (mode === "--browse-only") {
      await checkIdentification(devices[0]);
      process.stdout.write("{}\n");
      return;
    }
    const subscription = opcua.ClientSubscription.create(session, { requestedPublishingInterval: 10,
      requestedMaxKeepAliveCount: 200, requestedLifetimeCount: 2000, publishingEnabled: true, priority: 1 });
    await Promise.all(devices.map((d) => d.subscribe(subscription)));
    await Promise.all(devices.map((d) => checkIdentification(d)));
    log("identification matches HTTP");
    await Promise.all(devices.map((d, i) => checkIsdu(d, i === 0 ? 1000 : 2000)));
    log("WriteISDU/ReadISDU, 0x8030 with Status -3, the parameter variable");
    // Both ports at once: motor on (T1), then a move each (T3, T5, T7).
    await Promise.all(devices.map(async (d) => {
      await d.until((s) => s.bits & kMotorOff, "Motor Off at start");
      await d.writePdOut(pdOut(0, 0, kMotorOn));
      await d.until((s) => s.bits & kReady, "Ready after Motor On");
    }));
    const targets = [16384, -8192]; // 90 deg, -45 deg (manual 2.5)
    await Promise.all(devices.map((d, i) => d.move(targets[i], 1)));
    log("moves done on both ports through ProcessDataOutput/ProcessDataInput");
    // A blocked move (docs/serve.md faults): the device reports an error event.
    const events = [];
    const filter = opcua.constructEventFilter(["EventType", "SourceNode", "Message", "Severity", "ActiveState.Id",
      `${iol}:IOLinkEventCode`]);
    const eventItem = opcua.ClientMonitoredItem.create(subscription, { nodeId: "ns=0;i=2253", attributeId: AttributeIds.EventNotifier },
      { samplingInterval: 0, discardOldest: true, queueSize: 100, filter }, TimestampsToReturn.Neither);
    eventItem.on("changed", (fields) => events.push(fields.map((f) => f.value)));
    await new Promise((r) => setTimeout(r, 300));
    const alarmType = `ns=${iol};i=1008`; // IOLinkDeviceAlarmType
    await Promise.all(devices.map((d, i) => blockedMove(d, targets[i], events, alarmType)));
    // What the client sees now, for the comparison with Modbus and HTTP.
    const out = { ports: [] };
    for (const d of devices) {
      const pin = await read(session, d.pdInNode);
      const pout = await read(session, d.pdOutNode);
      out.ports.push({ pd_in: Buffer.from(pin.value.value).toString("hex").toUpperCase(),
        pd_out: Buffer.from(pout.value.value).toString("hex").toUpperCase(),
        speed_65_1: Buffer.from((await d.readIsdu(65, 1))[0]).readUInt16BE(0), changes: d.changes });
    }
    await subscription.terminate();
    process.stdout.write(JSON.stringify(out) + "\n");
  } finally {
    await session.close();
    await client.disconnect();
  }
}

main().catch((e) => {
  process.stderr.write(`FAIL: ${e.stack || e}\n`);
  process.exit(1);
});
