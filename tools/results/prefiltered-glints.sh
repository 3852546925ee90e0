# The "prefiltered-glints" section of docs/results.md (sourced by tools/make-results.sh, which
# defines $B, $out, metric, field, fmt, calc, anim, ranking_note, thumbnails): deng2022 against its
# exact baseline yan2016 and the normal-map filters on normal-map-glints materials. The precompute
# of a 1024^2 map (time, storage, per level), the rank study (paper fig. 18), images and flicker on
# the four built-in scenes against references filtered with the methods' footprint Gaussian, and
# the constant-cost sweeps (tools/bench-constant-cost.sh).

prefiltered_methods=conventional,toksvig,lean,yan2016,deng2022
prefiltered_scenes="normal-glints-noise normal-glints-brushed normal-glints-scratches normal-glints-flakes"

# builtin:normal-glints-noise with its map at 1024^2 (the waves and frequencies scaled with it).
noise_1024() {
  $B scenes --print normal-glints-noise |
    sed -e 's/resolution = 256, alpha = 0.25, waves = 128, max_frequency = 24/resolution = 1024, alpha = 0.25, waves = 1024, max_frequency = 96/'
}

# A level table from a `glintlab prefilter -o` JSON: prefilter_levels FILE.
prefilter_levels() {
  jq -r '.[0] as $m | range(0; $m.levels | length) as $l | $m.levels[$l] as $v |
    ($m.accuracy // [])[$l] as $a |
    "| \($l) | \($v.sigma) | \($v.footprints) | \($v.kept_blocks) | \($v.compression_error * 1000 | round / 1000) | " +
    "\(if $a then ($a.stored_error * 1000 | round / 1000 | tostring) else "" end) | " +
    "\(if $a then ($a.interpolated_error * 1000 | round / 1000 | tostring) else "" end) | " +
    "\(if $a then ($a.mass * 1000 | round / 1000 | tostring) else "" end) | " +
    "\($v.distance_to_level_below * 1000 | round / 1000) | \($v.ndf_seconds | round) | \($v.compress_seconds | round) |"' "$1"
}
pf() { jq -r --arg k "$2" '.[0][$k]' "$1"; }
# The mean over levels of an accuracy field: pf_mean FILE FIELD.
pf_mean() { jq -r --arg k "$2" '[.[0].accuracy[][$k]] | add / length' "$1"; }

prefiltered_glints_section() {
  local dir="$out/prefiltered" S="--width 320 --height 180 --spp 64 --reference-filter gaussian:0.5"
  local A="--width 160 --height 90 --frames 8 --spp 64 --reference-filter gaussian:0.5"
  mkdir -p "$dir"
  noise_1024 > "$dir/noise-1024.toml"
  $B prefilter --scene "$dir/noise-1024.toml" --accuracy 4 -o "$dir/noise-1024.json" > /dev/null
  for rank in 8 16 32; do
    for s in noise flakes; do
      $B prefilter --scene "builtin:normal-glints-$s" --param rank=$rank --accuracy 4 -o "$dir/rank-$s-$rank.json" > /dev/null
    done
    $B compare -q --scene builtin:normal-glints-noise --methods deng2022 --param deng2022.rank=$rank $S \
      -o "$dir/rank-compare-$rank" > /dev/null
  done
  for s in $prefiltered_scenes; do
    $B compare -q --scene "builtin:$s" --methods "$prefiltered_methods" $S -o "$dir/$s-near" > /dev/null
    $B compare -q --scene "builtin:$s" --methods "$prefiltered_methods" $S --frame 23 -o "$dir/$s-far" > /dev/null
    $B animate -q --scene "builtin:$s" --methods "$prefiltered_methods" $A -o "$dir/$s-anim" > /dev/null
  done

  echo "## Prefiltered glints: Deng et al. 2022 (and its exact baseline, Yan et al. 2016)"
  echo
  echo "normal-map-glints materials (docs/scene-format.md): the map is the microsurface. \`deng2022\`"
  echo "queries a CP-compressed pyramid of NDF images (docs/methods.md#deng2022), \`yan2016\` sums the"
  echo "map's Gaussian elements over the footprint (docs/methods.md#yan2016); \`lean\` and \`toksvig\`"
  echo "filter the map as any normal map. References use the Gaussian pixel filter of the methods'"
  echo "footprint (\`--reference-filter gaussian:0.5\`), so that the comparison measures the NDF. The"
  echo "Chermain methods and \`podee\` do not apply to this material (they shade glinty materials and"
  echo "smooth lobes; on it they fall back to the normal-mapped Beckmann lobe, which \`conventional\` shows)."
  echo
  local f="$dir/noise-1024.json"
  echo "### Precompute of a 1024^2 map"
  echo
  echo "builtin:normal-glints-noise's map at 1024^2 (bumps, 1024 waves), default settings"
  echo "(\`$(pf "$f" settings)\`), \`glintlab prefilter --scene ... --accuracy 4\`:"
  echo "$(fmt %.1f "$(calc "$(pf "$f" precompute_seconds) / 60")") minutes wall on this machine's $(nproc) cores"
  echo "(thread-seconds: NDF images $(fmt %.0f "$(pf "$f" ndf_thread_seconds)"), CP $(fmt %.0f "$(pf "$f" compress_thread_seconds)")),"
  echo "storage $(fmt %.1f "$(calc "$(pf "$f" storage_bytes) / 1e6")") MB at rank $(pf "$f" rank) (the paper's Table 2: 6.9 to 107 MB"
  echo "for its maps, 15 to 504 minutes on 40 cores). Per level: CP error = ||X - X^|| / ||X|| of its"
  echo "kept blocks; against yan2016 = relative L2 of the NDF image at 4 stored footprints (the"
  echo "compression alone) and at 4 footprints anywhere between centres and levels (compression and"
  echo "trilinear interpolation); mass = the reconstructed images' integral (1 exact); vs below = the"
  echo "stop rule's distance to the level below; NDF and CP = thread-seconds."
  echo
  echo "| level | sigma (texels) | footprints | kept blocks | CP error | vs yan2016, stored | vs yan2016, anywhere | mass | vs below | NDF s | CP s |"
  echo "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
  prefilter_levels "$f"
  echo
  echo "### Rank (the paper's fig. 18)"
  echo
  echo "The built-in scenes' 256^2 maps (isotropic noise, flakes) at rank 8, 16 and 32: precompute wall"
  echo "time, storage, the mean over levels of the NDF error against yan2016 (stored footprints;"
  echo "anywhere), the CPU box query's time per query, and the image RMSE of \`deng2022\` on"
  echo "builtin:normal-glints-noise (frame 0, 320x180, 64 spp, Gaussian-filtered reference)."
  echo
  echo "| map | rank | precompute s | storage MB | NDF error, stored | NDF error, anywhere | box query us | image RMSE |"
  echo "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
  for s in noise flakes; do
    for rank in 8 16 32; do
      local g="$dir/rank-$s-$rank.json" img=""
      [ "$s" = noise ] && img=$(fmt %.4f "$(metric "$dir/rank-compare-$rank" deng2022 rmse)")
      echo "| $s | $rank | $(fmt %.1f "$(pf "$g" precompute_seconds)") | $(fmt %.2f "$(calc "$(pf "$g" storage_bytes) / 1e6")")" \
        "| $(fmt %.3f "$(pf_mean "$g" stored_error)") | $(fmt %.3f "$(pf_mean "$g" interpolated_error)")" \
        "| $(fmt %.1f "$(pf_mean "$g" box_query_microseconds)") | $img |"
    done
  done
  echo
  echo "### Images and flicker"
  echo
  echo "Each built-in scene at frame 0 (near: a texel over several pixels) and frame 23 (far: tens of"
  echo "texels a pixel), 320x180, 64 spp; mean RMSE and flicker over 8 frames of the path at 160x90."
  echo
  echo "| scene | method | RMSE near | energy near | RMSE far | energy far | mean RMSE (8 frames) | flicker |"
  echo "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |"
  for s in $prefiltered_scenes; do
    for m in ${prefiltered_methods//,/ }; do
      echo "| $s | $m | $(fmt %.4f "$(metric "$dir/$s-near" $m rmse)") | $(fmt %.3f "$(metric "$dir/$s-near" $m energy_ratio)")" \
        "| $(fmt %.4f "$(metric "$dir/$s-far" $m rmse)") | $(fmt %.3f "$(metric "$dir/$s-far" $m energy_ratio)")" \
        "| $(fmt %.4f "$(anim "$dir/$s-anim" $m mean_rmse)") | $(fmt %.4f "$(anim "$dir/$s-anim" $m flicker)") |"
    done
    echo "| $s | (reference noise near, far; flicker floor) | $(fmt %.4f "$(field "$dir/$s-near" reference_noise_rmse)") |" \
      "| $(fmt %.4f "$(field "$dir/$s-far" reference_noise_rmse)") | | | $(fmt %.4f "$(field "$dir/$s-anim" flicker_floor)") |"
  done
  echo
  for s in $prefiltered_scenes; do
    echo "$s, near: $(ranking_note "$dir/$s-near") Far: $(ranking_note "$dir/$s-far")"
    echo
  done
  for s in normal-glints-noise normal-glints-flakes; do
    thumbnails "$s-far" "$dir/$s-far" lean yan2016 deng2022
    echo
  done
  echo "### Constant cost"
  echo
  echo "\`tools/bench-constant-cost.sh build/release/glintlab 64 2\` on this machine (llvmpipe: times are"
  echo "CPU-rasteriser times; an NVIDIA H200's, at 512x512, are in docs/gpu-timings.md):"
  echo
  # shellcheck disable=SC2086
  tools/bench-constant-cost.sh "$glintlab_bin" $constant_cost_args
  echo
  echo "Regenerate: \`tools/make-results.sh prefiltered-glints\`."
}
