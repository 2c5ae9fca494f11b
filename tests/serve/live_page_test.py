"""The live page (issue 18) in headless Chromium, driven over the DevTools
protocol (--remote-debugging-pipe): it loads without console errors or
exceptions, its charting library comes from the binary, mouse clicks on its
buttons switch the motor on and move the twin to 90 deg (checked through the
HTTP API and on the page), and a screenshot is taken. Skipped (77) without
chromium (SREH_WITH_BROWSER=1 ./setup.sh installs it)."""
import base64
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time

from harness import Serve, check, fail, wait_until

exe = sys.argv[1]
browser = shutil.which("chromium")
if not browser:
    print("SKIP: chromium not installed")
    sys.exit(77)


class Cdp:
    """DevTools protocol over the pipe: NUL-terminated JSON on fds 3 (to Chromium) and 4 (from it)."""

    def __init__(self, url_dir):
        to_r, self.to_w = os.pipe()
        self.from_r, from_w = os.pipe()
        self.proc = subprocess.Popen(
            [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--remote-debugging-pipe", "--user-data-dir=" + url_dir, "--window-size=1400,900", "about:blank"],
            pass_fds=(3, 4), preexec_fn=lambda: (os.dup2(to_r, 3), os.dup2(from_w, 4)),
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_r)
        os.close(from_w)
        self.buf = b""
        self.next_id = 0
        self.events = []
        self.session = None

    def send(self, method, params=None, session=True, timeout=20):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session and self.session:
            msg["sessionId"] = self.session
        os.write(self.to_w, json.dumps(msg).encode() + b"\0")
        end = time.monotonic() + timeout
        while True:
            for m in self.pump(end):
                if m.get("id") == self.next_id:
                    if "error" in m:
                        fail("CDP %s: %s" % (method, m["error"]))
                    return m["result"]

    def pump(self, end):
        if time.monotonic() > end:
            fail("Chromium did not answer in time")
        r, _, _ = select.select([self.from_r], [], [], max(0.0, min(0.2, end - time.monotonic())))
        if r:
            chunk = os.read(self.from_r, 1 << 20)
            if not chunk:
                fail("Chromium closed the pipe")
            self.buf += chunk
        out = []
        while b"\0" in self.buf:
            raw, self.buf = self.buf.split(b"\0", 1)
            m = json.loads(raw)
            if "method" in m:
                self.events.append(m)
            out.append(m)
        return out

    def evaluate(self, expr):
        r = self.send("Runtime.evaluate", {"expression": expr, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in r:
            fail("page script failed: %s" % r["exceptionDetails"])
        return r["result"].get("value")

    def click(self, element_id):
        """A real mouse click at the button's centre."""
        box = self.evaluate("(() => { const r = document.getElementById(%s).getBoundingClientRect();"
                            " return [r.x + r.width / 2, r.y + r.height / 2]; })()" % json.dumps(element_id))
        for kind in ("mousePressed", "mouseReleased"):
            self.send("Input.dispatchMouseEvent", {"type": kind, "x": box[0], "y": box[1], "button": "left",
                                                   "clickCount": 1})

    def close(self):
        try:
            self.send("Browser.close", session=False, timeout=5)
        except SystemExit:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


tmp = tempfile.mkdtemp()
shot = os.path.join(os.getcwd(), "serve_live_page.png")
s = Serve(exe, "--ports", "2")
cdp = Cdp(os.path.join(tmp, "profile"))
try:
    target = cdp.send("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
    cdp.session = cdp.send("Target.attachToTarget", {"targetId": target, "flatten": True}, session=False)["sessionId"]
    for domain in ("Runtime.enable", "Log.enable", "Page.enable"):
        cdp.send(domain)
    cdp.send("Page.navigate", {"url": s.http + "/"})
    end = time.monotonic() + 20
    while not cdp.evaluate("!!document.getElementById('p2-card') && document.getElementById('status').textContent === 'live'"):
        cdp.pump(end)
    check(cdp.evaluate("typeof Dygraph") == "function", "charting library not loaded from /assets")
    check(cdp.evaluate("document.querySelectorAll('.dygraph-axis-label').length") > 0, "plots not drawn")

    state = lambda: s.get("/v1/ports/1/processdata")["in"]["state"]
    cdp.click("p1-motor-on")
    wait_until(lambda: state() == "Ready", "Ready after clicking Motor on")
    cdp.evaluate("document.getElementById('p1-target').value = '90'")
    cdp.click("p1-move")
    # The page holds Move until Done, then releases it (manual 3.2): the device ends in Ready at 90 deg.
    wait_until(lambda: abs(s.get("/v1/ports/1/processdata")["in"]["position_deg"] - 90) < 0.1 and state() == "Ready"
               and not s.get("/v1/ports/1/processdata")["out"]["move"], "the twin at 90 deg with Move released")
    end = time.monotonic() + 10
    while abs(float(cdp.evaluate("document.getElementById('p1-card').dataset.position || 'nan'")) - 90) > 0.1:
        cdp.pump(end)
    check(s.get("/v1/ports/2/processdata")["in"]["state"] == "MotorOff", "port 2 moved too")
    png = base64.b64decode(cdp.send("Page.captureScreenshot", {"format": "png"})["data"])
    check(png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 20000, "screenshot is not a plausible PNG")
    with open(shot, "wb") as f:
        f.write(png)
    problems = [e for e in cdp.events if e["method"] == "Runtime.exceptionThrown"
                or (e["method"] == "Runtime.consoleAPICalled" and e["params"]["type"] in ("error", "warning", "assert"))
                or (e["method"] == "Log.entryAdded" and e["params"]["entry"]["level"] in ("error", "warning"))]
    check(not problems, "console errors: %s" % json.dumps(problems)[:2000])
finally:
    cdp.close()
    rc, err = s.stop()
    s.kill()
    shutil.rmtree(tmp, ignore_errors=True)
check(rc == 0, "exit %d: %s" % (rc, err))
print("PASS (screenshot %s)" % shot)
