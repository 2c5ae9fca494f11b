#!/usr/bin/python3
"""Issue 16 done-when: `run` of a short single-move scenario with --video gives
>= 2 s of video with >= 40 frames whose flange pixels change; the container
follows the extension. Usage: video_check.py SRE_TWIN SCENARIO OUT_DIR"""
import pathlib
import subprocess
import sys

import numpy as np

W, H = 640, 360


def frames(path):
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", str(path), "-f", "rawvideo", "-pix_fmt", "rgb24", "-"],
                         check=True, capture_output=True).stdout
    return np.frombuffer(raw, np.uint8).reshape(-1, H, W, 3)


def probe(path, entry):
    return subprocess.run(["ffprobe", "-v", "error", "-show_entries", entry, "-of", "csv=p=0", str(path)],
                          check=True, capture_output=True, text=True).stdout.strip()


def main():
    twin, scenario, out = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    out.mkdir(parents=True, exist_ok=True)
    video = out / "single_move.mp4"
    subprocess.run([twin, "run", scenario, "--video", str(video), "--size", f"{W}x{H}"], check=True,
                   stdout=subprocess.DEVNULL)
    assert probe(video, "stream=codec_name") == "h264", probe(video, "stream=codec_name")
    f = frames(video).astype(np.int16)
    seconds = len(f) / 30.0
    # The module: right of the overlay column, below the time-scale banner
    # (renders/offscreen.cpp keeps the framing clear of both).
    module = f[:, int(0.2 * H):, int(0.36 * W):]
    changed = int((np.abs(np.diff(module, axis=0)).max(axis=3) > 24).sum(axis=(1, 2)).__gt__(20).sum())
    print(f"{len(f)} frames, {seconds:.2f} s, {changed} frames with changed flange pixels")
    assert seconds >= 2.0, seconds
    assert changed >= 40, changed
    # WebM by extension; an unknown extension is refused before any rendering.
    webm = out / "single_move.webm"
    subprocess.run([twin, "run", scenario, "--video", str(webm), "--size", "320x240"], check=True,
                   stdout=subprocess.DEVNULL)
    assert probe(webm, "stream=codec_name") == "vp8"
    bad = subprocess.run([twin, "run", scenario, "--video", str(out / "x.avi")], capture_output=True, text=True)
    assert bad.returncode == 2 and ".mp4, .webm or .gif" in bad.stderr and not bad.stdout, bad
    assert not (out / "x.avi").exists()


if __name__ == "__main__":
    main()
