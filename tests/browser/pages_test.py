"""Every page of sreh-twin laid out in headless Chromium (issue 29): the run
report, the single-move sizing page, the cycle page, the sweep page and
serve's live page, each at a window 1400 and 800 px wide. In the page
(Runtime.evaluate, layout_check.js): no element of an SVG plot outside its
plot's box and no two of its texts on top of each other, no title, legend or
axis label of an interactive plot outside its figure, nothing wider than the
page; both the interactive and the static (print) rendering of each plot.
The sizing pages carry the verdict block and the 70 / 75 degC lines. A
deliberately broken plot and a too-wide element must be reported (the check
can fail). Printed, the sizing page keeps every plot, table and the verdict
whole and gives an A4 PDF. Skipped (77) without chromium.

usage: pages_test.py SREH_TWIN SOURCE_DIR"""
import base64
import os
import re
import shutil
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(here, "..", "serve"))
from cdp import Cdp, browser_or_skip, fail  # noqa: E402
from pages import make_pages  # noqa: E402

WIDTHS = (1400, 800)
CHECK_JS = open(os.path.join(here, "layout_check.js")).read()
# Interactive figures are drawn while the page parses: each .fig with a
# dygraph has turned 'live' once its script ran.
REPORT_READY = ("document.readyState === 'complete' && "
                "document.querySelectorAll('.fig .dy').length === document.querySelectorAll('.fig.live').length")
SHOW_STATIC = "document.querySelectorAll('.fig.live').forEach((f) => f.classList.remove('live')); true"


def check(cond, msg):
    if not cond:
        fail(msg)


def layout_problems(cdp, label):
    """The problems of the page as shown, then with every plot in its static (print) form."""
    found = ["%s: %s" % (label, p) for p in cdp.evaluate(CHECK_JS)]
    cdp.evaluate(SHOW_STATIC)
    found += ["%s (static plots): %s" % (label, p) for p in cdp.evaluate(CHECK_JS)]
    return found


def check_sizing_page(cdp, name):
    """The verdict block with its four bars and the binding limit; the temperature plot's 70 and 75 degC lines."""
    got = cdp.evaluate("""(() => {
      const v = document.getElementById('verdict');
      const t = document.getElementById('svg-temperature');
      const texts = t ? [...t.querySelectorAll('text')].map((e) => e.textContent) : [];
      return {verdict: !!v, bars: v ? v.querySelectorAll('tr[id^=bar-] .fill').length : 0,
              binding: (document.getElementById('binding-limit') || {}).textContent || '',
              ratio: (document.getElementById('inertia-ratio') || {}).textContent || '',
              warning: texts.some((s) => s.startsWith('70 degC warning')), trip: texts.some((s) => s.startsWith('75 degC trip')),
              limits: t ? t.querySelectorAll('line.limit').length : 0, offscale: t ? t.querySelectorAll('.offscale').length : -1};
    })()""")
    check(got["verdict"] and got["bars"] == 4, "%s: no verdict block with 4 bars: %s" % (name, got))
    check(got["binding"] and "J_load / J_intern" in got["ratio"], "%s: verdict without binding limit or ratio: %s" % (name, got))
    check(got["warning"] and got["trip"] and got["limits"] >= 2 and got["offscale"] == 0,
          "%s: the temperature plot lacks the 70 / 75 degC lines on scale: %s" % (name, got))


def check_print(cdp, url):
    """Printed (media print): every plot, table and the verdict one unbreakable block, static plots
    shown instead of the dygraphs, and Chromium makes an A4 PDF of it."""
    cdp.navigate(url, REPORT_READY)
    cdp.send("Emulation.setEmulatedMedia", {"media": "print"})
    got = cdp.evaluate("""(() => {
      const style = (e) => getComputedStyle(e);
      const blocks = [...document.querySelectorAll('.fig, svg.plot, table, .verdict')];
      return {blocks: blocks.length, whole: blocks.filter((e) => style(e).breakInside === 'avoid').length,
              statics: [...document.querySelectorAll('.fig .static')].filter((e) => style(e).display !== 'none').length,
              figs: document.querySelectorAll('.fig').length,
              dygraphs: [...document.querySelectorAll('.fig .dy')].filter((e) => style(e).display !== 'none').length};
    })()""")
    check(got["blocks"] > 5 and got["whole"] == got["blocks"], "print: blocks a page break may cut: %s" % got)
    check(got["statics"] == got["figs"] and got["dygraphs"] == 0, "print: not the static plots: %s" % got)
    pdf = base64.b64decode(cdp.send("Page.printToPDF", {"preferCSSPageSize": True}, timeout=60)["data"])
    check(pdf[:5] == b"%PDF-" and re.search(rb"/MediaBox ?\[0 0 59[45]\.?[0-9]* 84[12]", pdf) is not None,  # A4: 595 x 842 pt
          "print: no A4 PDF (%d bytes)" % len(pdf))
    cdp.send("Emulation.setEmulatedMedia", {"media": ""})


def check_the_check_can_fail(cdp, url):
    """A label far too long for its plot and an element wider than the page are both reported."""
    cdp.navigate(url, REPORT_READY)
    cdp.evaluate(SHOW_STATIC)
    cdp.evaluate("""(() => {
      const svg = document.getElementById('svg-temperature');
      const t = document.createElementNS('http://www.w3.org/2000/svg', 'text');
      t.setAttribute('x', '900'); t.setAttribute('y', '30'); t.setAttribute('class', 'broken');
      t.textContent = 'a deliberately long title that runs far past the right edge of its plot';
      svg.appendChild(t);
      const d = document.createElement('div'); d.id = 'too-wide'; d.style.width = '3000px'; d.textContent = 'x';
      document.body.appendChild(d);
      return true; })()""")
    found = cdp.evaluate(CHECK_JS)
    check(any("text.broken" in p and "outside its plot" in p for p in found), "a clipped label went unnoticed: %s" % found)
    check(any("div#too-wide" in p for p in found) and any("scrolls sideways" in p for p in found),
          "a too-wide element went unnoticed: %s" % found)


def check_live_page(cdp, exe, width):
    from harness import Serve  # pymodbus etc.: only needed here
    s = Serve(exe, "--ports", "2")
    try:
        cdp.set_width(width)
        cdp.navigate(s.http + "/", "!!document.getElementById('p2-card') && "
                                   "document.getElementById('status').textContent === 'live'")
        end = time.monotonic() + 10  # a few samples drawn
        while not cdp.evaluate("document.querySelectorAll('.dygraph-axis-label').length > 8 && "
                               "!!document.getElementById('p1-card').dataset.position"):
            cdp.pump(end)
        return ["live page at %d px: %s" % (width, p) for p in cdp.evaluate(CHECK_JS)]
    finally:
        cdp.navigate("about:blank")
        rc, err = s.stop()
        s.kill()
        check(rc == 0, "serve exit %d: %s" % (rc, err))


def main():
    exe, src = sys.argv[1], sys.argv[2]
    browser_or_skip()
    tmp = tempfile.mkdtemp()
    cdp = None
    try:
        pages = make_pages(exe, src, tmp)
        cdp = Cdp(os.path.join(tmp, "profile"))
        cdp.open_tab()
        problems = []
        for name, url in pages.items():
            for width in WIDTHS:
                cdp.set_width(width)
                cdp.navigate(url, REPORT_READY)
                if name in ("size", "cycle"):
                    check_sizing_page(cdp, name)
                if name != "run":  # issue 37: the command line, version, date and inputs under the title
                    prov = cdp.evaluate("(document.getElementById('provenance') || {}).textContent || ''")
                    check("sreh-twin " in prov and "made by" in prov and "date" in prov, "%s page without provenance: %r" % (name, prov[:200]))
                if name == "sweep":  # no page per point: a verdict row each
                    rows = cdp.evaluate("document.querySelectorAll('#verdicts tr td.mini .fill').length")
                    check(rows == 4 * 6, "sweep page: %s verdict bars, expected 4 for each of 6 points" % rows)
                problems += layout_problems(cdp, "%s page at %d px" % (name, width))
        for width in WIDTHS:
            problems += check_live_page(cdp, exe, width)
        check(not problems, "%d layout problems:\n  %s" % (len(problems), "\n  ".join(problems[:40])))
        console = cdp.problems()
        check(not console, "console errors: %s" % str(console)[:2000])
        check_print(cdp, pages["size"])
        check_the_check_can_fail(cdp, pages["size"])
    finally:
        if cdp:
            cdp.close()
        shutil.rmtree(tmp, ignore_errors=True)
    print("PASS: %d pages x %d widths and the live page laid out cleanly" % (len(pages), len(WIDTHS)))


main()
