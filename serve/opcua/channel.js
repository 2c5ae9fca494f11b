// The local channel to `sreh-twin serve` (docs/opcua.md "Channel"): JSON
// lines on stdin (serve -> front) and stdout (front -> serve). Requests carry
// an id; serve answers each with {"t": "reply", "id", ...}. stdin closing
// means serve is gone: the front exits.
"use strict";
const readline = require("readline");

const kRequestTimeoutMs = 5000; // an IO-Link master waits about 5 s for an ISDU answer (iolink.md)

class Channel {
  constructor(input = process.stdin, output = process.stdout) {
    this.output = output;
    this.nextId = 1;
    this.pending = new Map(); // id -> {resolve, timer}
    this.handlers = new Map(); // message type -> function(message)
    this.rl = readline.createInterface({ input, crlfDelay: Infinity });
    this.rl.on("line", (line) => this.dispatch(line));
    this.rl.on("close", () => this.emitClose());
  }

  on(type, handler) {
    this.handlers.set(type, handler);
  }

  emitClose() {
    const h = this.handlers.get("close");
    if (h) h();
  }

  dispatch(line) {
    if (!line) return;
    let m;
    try {
      m = JSON.parse(line);
    } catch (e) {
      process.stderr.write(`opcua front: a line from serve is not JSON (${e.message})\n`);
      return;
    }
    if (m.t === "reply") {
      const p = this.pending.get(m.id);
      if (!p) return; // answered after its timeout
      this.pending.delete(m.id);
      clearTimeout(p.timer);
      p.resolve(m);
      return;
    }
    const h = this.handlers.get(m.t);
    if (h) h(m);
  }

  send(message) {
    this.output.write(JSON.stringify(message) + "\n");
  }

  // A request to serve; resolves with its reply, or {ok: false, timeout: true}.
  request(body) {
    const id = this.nextId++;
    return new Promise((resolve) => {
      const timer = setTimeout(() => {
        this.pending.delete(id);
        resolve({ ok: false, timeout: true });
      }, kRequestTimeoutMs);
      this.pending.set(id, { resolve, timer });
      this.send({ t: "req", id, ...body });
    });
  }
}

module.exports = { Channel };
