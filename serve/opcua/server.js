#!/usr/bin/env node
// OPC UA front of `sreh-twin serve` (issue 38): an OPC 30120 (IO-Link) server
// built with node-opcua, started and supervised by serve (serve/opcua_front.cpp)
// and coupled to its hub through JSON lines on stdin/stdout (channel.js;
// docs/opcua.md "Channel"). The first line from serve is the configuration;
// the front answers {"t": "ready"} once it listens, or {"t": "fatal"} and
// exits 1. stdin closing (serve gone) or {"t": "stop"} ends it.
"use strict";
// stdout is the channel: node-opcua's own console output goes to stderr, and
// only with SREH_TWIN_OPCUA_VERBOSE=1 (serve's stderr stays one line per event).
const verbose = process.env.SREH_TWIN_OPCUA_VERBOSE === "1";
const toStderr = console.error;
for (const k of ["log", "info", "warn", "debug", "error"]) console[k] = verbose ? toStderr : () => {};
const net = require("net");
const path = require("path");
const opcua = require("node-opcua");
const serverLib = require("node-opcua-server");
const { nodesets } = require("node-opcua-nodesets");
const { Channel } = require("./channel");
const { buildMaster, updateProcessData, updatePort, raiseDeviceEvent } = require("./model");

const channel = new Channel();
let server = null;
let model = null;
let stopping = false;

function fatal(message) {
  channel.send({ t: "fatal", message });
  process.exitCode = 1;
  setImmediate(() => process.exit(1));
}

// Port 0: any free port (node-opcua needs the number for its endpoint URL).
function freePort(host, port) {
  if (port !== 0) return Promise.resolve(port);
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.once("error", reject);
    s.listen(0, host, () => {
      const p = s.address().port;
      s.close(() => resolve(p));
    });
  });
}

// Fails early with a clear message if the address is taken (node-opcua would only log it).
function checkFree(host, port) {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.once("error", (e) => reject(new Error(e.code === "EADDRINUSE" ? "address in use" : e.message)));
    s.listen(port, host, () => s.close(() => resolve()));
  });
}

function securityOptions(config) {
  const { SecurityPolicy, MessageSecurityMode } = opcua;
  if (config.loopback)
    return {
      securityPolicies: [SecurityPolicy.None, SecurityPolicy.Basic256Sha256],
      securityModes: [MessageSecurityMode.None, MessageSecurityMode.SignAndEncrypt],
      allowAnonymous: true,
    };
  // Any other address: encrypted channels only, and a user (docs/opcua.md "Security").
  return {
    securityPolicies: [SecurityPolicy.Basic256Sha256],
    securityModes: [MessageSecurityMode.SignAndEncrypt],
    allowAnonymous: false,
  };
}

// With a password (serve's --token-file), anonymous sessions may read only.
function makeCanWrite(config) {
  if (!config.password) return () => true;
  return (context) => {
    const token = context && context.session && context.session.userIdentityToken;
    return !!token && token.constructor && token.constructor.name === "UserNameIdentityToken";
  };
}

async function start(config) {
  serverLib.MonitoredItem.minimumSamplingInterval = config.min_sampling_ms;
  serverLib.Subscription.minimumPublishingInterval = config.min_publishing_ms;
  const port = await freePort(config.host, config.port);
  await checkFree(config.host, port);
  const pki = config.pki_dir;
  const serverCertificateManager = new opcua.OPCUACertificateManager({
    rootFolder: pki,
    automaticallyAcceptUnknownCertificate: config.loopback, // elsewhere: trust a client by moving its certificate (docs/opcua.md)
  });
  const userCertificateManager = new opcua.OPCUACertificateManager({
    rootFolder: path.join(pki, "user"),
    automaticallyAcceptUnknownCertificate: false,
  });
  const users = config.password
    ? { isValidUser: (user, password) => user === config.user && password === config.password }
    : { isValidUser: () => false };
  server = new opcua.OPCUAServer({
    port,
    hostname: config.host,
    alternateHostname: [config.host],
    nodeset_filename: [nodesets.standard, nodesets.di, nodesets.iolink],
    serverCertificateManager,
    userCertificateManager,
    userManager: users,
    ...securityOptions(config),
    buildInfo: { productName: "sreh-twin OPC UA front", manufacturerName: "sreh-twin", softwareVersion: config.version },
    serverInfo: { applicationUri: "urn:sreh-twin:opcua", productUri: "urn:sreh-twin", applicationName: { text: "sreh-twin" } },
  });
  await server.initialize();
  const addressSpace = server.engine.addressSpace;
  addressSpace.registerNamespace("urn:sreh-twin:opcua");
  model = buildMaster(addressSpace, config, channel, makeCanWrite(config));
  await server.start();
  channel.send({ t: "ready", port, endpoint: server.getEndpointUrl() });
}

async function stop(code) {
  if (stopping) return;
  stopping = true;
  try {
    if (server) await server.shutdown(0);
  } finally {
    process.exit(code);
  }
}

channel.on("config", (config) => {
  start(config).catch((e) => fatal(e.message || String(e)));
});
channel.on("pd", (m) => model && updateProcessData(model.ports[m.p - 1], m));
channel.on("port", (m) => model && updatePort(model.ports[m.p - 1], m));
channel.on("event", (m) => model && raiseDeviceEvent(server.engine.addressSpace, model.ports[m.p - 1], m));
channel.on("stop", () => stop(0));
channel.on("close", () => stop(0));
process.on("SIGTERM", () => stop(0));
process.on("SIGINT", () => {}); // serve decides when the front stops (a Ctrl-C reaches the whole group)
process.on("uncaughtException", (e) => {
  process.stderr.write(`opcua front: ${e.stack || e}\n`);
  process.exit(1);
});
