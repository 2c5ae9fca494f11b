#!/bin/sh
# Regenerates docs/img/video-title-card.png and docs/img/video-frame.png
# (issue 29) from the demo scenario: a frame of the 1.5 s title card and
# one mid-run frame with the overlay, the degree scale and the labelled
# pointers. Usage: docs/img/make-video-images.sh [BUILD_DIR]  (default: build)
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/sreh-twin" run "$root/scenarios/demo.yaml" --quiet --size 1280x720 --frames "$tmp/frames" > /dev/null
# Frame 20 lies inside the title card (45 frames at 30 fps); 45 + 190 is
# the second move of the demo.
cp "$tmp/frames/frame_000020.png" "$root/docs/img/video-title-card.png"
cp "$tmp/frames/frame_000235.png" "$root/docs/img/video-frame.png"
echo "wrote docs/img/video-title-card.png docs/img/video-frame.png"
