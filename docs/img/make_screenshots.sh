#!/bin/sh
# Regenerates the screenshots of every page in docs/img/ (issue 29): run
# report, sizing, cycle, sweep and calibration pages, serve's live page, at 1400 px in
# headless Chromium (tests/browser/screenshots.py, the browser test's DevTools
# client), and the video's title-card frame (frame 20, docs/img/video-title-card.png)
# when a demo video exists (default out/demo.mp4, from ./demo.sh).
# usage: docs/img/make_screenshots.sh [BUILD_DIR] [DEMO_VIDEO.mp4]
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
video=${2:-$root/out/demo.mp4}  # what ./demo.sh renders
exec /usr/bin/python3 "$root/tests/browser/screenshots.py" "$build/sreh-twin" "$root" "$root/docs/img" "$video"
