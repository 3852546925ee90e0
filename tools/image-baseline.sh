#!/usr/bin/env bash
# Bitwise image baseline: renders every method on every built-in scene (and the references, the
# compile-time choices and the variants that take other code paths) at a small size, so that a
# refactoring that must not change images can be checked to the last bit.
#
#   tools/image-baseline.sh record DIR [GLINTLAB]   render into DIR (the EXRs and their sha256sums)
#   tools/image-baseline.sh check DIR [GLINTLAB]    render again into DIR.check and list every EXR
#                                                   whose bytes differ from DIR's; exit 1 if any does
#
# GLINTLAB defaults to build/release/glintlab. Record with the commit before the change (copy its
# binary aside), check with the one after. IMAGE_BASELINE_ONLY='a|b|c' renders only the runs of
# those names (an extended regex of whole names; the check then compares those). About an hour
# on 2 cores with an empty shader cache.
set -euo pipefail

mode=${1:?usage: tools/image-baseline.sh record|check DIR [GLINTLAB]}
dir=${2:?usage: tools/image-baseline.sh record|check DIR [GLINTLAB]}
glintlab=${3:-build/release/glintlab}
[[ $mode == record || $mode == check ]] || { echo "image-baseline: mode must be record or check, not '$mode'" >&2; exit 2; }
[[ -x $glintlab ]] || { echo "image-baseline: no executable at '$glintlab'" >&2; exit 2; }
out=$dir
[[ $mode == check ]] && out=$dir.check
mkdir -p "$out"

size=(--width 64 --height 36 --spp 4 --no-cache -q)

# run NAME ARGS...: one compare run into $out/NAME.
run() {
  local name=$1
  shift
  [[ -z ${IMAGE_BASELINE_ONLY:-} || $name =~ ^(${IMAGE_BASELINE_ONLY})$ ]] || return 0
  echo "image-baseline: $name" >&2
  "$glintlab" compare "${size[@]}" "$@" -o "$out/$name" >/dev/null
}

for scene in $("$glintlab" scenes | grep '^builtin:' | sed 's/^builtin://'); do
  run "$scene" --scene "builtin:$scene" --methods all
done
# Frames further along the paths: sub-pixel normal-map features (deng2022's pyramid levels).
run normal-glints-noise-far --scene builtin:normal-glints-noise --methods all --frame 20
# The other reference backends and the Gaussian pixel filter.
run glint-area-lights-realisation --scene builtin:glint-area-lights --methods conventional \
  --reference-backend raster-realisation
run glint-binomial-realisation --scene builtin:glint-binomial --methods conventional --reference-backend raster-realisation
run normal-glints-noise-gaussian --scene builtin:normal-glints-noise --methods conventional --reference-filter gaussian:0.5
# Every compile-time choice that is not a default, and the run-time choices that take other paths.
run quad-light-representative-point --scene builtin:quad-light --methods all --param area_lights=representative-point
run glint-area-lights-glinty-centre --scene builtin:glint-area-lights-glinty --methods chermain2020,chermain2021 \
  --param light_extent=centre
run glint-sphere-lean-swapped --scene builtin:glint-sphere --methods chermain2020,chermain2021 \
  --param chermain2020.lean=on --param chermain2021.lean=off
run glint-area-lights-gaussian-count --scene builtin:glint-area-lights --methods deliot2023,kneiphof2024 \
  --param remaining_count=gaussian
run glint-area-lights-2x2 --scene builtin:glint-area-lights --methods kneiphof2024 --param subdivision=2x2
run glint-area-lights-4x4 --scene builtin:glint-area-lights --methods kneiphof2024 --param subdivision=4x4 \
  --param point_light_solid_angle=6.8e-5
run spheres-podee-lens --scene builtin:spheres --methods podee --param area=lens --param corners=derivatives \
  --param origin=centre --param lobe=lean
run spheres-podee-circle --scene builtin:spheres --methods podee --param area=circle --param glossy=off
run normal-glints-noise-clamp --scene builtin:normal-glints-noise --methods deng2022 --param small_footprints=clamp

(cd "$out" && find . -name '*.exr' | sort | xargs sha256sum) >"$out/SHA256SUMS"
if [[ $mode == record ]]; then
  echo "image-baseline: recorded $(wc -l <"$out/SHA256SUMS") images in $out"
  exit 0
fi
recorded=$dir/SHA256SUMS
if [[ -n ${IMAGE_BASELINE_ONLY:-} ]]; then  # only the runs rendered now
  recorded=$(mktemp)
  grep -E "^[0-9a-f]+  \./(${IMAGE_BASELINE_ONLY})/" "$dir/SHA256SUMS" >"$recorded" || true
fi
if diff <(awk '{print $2}' "$recorded") <(awk '{print $2}' "$out/SHA256SUMS") >/dev/null; then :; else
  echo "image-baseline: the set of images differs:" >&2
  diff <(awk '{print $2}' "$recorded") <(awk '{print $2}' "$out/SHA256SUMS") >&2 || true
fi
differ=$(join -j 2 <(sort -k 2 "$recorded") <(sort -k 2 "$out/SHA256SUMS") | awk '$2 != $3 {print $1}')
total=$(wc -l <"$recorded")
if [[ -n $differ ]]; then
  echo "image-baseline: $(echo "$differ" | wc -l) of $total images differ:"
  echo "$differ"
  exit 1
fi
echo "image-baseline: 0 of $total images differ"
