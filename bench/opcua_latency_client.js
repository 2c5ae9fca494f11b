// bench/opcua_latency.py's OPC UA client: subscribes to Port1's
// ProcessDataInput with the given sampling and publishing intervals for D
// seconds and prints, as one JSON line, how long each change took from serve
// reading it in a master cycle (the value's SourceTimestamp, A-OPCUA-9) to
// this client receiving it (same machine, same clock; 1 ms resolution).
// Usage: node opcua_latency_client.js opc.tcp://HOST:PORT SAMPLING_MS PUBLISHING_MS SECONDS
"use strict";
for (const k of ["log", "info", "warn", "debug"]) console[k] = console.error; // stdout carries the result only
const opcua = require("node-opcua");

const [endpoint, samplingMs, publishingMs, seconds] = process.argv.slice(2);

function quantile(sorted, q) {
  return sorted.length ? sorted[Math.min(sorted.length - 1, Math.ceil(q * sorted.length) - 1)] : null;
}

(async () => {
  const client = opcua.OPCUAClient.create({ endpointMustExist: false });
  await client.connect(endpoint);
  const session = await client.createSession();
  const ns = await session.readNamespaceArray();
  const iol = ns.indexOf("http://opcfoundation.org/UA/IOLink/"), di = ns.indexOf("http://opcfoundation.org/UA/DI/");
  const path = opcua.makeBrowsePath("ns=1;s=IOLinkMaster", `/${iol}:Port1/${iol}:Device/${di}:ParameterSet/${iol}:ProcessDataInput`);
  const found = await session.translateBrowsePath(path);
  if (!found.targets || found.targets.length !== 1) throw new Error("Port1's ProcessDataInput not found");
  const nodeId = found.targets[0].targetId;
  const sub = opcua.ClientSubscription.create(session, { requestedPublishingInterval: Number(publishingMs),
    requestedMaxKeepAliveCount: 100, requestedLifetimeCount: 1000, publishingEnabled: true, priority: 1 });
  const item = opcua.ClientMonitoredItem.create(sub, { nodeId, attributeId: opcua.AttributeIds.Value },
    { samplingInterval: Number(samplingMs), discardOldest: true, queueSize: 1 }, opcua.TimestampsToReturn.Both);
  const latencies = [];
  let skipped = 0;
  item.on("changed", (dv) => {
    const now = Date.now();
    if (!dv.sourceTimestamp) return;
    if (latencies.length === 0 && skipped++ === 0) return; // the initial value is not a change
    latencies.push(now - dv.sourceTimestamp.getTime());
  });
  await new Promise((r) => setTimeout(r, Number(seconds) * 1000));
  const revised = { sampling_ms: item.monitoringParameters.samplingInterval, publishing_ms: sub.publishingInterval };
  await sub.terminate();
  await session.close();
  await client.disconnect();
  latencies.sort((a, b) => a - b);
  process.stdout.write(JSON.stringify({ n: latencies.length, p50_ms: quantile(latencies, 0.5),
    p99_ms: quantile(latencies, 0.99), max_ms: latencies[latencies.length - 1], ...revised }) + "\n");
})().catch((e) => {
  process.stderr.write(`FAIL: ${e.stack || e}\n`);
  process.exit(1);
});
