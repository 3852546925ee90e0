#!/usr/bin/env bash
# Regenerates docs/results.md and docs/images/ from measurements on this machine:
#   tools/make-results.sh            (after `make build`; about an hour on 2 cores cold, most of it
#                                     the 1024-spp references, which are cached for later runs)
#   tools/make-results.sh glints     only the glints section (about 20 minutes cold), spliced into
#                                     docs/results.md between its markers
set -euo pipefail
cd "$(dirname "$0")/.."
B=build/release/glintlab
out=out/results
mkdir -p "$out" docs/images
aa_scenes="spheres tubes bumpy-plane"

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

# Flicker of every method over 12 frames of builtin:$2 at 320x180, under the heading $1.
flicker_table() {
  echo "$1"
  echo
  echo '```'
  $B animate -q --scene "builtin:$2" --methods all --width 320 --height 180 --frames 12 -o "$out/animate-$2" | sed '$d'
  echo '```'
  echo
}

# RMSE of method $2 in the compare output directory $1 (metrics.csv).
rmse_of() { awk -F, -v m="$2" '$1 == m { printf "%.4f", $2 }' "$1/metrics.csv"; }
energy_of() { awk -F, -v m="$2" '$1 == m { printf "%.3f", $5 }' "$1/metrics.csv"; }
# Median wall milliseconds of the method (first row) in a `glintlab bench` JSON.
bench_ms() { grep -m1 wall_ms_median | sed 's/[^0-9.]//g' | xargs printf '%.0f'; }

# Glints (issue 5): the methods of Chermain et al. 2020 and 2021 and their variants against the
# papers' reference (the glinty BRDF at each sub-pixel with its own footprint, 1024 spp), flicker,
# speed and the dictionary's memory. 320x180: on llvmpipe the cell loops of a 1024-spp reference
# cost minutes per frame at 640x360.
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
glint_section() {
  local scenes="glint-tubes glint-sphere" size="--width 320 --height 180"
  echo "## Glints: Chermain et al. 2020 and 2021"
  echo
  echo "RMSE of linear radiance at 320x180, frame 0, against the papers' reference (the glinty BRDF"
  echo "evaluated at the centre of each of 32x32 sub-pixels with the sub-pixel's own footprint, no"
  echo "anti-aliasing); flicker over 12 frames of the camera path against 64-spp references. Lights"
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
      $B animate -q --scene builtin:$s --methods "$id" $params $size --frames 12 -o "$out/glints-anim-$s-$i" |
        awk -v m="$id" '$1 == m { print $3 }' > "$out/glints-anim-$s-$i.flicker"
    done
    i=$((i + 1))
  done
  echo "| variant | RMSE glint-tubes | RMSE glint-sphere | flicker glint-tubes | flicker glint-sphere |"
  echo "| --- | --- | --- | --- | --- |"
  i=0
  for v in "${glint_variants[@]}"; do
    IFS='|' read -r label id params <<< "$v"
    printf '| %s |' "$label"
    for s in $scenes; do printf ' %s |' "$(rmse_of "$out/glints-$s-$i" "$id")"; done
    for s in $scenes; do printf ' %.4f |' "$(cat "$out/glints-anim-$s-$i.flicker")"; done
    echo
    i=$((i + 1))
  done
  echo
  cat <<'TEXT'
Reading this table: geometric glint anti-aliasing lowers both RMSE and flicker against
`chermain2020` on both scenes, more with s_K = 1 than 0.5, as the paper reports (fig. 9: s_K = 1
shimmers less); the two derivative variants are within 2% of each other here. LEAN + glints is what
brings the normal-mapped sphere down (its anisotropic bumps are sub-pixel at this size), and it
only helps when rho carries their orientation: `chermain2020 + LEAN`, which drops rho, is worse
than without. Pixel RMSE favours the smooth limit that `conventional` draws: it is the glints'
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
  echo "this machine's 2 cores: the cell loops run on the CPU, and textureGrad is a software path)."
  echo
  $B bench -q --scene builtin:glint-tubes --methods conventional,chermain2020,chermain2021 --width 640 --height 360 \
    --bench-frames 5 > "$out/glints-bench.json"
  local base=$(sed -n '/"chermain2020"/,/wall_ms_median/p' "$out/glints-bench.json" | grep wall_ms_median | sed 's/[^0-9.]//g')
  local ggaa=$(sed -n '/"chermain2021"/,/wall_ms_median/p' "$out/glints-bench.json" | grep wall_ms_median | sed 's/[^0-9.]//g')
  local conv=$(sed -n '/"conventional"/,/wall_ms_median/p' "$out/glints-bench.json" | grep wall_ms_median | sed 's/[^0-9.]//g')
  echo "| conventional | chermain2020 | chermain2021 | GGAA overhead (2021 / 2020 - 1) |"
  echo "| --- | --- | --- | --- |"
  printf '| %.0f ms | %.0f ms | %.0f ms | %+.0f%% |\n' "$conv" "$base" "$ggaa" "$(echo "($ggaa / $base - 1) * 100" | bc -l)"
  echo
  echo "The paper reports +0.6% to +4.2% on an RTX 2080, where filtered texture reads are nearly free."
  echo
  echo '```'
  $B info | grep 'glint dictionary'
  echo '```'
  echo
  echo "The paper counts 384 KiB and 512 KiB with mips (one third more, as for 2D textures); a 1D mip"
  echo "chain adds 64/2 + 64/4 + ... + 1 = 63 texels to 64, nearly doubling it. The dictionary is"
  echo "generated once (about a second on 2 cores) and cached (\`glintlab info\` shows the time)."
  echo
  echo "Cells inside each pixel's footprint per level, at 1920x1080, unguarded (test"
  echo "\`Chermain.TheCellGuardNeverTruncatesOnTheBuiltInScenesAt1080p\`):"
  echo
  echo '```'
  build/release/tests/test_render --gtest_filter='Chermain.TheCellGuard*' | grep 'cells per level'
  echo '```'
}

# Micro-specular highlights (issue 4): the paper's Table 1 on our two near-mirror scenes, flicker,
# the failure case, the variants of `podee` (cost and error) and where the lobe extension holds.
podee_section() {
  local scenes="mirror-disk mirror-bumps"
  echo "## Micro-specular highlights: the structure of Podee et al.'s Table 1"
  echo
  echo "RMSE of linear radiance at 640x360, frame 0, against the 64x tiled supersampling reference"
  echo "(8x8 sub-pixels per pixel, rendered in tiles; the paper's reference) and against 1024 spp."
  echo "Podee et al. report 0.0845 (conventional), 0.0977 (LEAN), 0.0826 (theirs) on their own scene,"
  echo "on values we cannot reproduce; ours are linear HDR radiance (lights of radiance 400-2500)."
  echo
  for s in $scenes; do
    for spp in 64 1024; do
      $B compare -q --scene builtin:$s --methods all --spp $spp -o "$out/podee-$s-$spp" > /dev/null
    done
  done
  cat <<'TEXT'
Reading these tables: `podee` has the lowest RMSE of every method on both scenes and the lowest
flicker on builtin:mirror-disk; the filtering methods trade the aliased highlight for a blurred one
(the paper: LEAN "overly blurs"). On builtin:mirror-bumps the camera path pulls back into the failure
case below, so over the whole path `podee` flickers less than `conventional` but more than the
methods that filter the normal map. The 64x and 1024-spp references agree to a few percent, so the
paper's 64x tiled reference is enough to rank these methods. On llvmpipe `podee` costs several
times `conventional` per frame (Speed, and the variants below): the CPU rasteriser runs both corner
variants and every branch of the clipping for every pixel and light.

TEXT
  echo "| method | mirror-disk, 64x | mirror-disk, 1024 spp | mirror-bumps, 64x | mirror-bumps, 1024 spp |"
  echo "| --- | --- | --- | --- | --- |"
  for m in $(awk -F, 'NR > 1 { print $1 }' "$out/podee-mirror-disk-64/metrics.csv"); do
    printf '| %s |' "$m"
    for s in $scenes; do for spp in 64 1024; do printf ' %s |' "$(rmse_of "$out/podee-$s-$spp" "$m")"; done; done
    echo
  done
  echo
  for s in $scenes; do
    echo "builtin:$s (1024 spp reference):"
    echo
    thumbnails "$s" "$out/podee-$s-1024" conventional lean tokuyoshi podee
    echo
  done
  echo "### Flicker over the camera path (320x180, 12 frames, 64-spp reference per frame)"
  echo
  for s in $scenes; do flicker_table "builtin:$s" "$s"; done
  echo "### The failure case: far away, many bumps inside a pixel"
  echo
  echo "The last frame of builtin:mirror-bumps' camera path (frame 23), 1024-spp reference. The four"
  echo "corner normals are read from the normal map filtered over the pixel's footprint, so the bumps"
  echo "inside the pixel are invisible to them: the reflection space is far too small, and \`podee\`"
  echo "lights a narrow patch where the filtered normals reflect the light, while the reference's cloud"
  echo "of glints is much wider (the paper: 'fails to capture the reflection at far distances')."
  echo "The lobe extension with \`lobe=lean\` widens the lobe"
  echo "by the normal map's slope covariance inside the footprint, the variation the corners miss:"
  echo
  local far="$out/podee-far"
  $B compare -q --scene builtin:mirror-bumps --frame 23 --methods conventional,lean,podee --spp 1024 -o "$far" > /dev/null
  $B compare -q --scene builtin:mirror-bumps --frame 23 --methods podee --param lobe=lean --spp 1024 -o "$far-lean" > /dev/null
  $B compare -q --scene builtin:mirror-bumps --frame 0 --methods podee --param lobe=lean --spp 1024 -o "$out/podee-near-lean" > /dev/null
  echo "| frame | conventional | lean | podee | podee, lobe=lean |"
  echo "| --- | --- | --- | --- | --- |"
  echo "| 0 (near) | $(rmse_of "$out/podee-mirror-bumps-1024" conventional) | $(rmse_of "$out/podee-mirror-bumps-1024" lean) | $(rmse_of "$out/podee-mirror-bumps-1024" podee) | $(rmse_of "$out/podee-near-lean" podee) |"
  echo "| 23 (far) | $(rmse_of "$far" conventional) | $(rmse_of "$far" lean) | $(rmse_of "$far" podee) | $(rmse_of "$far-lean" podee) |"
  echo
  cp "$far-lean/podee.png" "$far/podee-lobe-lean.png"
  thumbnails mirror-bumps-far "$far" conventional lean podee podee-lobe-lean
  echo
  echo "At frame 0 the footprint's covariance double-counts what the corners already resolve, and"
  echo "\`lobe=lean\` over-blurs like LEAN; far away it matches LEAN. It is therefore a parameter, not the default."
  echo
  echo "### Variants of \`podee\`: error and cost"
  echo
  echo "Error on builtin:mirror-disk (640x360, 1024 spp) and on a flat mirror's rim"
  echo "(tests/render/test_podee.cpp asserts the latter below 2% for both corner variants); cost: median"
  echo "wall ms of a 1920x1080 frame of builtin:mirror-disk (\`glintlab bench\`, 10 frames), \`conventional\` first."
  echo
  local conv_ms
  conv_ms=$($B bench -q --scene builtin:mirror-disk --methods conventional --width 1920 --height 1080 --bench-frames 10 | bench_ms)
  echo "| variant | RMSE | energy | ms per frame | vs conventional ($conv_ms ms) |"
  echo "| --- | --- | --- | --- | --- |"
  for p in "corners=interpolated" "corners=derivatives" "origin=centre" "area=circle" "area=lens" "glossy=off"; do
    $B compare -q --scene builtin:mirror-disk --methods podee --param "$p" --spp 1024 -o "$out/podee-variant" > /dev/null
    local ms
    ms=$($B bench -q --scene builtin:mirror-disk --methods podee --param "$p" --width 1920 --height 1080 --bench-frames 10 | bench_ms)
    echo "| $p | $(rmse_of "$out/podee-variant" podee) | $(energy_of "$out/podee-variant" podee) | $ms | $(echo "scale=2; $ms / $conv_ms" | bc)x |"
  done
  echo
  echo "### Where the lobe extension holds: one sphere under a small sphere light"
  echo
  echo "A sphere of radius 0.6 (64x48 pixels, highlight under a pixel across), GGX alpha from a mirror"
  echo "to 0.3, a sphere light of angular radius 3.2 degrees; RMSE against 1024 spp. \`glossy=off\` is"
  echo "the paper's shading of every material as a mirror."
  echo
  echo "| alpha | conventional | tokuyoshi | kaplanyan-ggx | podee | podee, glossy=off |"
  echo "| --- | --- | --- | --- | --- | --- |"
  for a in 0 0.01 0.03 0.1 0.3; do
    sed "s/%ALPHA%/$a/" tools/podee-sphere.toml > "$out/podee-sphere.toml"
    $B compare -q --scene "$out/podee-sphere.toml" --methods conventional,tokuyoshi,kaplanyan-ggx,podee --spp 1024 -o "$out/podee-sphere" > /dev/null
    $B compare -q --scene "$out/podee-sphere.toml" --methods podee --param glossy=off --spp 1024 -o "$out/podee-sphere-off" > /dev/null
    echo "| $a | $(rmse_of "$out/podee-sphere" conventional) | $(rmse_of "$out/podee-sphere" tokuyoshi) | $(rmse_of "$out/podee-sphere" kaplanyan-ggx) | $(rmse_of "$out/podee-sphere" podee) | $(rmse_of "$out/podee-sphere-off" podee) |"
  done
  echo
}

if [[ "${1:-all}" == glints ]]; then
  { echo '<!-- section:glints -->'; glint_section; echo '<!-- /section:glints -->'; } > "$out/glints.md"
  if grep -q '<!-- section:glints -->' docs/results.md; then
    awk -v f="$out/glints.md" '/<!-- section:glints -->/ { while ((getline l < f) > 0) print l; skip = 1; next }
      /<!-- \/section:glints -->/ { skip = 0; next } !skip { print }' docs/results.md > docs/results.md.tmp
  else
    awk -v f="$out/glints.md" '/^## Speed/ { while ((getline l < f) > 0) print l; print "" } { print }' \
      docs/results.md > docs/results.md.tmp
  fi
  mv docs/results.md.tmp docs/results.md
  echo "wrote the glints section of docs/results.md"
  exit 0
fi

{
  echo "# Measured results"
  echo
  echo "Regenerated by \`tools/make-results.sh\`; every number below was measured by that run."
  echo "Device: \`$($B info | sed -n 's/^renderer: *//p')\`, $(nproc) CPU cores."
  echo "Definitions of the metrics: README.md, \"Metrics\". RMSE on linear radiance; \`rmse_spec\` on the"
  echo "specular part only; energy = mean luminance ratio to the reference (below 1: lost highlights,"
  echo "above 1: highlights smeared over too large an area)."
  echo
  cat <<'TEXT'
## Reading the specular anti-aliasing results

What the test suite holds true on 160x90 versions of these scenes (tests/render/test_specular_aa.cpp),
and the tables below show at full size:

- Curvature (spheres) and thin tubes: every geometric method (vlachos, the three Kaplanyan variants,
  tokuyoshi) has lower RMSE than `conventional`, and all but two lower flicker. The exceptions are
  `kaplanyan-beckmann` and `kaplanyan-ggx` on the tubes: the tubes are thinner than a pixel, so
  their half-vector derivatives come from helper pixels off the tube and measure nothing (the
  paper: shading filtering does not address geometric aliasing); the full covariance and the box
  then follow those derivatives, while the rectangle's Gaussian, Vlachos' floor and Tokuyoshi's
  bounded projected space do not.
- `toksvig` and `lean` read the normal map only: on scenes without one they are exactly
  `conventional`; on the normal-mapped plane they are the best by far (RMSE and flicker roughly
  halved). `vlachos` sees only the vertex normal, so on the flat normal-mapped plane it is exactly
  `conventional`. The half-vector methods help there too (the normal map changes the shading frame
  across the quad), less than LEAN and Toksvig.
- Energy: `conventional` on the normal-mapped plane has 1.7x the reference's energy (the filtered
  normal is smooth, so the highlight is as bright as on a flat mirror of the mean normal, while the
  true bumps spread it); LEAN and Toksvig bring it below 1 (over-blur); the Kaplanyan covariance and
  box variants above 1 on tubes show highlights smeared over too large an area.
- Speed: the roughness-modifying methods cost 0-10% over `conventional` here. `kaplanyan-ggx` costs
  about 3.7x on llvmpipe, which executes every branch of the box average (closed form, strip and
  quadrature paths) for every light; a GPU takes one path per warp. The `(unshaded)` row is the
  floor under every method: the same frame with a module that shades nothing.

TEXT
  echo "## Specular anti-aliasing against the 1024-spp reference (frame 0, 640x360)"
  echo
  for s in $aa_scenes; do
    $B compare -q --scene builtin:$s --methods all --spp 1024 -o "$out/$s" > "$out/$s.txt"
    echo "### builtin:$s"
    echo
    echo '```'
    sed '$d' "$out/$s.txt"
    echo '```'
    echo
    thumbnails "$s" "$out/$s" conventional vlachos kaplanyan-ggx tokuyoshi lean
    echo
  done
  echo "## Flicker over the camera path (320x180, 12 frames, 64-spp reference per frame)"
  echo
  echo "Flicker: mean over pixels and frames of |(m_t - r_t) - (m_{t-1} - r_{t-1})| (README)."
  echo
  for s in $aa_scenes; do flicker_table "### builtin:$s" "$s"; done
  podee_section
  echo '<!-- section:glints -->'
  glint_section
  echo '<!-- /section:glints -->'
  echo "## Speed"
  echo
  echo "Every method on builtin:spheres at 1920x1080 (\`glintlab bench\`; methods take turns frame by"
  echo "frame; ratios are to \`conventional\`, the first listed). On llvmpipe the GL timer query does not"
  echo "measure the rasteriser's work: read wall-clock times."
  echo
  echo '```'
  $B bench -q --scene builtin:spheres --methods all --width 1920 --height 1080 --bench-frames 20
  echo '```'
  t0=$(date +%s.%N); $B render -q --no-cache --reference=64 --width 512 --height 512 -o "$out/ref64" > /dev/null; t1=$(date +%s.%N)
  t2=$(date +%s.%N); $B render -q --no-cache --reference=1024 --width 512 --height 512 -o "$out/ref1024" > /dev/null; t3=$(date +%s.%N)
  echo
  echo "| reference of builtin:spheres at 512x512 | seconds |"
  echo "| --- | --- |"
  echo "| 64 spp | $(echo "$t1 - $t0" | bc | xargs printf '%.1f') |"
  echo "| 1024 spp | $(echo "$t3 - $t2" | bc | xargs printf '%.1f') |"
} > docs/results.md.tmp
mv docs/results.md.tmp docs/results.md
echo "wrote docs/results.md"
