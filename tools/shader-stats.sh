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
tools/splice-generated.sh --check docs/shader-statistics.md shader-statistics
generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
"$tool" >"$generated"
tools/splice-generated.sh docs/shader-statistics.md shader-statistics "$generated"
echo "written docs/shader-statistics.md"
