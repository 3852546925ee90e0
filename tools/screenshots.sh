#!/usr/bin/env bash
# Regenerates the README's pictures of the interactive tools:
#   docs/images/viewer.png   `glintlab view` on a virtual display (Xvfb), driven by tools/viewer-readme.script
#   docs/images/report.png   docs/report/index.html#run/spheres (tools/results.py writes it) in headless chromium
# Usage: tools/screenshots.sh   (installs what it uses, builds glintlab)
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake --preset release > /dev/null
cmake --build build/release -j "$(nproc)" --target glintlab > /dev/null
B=build/release/glintlab
mkdir -p docs/images
xvfb-run -a -s "-screen 0 1280x800x24" \
  "$B" view -q --scene builtin:glint-sphere --width 320 --height 180 --method chermain2021 \
  --script tools/viewer-readme.script
echo "written docs/images/viewer.png"

if [[ -f docs/report/index.html ]]; then
  profile=$(mktemp -d)
  trap 'rm -rf "$profile"' EXIT
  chromium --headless --no-sandbox --disable-gpu --user-data-dir="$profile" --hide-scrollbars \
    --virtual-time-budget=10000 --window-size=1280,1200 --screenshot="$PWD/docs/images/report.png" \
    "file://$PWD/docs/report/index.html#run/spheres" 2>/dev/null
  echo "written docs/images/report.png"
else
  echo "docs/report/index.html missing: run tools/results.py first for docs/images/report.png" >&2
fi
