#!/usr/bin/env bash
# Regenerates the tables of docs/shader-statistics.md, between its marker lines
# <!-- generated:shader-statistics --> and <!-- /generated:shader-statistics -->, from
# glintlab-shader-stats (every method's forward programs compiled to SPIR-V and counted; no GPU
# needed; about 15 minutes of CPU, spread over the cores).
# Usage: tools/shader-stats.sh [BUILD]   (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
tool=$build/glintlab-shader-stats
[[ -x $tool ]] || { echo "shader-stats: no executable at '$tool' (make build)" >&2; exit 2; }
doc=docs/shader-statistics.md
begin="<!-- generated:shader-statistics -->" end="<!-- /generated:shader-statistics -->"
grep -qxF "$begin" "$doc" && grep -qxF "$end" "$doc" || { echo "$doc: needs the lines $begin and $end" >&2; exit 1; }
generated=$(mktemp)
trap 'rm -f "$generated" "$doc.tmp"' EXIT
"$tool" >"$generated"
awk -v f="$generated" -v b="$begin" -v e="$end" '
  $0 == b { print; while ((getline line < f) > 0) print line; skip = 1; next }
  $0 == e { skip = 0 }
  !skip { print }' "$doc" >"$doc.tmp"
mv "$doc.tmp" "$doc"
echo "written $doc"
