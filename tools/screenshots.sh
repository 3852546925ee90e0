#!/usr/bin/env bash
# Regenerates the README's pictures of the interactive tools:
#   docs/images/viewer.png   `glintlab view` on a virtual display (Xvfb), driven by tools/viewer-readme.script
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
