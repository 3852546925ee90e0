#!/usr/bin/env bash
# glintlab's FLIP against the authors' implementation (NVlabs/flip, BSD-3-Clause), on glintlab's own
# image pairs: the synthetic pairs of tests/core/flip_validation_pairs.hpp and a compare run of
# builtin:glint-area-lights (every method's PNG and EXR against the reference's). Writes a markdown
# table (pair, kind, the authors' mean, glintlab's, the difference) into docs/methods.md between
# the lines <!-- generated:flip-validation --> and <!-- /generated:flip-validation -->, and prints it.
#
# The authors' tool is built outside the repository, never vendored:
#   git clone https://github.com/NVlabs/flip && cd flip/src/cpp/tool &&
#     g++ -O2 -std=c++17 -I.. FLIP-tool.cpp -o /somewhere/flip
# Usage: tools/flip-validation.sh FLIP_TOOL [BUILD]   (default build/release; about a minute)
set -euo pipefail
cd "$(dirname "$0")/.."
authors=${1:?usage: tools/flip-validation.sh FLIP_TOOL [BUILD]}
build=${2:-build/release}
[[ -x $authors ]] || { echo "flip-validation: no executable at '$authors'" >&2; exit 2; }
for t in "$build/glintlab" "$build/tests/flip_validation_pairs"; do
  [[ -x $t ]] || { echo "flip-validation: no executable at '$t' (make build)" >&2; exit 2; }
done
tools/splice-generated.sh --check docs/methods.md flip-validation
authors=$(realpath "$authors")
glintlab=$(realpath "$build/glintlab")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/tests/flip_validation_pairs" "$work/pairs" >/dev/null
"$glintlab" compare -q --scene builtin:glint-area-lights --width 160 --height 90 --spp 64 --no-cache \
  --methods conventional,deliot2023,kneiphof2024 -o "$work/render" >/dev/null

# mean FLIP by the authors' tool: reference, test, then its options
authors_mean() { (cd "$work" && "$authors" -r "$1" -t "$2" -v 1 "${@:3}" | awk '/Mean:/ { print $2 }'); }
ours_mean() {
  "$glintlab" metrics "$2" "$1" -o "$work/ours.json" "${@:3}" >/dev/null
  python3 -c "import json; print('%.6f' % json.load(open('$work/ours.json'))['$KEY'])"
}
row() {  # name kind reference test [authors' options] -- [glintlab's options]
  local name=$1 kind=$2 ref=$3 test=$4; shift 4
  local a_opts=() g_opts=()
  while (($#)) && [[ $1 != -- ]]; do a_opts+=("$1"); shift; done
  (($#)) && shift
  g_opts=("$@")
  local a g
  a=$(authors_mean "$ref" "$test" "${a_opts[@]}")
  if [[ $kind == HDR ]]; then KEY=flip_hdr; else KEY=flip_ldr; fi
  g=$(KEY=$KEY ours_mean "$ref" "$test" "${g_opts[@]}")
  python3 -c "print('| %s | %s | %s | %s | %.1e |' % ('$name', '$kind', '$a', '$g', abs($a - $g)))"
}
table() {
echo "| pair | FLIP | authors' mean (v1.6) | glintlab's | difference |"
echo "| --- | --- | --- | --- | --- |"
while read -r name kind rest; do
  if [[ $kind == ldr ]]; then
    row "$name" LDR "$work/pairs/$name-reference.png" "$work/pairs/$name-test.png"
  elif [[ $rest == auto ]]; then
    row "$name" HDR "$work/pairs/$name-reference.exr" "$work/pairs/$name-test.exr"
  else
    read -r start stop count <<<"$rest"
    row "$name" HDR "$work/pairs/$name-reference.exr" "$work/pairs/$name-test.exr" \
      -cstart "$start" -cstop "$stop" -n "$count" -- --hdr-exposures "$start,$stop,$count"
  fi
done <"$work/pairs/pairs.txt"
for m in conventional deliot2023 kneiphof2024; do
  row "glint-area-lights $m" LDR "$work/render/reference.png" "$work/render/$m.png"
  row "glint-area-lights $m" HDR "$work/render/reference.exr" "$work/render/$m.exr"
done
}
table >"$work/table.md"
cat "$work/table.md"
tools/splice-generated.sh docs/methods.md flip-validation "$work/table.md"
echo "written docs/methods.md"
