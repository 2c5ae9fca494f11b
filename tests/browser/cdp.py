"""Headless Chromium driven over the DevTools protocol (--remote-debugging-pipe),
shared by the browser tests (tests/browser/pages_test.py, tests/serve/live_page_test.py)
and the screenshot script (docs/img/make_screenshots.sh). Standard library only."""
import base64
import json
import os
import select
import shutil
import subprocess
import sys
import time


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def browser_or_skip():
    """The chromium binary, or exit 77 (CTest: skipped) without it."""
    browser = shutil.which("chromium")
    if not browser:
        print("SKIP: chromium not installed (SREH_WITH_BROWSER=1 ./setup.sh installs it)")
        sys.exit(77)
    return browser


class Cdp:
    """DevTools protocol over the pipe: NUL-terminated JSON on fds 3 (to Chromium) and 4 (from it)."""

    def __init__(self, profile_dir, width=1400, height=900, browser=None):
        browser = browser or browser_or_skip()
        to_r, self.to_w = os.pipe()
        self.from_r, from_w = os.pipe()
        self.proc = subprocess.Popen(
            [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--hide-scrollbars", "--remote-debugging-pipe", "--user-data-dir=" + profile_dir,
             "--window-size=%d,%d" % (width, height), "about:blank"],
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

    def open_tab(self):
        """A new tab, attached, with Runtime, Log and Page events on."""
        target = self.send("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
        self.session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True}, session=False)["sessionId"]
        for domain in ("Runtime.enable", "Log.enable", "Page.enable"):
            self.send(domain)

    def set_width(self, width, height=900):
        """The viewport the page lays out in, CSS pixels (scale 1)."""
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})

    def navigate(self, url, ready="document.readyState === 'complete'", timeout=20):
        """Loads `url` and waits until the expression `ready` holds."""
        self.send("Page.navigate", {"url": url})
        end = time.monotonic() + timeout
        time.sleep(0.05)
        while not self.evaluate(ready):
            self.pump(end)

    def evaluate(self, expr):
        r = self.send("Runtime.evaluate", {"expression": expr, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in r:
            fail("page script failed: %s" % r["exceptionDetails"])
        return r["result"].get("value")

    def click(self, element_id):
        """A real mouse click at the element's centre, scrolled into the viewport first."""
        box = self.evaluate("(() => { const e = document.getElementById(%s); e.scrollIntoView({block: 'center'});"
                            " const r = e.getBoundingClientRect();"
                            " return [r.x + r.width / 2, r.y + r.height / 2]; })()" % json.dumps(element_id))
        for kind in ("mousePressed", "mouseReleased"):
            self.send("Input.dispatchMouseEvent", {"type": kind, "x": box[0], "y": box[1], "button": "left",
                                                   "clickCount": 1})

    def screenshot(self, path=None, max_height=None, scale=1.0):
        """PNG of the whole page (not just the viewport), at most `max_height` CSS pixels from the top."""
        w, h = self.evaluate("[document.documentElement.clientWidth, document.documentElement.scrollHeight]")
        if max_height:
            h = min(h, max_height)
        png = base64.b64decode(self.send("Page.captureScreenshot", {
            "format": "png", "captureBeyondViewport": True,
            "clip": {"x": 0, "y": 0, "width": w, "height": h, "scale": scale}}, timeout=60)["data"])
        if path:
            with open(path, "wb") as f:
                f.write(png)
        return png

    def problems(self):
        """Console errors and warnings and uncaught exceptions seen so far."""
        return [e for e in self.events if e["method"] == "Runtime.exceptionThrown"
                or (e["method"] == "Runtime.consoleAPICalled" and e["params"]["type"] in ("error", "warning", "assert"))
                or (e["method"] == "Log.entryAdded" and e["params"]["entry"]["level"] in ("error", "warning"))]

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
