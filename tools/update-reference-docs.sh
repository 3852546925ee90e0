#!/usr/bin/env bash
# Regenerates the references generated from the declarations and splices each into its doc
# between its marker lines, replacing what was there:
#   docs/methods.md       <!-- generated:method-reference -->    `glintlab methods --markdown`
#   docs/scene-format.md  <!-- generated:material-reference -->  `glintlab materials --markdown`
# Usage: tools/update-reference-docs.sh [GLINTLAB]   (default build/release/glintlab)
# tests/docs/ fail while the docs and the declarations differ.
set -euo pipefail
cd "$(dirname "$0")/.."
glintlab=${1:-build/release/glintlab}
[[ -x $glintlab ]] || { echo "update-reference-docs: no executable at '$glintlab'" >&2; exit 2; }

generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
"$glintlab" methods --markdown >"$generated"
tools/splice-generated.sh docs/methods.md method-reference "$generated"
"$glintlab" materials --markdown >"$generated"
tools/splice-generated.sh docs/scene-format.md material-reference "$generated"
