#!/bin/sh
# Regenerates the screenshots of every page in docs/img/ (issue 29): run
# report, sizing, cycle and sweep pages, serve's live page, at 1400 px in
# headless Chromium (tests/browser/screenshots.py, the browser test's DevTools
# client), and the video's title-card frame when a demo video exists.
# usage: docs/img/make_screenshots.sh [BUILD_DIR] [DEMO_VIDEO.mp4]
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
video=${2:-$build/demo.mp4}
exec /usr/bin/python3 "$root/tests/browser/screenshots.py" "$build/sreh-twin" "$root" "$root/docs/img" "$video"
