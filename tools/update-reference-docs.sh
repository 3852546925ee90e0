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

# splice DOC MARKER GENERATED: replaces the lines between <!-- generated:MARKER --> and
# <!-- /generated:MARKER --> of DOC with the file GENERATED.
splice() {
  local doc=$1 begin="<!-- generated:$2 -->" end="<!-- /generated:$2 -->" generated=$3
  if ! grep -qxF "$begin" "$doc" || ! grep -qxF "$end" "$doc"; then
    echo "$doc: needs the lines $begin and $end" >&2
    exit 1
  fi
  awk -v f="$generated" -v b="$begin" -v e="$end" '
    $0 == b { print; while ((getline line < f) > 0) print line; skip = 1; next }
    $0 == e { skip = 0 }
    !skip { print }' "$doc" >"$doc.tmp"
  mv "$doc.tmp" "$doc"
}

generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
"$glintlab" methods --markdown >"$generated"
splice docs/methods.md method-reference "$generated"
"$glintlab" materials --markdown >"$generated"
splice docs/scene-format.md material-reference "$generated"
