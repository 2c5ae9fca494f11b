"""The reports on paper and in narrow windows (issue 37): the studio (its page
and its printable report), `size`, `size --cycle`, `sweep` and `calibrate`
reports, each in headless Chromium

- at 1400 x 900 and 800 x 900: nothing wider than the page (layout_check.js)
  and no table cell narrower than its longest word (print_check.js); a
  screenshot of each is written;
- laid out for A4 (print media, 186 mm = 703 CSS px between the 12 mm
  margins): the same, and no box that scrolls sideways (on paper its hidden
  part is cut); page 1 (273 mm = 1032 px) holds where the report came from
  (the inputs) and the verdict (a sweep: its verdict table begins there; a
  calibration: its constants); Chromium prints an A4 PDF, written.
A narrow cell with a long word and a sideways-scrolling box are reported
(the check can fail). Skipped (77) without chromium.

usage: print_test.py SREH_TWIN SOURCE_DIR OUT_DIR"""
import base64
import json
import os
import re
import shutil
import sys
import tempfile
import urllib.parse

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from cdp import Cdp, browser_or_skip, fail  # noqa: E402
from pages import make_pages  # noqa: E402
from studio_test import ANSWERED, Studio  # noqa: E402

LAYOUT_JS = open(os.path.join(here, "layout_check.js")).read()
PRINT_JS = open(os.path.join(here, "print_check.js")).read()
REPORT_READY = ("document.readyState === 'complete' && "
                "document.querySelectorAll('.fig .dy').length === document.querySelectorAll('.fig.live').length")
A4_WIDTH_PX, A4_HEIGHT_PX = 703, 1032  # 186 x 273 mm at 96 px per inch
# What page 1 must hold: (element, "bottom": it ends there | "top": it begins there).
PAGE_ONE = {
    "size": [("#provenance", "bottom"), ("#verdict", "bottom")],
    "cycle": [("#provenance", "bottom"), ("#verdict", "bottom")],
    "studio-report": [("#provenance", "bottom"), ("#verdict", "bottom")],
    "studio": [("#load-figures", "bottom"), ("#verdict-box .verdict", "bottom")],
    "sweep": [("#provenance", "bottom"), ("#verdicts", "top")],
    "calibration": [("#provenance", "bottom"), ("h2 + table, h2 + * table", "top")],
}
# A studio state: a plate on the axis and a block 50 mm off it, 90 deg within 300 ms.
STATE = {"name": "print check", "angle_deg": 90, "target": "positioning", "target_ms": 300,
         "parts": [{"name": "plate", "shape": "disk", "mass_kg": 0.2, "radius_m": 0.04, "thickness_m": 0.01, "at_m": [0, 0, 0.005]},
                   {"name": "block", "shape": "box", "mass_kg": 0.1, "x_m": 0.02, "y_m": 0.02, "z_m": 0.02, "at_m": [0.05, 0, 0.02]}]}


def check(cond, msg):
    if not cond:
        fail(msg)


def problems(cdp, label, printed):
    found = ["%s: %s" % (label, p) for p in cdp.evaluate(LAYOUT_JS)]
    return found + ["%s: %s" % (label, p) for p in cdp.evaluate("(%s)(%s)" % (PRINT_JS, "true" if printed else "false"))]


def page_one(cdp, name):
    """Where each element that must be on page 1 begins or ends, px from the top of the document."""
    out = []
    for selector, edge in PAGE_ONE[name]:
        y = cdp.evaluate("""(() => { const e = document.querySelector(%s); if (!e) return null;
          const r = e.getBoundingClientRect(); return (%s) + window.scrollY; })()"""
                         % (json.dumps(selector), "r.bottom" if edge == "bottom" else "r.top + 60"))
        if y is None:
            out.append("%s printed: no %s" % (name, selector))
        elif y > A4_HEIGHT_PX:
            out.append("%s printed: %s %s at %d px, past page 1 (%d px)" % (name, selector, "ends" if edge == "bottom" else "begins",
                                                                              y, A4_HEIGHT_PX))
    return out


def check_page(cdp, name, url, ready, out):
    found = []
    for width in (1400, 800):
        cdp.set_width(width)
        cdp.navigate(url, ready, timeout=60)
        found += problems(cdp, "%s at %d px" % (name, width), False)
        cdp.screenshot(os.path.join(out, "%s-%d.png" % (name, width)), max_height=3000)
    cdp.set_width(A4_WIDTH_PX, A4_HEIGHT_PX)
    cdp.send("Emulation.setEmulatedMedia", {"media": "print"})
    found += problems(cdp, "%s printed" % name, True)
    found += page_one(cdp, name)
    pdf = base64.b64decode(cdp.send("Page.printToPDF", {"preferCSSPageSize": True, "printBackground": True}, timeout=60)["data"])
    if not (pdf[:5] == b"%PDF-" and re.search(rb"/MediaBox ?\[0 0 59[45]\.?[0-9]* 84[12]", pdf)):
        found.append("%s: no A4 PDF" % name)
    with open(os.path.join(out, name + ".pdf"), "wb") as f:
        f.write(pdf)
    cdp.send("Emulation.setEmulatedMedia", {"media": ""})
    return found


def check_the_check_can_fail(cdp, url):
    cdp.set_width(800)
    cdp.navigate(url, REPORT_READY)
    cdp.evaluate("""(() => {
      const t = document.createElement('table'); t.id = 'narrow';
      t.innerHTML = '<tr><td style="width:30px;max-width:30px;overflow-wrap:anywhere">unbreakablelongword</td></tr>';
      document.body.prepend(t);
      const d = document.createElement('div'); d.id = 'scrolls'; d.style.overflowX = 'auto';
      d.innerHTML = '<div style="width:2000px">wide</div>'; document.body.prepend(d);
      return true; })()""")
    found = cdp.evaluate("(%s)(true)" % PRINT_JS)
    check(any("unbreakablelongword" in p and "broken" in p for p in found), "a word broken in a narrow cell went unnoticed: %s" % found)
    check(any("div#scrolls" in p and "cut" in p for p in found), "a sideways-scrolling box went unnoticed: %s" % found)


def main():
    exe, src, out = sys.argv[1], sys.argv[2], sys.argv[3]
    browser_or_skip()
    os.makedirs(out, exist_ok=True)
    tmp = tempfile.mkdtemp()
    studio = None
    cdp = None
    try:
        pages = make_pages(exe, src, tmp)
        pages.pop("run")  # the run report is checked by pages_test.py; issue 37 names the sizing and calibration reports
        studio = Studio(exe)
        pages["studio-report"] = studio.url + "report?s=" + urllib.parse.quote(json.dumps(STATE))
        cdp = Cdp(os.path.join(tmp, "profile"))
        cdp.open_tab()
        found = []
        for name, url in pages.items():
            # The studio's printable page has the static plots only (no plotting script is served with it).
            found += check_page(cdp, name, url, "document.readyState === 'complete'" if name == "studio-report" else REPORT_READY, out)
        state_link = studio.url + "#state=" + urllib.parse.quote(json.dumps({"state": STATE, "pins": []}))
        found += check_page(cdp, "studio", state_link, ANSWERED + " && !!window.studio.answer.size", out)
        check(not found, "%d problems:\n  %s" % (len(found), "\n  ".join(found[:60])))
        check_the_check_can_fail(cdp, pages["size"])
    finally:
        if cdp:
            cdp.close()
        if studio:
            studio.stop()
        shutil.rmtree(tmp, ignore_errors=True)
    print("PASS: %d pages at 1400 and 800 px and on A4: nothing too wide, no word broken in a cell, page 1 holds "
          "the inputs and the verdict; screenshots and PDFs in %s" % (len(pages) + 1, out))


if __name__ == "__main__":
    main()
