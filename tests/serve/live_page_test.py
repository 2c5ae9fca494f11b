"""The live page (issue 18) in headless Chromium, driven over the DevTools
protocol (--remote-debugging-pipe): it loads without console errors or
exceptions, its charting library comes from the binary, mouse clicks on its
buttons switch the motor on and move the twin to 90 deg (checked through the
HTTP API and on the page), and a screenshot is taken. Skipped (77) without
chromium (SREH_WITH_BROWSER=1 ./setup.sh installs it)."""
import base64
import json
import os
import shutil
import sys
import tempfile
import time

from harness import Serve, check, wait_until

# The DevTools client all browser tests share (tests/browser/cdp.py).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "browser"))
from cdp import Cdp, browser_or_skip  # noqa: E402

exe = sys.argv[1]
browser_or_skip()


tmp = tempfile.mkdtemp()
shot = os.path.join(os.getcwd(), "serve_live_page.png")
s = Serve(exe, "--ports", "2")
cdp = Cdp(os.path.join(tmp, "profile"))
try:
    cdp.open_tab()
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
    problems = cdp.problems()
    check(not problems, "console errors: %s" % json.dumps(problems)[:2000])
finally:
    cdp.close()
    rc, err = s.stop()
    s.kill()
    shutil.rmtree(tmp, ignore_errors=True)
check(rc == 0, "exit %d: %s" % (rc, err))
print("PASS (screenshot %s)" % shot)
