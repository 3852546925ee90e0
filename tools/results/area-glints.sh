# The "area-glints" section of docs/results.md (sourced by tools/make-results.sh, which defines $B,
# $out, metric, field, fmt, calc, bench_ms, anim): glints under area lights, kneiphof2024 against
# deliot2023 and conventional on binomial-glints materials, and the Chermain methods with and
# without their area-light extension on the same scenes made glinty. The structure of Kneiphof &
# Klein's experiments: the scene, convergence as density grows, the light-size sweep, runtime.

# The Chermain methods' choice for lights with extent: the extension and the old point at the centre.
chermain_area_on="light_extent=half-vector-kernel"
chermain_area_off="light_extent=centre"

# Whether two RMSEs against the same reference rank: gap_note LABEL_A DIR_A METHOD_A LABEL_B DIR_B
# METHOD_B (the reference's noise from DIR_A); a gap within twice the reference's noise RMSE is not
# a ranking (computed, never typed, as make-results.sh's ranking_note).
gap_note() {
  local a b n
  a=$(metric "$2" "$3" rmse) b=$(metric "$5" "$6" rmse) n=$(field "$2" reference_noise_rmse)
  awk -v la="$1" -v lb="$4" -v a="$a" -v b="$b" -v n="$n" 'BEGIN {
    d = a - b; if (d < 0) d = -d
    printf "%s %.4f against %s %.4f: a gap of %.4f, %s twice the reference noise (%.4f)%s\n", la, a, lb, b, d,
      (d > 2 * n ? "larger than" : "within"), 2 * n, (d > 2 * n ? "." : ": not a ranking.") }'
}

# A binomial-glints scene made glinty (stdin to stdout): the same ln density per uv area and
# sigma = alpha / sqrt 2 (Beckmann alpha = the GGX alpha); R, randomization, slope grid dropped.
glinty_version() {
  awk '/^type = "binomial-glints"$/ { print "type = \"glinty\""; next }
       /^alpha = / { printf "sigma = %.4f\n", $3 / sqrt(2); next }
       /^(microfacet_roughness|density_randomization|slope_grid_scale) = / { next } { print }'
}

# A glittering floor under one quad light of side $1 m behind the lobe's peak, the camera orbiting
# slightly: from about a point (0.02 m, 4e-5 sr) to a large panel (2 m, 0.35 sr).
light_size_scene() {
  cat <<TOML
description = "light-size sweep: a binomial-glints floor under a quad light of side $1 m"
[film]
width = 192
height = 108
[camera]
position = [0.0, 1.2, 3.0]
target = [0.0, 0.0, -0.5]
fov = 40
[camera.path]
type = "orbit"
degrees = 4
frames = 8
[[material]]
name = "glitter"
type = "binomial-glints"
alpha = 0.15
log_density = 14
microfacet_roughness = 0.01
slope_grid_scale = 20
f0 = 0.9
diffuse = 0.02
[[shape]]
type = "plane"
material = "glitter"
size = 20
uv_scale = 20
[[light]]
type = "quad"
position = [0.0, 1.3, -3.5]
direction = [0.0, -0.4, 1.0]
size = [$1, $1]
up = [0, 1, 0]
radiance = $(calc "0.4 / ($1 * $1)")
visible = false
TOML
}

area_glints_section() {
  local dir="$out/area-glints" S="--width 320 --height 180" A="--width 160 --height 90 --frames 8 --spp 64"
  local B2="--width 640 --height 360 --bench-frames 5" m
  mkdir -p "$dir"
  $B compare -q --scene builtin:glint-area-lights --methods conventional,deliot2023,kneiphof2024 --spp 256 $S \
    -o "$dir/bin" > /dev/null
  $B compare -q --scene builtin:glint-area-lights --methods kneiphof2024 --param kneiphof2024.subdivision=4x4 \
    --spp 256 $S -o "$dir/bin-4x4" > /dev/null
  $B compare -q --scene builtin:glint-area-lights --methods conventional,deliot2023,kneiphof2024 --spp 256 $S \
    --reference-backend raster-realisation -o "$dir/bin-real" > /dev/null
  $B compare -q --scene builtin:glint-area-lights-glinty --methods conventional,chermain2020,chermain2021 --spp 256 $S \
    --param chermain2020.$chermain_area_on --param chermain2021.$chermain_area_on -o "$dir/gl-on" > /dev/null
  $B compare -q --scene builtin:glint-area-lights-glinty --methods chermain2020,chermain2021 --spp 256 $S \
    --param chermain2020.$chermain_area_off --param chermain2021.$chermain_area_off -o "$dir/gl-off" > /dev/null
  $B animate -q --scene builtin:glint-area-lights --methods conventional,deliot2023,kneiphof2024 $A -o "$dir/anim-bin" > /dev/null
  $B animate -q --scene builtin:glint-area-lights --methods kneiphof2024 --param kneiphof2024.subdivision=4x4 $A \
    -o "$dir/anim-bin-4x4" > /dev/null
  $B animate -q --scene builtin:glint-area-lights-glinty --methods conventional,chermain2020,chermain2021 $A \
    --param chermain2020.$chermain_area_on --param chermain2021.$chermain_area_on -o "$dir/anim-gl-on" > /dev/null
  $B animate -q --scene builtin:glint-area-lights-glinty --methods chermain2020,chermain2021 $A \
    --param chermain2020.$chermain_area_off --param chermain2021.$chermain_area_off -o "$dir/anim-gl-off" > /dev/null
  row() {  # row LABEL COMPARE_DIR ANIMATE_DIR METHOD
    echo "| $1 | $(fmt %.4f "$(metric "$2" "$4" rmse)") | $(fmt %.3f "$(metric "$2" "$4" energy_ratio)")" \
      "| $(fmt %.4f "$(anim "$3" "$4" mean_rmse)") | $(fmt %.4f "$(anim "$3" "$4" flicker)") |"
  }
  noise() { echo "| (reference noise; flicker floor) | $(fmt %.4f "$(field "$1" reference_noise_rmse)") | | | $(fmt %.4f "$(field "$2" flicker_floor)") |"; }
  echo "## Glints under area lights: Kneiphof & Klein 2024"
  echo
  echo "builtin:glint-area-lights: binomial-glints materials under a large quad, a disk and a small sphere"
  echo "light; and builtin:glint-area-lights-glinty, the same scene made glinty for the Chermain methods"
  echo "(the same ln density per uv area, sigma = alpha / sqrt 2). Each method against the reference of the"
  echo "material it renders: for binomial glints the counting model with p integrated numerically over each"
  echo "light (the paper's ablation reference, docs/methods.md#kneiphof2024); for glinty materials the"
  echo "glinty BRDF integrated over the light by MIS. RMSE: 320x180, frame 0, 256 spp. Mean RMSE and"
  echo "flicker: 8 frames of the orbit at 160x90 against 64-spp references."
  echo
  echo "| scene / method | RMSE | energy ratio | mean RMSE (8 frames) | flicker |"
  echo "| --- | --- | --- | --- | --- |"
  row "binomial: conventional (smooth GGX by LTC)" "$dir/bin" "$dir/anim-bin" conventional
  row "binomial: deliot2023 (a point at each light's centre, R)" "$dir/bin" "$dir/anim-bin" deliot2023
  row "binomial: kneiphof2024" "$dir/bin" "$dir/anim-bin" kneiphof2024
  row "binomial: kneiphof2024, subdivision=4x4" "$dir/bin-4x4" "$dir/anim-bin-4x4" kneiphof2024
  noise "$dir/bin" "$dir/anim-bin"
  row "glinty: conventional (smooth limit)" "$dir/gl-on" "$dir/anim-gl-on" conventional
  row "glinty: chermain2020, $chermain_area_off" "$dir/gl-off" "$dir/anim-gl-off" chermain2020
  row "glinty: chermain2020, $chermain_area_on" "$dir/gl-on" "$dir/anim-gl-on" chermain2020
  row "glinty: chermain2021, $chermain_area_off" "$dir/gl-off" "$dir/anim-gl-off" chermain2021
  row "glinty: chermain2021, $chermain_area_on" "$dir/gl-on" "$dir/anim-gl-on" chermain2021
  noise "$dir/gl-on" "$dir/anim-gl-on"
  echo
  gap_note kneiphof2024 "$dir/bin" kneiphof2024 deliot2023 "$dir/bin" deliot2023
  echo
  gap_note "chermain2021 (kernel)" "$dir/gl-on" chermain2021 "chermain2021 (centre)" "$dir/gl-off" chermain2021
  echo
  echo "The same binomial methods against the reference of the physical question (\`--reference-backend"
  echo "raster-realisation\`: one fixed microfacet realisation integrated over each light; docs/methods.md,"
  echo "kneiphof2024, \"Two references\"), 320x180, 256 spp:"
  echo
  echo "| method | RMSE (counting-model reference) | RMSE (realisation reference) | energy (realisation) |"
  echo "| --- | --- | --- | --- |"
  for m in conventional deliot2023 kneiphof2024; do
    echo "| $m | $(fmt %.4f "$(metric "$dir/bin" $m rmse)") | $(fmt %.4f "$(metric "$dir/bin-real" $m rmse)") | $(fmt %.3f "$(metric "$dir/bin-real" $m energy_ratio)") |"
  done
  echo "| (reference noise) | $(fmt %.4f "$(field "$dir/bin" reference_noise_rmse)") | $(fmt %.4f "$(field "$dir/bin-real" reference_noise_rmse)") | |"
  echo
  cp "$dir/bin/reference.png" docs/images/glint-area-lights-reference.png
  cp "$dir/bin/deliot2023.png" docs/images/glint-area-lights-deliot2023.png
  cp "$dir/bin/kneiphof2024.png" docs/images/glint-area-lights-kneiphof2024.png
  cp "$dir/gl-on/reference.png" docs/images/glint-area-lights-glinty-reference.png
  cp "$dir/gl-on/chermain2021.png" docs/images/glint-area-lights-glinty-chermain2021.png
  echo "| reference (binomial) | deliot2023 | kneiphof2024 | reference (glinty) | chermain2021, $chermain_area_on |"
  echo "| --- | --- | --- | --- | --- |"
  echo "| ![](images/glint-area-lights-reference.png) | ![](images/glint-area-lights-deliot2023.png) | ![](images/glint-area-lights-kneiphof2024.png) | ![](images/glint-area-lights-glinty-reference.png) | ![](images/glint-area-lights-glinty-chermain2021.png) |"
  echo

  # Convergence as density grows (the paper's fig. 10): the glints approach the smooth LTC render.
  echo "**Convergence with density** (the paper's fig. 10): builtin:glint-area-lights with both materials'"
  echo "\`log_density\` set to each value, 160x90, 64-spp references. As the facets multiply the glints average"
  echo "out: kneiphof2024's energy approaches \`conventional\`'s (the smooth GGX by LTC) and its RMSE falls to the"
  echo "floor of its smooth approximations (the LTC's, and the point form's for the small sphere light)."
  echo
  echo "| ln density | kneiphof2024 RMSE | conventional RMSE | kneiphof2024 energy / conventional energy | reference noise |"
  echo "| --- | --- | --- | --- | --- |"
  local ld
  for ld in 8 12 16 20 30; do
    $B scenes --print glint-area-lights | sed -e "s/^log_density = .*/log_density = $ld/" > "$dir/density-$ld.toml"
    $B compare -q --scene "$dir/density-$ld.toml" --methods conventional,kneiphof2024 --width 160 --height 90 \
      --spp 64 -o "$dir/density-$ld" > /dev/null
    echo "| $ld | $(fmt %.4f "$(metric "$dir/density-$ld" kneiphof2024 rmse)") | $(fmt %.4f "$(metric "$dir/density-$ld" conventional rmse)")" \
      "| $(calc "$(metric "$dir/density-$ld" kneiphof2024 energy_ratio) / $(metric "$dir/density-$ld" conventional energy_ratio)" | xargs printf '%.3f')" \
      "| $(fmt %.4f "$(field "$dir/density-$ld" reference_noise_rmse)") |"
  done
  echo

  # The light-size sweep: from about a point to a large quad.
  echo "**Light size**: a binomial-glints floor (alpha 0.15, ln density 14) under one quad light behind"
  echo "the lobe's peak, of side 0.02 m (4e-5 sr, about a point) to 2 m (0.35 sr), radiance x area fixed;"
  echo "and the floor made glinty for the Chermain methods. 192x108, 64-spp references; flicker over the"
  echo "8-frame orbit. Read each column down: how a method's error and flicker change as the light grows,"
  echo "for a point at the light's centre (deliot2023, the Chermain methods with light_extent=centre)"
  echo "against the light's own extent (kneiphof2024, the Chermain methods' half-vector kernel)."
  echo
  echo "| side (m) | deliot2023 RMSE / flicker | kneiphof2024 RMSE / flicker | chermain2020 off / on RMSE | chermain2021 off / on RMSE | chermain2021 off / on flicker | reference noise (binomial / glinty) | flicker floor (binomial / glinty) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  local side d
  for side in 0.02 0.1 0.3 0.8 2.0; do
    d="$dir/size-$side"
    mkdir -p "$d"
    light_size_scene "$side" > "$d/bin.toml"
    glinty_version < "$d/bin.toml" > "$d/glinty.toml"
    $B compare -q --scene "$d/bin.toml" --methods deliot2023,kneiphof2024 --spp 64 -o "$d/bin" > /dev/null
    $B animate -q --scene "$d/bin.toml" --methods deliot2023,kneiphof2024 --spp 64 -o "$d/anim-bin" > /dev/null
    for m in on off; do
      local choice=$chermain_area_on
      [[ $m == off ]] && choice=$chermain_area_off
      $B compare -q --scene "$d/glinty.toml" --methods chermain2020,chermain2021 --spp 64 \
        --param chermain2020.$choice --param chermain2021.$choice -o "$d/gl-$m" > /dev/null
      $B animate -q --scene "$d/glinty.toml" --methods chermain2021 --spp 64 --param chermain2021.$choice \
        -o "$d/anim-gl-$m" > /dev/null
    done
    echo "| $side | $(fmt %.4f "$(metric "$d/bin" deliot2023 rmse)") / $(fmt %.4f "$(anim "$d/anim-bin" deliot2023 flicker)")" \
      "| $(fmt %.4f "$(metric "$d/bin" kneiphof2024 rmse)") / $(fmt %.4f "$(anim "$d/anim-bin" kneiphof2024 flicker)")" \
      "| $(fmt %.4f "$(metric "$d/gl-off" chermain2020 rmse)") / $(fmt %.4f "$(metric "$d/gl-on" chermain2020 rmse)")" \
      "| $(fmt %.4f "$(metric "$d/gl-off" chermain2021 rmse)") / $(fmt %.4f "$(metric "$d/gl-on" chermain2021 rmse)")" \
      "| $(fmt %.4f "$(anim "$d/anim-gl-off" chermain2021 flicker)") / $(fmt %.4f "$(anim "$d/anim-gl-on" chermain2021 flicker)")" \
      "| $(fmt %.4f "$(field "$d/bin" reference_noise_rmse)") / $(fmt %.4f "$(field "$d/gl-on" reference_noise_rmse)")" \
      "| $(fmt %.4f "$(field "$d/anim-bin" flicker_floor)") / $(fmt %.4f "$(field "$d/anim-gl-on" flicker_floor)") |"
  done
  echo

  # Runtime (the paper's table 1).
  $B bench -q --scene builtin:glint-area-lights --methods conventional,deliot2023,kneiphof2024 $B2 -o "$dir/bench" > /dev/null
  local sub
  for sub in 2x2 4x4; do
    $B bench -q --scene builtin:glint-area-lights --methods kneiphof2024 --param kneiphof2024.subdivision=$sub $B2 \
      -o "$dir/bench-$sub" > /dev/null
  done
  for m in on off; do
    local choice=$chermain_area_on
    [[ $m == off ]] && choice=$chermain_area_off
    $B bench -q --scene builtin:glint-area-lights-glinty --methods chermain2020,chermain2021 --param chermain2020.$choice \
      --param chermain2021.$choice $B2 -o "$dir/bench-gl-$m" > /dev/null
  done
  local base
  base=$(bench_ms "$dir/bench/bench.json" conventional)
  brow() { echo "| $1 | $(fmt %.1f "$2") | $(calc "$2 / $base" | xargs printf '%.2f')x |"; }
  echo "**Runtime** (the paper's table 1): builtin:glint-area-lights at 640x360, median wall ms per frame of"
  echo "5 (\`glintlab bench\`), and the ratio to \`conventional\`:"
  echo
  echo "| method | wall ms | / conventional |"
  echo "| --- | --- | --- |"
  brow conventional "$base"
  brow deliot2023 "$(bench_ms "$dir/bench/bench.json" deliot2023)"
  brow kneiphof2024 "$(bench_ms "$dir/bench/bench.json" kneiphof2024)"
  brow "kneiphof2024, subdivision=2x2" "$(bench_ms "$dir/bench-2x2/bench.json" kneiphof2024)"
  brow "kneiphof2024, subdivision=4x4" "$(bench_ms "$dir/bench-4x4/bench.json" kneiphof2024)"
  for m in off on; do
    local choice=$chermain_area_on
    [[ $m == off ]] && choice=$chermain_area_off
    brow "chermain2020, $choice (glinty scene)" "$(bench_ms "$dir/bench-gl-$m/bench.json" chermain2020)"
    brow "chermain2021, $choice (glinty scene)" "$(bench_ms "$dir/bench-gl-$m/bench.json" chermain2021)"
  done
  echo
  echo "Not measured on a GPU (no device was lent). Regenerate: \`tools/make-results.sh area-glints\`."
}
