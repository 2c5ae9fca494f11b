#!/bin/sh
# Regenerates the screenshots of every page in docs/img/ (issue 29): run
# report, sizing, cycle, sweep and calibration pages, serve's live page, at
# 1400 px in headless Chromium (tests/browser/screenshots.py, the browser
# test's DevTools client), then the video's title card and a mid-run frame
# (docs/img/make-video-images.sh).
# usage: docs/img/make_screenshots.sh [BUILD_DIR]
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
/usr/bin/python3 "$root/tests/browser/screenshots.py" "$build/sreh-twin" "$root" "$root/docs/img"
sh "$root/docs/img/make-video-images.sh" "$build"
