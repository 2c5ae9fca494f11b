#!/usr/bin/python3
"""Issue 39 done-when: a video of scenarios/demo.yaml, its frames at the title
card, mid-move and the closing card checked. OCR is not available: the
renderer records every text it draws and where (frames/text.tsv, see
renders/video.hpp kTextLogHeader), and each text checked here must also be
in the PNG at that place (bright glyph pixels on a dark box), so the log
cannot claim a text the frame does not show.

Checked: the title card holds the scenario's full name (wrapped, never cut
with "...") and the load's own name (not FILE:LINE:COL); every move plays at
one slow-motion factor, or the banner names each change ("was Nx"); the
`comment:` steps are captions while they apply; the closing card says PASS
with the final state. Usage: demo_video_check.py SREH_TWIN SOURCE_DIR OUT_DIR"""
import collections
import pathlib
import re
import shutil
import subprocess
import sys

import numpy as np
import yaml

W, H, FPS = 640, 360, 10


def png_rgb(path):
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                         check=True, capture_output=True).stdout
    return np.frombuffer(raw, np.uint8).reshape(H, W, 3)


def text_log(path):
    rows = []
    lines = path.read_text(encoding="utf-8").splitlines()
    assert lines[0].split("\t")[:3] == ["first_frame", "last_frame", "kind"], lines[0]
    for line in lines[1:]:
        first, last, kind, x, y, w, h, text = line.split("\t", 7)
        rows.append(dict(first=int(first), last=int(last), kind=kind, x=int(x), y=int(y), w=int(w), h=int(h), text=text))
    return rows


def on_frame(rows, k):
    return [r for r in rows if r["first"] <= k <= r["last"]]


def shown(frames, k, row):
    """The row's text is drawn in frame k: bright glyph pixels and a dark box behind them."""
    img = png_rgb(frames / f"frame_{k:06d}.png").astype(int)
    box = img[row["y"]:row["y"] + row["h"], row["x"]:row["x"] + max(row["w"], 1)]
    assert box.size, row
    lum = box.max(axis=2)
    bright, dark = (lum > 170).mean(), (lum < 90).mean()
    assert bright > 0.03 and dark > 0.3, f"frame {k}: '{row['text']}' not visible there ({bright:.2f} bright, {dark:.2f} dark)"


def main():
    twin, src, out = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    frames = out / "frames"
    scenario = src / "scenarios" / "demo.yaml"
    run = subprocess.run([twin, "run", str(scenario), "--frames", str(frames), "--size", f"{W}x{H}", "--fps", str(FPS),
                          "--quiet"], capture_output=True, text=True)
    assert run.returncode == 0 and "PASS" in run.stdout, (run.returncode, run.stdout, run.stderr)
    rows = text_log(frames / "text.tsv")
    n = len(list(frames.glob("frame_*.png")))
    spec = yaml.safe_load(scenario.read_text())
    name = spec["name"]
    comments = [s["comment"] for s in spec["steps"] if "comment" in s and len(s) == 1]

    # Title card: frame 0.
    card = [r for r in on_frame(rows, 0) if r["kind"] == "card"]
    joined = " ".join(r["text"] for r in card)
    assert name in joined, f"the full name is not on the title card: {joined}"
    assert len([r for r in card if r["text"] in name]) >= 2, "a long name at 640x360 should wrap"
    assert not any(r["text"].endswith("...") for r in card), "a text on the title card is cut"
    load = re.search(r"\bload (.*?) load inertia", joined)
    assert load and "gripper with jaws and a part on an adapter" in load.group(1), joined
    assert not re.search(r"\.yaml:\d+:\d+", joined), joined
    for r in card[:3]:
        shown(frames, 0, r)

    # Mid-move: frames whose panel says Busy; the banner's factor.
    busy = sorted({r["first"] for r in rows if r["kind"] == "panel" and r["text"] == "Busy"})
    assert busy, "no frame shows a move"
    banners = {}
    for r in rows:
        if r["kind"] == "banner" and r["text"].startswith("slow motion"):
            banners[r["first"]] = r["text"]
    factors = collections.OrderedDict()
    for k in sorted(banners):
        m = re.match(r"slow motion ([\d.]+)x( \(was ([\d.]+)x\))?$", banners[k])
        assert m, banners[k]
        factors.setdefault(m.group(1), k)
    changes = [t for t in banners.values() if "(was" in t]
    assert len(factors) == 1 or len(changes) >= len(factors) - 1, f"factor changes without a name: {list(factors)}"
    print(f"slow-motion factors: {list(factors)} (changes named: {len(changes)})")
    mid = busy[len(busy) // 2]
    mid_rows = on_frame(rows, mid)
    banner = [r for r in mid_rows if r["kind"] == "banner"]
    assert banner and banner[0]["text"].startswith("slow motion"), (mid, banner)
    shown(frames, mid, banner[0])
    caption = [r for r in mid_rows if r["kind"] == "caption"]
    assert caption, f"frame {mid}: no caption during the move"
    assert " ".join(r["text"] for r in caption) in comments, caption
    shown(frames, mid, caption[0])
    # Each comment is the caption while it applies, in the scenario's order.
    seen = []
    for k in sorted({r["first"] for r in rows if r["kind"] == "caption"}):
        text = " ".join(r["text"] for r in on_frame(rows, k) if r["kind"] == "caption")
        if not seen or seen[-1] != text:
            seen.append(text)
    assert seen == comments, (seen, comments)

    # Closing card: the last frame.
    last = [r for r in on_frame(rows, n - 1) if r["kind"] == "card"]
    text = " ".join(r["text"] for r in last)
    assert last and last[0]["text"].startswith("PASS: all"), text
    assert re.search(r"final state (Ready|Done) at (299\.9\d|300\.\d\d) deg, LED green", text), text
    shown(frames, n - 1, last[0])
    print(f"{n} frames; title card, frame {mid} (mid-move) and the closing card checked")


if __name__ == "__main__":
    main()
