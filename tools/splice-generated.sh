#!/usr/bin/env bash
# Replaces the lines between <!-- generated:MARKER --> and <!-- /generated:MARKER --> of DOC with
# the contents of GENERATED (the docs' generated tables: tools/update-reference-docs.sh,
# tools/shader-stats.sh, tools/flip-validation.sh). With --check, only checks that DOC has both
# lines (before a long run that makes GENERATED).
# Usage: tools/splice-generated.sh DOC MARKER GENERATED | tools/splice-generated.sh --check DOC MARKER
set -euo pipefail
check=false
if [[ ${1:-} == --check ]]; then check=true; shift; fi
doc=${1:?usage: splice-generated.sh [--check] DOC MARKER [GENERATED]} marker=${2:?usage: splice-generated.sh [--check] DOC MARKER [GENERATED]}
begin="<!-- generated:$marker -->" end="<!-- /generated:$marker -->"
if ! grep -qxF "$begin" "$doc" || ! grep -qxF "$end" "$doc"; then
  echo "$doc: needs the lines $begin and $end" >&2
  exit 1
fi
$check && exit 0
generated=${3:?usage: splice-generated.sh DOC MARKER GENERATED}
awk -v f="$generated" -v b="$begin" -v e="$end" '
  $0 == b { print; while ((getline line < f) > 0) print line; skip = 1; next }
  $0 == e { skip = 0 }
  !skip { print }' "$doc" >"$doc.tmp"
mv "$doc.tmp" "$doc"
