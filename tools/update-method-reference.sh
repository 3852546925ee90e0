#!/usr/bin/env bash
# Splices the method reference generated from the descriptors (stdin) into docs/methods.md, or
# into the markdown file given, between its marker lines, replacing what was there:
#   build/release/glintlab methods --markdown | tools/update-method-reference.sh
# tests/docs/test_method_reference.cpp fails while the docs and the descriptors differ.
set -euo pipefail
doc=${1:-"$(dirname "$0")/../docs/methods.md"}
begin='<!-- generated:method-reference -->'
end='<!-- /generated:method-reference -->'
if ! grep -qxF "$begin" "$doc" || ! grep -qxF "$end" "$doc"; then
  echo "$doc: needs the lines $begin and $end" >&2
  exit 1
fi
generated=$(mktemp)
trap 'rm -f "$generated"' EXIT
cat > "$generated"
if [ ! -s "$generated" ]; then
  echo "no reference on stdin; pipe 'glintlab methods --markdown' into this script" >&2
  exit 1
fi
awk -v f="$generated" -v b="$begin" -v e="$end" '
  $0 == b { print; while ((getline line < f) > 0) print line; skip = 1; next }
  $0 == e { skip = 0 }
  !skip { print }' "$doc" > "$doc.tmp"
mv "$doc.tmp" "$doc"
