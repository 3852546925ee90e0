#!/usr/bin/env bash
# deng2022's constant cost against yan2016's growth (docs/results.md "Prefiltered glints", issue 30
# item 7): ms per frame of a floor seen straight down with a 1024^2 normal map, under
#   - the footprint sweep: a point light, the pixel's footprint sigma = 1.5 sigma_0 2^(j/2) texels
#     (sigma_0 = 2, the pyramid's first level; sqrt(2) steps from 3 to 192 texels, so that half the
#     points lie between stored levels and none on the element fallback's side of the switch);
#   - the angular sweep: sigma = 6 texels (between levels 1 and 2), a sphere light of radius R m at
#     2 m from a point to a light whose half-vector box covers most of the NDF image.
# Methods: conventional, deng2022 (box queries through its prefix tables), deng2022 with the paper's
# block-by-block box queries, yan2016 (max_elements 60000). Prints two markdown tables (median GPU ms,
# wall where the GL timer does not measure) and each method's largest over smallest per sweep.
#   tools/bench-constant-cost.sh [GLINTLAB] [SIZE] [FRAMES]   (defaults: build/release/glintlab, 128, 5)
# The first run precomputes the map's pyramid (minutes; cached after). On llvmpipe keep SIZE small
# (yan2016 takes seconds a frame); on a GPU use 1024 or more. MAP=256 uses a 256^2 map instead.
set -euo pipefail
B=${1:-build/release/glintlab}
size=${2:-128}
frames=${3:-5}
map=${MAP:-1024}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
methods=(conventional deng2022 'deng2022{box_queries=blocks}' yan2016)

# A floor seen from above, a square film of $size pixels over 2 m of it, textured so that a pixel
# covers $1 texels per axis (footprint sigma = 0.5 pixel = $1 / 2 texels); light: $2 (a TOML table).
# The camera turns 17 degrees about its axis (the floor is 3 m wide to fill the turned view), so that
# pixel centres do not fall on the pyramid's footprint grid in step: at a whole number of texels a
# pixel they would land at the same place in every cell, where some of the trilinear weights are 0
# and their footprints are skipped, timing a cheaper query than a pixel's in general.
scene() {
  local tiles
  tiles=$(awk -v t="$1" -v s="$size" -v m="$map" 'BEGIN { printf "%.6f", 1.5 * t * s / m }')
  cat <<TOML
description = "constant-cost bench: $1 texels of a ${map}^2 map a pixel"
[film]
width = $size
height = $size
[camera]
type = "orthographic"
position = [0.0, 3.0, 0.0]
target = [0.0, 0.0, 0.0]
up = [0.2923717, 0.0, -0.9563048]
view_height = 2.0
[[material]]
name = "floor"
type = "normal-map-glints"
intrinsic_roughness = 0.015
f0 = 0.9
normal_map = { generator = "bumps", resolution = $map, alpha = 0.25, waves = 256, max_frequency = $((24 * map / 256)), seed = 7 }
[[shape]]
type = "plane"
material = "floor"
size = 3
uv_scale = $tiles
$2
TOML
}

# median GPU ms of a method in a bench.json (wall ms when the GPU timer gave 0).
ms() { jq -r --arg m "$2" '.methods[] | select(.method == $m) | (if .gpu_ms_median > 0 then .gpu_ms_median else .wall_ms_median end)' "$1"; }

run() {  # run LABEL TEXELS_A_PIXEL LIGHT
  scene "$2" "$3" > "$work/s.toml"
  local list
  list=$(IFS=,; echo "${methods[*]}")
  "$B" bench --scene "$work/s.toml" --methods "$list" --bench-frames "$frames" --warmup 1 \
    --param yan2016.max_elements=60000 --frames 1 -o "$work/run" > /dev/null
  local row="| $1 |"
  for m in "${methods[@]}"; do row+=$(LC_ALL=C printf ' %.2f |' "$(ms "$work/run/bench.json" "$m")"); done
  echo "$row"
}

header() {
  echo "| $1 | conventional | deng2022 | deng2022, box_queries=blocks | yan2016 |"
  echo "| ---: | ---: | ---: | ---: | ---: |"
}

point='[[light]]
type = "point"
position = [0.3, 2.0, 0.2]
intensity = 8'
echo "Footprint sweep ($size x $size pixels, ${map}^2 map, point light; ms per frame):"
echo
header "footprint sigma (texels)"
for j in $(seq 0 12); do
  sigma=$(awk -v j="$j" 'BEGIN { printf "%.3g", 3 * 2 ^ (j / 2) }')
  run "$sigma" "$(awk -v s="$sigma" 'BEGIN { print 2 * s }')" "$point" | tee -a "$work/foot.md"
done
echo
echo "Angular sweep (footprint sigma 6 texels, a sphere light of radius R m at 2 m; ms per frame):"
echo
header "light"
run "point" 12 "$point" | tee "$work/point.md"
for r in 0.015 0.03 0.06 0.12 0.24 0.48 0.96; do
  run "R $r" 12 "[[light]]
type = \"sphere\"
position = [0.3, 2.0, 0.2]
radius = $r
radiance = $(awk "BEGIN{print 8 / (3.14159265 * $r * $r)}")" | tee -a "$work/ang.md"
done
echo
# ratios FILE... TITLE: each method's largest over smallest over the rows of the files.
ratios() {
  local title=${*: -1}
  awk -F'|' -v t="$title" -v names="conventional|deng2022|deng2022, box_queries=blocks|yan2016" '
    { for (m = 3; m <= 6; ++m) { v = $m + 0; if (!(m in lo) || v < lo[m]) lo[m] = v; if (v > hi[m]) hi[m] = v } }
    END { split(names, n, "|"); printf "%s, largest / smallest:", t
          for (m = 3; m <= 6; ++m) printf " %s %.2fx%s", n[m - 2], hi[m] / lo[m], (m < 6 ? "," : "\n") }' "${@:1:$#-1}"
}
ratios "$work/foot.md" "footprint sweep"
ratios "$work/ang.md" "angular sweep, sphere lights"
ratios "$work/point.md" "$work/ang.md" "angular sweep with the point light"
