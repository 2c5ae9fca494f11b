// opcua_security_test.py's client: one connection attempt in the given way,
// printing one JSON line {"ok": bool, "error": text, "status": ReadISDU's Status}.
// Usage: node opcua_secure_client.js ENDPOINT none|secure PKI_DIR [USER PASSWORD]
"use strict";
for (const k of ["log", "info", "warn", "debug"]) console[k] = console.error; // stdout carries the result only
const opcua = require("node-opcua");

const [endpoint, mode, pki, user, password] = process.argv.slice(2);

(async () => {
  const secure = mode === "secure";
  const client = opcua.OPCUAClient.create({
    endpointMustExist: false,
    connectionStrategy: { maxRetry: 0, initialDelay: 100 },
    securityMode: secure ? opcua.MessageSecurityMode.SignAndEncrypt : opcua.MessageSecurityMode.None,
    securityPolicy: secure ? opcua.SecurityPolicy.Basic256Sha256 : opcua.SecurityPolicy.None,
    clientCertificateManager: new opcua.OPCUACertificateManager({ rootFolder: pki, automaticallyAcceptUnknownCertificate: true }),
  });
  let result;
  try {
    await client.connect(endpoint);
    const identity = user ? { type: opcua.UserTokenType.UserName, userName: user, password } : undefined;
    const session = await client.createSession(identity);
    // A write needs the user (A-OPCUA-6): the tag of port 1 through WriteISDU.
    const device = "ns=1;s=IOLinkMaster-Port1-Device";
    const methodSet = (await session.browse(device)).references.find((r) => r.browseName.name === "MethodSet").nodeId;
    const write = (await session.browse(methodSet)).references.find((r) => r.browseName.name === "WriteISDU").nodeId;
    const r = await session.call({ objectId: methodSet, methodId: write, inputArguments: [
      { dataType: opcua.DataType.UInt16, value: 26 }, { dataType: opcua.DataType.Byte, value: 0 },
      { dataType: opcua.DataType.Byte, arrayType: opcua.VariantArrayType.Array, value: Buffer.from("hall 3") }] });
    result = { ok: true, call: r.statusCode.name, status: r.outputArguments.length ? r.outputArguments[1].value : null };
    await session.close();
  } catch (e) {
    result = { ok: false, error: String(e.message || e).split("\n")[0] };
  }
  await client.disconnect().catch(() => {});
  process.stdout.write(JSON.stringify(result) + "\n");
})();
