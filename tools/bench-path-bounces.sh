#!/usr/bin/env bash
# The cost of a path vertex (issue 31, "the cost per bounce"): seconds of the path tracer's render of
# builtin:normal-glints-kettle (a brushed body and a flake ball that see each other on a glossy
# table; two small sphere lights and an environment) at --max-depth 1 to 4, for the surface itself
# (`path`) and the methods' footprint NDFs (`path:yan2016`, `path:deng2022` with the environment by
# lobes and sampled). Each backend renders once untimed first (its programs compiled), then each
# depth is timed by the wall clock; prints a markdown table.
#   tools/bench-path-bounces.sh [GLINTLAB] [WIDTH] [HEIGHT] [SPP]   (defaults: build/release/glintlab, 80, 45, 64)
set -euo pipefail
B=${1:-build/release/glintlab}
width=${2:-80}
height=${3:-45}
spp=${4:-64}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
backends=(path path:yan2016 path:deng2022 'path:deng2022{environment_lobes=0}')
render() {
  "$B" render -q --no-cache --scene builtin:normal-glints-kettle --width "$width" --height "$height" \
    --light-samples 1 --reference="$1" --reference-backend "$2" --max-depth "$3" -o "$work/frame.exr" >/dev/null
}
echo "| backend | depth 1 (s) | depth 2 | depth 3 | depth 4 |"
echo "| --- | ---: | ---: | ---: | ---: |"
for b in "${backends[@]}"; do
  render 4 "$b" 2
  row="| \`$b\`"
  for d in 1 2 3 4; do
    start=$(date +%s.%N)
    render "$spp" "$b" "$d"
    end=$(date +%s.%N)
    row+=" | $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')"
  done
  echo "$row |"
done
