"""Screenshots of every page at 1400 px (issue 29) into docs/img/: the run
report (top and plots), the sizing, cycle, sweep and calibration pages and
serve's live page. Run by docs/img/make_screenshots.sh (which also makes the
video frames, docs/img/make-video-images.sh).

usage: screenshots.py SREH_TWIN SOURCE_DIR OUT_DIR [live]   (live: the live page only)"""
import base64
import os
import shutil
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(here, "..", "serve"))
from cdp import Cdp, browser_or_skip  # noqa: E402
from pages import make_pages  # noqa: E402

WIDTH = 1400
MAX_HEIGHT = 2000  # CSS px from the top: what a reader sees first, and small files


def shrink(path):
    """A 128-colour palette PNG when ffmpeg is there: the pages are flat colours, a fraction of the bytes."""
    if not shutil.which("ffmpeg"):
        return
    tmp = path + ".pal.png"
    subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", path, "-vf",
                    "split[a][b];[a]palettegen=max_colors=128:stats_mode=full[p];[b][p]paletteuse=dither=none",
                    tmp], check=True)
    os.replace(tmp, path)


def shoot(cdp, path, top=0, max_height=MAX_HEIGHT):
    w, h = cdp.evaluate("[document.documentElement.clientWidth, document.documentElement.scrollHeight]")
    png = base64.b64decode(cdp.send("Page.captureScreenshot", {
        "format": "png", "captureBeyondViewport": True,
        "clip": {"x": 0, "y": top, "width": w, "height": min(max_height, h - top), "scale": 1}}, timeout=60)["data"])
    with open(path, "wb") as f:
        f.write(png)
    shrink(path)
    print("%s: %d kB" % (path, os.path.getsize(path) // 1024))


def main():
    exe, src, out = sys.argv[1], sys.argv[2], sys.argv[3]
    browser_or_skip()
    tmp = tempfile.mkdtemp()
    cdp = None
    try:
        live_only = sys.argv[4:] == ["live"]
        pages = {} if live_only else make_pages(exe, src, tmp, cycle="examples/cycles/pick_and_place.yaml")
        cdp = Cdp(os.path.join(tmp, "profile"), width=WIDTH)
        cdp.open_tab()
        cdp.set_width(WIDTH)
        ready = ("document.readyState === 'complete' && "
                 "document.querySelectorAll('.fig .dy').length === document.querySelectorAll('.fig.live').length")
        for name, file in () if live_only else (("run", "run-report.png"), ("size", "sizing-report.png"), ("cycle", "cycle-report.png"),
                           ("sweep", "sweep-report.png"), ("calibration", "calibration-report.png")):
            cdp.navigate(pages[name], ready)
            time.sleep(0.3)
            shoot(cdp, os.path.join(out, file))
        if not live_only:
            cdp.navigate(pages["run"], ready)
            top = cdp.evaluate("Math.round(document.getElementById('over-time').getBoundingClientRect().top + window.scrollY)")
            shoot(cdp, os.path.join(out, "run-report-plots.png"), top=top)
        from harness import Serve
        s = Serve(exe, "--ports", "2")
        try:
            cdp.navigate(s.http + "/", "document.getElementById('status').textContent === 'live'")
            cdp.click("p1-motor-on")
            time.sleep(0.3)
            cdp.evaluate("document.getElementById('p1-target').value = '135'; true")
            cdp.click("p1-move")
            time.sleep(2.5)
            # Port 2 against a blocked flange: the injected fault and the named event (issue 39).
            cdp.click("p2-block")
            cdp.click("p2-motor-on")
            time.sleep(0.3)
            cdp.click("p2-move")
            time.sleep(1.5)
            shoot(cdp, os.path.join(out, "live-page.png"), max_height=1400)
        finally:
            cdp.navigate("about:blank")
            s.stop()
            s.kill()
    finally:
        if cdp:
            cdp.close()
        shutil.rmtree(tmp, ignore_errors=True)


main()
