#!/usr/bin/env bash
# deng2022's constant cost against yan2016's growth (docs/results.md "Prefiltered glints"): GPU time
# per frame of a floor seen straight down, the camera's pixel covering 1 to 1024 texels of the map
# (the footprint sweep, a point light), and under a sphere light from a point to a large light (the
# angular sweep, 4 texels a pixel). Prints two markdown tables: median GPU ms (wall where the GL
# timer does not measure), and each method's largest over smallest.
#   tools/bench-constant-cost.sh [GLINTLAB] [SIZE] [FRAMES]   (defaults: build/release/glintlab, 128, 5)
# On llvmpipe keep SIZE small (yan2016 takes seconds a frame); on a GPU use 1024 or more.
set -euo pipefail
B=${1:-build/release/glintlab}
size=${2:-128}
frames=${3:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
methods=conventional,deng2022,yan2016

# A floor of 2 m seen from above filling a square film of $size pixels; $1 map tiles across it, so
# that a pixel covers $1 * 256 / $size texels; light: $2 (a TOML [[light]] table).
scene() {
  cat <<TOML
description = "constant-cost bench: $1 tiles of a 256^2 map across the view"
[film]
width = $size
height = $size
[camera]
type = "orthographic"
position = [0.0, 3.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
view_height = 2.0
[[material]]
name = "floor"
type = "normal-map-glints"
intrinsic_roughness = 0.015
f0 = 0.9
normal_map = { generator = "bumps", resolution = 256, alpha = 0.25, waves = 128, max_frequency = 24, seed = 7 }
[[shape]]
type = "plane"
material = "floor"
size = 2
uv_scale = $1
$2
TOML
}

# median GPU ms of a method in a bench.json (wall ms when the GPU timer gave 0).
ms() { jq -r --arg m "$2" '.methods[] | select(.method == $m) | (if .gpu_ms_median > 0 then .gpu_ms_median else .wall_ms_median end)' "$1"; }

run() {  # run LABEL TILES LIGHT
  scene "$2" "$3" > "$work/s.toml"
  "$B" bench --scene "$work/s.toml" --methods "$methods" --bench-frames "$frames" --warmup 1 \
    --param yan2016.max_radius=128 --frames 1 -o "$work/$1" > /dev/null
  LC_ALL=C printf '| %s | %.2f | %.2f | %.2f |\n' "$1" "$(ms "$work/$1/bench.json" conventional)" \
    "$(ms "$work/$1/bench.json" deng2022)" "$(ms "$work/$1/bench.json" yan2016)"
}

point='[[light]]
type = "point"
position = [0.3, 2.0, 0.2]
intensity = 8'
echo "Footprint sweep ($size x $size pixels, point light; ms per frame):"
echo
echo "| texels a pixel | conventional | deng2022 | yan2016 |"
echo "| ---: | ---: | ---: | ---: |"
for tiles in 1 4 16 64 256 1024; do
  px=$(( tiles * 256 / size )); [ "$px" -lt 1 ] && px="$(awk "BEGIN{print $tiles*256/$size}")"
  run "$px" "$tiles" "$point" | tee -a "$work/foot.md"
done
echo
echo "Angular sweep (4 texels a pixel, a sphere light of radius R m at 2 m; ms per frame):"
echo
echo "| light | conventional | deng2022 | yan2016 |"
echo "| ---: | ---: | ---: | ---: |"
tiles=$(( 4 * size / 256 )); [ "$tiles" -lt 1 ] && tiles=1
run "point" "$tiles" "$point" | tee -a "$work/ang.md"
for r in 0.01 0.05 0.2 0.5 1.0; do
  run "R $r" "$tiles" "[[light]]
type = \"sphere\"
position = [0.3, 2.0, 0.2]
radius = $r
radiance = $(awk "BEGIN{print 8 / (3.14159265 * $r * $r)}")" | tee -a "$work/ang.md"
done
echo
for sweep in foot ang; do
  awk -F'|' -v s="$sweep" '{ for (m = 3; m <= 5; ++m) { v = $m + 0; if (!(m in lo) || v < lo[m]) lo[m] = v; if (v > hi[m]) hi[m] = v } }
    END { printf "%s sweep, largest / smallest: conventional %.2fx, deng2022 %.2fx, yan2016 %.2fx\n",
          (s == "foot" ? "footprint" : "angular"), hi[3] / lo[3], hi[4] / lo[4], hi[5] / lo[5] }' "$work/$sweep.md"
done
