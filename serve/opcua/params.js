// The device's parameters as variables of the Device's ParameterSet,
// generated from the one parameter table (device_logic/parameter_table, the
// same source as `sreh-twin params` and the IODD export; serve sends it in the
// config message). Per OPC 30120's IODD mapping (11): a variable per IODD
// Variable named by its name; a record is a variable whose record items are
// its components. Numbers are AnalogItemType (OPC 10000-8) in display units
// with EURange and EngineeringUnits (UNECE codes); reads and writes are ISDU
// transfers through serve, so a refused write answers the device's code.
"use strict";
const { DataType, Variant, StatusCodes, DataValue } = require("node-opcua");
const { makeEUInformation } = require("node-opcua-data-access");

// Display unit of the table -> UNECE common code, symbol, description.
const kUnits = {
  "deg": ["DD", "°", "degree [unit of angle]"],
  "deg/s": ["E96", "°/s", "degree per second"],
  "%": ["P1", "%", "percent"],
  "ms": ["C26", "ms", "millisecond"],
  "V": ["VLT", "V", "volt"],
  "degC": ["CEL", "°C", "degree Celsius"],
  "h": ["HUR", "h", "hour"],
  "octet": ["AD", "B", "byte"],
  "g cm^2": ["B32", "g·cm²", "gram centimetre squared (UNECE has no code for it: kg m² used, A-OPCUA-4)"],
  "1": ["C62", "1", "one (a count)"],
};

// Indices the 30120 model already shows as standard nodes of the Device or
// as methods: identification (13, 16..26 -> properties and tags), system
// command (2, write-only), error count (32), detailed status (37), the
// process data images (40, 41 -> ProcessDataInput/Output).
const kCovered = new Set([2, 13, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 32, 37, 40, 41]);

const kWire = {
  uint8: { bytes: 1, read: (b) => b.readUInt8(0), write: (b, v) => b.writeUInt8(v) },
  uint16: { bytes: 2, read: (b) => b.readUInt16BE(0), write: (b, v) => b.writeUInt16BE(v) },
  uint32: { bytes: 4, read: (b) => b.readUInt32BE(0), write: (b, v) => b.writeUInt32BE(v) },
  int32: { bytes: 4, read: (b) => b.readInt32BE(0), write: (b, v) => b.writeInt32BE(v) },
};

function euInformation(unit) {
  const u = kUnits[unit];
  if (!u) return undefined;
  return makeEUInformation(u[0], u[1], u[2]);
}

// ISDU request through serve -> DataValue / StatusCode.
function readValue(channel, port, row, decode) {
  return channel.request({ p: port, op: "isdu_read", index: row.index, sub: row.subindex }).then((r) => {
    if (!r.ok) return new DataValue({ statusCode: r.iolink_error !== undefined ? StatusCodes.BadNotReadable : StatusCodes.BadNoCommunication });
    return new DataValue({ value: decode(Buffer.from(r.data, "hex")), statusCode: StatusCodes.Good, sourceTimestamp: new Date() });
  });
}

function writeStatus(r) {
  if (r.ok) return StatusCodes.Good;
  if (r.iolink_error === undefined) return StatusCodes.BadNoCommunication;
  const code = r.iolink_error;
  if (code >= 0x8030 && code <= 0x8034) return StatusCodes.BadOutOfRange; // value / length out of range (iolink.md)
  if (code === 0x8023) return StatusCodes.BadNotWritable;
  return StatusCodes.BadInvalidState; // 0x8020.., 0x8040, 0x8041: not now / not this way
}

function addNumeric(ns, parent, port, row, channel, canWrite) {
  const wire = kWire[row.type];
  const scale = row.display_scale;
  const writable = row.access !== "r";
  const variable = ns.addAnalogDataItem({
    componentOf: parent,
    browseName: row.name,
    nodeId: `s=Port${port}.${row.index}.${row.subindex}`,
    description: `${row.notes ? row.notes + "; " : ""}ISDU index ${row.index}, subindex ${row.subindex}; manual ${row.section}; raw unit ${row.raw_unit || "-"}`,
    dataType: "Double",
    engineeringUnitsRange: { low: row.min * scale, high: row.max * scale },
    engineeringUnits: euInformation(row.display_unit),
    accessLevel: writable ? "CurrentRead | CurrentWrite" : "CurrentRead",
    minimumSamplingInterval: 100,
  });
  const decode = (b) => new Variant({ dataType: DataType.Double, value: b.length >= wire.bytes ? wire.read(b) * scale : NaN });
  const options = { refreshFunc: (cb) => readValue(channel, port, row, decode).then((dv) => cb(null, dv)) };
  if (writable)
    options.set = (variant, cb) => {
      const raw = Math.round(Number(variant.value) / scale);
      const b = Buffer.alloc(wire.bytes);
      try {
        wire.write(b, raw);
      } catch (e) {
        return cb(null, StatusCodes.BadOutOfRange); // does not fit the wire type
      }
      channel.request({ p: port, op: "isdu_write", index: row.index, sub: row.subindex, data: b.toString("hex") })
        .then((r) => cb(null, writeStatus(r)));
    };
  variable.bindVariable(options, true);
  if (writable) variable.isUserWritable = (context) => canWrite(context);
  return variable;
}

function addOctets(ns, parent, port, row, channel, canWrite, browseName) {
  const isText = row.type === "string";
  const variable = ns.addVariable({
    componentOf: parent,
    browseName: browseName || row.name,
    nodeId: `s=Port${port}.${row.index}.${row.subindex}`,
    description: `ISDU index ${row.index}, subindex ${row.subindex}; manual ${row.section}`,
    dataType: isText ? "String" : "ByteString",
    accessLevel: row.access === "rw" ? "CurrentRead | CurrentWrite" : "CurrentRead",
    minimumSamplingInterval: 100,
  });
  const decode = (b) => isText ? new Variant({ dataType: DataType.String, value: b.toString("latin1").replace(/\0+$/, "") })
    : new Variant({ dataType: DataType.ByteString, value: b });
  const options = { refreshFunc: (cb) => readValue(channel, port, row, decode).then((dv) => cb(null, dv)) };
  if (row.access === "rw")
    options.set = (variant, cb) => {
      const b = isText ? Buffer.from(String(variant.value), "latin1") : Buffer.from(variant.value || []);
      channel.request({ p: port, op: "isdu_write", index: row.index, sub: row.subindex, data: b.toString("hex") })
        .then((r) => cb(null, writeStatus(r)));
    };
  variable.bindVariable(options, true);
  if (row.access === "rw") variable.isUserWritable = (context) => canWrite(context);
  return variable;
}

function addParameters(addressSpace, device, port, rows, channel, canWrite) {
  const ns = addressSpace.getOwnNamespace();
  const ps = device.getComponentByName("ParameterSet");
  const records = new Map(); // index -> record variable
  for (const row of rows) {
    if (kCovered.has(row.index) || row.access === "w") continue;
    let parent = ps;
    if (row.record) {
      if (!records.has(row.index)) {
        const rec = { index: row.index, subindex: 0, type: "octets", access: "r", section: row.section };
        records.set(row.index, addOctets(ns, ps, port, rec, channel, canWrite, row.record));
      }
      parent = records.get(row.index);
    }
    if (kWire[row.type]) addNumeric(ns, parent, port, row, channel, canWrite);
    else addOctets(ns, parent, port, row, channel, canWrite);
  }
}

module.exports = { addParameters };
