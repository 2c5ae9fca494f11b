// The OPC 30120 (OPC UA for IO-Link) address space of the virtual master:
// one IOLinkMasterType instance in IOLinkMasterSet (spec 8.4), Port1..n
// (IOLinkPortType, 7.2), each with its Device (IOLinkDeviceType, 7.1):
// identification, ProcessDataInput/Output (ProcessDataVariableType), the
// MethodSet (7.1.4) and the parameters (params.js). docs/opcua.md has the tree.
"use strict";
const { DataType, Variant, VariantArrayType, StatusCodes, DataValue, coerceLocalizedText, resolveNodeId } = require("node-opcua");
const { lowerFirstLetter } = require("node-opcua-utils");
const { addParameters } = require("./params");

const IOL = "http://opcfoundation.org/UA/IOLink/";
const DI = "http://opcfoundation.org/UA/DI/";

// Status of the spec's ISDU and system-command methods (7.1.4.1).
const kStatusOk = 0;
const kStatusNotActive = -2;
const kStatusDeviceError = -3;
// IO-Link system commands behind the MethodSet (iolink.md "System commands").
const kSystemCommands = {
  ParamUploadFromDeviceStart: 1,
  ParamUploadFromDeviceStop: 2,
  ParamDownloadToDeviceStart: 3,
  ParamDownloadToDeviceStop: 4,
  ParamDownloadToDeviceStore: 5,
  ParamBreak: 6,
  DeviceReset: 128,
  ApplicationReset: 129,
  RestoreFactorySettings: 130,
};

const bytes = (hex) => Buffer.from(hex || "", "hex");
const byteArray = (buf) => new Variant({ dataType: DataType.Byte, arrayType: VariantArrayType.Array, value: buf });

// Index of the entry of an EnumStrings / OptionSetValues property that matches `want`.
function enumIndex(variable, want) {
  const prop = variable.getPropertyByName("EnumStrings");
  const list = prop ? prop.readValue().value.value : [];
  const i = list.findIndex((t) => t && t.text === want);
  if (i < 0) throw new Error(`${variable.browseName.toString()}: no enumeration entry '${want}'`);
  return i;
}

function setValue(node, dataType, value) {
  node.setValueFromSource(new Variant({ dataType, value }));
}

// ISDU through serve: {status, errorType, data}.
async function isdu(channel, port, op, index, subindex, dataHex) {
  const r = await channel.request({ p: port, op, index, sub: subindex, data: dataHex });
  if (r.ok) return { status: kStatusOk, errorType: 0, data: bytes(r.data) };
  if (r.iolink_error !== undefined) return { status: kStatusDeviceError, errorType: r.iolink_error, data: Buffer.alloc(0) };
  return { status: kStatusNotActive, errorType: 0, data: Buffer.alloc(0) };
}

function bindMethodSet(device, port, channel, canWrite) {
  const methods = device.getComponentByName("MethodSet");
  const answer = (r, withResult) => {
    const out = [];
    if (withResult) out.push(byteArray(r.data));
    out.push(new Variant({ dataType: DataType.UInt16, value: r.errorType }));
    out.push(new Variant({ dataType: DataType.Int32, value: r.status }));
    return { statusCode: StatusCodes.Good, outputArguments: out };
  };
  const denied = { statusCode: StatusCodes.BadUserAccessDenied };
  methods.getMethodByName("ReadISDU").bindMethod(async (args, _context) =>
    answer(await isdu(channel, port, "isdu_read", args[0].value, args[1].value), true));
  methods.getMethodByName("WriteISDU").bindMethod(async (args, context) => {
    if (!canWrite(context)) return denied;
    const data = Buffer.from(args[2].value || []);
    return answer(await isdu(channel, port, "isdu_write", args[0].value, args[1].value, data.toString("hex")), false);
  });
  const systemCommand = async (cmd) => isdu(channel, port, "isdu_write", 2, 0, Buffer.from([cmd]).toString("hex"));
  methods.getMethodByName("SystemCommand").bindMethod(async (args, context) =>
    canWrite(context) ? answer(await systemCommand(args[0].value), false) : denied);
  for (const [name, cmd] of Object.entries(kSystemCommands))
    methods.getMethodByName(name).bindMethod(async (_args, context) =>
      canWrite(context) ? answer(await systemCommand(cmd), false) : denied);
}

// Identification (7.1.2; manual 6.5): read once at start by serve (config.identity, by index).
function setIdentification(device, identity, config) {
  const text = (i) => bytes(identity[String(i)]).toString("latin1").replace(/\0+$/, "");
  setValue(device.getPropertyByName("Manufacturer"), DataType.LocalizedText, coerceLocalizedText(text(16)));
  setValue(device.getPropertyByName("Model"), DataType.LocalizedText, coerceLocalizedText(text(18)));
  setValue(device.getPropertyByName("VendorID"), DataType.UInt16, config.vendor_id);
  setValue(device.getPropertyByName("DeviceID"), DataType.UInt32, config.device_id);
  setValue(device.getPropertyByName("RevisionID"), DataType.String, config.iolink_revision);
  setValue(device.getPropertyByName("MinCycleTime"), DataType.Double, config.min_cycle_time_ms);
  setValue(device.getPropertyByName("SerialNumber"), DataType.String, text(21));
  setValue(device.getPropertyByName("HardwareRevision"), DataType.String, text(22));
  setValue(device.getPropertyByName("SoftwareRevision"), DataType.String, text(23));
  setValue(device.getPropertyByName("ProductID"), DataType.String, text(19));
  setValue(device.getPropertyByName("ProductText"), DataType.String, text(20));
  setValue(device.getPropertyByName("VendorText"), DataType.String, text(17));
  const profiles = bytes(identity["13"]);
  const list = [];
  for (let i = 0; i + 1 < profiles.length; i += 2) list.push(profiles.readUInt16BE(i));
  device.getPropertyByName("ProfileCharacteristic").setValueFromSource(
    new Variant({ dataType: DataType.UInt16, arrayType: VariantArrayType.Array, value: new Uint16Array(list) }));
}

// A device variable read through ISDU on demand (tags, error count, detailed status).
function bindIsduVariable(variable, port, channel, index, toVariant, canWrite, fromVariant) {
  variable.minimumSamplingInterval = 100;
  const options = {
    refreshFunc: (callback) => {
      isdu(channel, port, "isdu_read", index, 0).then((r) => {
        const dv = r.status === kStatusOk
          ? new DataValue({ value: toVariant(r.data), statusCode: StatusCodes.Good, sourceTimestamp: new Date() })
          : new DataValue({ statusCode: StatusCodes.BadNoCommunication, sourceTimestamp: new Date() });
        callback(null, dv);
      });
    },
  };
  if (fromVariant)
    options.set = (variant, callback) => {
      isdu(channel, port, "isdu_write", index, 0, fromVariant(variant).toString("hex")).then((r) =>
        callback(null, r.status === kStatusOk ? StatusCodes.Good
          : r.status === kStatusDeviceError ? StatusCodes.BadOutOfRange : StatusCodes.BadNoCommunication));
    };
  variable.bindVariable(options, true);
  if (fromVariant) variable.isUserWritable = (context) => canWrite(context);
}

function buildDevice(addressSpace, port, portNode, config, channel, canWrite) {
  const iol = addressSpace.getNamespaceIndex(IOL);
  const deviceType = addressSpace.findObjectType("IOLinkDeviceType", iol);
  const device = deviceType.instantiate({
    browseName: { name: "Device", namespaceIndex: iol },
    componentOf: portNode,
    eventNotifier: 1, // SubscribeToEvents: the device is the source of its IO-Link events (9.3, 9.8)
    optionals: ["SerialNumber", "HardwareRevision", "SoftwareRevision", "ProductID", "ProductText", "VendorText",
      "ProfileCharacteristic", "ParameterSet.ErrorCount", "ParameterSet.DetailedDeviceStatus"],
  });
  setIdentification(device, config.identity[port - 1], config);
  const ps = device.getComponentByName("ParameterSet");
  const pdIn = ps.getComponentByName("ProcessDataInput");
  const pdOut = ps.getComponentByName("ProcessDataOutput");
  setValue(pdIn.getPropertyByName("ProcessDataLength"), DataType.Byte, config.pd_in_bytes * 8);
  setValue(pdOut.getPropertyByName("ProcessDataLength"), DataType.Byte, config.pd_out_bytes * 8);
  pdIn.minimumSamplingInterval = 0; // exception-based monitoring allowed: every master cycle that changes it
  pdOut.minimumSamplingInterval = 0;
  pdIn.setValueFromSource(byteArray(Buffer.alloc(config.pd_in_bytes)), StatusCodes.BadWaitingForInitialData);
  pdOut.setValueFromSource(byteArray(Buffer.alloc(config.pd_out_bytes)), StatusCodes.BadWaitingForInitialData);
  // Writing ProcessDataOutput is the PLC's output (7.1.3): the raw 6 octets (manual 2.2).
  pdOut.bindVariable({
    timestamped_get: () => pdOut.$dataValue, // what the last cycle showed (updateProcessData)
    set: (variant, callback) => {
      const buf = Buffer.from(variant.value || []);
      if (buf.length !== config.pd_out_bytes) return callback(null, StatusCodes.BadOutOfRange);
      channel.request({ p: port, op: "pd_out", raw: buf.toString("hex") }).then((r) =>
        callback(null, r.ok ? StatusCodes.Good : StatusCodes.BadNoCommunication));
    },
  }, true);
  pdOut.isUserWritable = (context) => canWrite(context);
  const tag = (name, index) => bindIsduVariable(ps.getComponentByName(name), port, channel, index,
    (b) => new Variant({ dataType: DataType.String, value: b.toString("latin1") }), canWrite,
    (v) => Buffer.from(String(v.value), "latin1"));
  tag("ApplicationSpecificTag", 24);
  tag("FunctionTag", 25);
  tag("LocationTag", 26);
  for (const name of ["ApplicationSpecificTag", "FunctionTag", "LocationTag"])
    setValue(ps.getComponentByName(name).getPropertyByName("StoredInDevice"), DataType.Boolean, true);
  bindIsduVariable(ps.getComponentByName("ErrorCount"), port, channel, 32,
    (b) => new Variant({ dataType: DataType.UInt16, value: b.length >= 2 ? b.readUInt16BE(0) : 0 }));
  bindIsduVariable(ps.getComponentByName("DetailedDeviceStatus"), port, channel, 37, (b) => {
    const rows = [];
    for (let i = 0; i + 2 < b.length; i += 3) rows.push(b.subarray(i, i + 3));
    return new Variant({ dataType: DataType.Byte, arrayType: VariantArrayType.Matrix, dimensions: [rows.length, 3],
      value: Buffer.concat(rows) });
  });
  bindMethodSet(device, port, channel, canWrite);
  addParameters(addressSpace, device, port, config.params, channel, canWrite);
  return { device, pdIn, pdOut };
}

function buildPort(addressSpace, master, port, config, channel, canWrite) {
  const iol = addressSpace.getNamespaceIndex(IOL);
  const portType = addressSpace.findObjectType("IOLinkPortType", iol);
  const portNode = portType.instantiate({
    browseName: { name: `Port${port}`, namespaceIndex: iol },
    componentOf: master,
    eventNotifier: 1,
    optionals: ["ParameterSet.NumberOfCycles", "ParameterSet.NumberOfDeviceHasBeenExchanged"],
  });
  const ps = portNode.getComponentByName("ParameterSet");
  const set = (name, dataType, value) => setValue(ps.getComponentByName(name), dataType, value);
  set("CycleTime", DataType.Double, config.cycle_ms);
  set("ActualCycleTime", DataType.Double, config.cycle_ms);
  set("PortMode", DataType.Byte, enumIndex(ps.getComponentByName("PortMode"), "IOL_AUTOSTART"));
  set("ValidationAndBackup", DataType.Byte,
    enumIndex(ps.getComponentByName("ValidationAndBackup"), "Type compatible Device V1.1, Backup + Restore"));
  set("Pin2Configuration", DataType.Byte, enumIndex(ps.getComponentByName("Pin2Configuration"), "Not supported"));
  set("PortClass", DataType.Byte, enumIndex(ps.getComponentByName("PortClass"), "CLASS A"));
  set("Baudrate", DataType.Byte, enumIndex(ps.getComponentByName("Baudrate"), "COM3")); // manual 1
  set("Pin2Support", DataType.Boolean, false);
  set("UseIODD", DataType.Boolean, false);
  set("DeviceID", DataType.UInt32, config.device_id);
  set("VendorID", DataType.UInt16, config.vendor_id);
  setValue(portNode.getPropertyByName("DeviceConfigurationDisabled"), DataType.Boolean, true);
  portNode.getComponentByName("MethodSet").getMethodByName("UpdateConfiguration")
    .bindMethod(async (_args, _context) => ({ statusCode: StatusCodes.BadNotSupported }));
  const statusNode = ps.getComponentByName("Status");
  const status = {
    OPERATE: enumIndex(statusNode, "OPERATE"),
    NO_DEVICE: enumIndex(statusNode, "NO_DEVICE"),
    PORT_FAULT: enumIndex(statusNode, "PORT_FAULT"),
  };
  const d = buildDevice(addressSpace, port, portNode, config, channel, canWrite);
  return { portNode, ...d, ps, status };
}

function buildMaster(addressSpace, config, channel, canWrite) {
  const ns = addressSpace.getOwnNamespace();
  const iol = addressSpace.getNamespaceIndex(IOL);
  const di = addressSpace.getNamespaceIndex(DI);
  const masterType = addressSpace.findObjectType("IOLinkMasterType", iol);
  const masterSet = addressSpace.findNode(resolveNodeId(`ns=${iol};i=5005`)); // IOLinkMasterSet (8.4)
  const master = masterType.instantiate({
    browseName: { name: "IOLinkMaster", namespaceIndex: ns.index },
    nodeId: `ns=${ns.index};s=IOLinkMaster`,
    organizedBy: masterSet,
    eventNotifier: 1,
    optionals: ["ProductID", "ProductText"],
  });
  const deviceSet = addressSpace.findNode(resolveNodeId(`ns=${di};i=5001`)); // DI DeviceSet
  if (deviceSet) deviceSet.addReference({ referenceType: "Organizes", nodeId: master });
  setValue(master.getPropertyByName("DeviceID"), DataType.UInt32, 0);
  setValue(master.getPropertyByName("ProductID"), DataType.String, "sreh-twin serve");
  setValue(master.getPropertyByName("ProductText"), DataType.String, "Virtual IO-Link master of the sreh-twin digital twin");
  setValue(master.getPropertyByName("MasterConfigurationDisabled"), DataType.Boolean, true);
  const mps = master.getComponentByName("ParameterSet");
  setValue(mps.getComponentByName("MaxNumberOfPorts"), DataType.Byte, config.ports);
  setValue(mps.getComponentByName("MasterType"), DataType.Byte, enumIndex(mps.getComponentByName("MasterType"), "Master acc. V1.1"));
  for (const tag of ["ApplicationSpecificTag", "FunctionTag", "LocationTag"])
    setValue(mps.getComponentByName(tag), DataType.String, "");
  master.getComponentByName("MethodSet").getMethodByName("Restart")
    .bindMethod(async (_args, _context) => ({ statusCode: StatusCodes.BadNotSupported }));
  const ports = [];
  for (let p = 1; p <= config.ports; ++p) ports.push(buildPort(addressSpace, master, p, config, channel, canWrite));
  return { master, ports };
}

// Process data of one master cycle (serve sends it when it changed).
function updateProcessData(port, m) {
  const inStatus = m.in_valid ? StatusCodes.Good : StatusCodes.BadNoCommunication;
  const when = m.ts ? new Date(m.ts) : undefined; // when serve read it from the master cycle
  port.pdIn.setValueFromSource(byteArray(bytes(m.in)), inStatus, when);
  port.pdOut.setValueFromSource(byteArray(bytes(m.out)), m.out_valid ? StatusCodes.Good : StatusCodes.UncertainLastUsableValue, when);
  const quality = (m.in_valid ? 0 : 1) | (m.out_valid ? 0 : 2); // OptionSet: PDIn invalid, PDOut invalid
  setValue(port.ps.getComponentByName("Quality"), DataType.Byte, quality);
}

// Port status and statistics (a few times a second).
function updatePort(port, m) {
  const status = m.failure ? port.status.PORT_FAULT : m.link_up && m.powered ? port.status.OPERATE : port.status.NO_DEVICE;
  setValue(port.ps.getComponentByName("Status"), DataType.Byte, status);
  setValue(port.ps.getComponentByName("NumberOfCycles"), DataType.UInt32, m.cycles >>> 0);
  setValue(port.ps.getComponentByName("NumberOfDeviceHasBeenExchanged"), DataType.UInt32, m.device_replacements >>> 0);
}

// An IO-Link event of the device (iolink.md: qualifier bits 5-4 type, 7-6 mode):
// warnings and errors appear/disappear as IOLinkDeviceAlarmType (9.8, ActiveState),
// notifications as IOLinkDeviceEventType's concrete use with severity 200 (9.3).
function raiseDeviceEvent(addressSpace, port, m) {
  const iol = addressSpace.getNamespaceIndex(IOL);
  const qualifier = parseInt(m.qualifier, 16);
  const code = parseInt(m.code, 16);
  const type = (qualifier >> 4) & 3; // 1 notification, 2 warning, 3 error
  const severity = type === 3 ? 700 : type === 2 ? 500 : 200;
  const alarm = type >= 2;
  const eventType = addressSpace.findEventType(alarm ? "IOLinkDeviceAlarmType" : "IOLinkIODDDeviceEventType", iol);
  const active = m.mode === "appears";
  const data = {
    message: { dataType: DataType.LocalizedText, value: coerceLocalizedText(`IO-Link EventCode: 0x${code.toString(16).toUpperCase().padStart(4, "0")}`) },
    severity: { dataType: DataType.UInt16, value: severity },
    sourceName: { dataType: DataType.String, value: "Device" },
    [lowerFirstLetter("IOLinkEventCode")]: { dataType: DataType.UInt16, value: code },
  };
  if (alarm) {
    data["activeState"] = { dataType: DataType.LocalizedText, value: coerceLocalizedText(active ? "Active" : "Inactive") };
    data["activeState.id"] = { dataType: DataType.Boolean, value: active };
    data["ackedState"] = { dataType: DataType.LocalizedText, value: coerceLocalizedText("Acknowledged") };
    data["ackedState.id"] = { dataType: DataType.Boolean, value: true };
    data["enabledState"] = { dataType: DataType.LocalizedText, value: coerceLocalizedText("Enabled") };
    data["enabledState.id"] = { dataType: DataType.Boolean, value: true };
    data["retain"] = { dataType: DataType.Boolean, value: active };
  }
  port.device.raiseEvent(eventType, data);
}

module.exports = { buildMaster, updateProcessData, updatePort, raiseDeviceEvent };
