#!/usr/bin/env bash
# Regenerates docs/results.md, docs/images/ and the README's speed table from measurements on this
# machine. Every number in them comes from this run.
#   tools/make-results.sh              everything (about 1.5 hours on 2 cores cold; references are
#                                      cached, so a second run takes minutes)
#   tools/make-results.sh SECTION      one section, spliced into docs/results.md between its
#                                      markers: ground-truth, aa, podee, glints, binomial-glints,
#                                      area-lights, area-glints, prefiltered-glints, speed
# It installs what it uses (jq, ffmpeg) and builds what it needs. After the sections, `glintlab
# report` writes the HTML report of the runs: docs/report/ (headline runs) and out/results/report/.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh results
cmake --preset release > /dev/null
cmake --build build/release -j "$(nproc)" --target glintlab test_render > /dev/null
B=build/release/glintlab
glintlab_bin=$B
constant_cost_args="64 2"
# GLINTLAB_RESULTS_QUICK=1: sizes, samples and frames reduced (a check of this script and of its
# replacement, tools/results.py, which applies the same rules; never numbers to commit).
if [[ "${GLINTLAB_RESULTS_QUICK:-}" == 1 ]]; then
  quick_glintlab() {
    local args=() command=$1 frames_given=0 n
    while [[ $# -gt 0 ]]; do
      case $1 in
        --spp) args+=(--spp $(($2 / 64 > 4 ? $2 / 64 : 4))); shift 2 ;;
        --reference=*) n=${1#--reference=}; args+=(--reference=$((n / 64 > 4 ? n / 64 : 4))); shift ;;
        --width | --height) args+=("$1" $(($2 / 4 > 16 ? $2 / 4 : 16))); shift 2 ;;
        --frames) args+=(--frames $(($2 < 3 ? $2 : 3))); frames_given=1; shift 2 ;;
        --bench-frames) args+=(--bench-frames $(($2 < 2 ? $2 : 2))); shift 2 ;;
        --accuracy) args+=(--accuracy $(($2 < 1 ? $2 : 1))); shift 2 ;;
        *) args+=("$1"); shift ;;
      esac
    done
    if [[ $command == animate && $frames_given == 0 ]]; then args+=(--frames 3); fi
    "$glintlab_bin" "${args[@]}"
  }
  B=quick_glintlab
  constant_cost_args="16 1"
fi
out=out/results
mkdir -p "$out" docs/images
aa_scenes="spheres tubes bumpy-plane"

# --- reading measurements -------------------------------------------------------------------------

# A method's field in a compare output directory: metric DIR METHOD KEY (e.g. rmse, energy_ratio).
metric() { jq -r --arg m "$2" --arg k "$3" '.methods[] | select(.method == $m) | .[$k]' "$1/metrics.json"; }
# A top-level field of a compare or animate metrics.json: field DIR KEY.
field() { jq -r --arg k "$2" '.[$k]' "$1/metrics.json"; }
# printf with a format and one number (jq's numbers may be long).
fmt() { LC_ALL=C printf "$1" "$2"; }
# awk arithmetic: calc 'expression' (no bc needed).
calc() { awk "BEGIN { printf \"%.6g\", $1 }"; }
# Median wall milliseconds of a method in a bench JSON: bench_ms FILE METHOD.
bench_ms() { jq -r --arg m "$2" '.methods[] | select(.method == $m) | .wall_ms_median' "$1"; }

# One row of thumbnails: reference, then the given methods, from a compare output directory.
thumbnails() {
  local scene=$1 dir=$2; shift 2
  local header="| reference |" rule="| --- |" row="| ![](images/$scene-reference.png) |"
  cp "$dir/reference.png" "docs/images/$scene-reference.png"
  for m in "$@"; do
    cp "$dir/$m.png" "docs/images/$scene-$m.png"
    header+=" $m |"; rule+=" --- |"; row+=" ![](images/$scene-$m.png) |"
  done
  printf '%s\n%s\n%s\n' "$header" "$rule" "$row"
}

# Which differences a table can rank: the best method, and whether its lead over the next is larger
# than twice the reference's noise RMSE (computed, never typed).
ranking_note() {
  local dir=$1
  jq -r '(.reference_noise_rmse) as $n | [.methods[] | {m: .method, r: .rmse}] | sort_by(.r) as $s |
    if ($s | length) < 2 then "" else
      "Lowest RMSE: `\($s[0].m)` (\($s[0].r * 1000 | round / 1000)); next `\($s[1].m)` (\($s[1].r * 1000 | round / 1000)); " +
      (if ($s[1].r - $s[0].r) > 2 * $n then "the gap is larger than twice the reference noise (\($n * 1000 | round / 1000))."
       else "the gap is within twice the reference noise (\($n * 1000 | round / 1000)): not a ranking." end) end' \
    "$dir/metrics.json"
}

# Flicker of methods over 12 frames of builtin:$2 at 320x180 against 256-spp references, under
# heading $1; extra arguments go to animate.
flicker_table() {
  local heading=$1 scene=$2; shift 2
  echo "$heading"
  echo
  echo '```'
  $B animate -q --scene "builtin:$scene" --width 320 --height 180 --frames 12 --spp 256 -o "$out/animate-$scene" "$@" |
    sed '$d'
  echo '```'
  echo
}

# --- sections -------------------------------------------------------------------------------------

ground_truth_section() {
  echo "## Ground truth"
  echo
  echo "The reference evaluates the surface at jittered sample points (normal maps at level 0, never"
  echo "filtered) in independent passes, and reports its own error (docs/methods.md, \"Ground truth\")."
  echo
  echo "### A highlight smaller than a pixel: mirror sphere under a sun"
  echo
  echo "\`tools/mirror-sphere-sun.toml\`, 160x160, orthographic: the sun is seen in a disk of radius"
  echo "R sin(gamma/2) pixels (R = 160/2.2), so the image's mean luminance is E R^2 / (4 cos^2(gamma/2))"
  echo "over 160^2. Measured: the reference's mean luminance over that closed form, with its own"
  echo "standard error (from the passes)."
  echo
  echo "| sun angular radius | highlight radius (px) | spp (passes) | reference / closed form | own error |"
  echo "| --- | --- | --- | --- | --- |"
  # Smaller suns need more samples for the same relative error (the highlight has fewer of them).
  for deg_spp in 0.25:16384 0.5:16384 2:4096; do
    local deg=${deg_spp%:*} spp=${deg_spp#*:}
    sed "s/%DEGREES%/$deg/" tools/mirror-sphere-sun.toml > "$out/sun-$deg.toml"
    {
      $B compare -q --scene "$out/sun-$deg.toml" --methods conventional --spp $spp -o "$out/sun-$deg-$spp" > /dev/null
      local d="$out/sun-$deg-$spp" half r expected
      half=$(calc "$deg / 2 * 3.14159265358979 / 180")
      r=$(calc "160 / 2.2")
      expected=$(calc "$r * $r / (4 * cos($half) ^ 2) / (160 * 160)")
      echo "| $deg deg | $(calc "$r * sin($half)" | xargs printf '%.3f') | $spp ($(field "$d" reference_passes)) |" \
        "$(calc "$(field "$d" reference_mean_luminance) / $expected" | xargs printf '%.4f') |" \
        "$(calc "100 * $(field "$d" reference_energy_error)" | xargs printf '%.2f%%') |"
    }
  done
  echo
  echo "### How many samples: the reference's noise against its sample count"
  echo
  echo "Noise RMSE of the reference (the RMSE it is expected to have against the converged image) and"
  echo "the standard error of its energy, frame 0 at 320x180. Every table below prints the noise of"
  echo "its own reference in its last row."
  echo
  echo "| scene | 64 spp | 256 spp | 1024 spp | 4096 spp |"
  echo "| --- | --- | --- | --- | --- |"
  for s in $aa_scenes mirror-bumps; do
    printf '| builtin:%s |' "$s"
    for spp in 64 256 1024 4096; do
      $B compare -q --scene "builtin:$s" --methods conventional --spp $spp --width 320 --height 180 \
        -o "$out/noise-$s-$spp" > /dev/null
      printf ' %s (+-%s) |' "$(fmt '%.4f' "$(field "$out/noise-$s-$spp" reference_noise_rmse)")" \
        "$(calc "100 * $(field "$out/noise-$s-$spp" reference_energy_error)" | xargs printf '%.2f%%')"
    done
    echo
  done
  echo
  cat <<'TEXT'
What changed against the tables before this reference: the old reference read the normal map
through the sub-pixel's mip level, so wherever a sub-pixel spanned several texels it shaded a
flattened map, brighter and narrower than the real one, and it sampled fixed sub-pixel centres.
On builtin:bumpy-plane and builtin:mirror-bumps the reference now shades the map's own normals
everywhere, so methods that widen their lobes by the map's variance (`toksvig`, `lean`) are judged
against the surface they model. The methods changed in the same issue too (lights with extent are
integrated over the light, no mirror switch, the kernels and frames of docs/methods.md), so no
number below compares with the former tables; the git history keeps them. Scenes without normal
maps changed by the reference's noise and by the method fixes of the same change (see docs/methods.md).
TEXT
  echo
}

aa_section() {
  echo "## Specular anti-aliasing against the 1024-spp reference (frame 0, 640x360)"
  echo
  echo "The \`(reference noise)\` row is the reference's noise RMSE and the standard error of its"
  echo "energy: RMSE differences much smaller than it are not a ranking."
  echo
  for s in $aa_scenes; do
    $B compare -q --scene "builtin:$s" --methods all --spp 1024 -o "$out/$s" > "$out/$s.txt"
    echo "### builtin:$s"
    echo
    echo '```'
    sed '$d' "$out/$s.txt"
    echo '```'
    echo
    ranking_note "$out/$s"
    echo
    thumbnails "$s" "$out/$s" conventional vlachos kaplanyan-ggx tokuyoshi lean
    echo
  done
  echo "## Flicker over the camera path (320x180, 12 frames, 256-spp reference per frame)"
  echo
  echo "Flicker: mean over pixels and frames of |(m_t - r_t) - (m_{t-1} - r_{t-1})| (README). The"
  echo "\`(reference floor)\` row gives the reference's noise RMSE and its flicker floor: the flicker a"
  echo "second independent reference shows against the first. Flicker near the floor is noise."
  echo
  for s in $aa_scenes; do flicker_table "### builtin:$s" "$s" --methods all; done
}

podee_section() {
  local scenes="mirror-disk mirror-bumps"
  echo "## Micro-specular highlights: the structure of Podee et al.'s Table 1"
  echo
  echo "RMSE of linear radiance at 640x360, frame 0, against a 64-spp reference (the paper's 64x) and"
  echo "a 1024-spp one. Podee et al. report 0.0845 (conventional), 0.0977 (LEAN), 0.0826 (theirs) on"
  echo "their own scene, in values we cannot reproduce; ours are linear HDR radiance."
  echo
  for s in $scenes; do
    for spp in 64 1024; do
      $B compare -q --scene "builtin:$s" --methods all --spp $spp -o "$out/podee-$s-$spp" > /dev/null
    done
  done
  echo "| method | mirror-disk, 64 spp | mirror-disk, 1024 spp | mirror-bumps, 64 spp | mirror-bumps, 1024 spp |"
  echo "| --- | --- | --- | --- | --- |"
  for m in $(jq -r '.methods[].method' "$out/podee-mirror-disk-64/metrics.json"); do
    printf '| %s |' "$m"
    for s in $scenes; do for spp in 64 1024; do printf ' %s |' "$(fmt '%.4f' "$(metric "$out/podee-$s-$spp" "$m" rmse)")"; done; done
    echo
  done
  printf '| (reference noise) |'
  for s in $scenes; do for spp in 64 1024; do printf ' %s |' "$(fmt '%.4f' "$(field "$out/podee-$s-$spp" reference_noise_rmse)")"; done; done
  echo
  echo
  for s in $scenes; do
    echo "builtin:$s: $(ranking_note "$out/podee-$s-1024")"
    echo
    thumbnails "$s" "$out/podee-$s-1024" conventional lean tokuyoshi podee
    echo
  done
  echo "### Flicker over the camera path (320x180, 12 frames, 256-spp reference per frame)"
  echo
  for s in $scenes; do flicker_table "builtin:$s" "$s" --methods all; done
  echo "### Far away: many bumps inside a pixel"
  echo
  echo "builtin:mirror-bumps near (frame 0) and far (frame 23, the end of its dolly), 1024-spp"
  echo "reference; RMSE and energy ratio. \`podee\` reads its corner normals at the footprint scaled by"
  echo "2^corner_lod (0: the pixel centre's mip level, which flattens the bumps far away; the default,"
  echo "-16, is the base level); \`lobe=lean\` widens its lobe by the map's slope covariance inside the"
  echo "footprint, the variation the four corners cannot see (the paper's stated failure case)."
  echo
  local variants=(
    "conventional|conventional|"
    "lean|lean|"
    "podee (default: corners at the base mip level)|podee|"
    "podee, corners at the centre's level (corner_lod=0)|podee|--param podee.corner_lod=0"
    "podee, corners two levels finer (corner_lod=-2)|podee|--param podee.corner_lod=-2"
    "podee, lobe=lean|podee|--param podee.lobe=lean"
  )
  echo "| variant | RMSE near | energy near | RMSE far | energy far |"
  echo "| --- | --- | --- | --- | --- |"
  local i=0
  for v in "${variants[@]}"; do
    IFS='|' read -r label id params <<< "$v"
    printf '| %s |' "$label"
    for frame in 0 23; do
      # shellcheck disable=SC2086
      if $B compare -q --scene builtin:mirror-bumps --frame $frame --methods "$id" $params --spp 1024 \
          -o "$out/podee-far-$i-$frame" > /dev/null 2> "$out/podee-far-$i-$frame.err"; then
        printf ' %s | %s |' "$(fmt '%.4f' "$(metric "$out/podee-far-$i-$frame" "$id" rmse)")" \
          "$(fmt '%.3f' "$(metric "$out/podee-far-$i-$frame" "$id" energy_ratio)")"
      else
        printf ' (%s) | |' "$(head -c 80 "$out/podee-far-$i-$frame.err")"
      fi
    done
    echo
    i=$((i + 1))
  done
  printf '| (reference noise) | %s | | %s | |\n' "$(fmt '%.4f' "$(field "$out/podee-far-0-0" reference_noise_rmse)")" \
    "$(fmt '%.4f' "$(field "$out/podee-far-0-23" reference_noise_rmse)")"
  echo
  cp "$out/podee-far-5-23/podee.png" "$out/podee-far-0-23/podee-lobe-lean.png"
  cp "$out/podee-far-3-23/podee.png" "$out/podee-far-0-23/podee-centre-level.png"
  cp "$out/podee-far-2-23/podee.png" "$out/podee-far-0-23/podee.png"
  cp "$out/podee-far-1-23/lean.png" "$out/podee-far-0-23/lean.png"
  thumbnails mirror-bumps-far "$out/podee-far-0-23" conventional lean podee podee-centre-level podee-lobe-lean
  echo
  echo "### Variants of \`podee\`: error and cost"
  echo
  echo "Error on builtin:mirror-disk (640x360, 1024 spp); cost: median wall ms of a 1920x1080 frame of"
  echo "builtin:mirror-disk (\`glintlab bench\`, 10 frames) and its ratio to \`conventional\`."
  echo
  $B bench -q --scene builtin:mirror-disk --methods conventional --width 1920 --height 1080 --bench-frames 10 \
    -o "$out/podee-bench-conventional" > /dev/null
  local conv_ms
  conv_ms=$(bench_ms "$out/podee-bench-conventional/bench.json" conventional)
  echo "| variant | RMSE | energy | ms per frame | vs conventional ($(fmt '%.0f' "$conv_ms") ms) |"
  echo "| --- | --- | --- | --- | --- |"
  for p in "corners=interpolated" "corners=derivatives" "origin=centre" "area=circle" "area=lens" "glossy=off"; do
    $B compare -q --scene builtin:mirror-disk --methods podee --param "$p" --spp 1024 -o "$out/podee-variant" > /dev/null
    $B bench -q --scene builtin:mirror-disk --methods podee --param "$p" --width 1920 --height 1080 --bench-frames 10 \
      -o "$out/podee-bench" > /dev/null
    local ms
    ms=$(bench_ms "$out/podee-bench/bench.json" podee)
    echo "| $p | $(fmt '%.4f' "$(metric "$out/podee-variant" podee rmse)") | $(fmt '%.3f' "$(metric "$out/podee-variant" podee energy_ratio)") |" \
      "$(fmt '%.0f' "$ms") | $(calc "$ms / $conv_ms" | xargs printf '%.2fx') |"
  done
  echo
  echo "### Where the lobe extension holds: one sphere under a small sphere light"
  echo
  echo "\`tools/podee-sphere.toml\`: a sphere of radius 0.6 (64x48 pixels), GGX alpha from a mirror to"
  echo "0.3, a sphere light of angular radius 3.2 degrees; RMSE against 1024 spp. \`glossy=off\` is the"
  echo "paper's shading of every material as a mirror."
  echo
  echo "| alpha | conventional | tokuyoshi | kaplanyan-ggx | podee | podee, glossy=off | (reference noise) |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  for a in 0 0.01 0.03 0.1 0.3; do
    sed "s/%ALPHA%/$a/" tools/podee-sphere.toml > "$out/podee-sphere.toml"
    $B compare -q --scene "$out/podee-sphere.toml" --methods conventional,tokuyoshi,kaplanyan-ggx,podee --spp 1024 \
      -o "$out/podee-sphere" > /dev/null
    $B compare -q --scene "$out/podee-sphere.toml" --methods podee --param glossy=off --spp 1024 \
      -o "$out/podee-sphere-off" > /dev/null
    printf '| %s |' "$a"
    for m in conventional tokuyoshi kaplanyan-ggx podee; do printf ' %s |' "$(fmt '%.4f' "$(metric "$out/podee-sphere" "$m" rmse)")"; done
    printf ' %s | %s |\n' "$(fmt '%.4f' "$(metric "$out/podee-sphere-off" podee rmse)")" \
      "$(fmt '%.4f' "$(field "$out/podee-sphere" reference_noise_rmse)")"
  done
  echo
}

# Glints: the methods of Chermain et al. 2020 and 2021 and their variants against the papers'
# reference (the glinty BRDF at each sub-pixel with its own footprint, 1024 spp), flicker, speed
# and the dictionary's memory, at 320x180.
glint_variants=(
  "conventional (smooth limit)|conventional|"
  "chermain2020|chermain2020|"
  "chermain2020 + LEAN|chermain2020|--param chermain2020.lean=on"
  "chermain2021 projected, s_K 0.5|chermain2021|--param chermain2021.lean=off"
  "chermain2021 projected, s_K 1|chermain2021|--param chermain2021.lean=off --param chermain2021.kernel=1"
  "chermain2021 slopes, s_K 0.5|chermain2021|--param chermain2021.lean=off --param chermain2021.derivatives=slopes"
  "chermain2021 slopes, s_K 1|chermain2021|--param chermain2021.lean=off --param chermain2021.derivatives=slopes --param chermain2021.kernel=1"
  "chermain2021 + LEAN (default)|chermain2021|"
)
glints_section() {
  local scenes="glint-tubes glint-sphere" size="--width 320 --height 180"
  echo "## Glints: Chermain et al. 2020 and 2021"
  echo
  echo "RMSE of linear radiance at 320x180, frame 0, against the papers' reference (the glinty BRDF"
  echo "evaluated at each of 1024 jittered samples per pixel with its sub-pixel's own footprint, no"
  echo "anti-aliasing); flicker over 12 frames of the camera path against 256-spp references. Lights"
  echo "are point lights, which is what the glinty BRDFs are defined for. builtin:glint-tubes has no"
  echo "normal map (LEAN changes nothing there); builtin:glint-sphere has an anisotropic one."
  echo
  local i=0
  for v in "${glint_variants[@]}"; do
    IFS='|' read -r label id params <<< "$v"
    for s in $scenes; do
      # shellcheck disable=SC2086
      $B compare -q --scene builtin:$s --methods "$id" $params --spp 1024 $size -o "$out/glints-$s-$i" > /dev/null
      # shellcheck disable=SC2086
      $B animate -q --scene builtin:$s --methods "$id" $params $size --frames 12 --spp 256 \
        -o "$out/glints-anim-$s-$i" > /dev/null
    done
    i=$((i + 1))
  done
  echo "| variant | RMSE glint-tubes | RMSE glint-sphere | flicker glint-tubes | flicker glint-sphere |"
  echo "| --- | --- | --- | --- | --- |"
  i=0
  for v in "${glint_variants[@]}"; do
    IFS='|' read -r label id params <<< "$v"
    printf '| %s |' "$label"
    for s in $scenes; do printf ' %s |' "$(fmt '%.4f' "$(metric "$out/glints-$s-$i" "$id" rmse)")"; done
    for s in $scenes; do
      printf ' %s |' "$(fmt '%.4f' "$(jq -r '.methods[0].flicker' "$out/glints-anim-$s-$i/metrics.json")")"
    done
    echo
    i=$((i + 1))
  done
  printf '| (reference noise; flicker floor) |'
  for s in $scenes; do printf ' %s |' "$(fmt '%.4f' "$(field "$out/glints-$s-0" reference_noise_rmse)")"; done
  for s in $scenes; do printf ' %s |' "$(fmt '%.4f' "$(field "$out/glints-anim-$s-0" flicker_floor)")"; done
  echo
  echo
  cat <<'TEXT'
Pixel RMSE does not reward sparkle: the smooth limit that `conventional` draws is the glints'
expected value, with no sparkle at all, so it is a reference for energy, not for appearance.
TEXT
  echo
  echo "Pictures (frame 0, with the scenes' star bloom; metrics never see it):"
  echo
  for s in $scenes; do
    cp "$out/glints-$s-0/reference.png" "docs/images/$s-reference.png"
    cp "$out/glints-$s-1/chermain2020.png" "docs/images/$s-chermain2020.png"
    cp "$out/glints-$s-3/chermain2021.png" "docs/images/$s-chermain2021.png"
    cp "$out/glints-$s-7/chermain2021.png" "docs/images/$s-chermain2021-lean.png"
    echo "| builtin:$s reference | chermain2020 | chermain2021 | chermain2021 + LEAN |"
    echo "| --- | --- | --- | --- |"
    echo "| ![](images/$s-reference.png) | ![](images/$s-chermain2020.png) | ![](images/$s-chermain2021.png) | ![](images/$s-chermain2021-lean.png) |"
    echo
  done
  echo "### Speed and memory"
  echo
  echo "Median wall time per frame of builtin:glint-tubes at 640x360 (\`glintlab bench\`; llvmpipe on"
  echo "this machine: the cell loops run on the CPU, and textureGrad is a software path)."
  echo
  $B bench -q --scene builtin:glint-tubes --methods conventional,chermain2020,chermain2021 --width 640 --height 360 \
    --bench-frames 5 -o "$out/glints-bench" > /dev/null
  local j="$out/glints-bench/bench.json" conv base ggaa
  conv=$(bench_ms "$j" conventional); base=$(bench_ms "$j" chermain2020); ggaa=$(bench_ms "$j" chermain2021)
  echo "| conventional | chermain2020 | chermain2021 | GGAA overhead (2021 / 2020 - 1) |"
  echo "| --- | --- | --- | --- |"
  echo "| $(fmt '%.0f' "$conv") ms | $(fmt '%.0f' "$base") ms | $(fmt '%.0f' "$ggaa") ms | $(calc "($ggaa / $base - 1) * 100" | xargs printf '%+.0f%%') |"
  echo
  echo "The paper reports +0.6% to +4.2% on an RTX 2080, where filtered texture reads are nearly free."
  echo
  echo '```'
  $B info | grep 'glint dictionary'
  echo '```'
  echo
  echo "The paper counts 384 KiB and 512 KiB with mips (one third more, as for 2D textures); a 1D mip"
  echo "chain adds 64/2 + 64/4 + ... + 1 = 63 texels to 64, nearly doubling it."
  echo
  echo "Cells inside each pixel's footprint per level, at 1920x1080, unguarded (test"
  echo "\`Chermain.TheCellGuardNeverTruncatesOnTheBuiltInScenesAt1080p\`):"
  echo
  echo '```'
  build/release/tests/test_render --gtest_filter='Chermain.TheCellGuard*' | grep 'cells per level'
  echo '```'
  echo
}

# A method's field in an animate output directory: anim DIR METHOD KEY (mean_rmse, flicker).
anim() { jq -r --arg m "$2" --arg k "$3" '.methods[] | select(.method == $m) | .[$k]' "$1/metrics.json"; }

binomial_glints_section() {
  local dir="$out/binomial" S="--width 320 --height 180" A="--width 160 --height 90 --frames 8 --spp 64"
  local B2="--width 640 --height 360 --bench-frames 5"
  mkdir -p "$dir"
  # The same scene for the Chermain methods: type glinty, the same ln density per uv area and
  # sigma = alpha / sqrt(2) (Beckmann alpha = sqrt(2) sigma = the GGX alpha); R has no counterpart.
  $B scenes --print glint-binomial | sed -e 's/type = "binomial-glints"/type = "glinty"/' \
    -e 's/^alpha = 0.25$/sigma = 0.1768/' -e 's/^alpha = 0.35$/sigma = 0.2475/' \
    -e '/^microfacet_roughness/d; /^density_randomization/d; /^slope_grid_scale/d' > "$dir/beckmann.toml"
  $B compare -q --scene builtin:glint-binomial --methods conventional,deliot2023 --spp 256 $S -o "$dir/bin" > /dev/null
  $B compare -q --scene builtin:glint-binomial --methods deliot2023 --param deliot2023.remaining_count=gaussian \
    --spp 256 $S -o "$dir/bin-gauss" > /dev/null
  $B compare -q --scene "$dir/beckmann.toml" --methods conventional,chermain2020,chermain2021 --spp 256 $S \
    -o "$dir/beck" > /dev/null
  $B animate -q --scene builtin:glint-binomial --methods conventional,deliot2023 $A -o "$dir/anim-bin" > /dev/null
  $B animate -q --scene builtin:glint-binomial --methods deliot2023 --param deliot2023.remaining_count=gaussian $A \
    -o "$dir/anim-bin-gauss" > /dev/null
  $B animate -q --scene "$dir/beckmann.toml" --methods conventional,chermain2020,chermain2021 $A -o "$dir/anim-beck" > /dev/null
  $B bench -q --scene builtin:glint-binomial --methods conventional,deliot2023 $B2 -o "$dir/bench-bin" > /dev/null
  $B bench -q --scene "$dir/beckmann.toml" --methods conventional,chermain2020,chermain2021 $B2 -o "$dir/bench-beck" > /dev/null
  cp "$dir/bin/reference.png" docs/images/glint-binomial-reference.png
  cp "$dir/bin/deliot2023.png" docs/images/glint-binomial-deliot2023.png
  cp "$dir/beck/reference.png" docs/images/glint-binomial-beckmann-reference.png
  cp "$dir/beck/chermain2021.png" docs/images/glint-binomial-beckmann-chermain2021.png
  row() {  # row LABEL COMPARE_DIR ANIMATE_DIR METHOD
    echo "| $1 | $(fmt %.4f "$(metric "$2" "$4" rmse)") | $(fmt %.3f "$(metric "$2" "$4" energy_ratio)")" \
      "| $(fmt %.4f "$(anim "$3" "$4" mean_rmse)") | $(fmt %.4f "$(anim "$3" "$4" flicker)") |"
  }
  echo "## Binomial glints: Deliot & Belcour 2023"
  echo
  echo "builtin:glint-binomial (binomial-glints materials) and the same scene made glinty for the Chermain"
  echo "methods: \`type = \"glinty\"\`, the same ln density per uv area and sigma = alpha / sqrt(2) (Beckmann"
  echo "alpha = sqrt(2) sigma = the GGX alpha). R has no counterpart in Chermain's model (its facets' own"
  echo "lobe, sigma_lobe / sigma_dict = 0.057, corresponds to R ~ 0.003; the scene uses 0.02 and 0.01)."
  echo "The scene's sun has extent: the reference counts its reflecting facets with the sun's own size (p"
  echo "integrated over it, as kneiphof2024 estimates it; docs/methods.md#kneiphof2024), deliot2023 with R."
  echo "Each method is measured against the reference of the material it renders. RMSE: 320x180,"
  echo "frame 0, 256 spp. Mean RMSE and flicker: 8 frames at 160x90 against 64-spp references."
  echo
  echo "| scene / method | RMSE | energy ratio | mean RMSE (8 frames) | flicker |"
  echo "| --- | --- | --- | --- | --- |"
  row "glint-binomial: conventional (smooth GGX limit)" "$dir/bin" "$dir/anim-bin" conventional
  row "glint-binomial: deliot2023 (lognormal count, default)" "$dir/bin" "$dir/anim-bin" deliot2023
  row "glint-binomial: deliot2023 (remaining_count=gaussian, the paper's)" "$dir/bin-gauss" "$dir/anim-bin-gauss" deliot2023
  echo "| (reference noise; flicker floor) | $(fmt %.4f "$(field "$dir/bin" reference_noise_rmse)") | | | $(fmt %.4f "$(field "$dir/anim-bin" flicker_floor)") |"
  row "matched Beckmann: conventional (smooth limit)" "$dir/beck" "$dir/anim-beck" conventional
  row "matched Beckmann: chermain2020" "$dir/beck" "$dir/anim-beck" chermain2020
  row "matched Beckmann: chermain2021" "$dir/beck" "$dir/anim-beck" chermain2021
  echo "| (reference noise; flicker floor) | $(fmt %.4f "$(field "$dir/beck" reference_noise_rmse)") | | | $(fmt %.4f "$(field "$dir/anim-beck" flicker_floor)") |"
  echo
  echo "Pixel RMSE does not reward sparkle (the smooth limit has none); the energy ratio shows the"
  echo "paper's Gaussian count's bias (docs/methods.md, deliot2023)."
  echo
  echo "| builtin:glint-binomial reference | deliot2023 | matched Beckmann reference | chermain2021 |"
  echo "| --- | --- | --- | --- |"
  echo "| ![](images/glint-binomial-reference.png) | ![](images/glint-binomial-deliot2023.png) | ![](images/glint-binomial-beckmann-reference.png) | ![](images/glint-binomial-beckmann-chermain2021.png) |"
  echo
  echo "Speed: median per frame at 640x360 (\`glintlab bench\`, 5 frames), wall / GL timer ms:"
  echo
  echo "| scene | method | wall ms | GL timer ms |"
  echo "| --- | --- | --- | --- |"
  local m
  for m in conventional deliot2023; do
    echo "| glint-binomial | $m | $(fmt %.1f "$(bench_ms "$dir/bench-bin/bench.json" $m)") | $(fmt %.1f "$(jq -r --arg m $m '.methods[] | select(.method == $m) | .gpu_ms_median' "$dir/bench-bin/bench.json")") |"
  done
  for m in conventional chermain2020 chermain2021; do
    echo "| matched Beckmann | $m | $(fmt %.1f "$(bench_ms "$dir/bench-beck/bench.json" $m)") | $(fmt %.1f "$(jq -r --arg m $m '.methods[] | select(.method == $m) | .gpu_ms_median' "$dir/bench-beck/bench.json")") |"
  done
  echo
  echo "Memory: \`deliot2023\` reads no table and no noise texture (its random numbers are a procedural"
  echo "pcg4d hash): 0 bytes; the material record stays 128 bytes. The Chermain methods read the glint"
  echo "dictionary (\`glintlab info\`). Regenerate: \`tools/make-results.sh binomial-glints\`."
}

# Glints under area lights: tools/results/area-glints.sh.
source tools/results/area-glints.sh
# Prefiltered glints (deng2022, yan2016): tools/results/prefiltered-glints.sh.
source tools/results/prefiltered-glints.sh

# A glossy mirror-coloured plane and sphere (f0 = 1, no diffuse) of GGX roughness $2 under one light
# of kind $1 (quad, disk, sphere) that crosses the sphere's horizon: area_light_scene KIND ALPHA.
area_light_scene() {
  local light
  case $1 in
    quad) light='type = "quad"
position = [0.0, 1.6, -1.2]
direction = [0.0, -1.0, 0.9]
size = [1.2, 0.5]
up = [0, 1, 0]' ;;
    disk) light='type = "disk"
position = [0.0, 1.6, -1.2]
direction = [0.0, -1.0, 0.9]
radius = 0.4' ;;
    sphere) light='type = "sphere"
position = [0.0, 1.6, -1.2]
radius = 0.3' ;;
  esac
  cat <<TOML
description = "area-light study: GGX alpha $2 under a $1 light"
[film]
width = 192
height = 108
[camera]
position = [0.0, 1.0, 3.0]
target = [0.0, 0.2, -0.6]
fov = 40
[[material]]
name = "glossy"
ndf = "ggx"
alpha = $2
f0 = 1
diffuse = 0
[[shape]]
type = "plane"
material = "glossy"
size = 12
[[shape]]
type = "sphere"
material = "glossy"
radius = 0.45
translate = [0.0, 0.45, -0.4]
[[light]]
$light
radiance = 4
visible = false
TOML
}

area_lights_section() {
  echo "## Area lights: representative point or LTC"
  echo
  echo "\`conventional\` with \`area_lights = representative-point\` (the lobe's mass over the light's"
  echo "image, Fresnel and masking at the representative point) and \`area_lights = ltc\` (the GGX LTC of"
  echo "\`ltc-ggx\` integrated over the light's polygon or disk, horizon clipped) against a 256-spp reference,"
  echo "on a glossy plane and sphere (f0 = 1, no diffuse, 192x108) under one light of each kind that"
  echo "crosses the sphere's horizon. RMSE on linear radiance; energy = mean ratio to the reference;"
  echo "noise = the reference's own RMSE estimate. The default of every lobe method is the column with"
  echo "the lower RMSE in most rows."
  echo
  echo "| light | alpha | reference noise | RMSE representative point | RMSE LTC | energy representative point | energy LTC |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  local kind alpha dir
  for kind in quad disk sphere; do
    for alpha in 0.02 0.05 0.1 0.2 0.5 1.0; do
      dir="$out/area-lights/$kind-$alpha"
      mkdir -p "$dir"
      area_light_scene "$kind" "$alpha" > "$dir/scene.toml"
      $B compare -q --scene "$dir/scene.toml" --methods conventional --param area_lights=representative-point \
        --spp 256 -o "$dir/rp" > /dev/null
      $B compare -q --scene "$dir/scene.toml" --methods conventional --param area_lights=ltc --spp 256 \
        -o "$dir/ltc" > /dev/null
      echo "| $kind | $alpha | $(fmt %.4f "$(field "$dir/rp" reference_noise_rmse)")" \
        "| $(fmt %.4f "$(metric "$dir/rp" conventional rmse)") | $(fmt %.4f "$(metric "$dir/ltc" conventional rmse)")" \
        "| $(fmt %.3f "$(metric "$dir/rp" conventional energy_ratio)") | $(fmt %.3f "$(metric "$dir/ltc" conventional energy_ratio)") |"
    done
  done
  echo
  # Cost: the same method with each choice on the quad and sphere scenes (alpha 0.1) at 640x360.
  local choice rp_ms ltc_ms
  echo "Cost of the choice (\`glintlab bench\`, 640x360, 10 frames, median wall ms per frame):"
  echo
  echo "| light | representative point | LTC | LTC / representative point |"
  echo "| --- | --- | --- | --- |"
  for kind in quad sphere; do
    dir="$out/area-lights/$kind-0.1"
    for choice in representative-point ltc; do
      $B bench -q --scene "$dir/scene.toml" --methods conventional --param area_lights=$choice --width 640 \
        --height 360 --bench-frames 10 -o "$dir/bench-$choice" > /dev/null
    done
    rp_ms=$(bench_ms "$dir/bench-representative-point/bench.json" conventional)
    ltc_ms=$(bench_ms "$dir/bench-ltc/bench.json" conventional)
    echo "| $kind | $(fmt %.1f "$rp_ms") | $(fmt %.1f "$ltc_ms") | $(calc "$ltc_ms / $rp_ms" | xargs printf '%.2f')x |"
  done
  echo
  echo "Regenerate: \`tools/make-results.sh area-lights\`."
}

speed_section() {
  echo "## Speed"
  echo
  echo "Every method on builtin:spheres at 1920x1080 (\`glintlab bench\`; methods take turns frame by"
  echo "frame; ratios are to \`conventional\`, the first listed). On llvmpipe the GL timer query does not"
  echo "measure the rasteriser's work: read wall-clock times."
  echo
  $B bench -q --scene builtin:spheres --methods all --width 1920 --height 1080 --bench-frames 20 -o "$out/bench" > /dev/null
  echo "| method | wall ms (median) | vs conventional | GL timer ms (median) |"
  echo "| --- | --- | --- | --- |"
  jq -r '.methods[] | "| \(.method) | \(.wall_ms_median * 10 | round / 10) | \(.wall_ratio * 100 | round / 100)x | \(.gpu_ms_median * 10 | round / 10) |"' \
    "$out/bench/bench.json"
  local t0 t1 t2 t3
  t0=$(date +%s.%N); $B render -q --no-cache --reference=64 --width 512 --height 512 -o "$out/ref64" > /dev/null; t1=$(date +%s.%N)
  t2=$(date +%s.%N); $B render -q --no-cache --reference=1024 --width 512 --height 512 -o "$out/ref1024" > /dev/null; t3=$(date +%s.%N)
  echo
  echo "| reference of builtin:spheres at 512x512 | seconds |"
  echo "| --- | --- |"
  echo "| 64 spp | $(calc "$t1 - $t0" | xargs printf '%.1f') |"
  echo "| 1024 spp | $(calc "$t3 - $t2" | xargs printf '%.1f') |"
  echo
  # The README's table, from the same numbers.
  local conv unshaded
  conv=$(bench_ms "$out/bench/bench.json" conventional)
  unshaded=$(bench_ms "$out/bench/bench.json" "(unshaded)")
  {
    echo "| what | target | measured |"
    echo "| --- | --- | --- |"
    echo "| \`conventional\`, builtin:spheres, 1920x1080, median wall time per frame | <= 50 ms | $(fmt '%.0f' "$conv") ms$(awk -v c="$conv" 'BEGIN { if (c > 50) printf " — **not met** (see below)" }') |"
    echo "| the same frame shading nothing (\`(unshaded)\`) | | $(fmt '%.0f' "$unshaded") ms |"
    echo "| 64-spp reference, 512x512 | <= 20 s | $(calc "$t1 - $t0" | xargs printf '%.1f') s |"
    echo "| 1024-spp reference, 512x512 | <= 120 s | $(calc "$t3 - $t2" | xargs printf '%.1f') s |"
  } > "$out/readme-speed.md"
  awk -v f="$out/readme-speed.md" '/<!-- table:speed -->/ { print; while ((getline l < f) > 0) print l; skip = 1; next }
    /<!-- \/table:speed -->/ { skip = 0 } !skip { print }' README.md > README.md.tmp
  mv README.md.tmp README.md
}

# --- the HTML report (docs/report.md) ---------------------------------------------------------------

# Every run under $out: $out/report/index.html (about 33 MB with its images and videos; not
# committed). The headline runs of each section: docs/report/ (about 9 MB; committed, linked from
# the README). Runs a section has not made yet are left out.
report_runs="spheres tubes animate-spheres animate-tubes bench podee-sphere podee-mirror-disk-1024 animate-mirror-disk
  podee-bench glints-glint-sphere-0 glints-anim-glint-sphere-0 glints-bench binomial/bin binomial/anim-bin
  binomial/bench-bin area-lights/sphere-0.1 area-glints/gl-on area-glints/anim-gl-on area-glints/bench
  prefiltered/normal-glints-flakes-near prefiltered/normal-glints-flakes-far prefiltered/normal-glints-flakes-anim"
write_reports() {
  $B report -o "$out/report" "$out"
  local inputs=() r
  for r in $report_runs; do if [[ -d "$out/$r" ]]; then inputs+=("$out/$r"); fi; done
  if [[ ${#inputs[@]} -gt 0 ]]; then $B report -o docs/report "${inputs[@]}"; fi
}

header() {
  echo "# Measured results"
  echo
  echo "Regenerated by \`tools/make-results.sh\`; every number below was measured by that run."
  echo "Device: \`$($B info | sed -n 's/^renderer: *//p')\`, $(nproc) CPU cores."
  echo "Definitions of the metrics: README.md, \"What the numbers mean\". RMSE on linear radiance;"
  echo "\`rmse_spec\` on the specular part only; energy = mean luminance ratio to the reference (below 1:"
  echo "lost highlights, above 1: highlights smeared over too large an area)."
  echo
}

# Prints a section between its markers.
section() { echo "<!-- section:$1 -->"; "${1//-/_}_section"; echo "<!-- /section:$1 -->"; }

sections="ground-truth aa podee glints binomial-glints area-lights area-glints prefiltered-glints speed"
if [[ $# -gt 0 && "$1" != all ]]; then
  [[ " $sections " == *" $1 "* ]] || { echo "make-results: unknown section '$1'; allowed: all $sections" >&2; exit 2; }
  grep -q "^<!-- section:$1 -->\$" docs/results.md ||
    { echo "make-results: docs/results.md has no '$1' section to replace; run tools/make-results.sh first" >&2; exit 2; }
  section "$1" > "$out/$1.md"
  awk -v f="$out/$1.md" -v s="$1" '$0 == "<!-- section:" s " -->" { while ((getline l < f) > 0) print l; skip = 1; next }
    $0 == "<!-- /section:" s " -->" { skip = 0; next } !skip { print }' docs/results.md > docs/results.md.tmp
  mv docs/results.md.tmp docs/results.md
  echo "wrote the $1 section of docs/results.md"
  write_reports
  exit 0
fi
{
  header
  for s in $sections; do section "$s"; echo; done
} > "$out/results.md"
mv "$out/results.md" docs/results.md
echo "wrote docs/results.md"
write_reports
