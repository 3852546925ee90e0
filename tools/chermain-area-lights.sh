#!/usr/bin/env bash
# The light-size sweep of the Chermain methods' area-light extension (docs/methods.md, "Area
# lights: the light's half-vector region as a slope-space kernel"): a glinty plane and sphere under
# one quad or sphere light of growing size at constant power, each method with
# light_extent = centre and = half-vector-kernel, against the reference that samples the light.
# Prints a markdown table of mean RMSE and flicker over a short orbit (glintlab animate), with the
# reference's noise and flicker floor. Run from the repository root after building:
#   tools/chermain-area-lights.sh [OUT_DIR]   (default out/chermain-area-lights; ~10 min on 2 cores)
set -euo pipefail
B=${GLINTLAB:-build/release/glintlab}
out=${1:-out/chermain-area-lights}
A="--width ${WIDTH:-160} --height ${HEIGHT:-90} --frames ${FRAMES:-6} --spp ${SPP:-64}"
mkdir -p "$out"

field() { jq -r --arg k "$2" '.[$k]' "$1/metrics.json"; }
anim() { jq -r --arg m "$2" --arg k "$3" '.methods[] | select(.method == $m) | .[$k]' "$1/metrics.json"; }
fmt() { LC_ALL=C printf "$1" "$2"; }

# scene KIND SIZE: the light's half size (quad: half side; sphere: radius) at constant power.
scene() {
  local kind=$1 size=$2 light
  if [ "$kind" = quad ]; then
    light="type = \"quad\"
position = [0.0, 2.0, -2.5]
direction = [0.0, -2.0, 2.0]
size = [$(awk "BEGIN { print 2 * $size }"), $(awk "BEGIN { print $size }")]
up = [0, 1, 0]
radiance = $(awk "BEGIN { printf \"%.6g\", 1.0 / (2 * $size * $size) }")"
  else
    light="type = \"sphere\"
position = [0.0, 2.0, -2.5]
radius = $size
radiance = $(awk "BEGIN { printf \"%.6g\", 1.0 / (3.14159265 * $size * $size) }")"
  fi
  cat <<TOML
description = "a glinty plane and sphere under one $kind light of half size $size (constant power)"

[film]
width = 160
height = 90

[camera]
position = [0.0, 1.0, 3.0]
target = [0.0, 0.1, -1.0]
fov = 40

[camera.path]
type = "orbit"
degrees = 4
frames = 6

[[material]]
name = "glitter"
type = "glinty"
sigma = 0.1
log_density = 16
relative_area = 0.8
f0 = 0.9
diffuse = 0.02

[[shape]]
type = "plane"
material = "glitter"
size = 12
uv_scale = 6

[[shape]]
type = "sphere"
material = "glitter"
radius = 0.5
translate = [0.9, 0.5, -0.6]

[[light]]
$light
visible = false
TOML
}

echo "| light | half size | reference noise | flicker floor | method | RMSE centre | RMSE kernel | flicker centre | flicker kernel |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for kind in quad sphere; do
  for size in ${SIZES:-0.002 0.05 0.15 0.4 0.8}; do
    dir="$out/$kind-$size"
    mkdir -p "$dir"
    scene "$kind" "$size" > "$dir/scene.toml"
    for choice in centre half-vector-kernel; do
      $B animate -q --scene "$dir/scene.toml" --methods chermain2020,chermain2021 \
        --param chermain2020.light_extent=$choice --param chermain2021.light_extent=$choice $A -o "$dir/$choice" > /dev/null
    done
    for m in chermain2020 chermain2021; do
      echo "| $kind | $size | $(fmt %.4f "$(field "$dir/centre" reference_noise_rmse)") | $(fmt %.4f "$(field "$dir/centre" flicker_floor)")" \
        "| $m | $(fmt %.4f "$(anim "$dir/centre" $m mean_rmse)") | $(fmt %.4f "$(anim "$dir/half-vector-kernel" $m mean_rmse)")" \
        "| $(fmt %.4f "$(anim "$dir/centre" $m flicker)") | $(fmt %.4f "$(anim "$dir/half-vector-kernel" $m flicker)") |"
    done
  done
done
