#!/usr/bin/env bash
# Installs the build into a temporary prefix, builds tests/install/consumer against it with
# find_package(glintlab) and runs it: the library, its headers and package files are complete, and
# a program needs nothing of glintlab's source tree. Usage: test_install.sh BUILD_DIR GENERATOR
set -euo pipefail
build=$1
generator=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
for f in lib/libglintlab.so include/glintlab/glintlab.hpp include/glintlab/error.hpp bin/glintlab \
         lib/cmake/glintlab/glintlabConfig.cmake share/glintlab/shaders/methods/conventional.glsl; do
  [ -e "$work/prefix/$f" ] || { echo "test_install: $f not installed" >&2; exit 1; }
done
cmake -S "$here/consumer" -B "$work/consumer" -G "$generator" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/consumer" >/dev/null
out=$("$work/consumer/render_a_scene" builtin:spheres)
echo "$out"
grep -q '^rmse ' <<<"$out"
# Bad input reaches the program as the library's InputError.
set +e
"$work/consumer/render_a_scene" builtin:no-such-scene 2>"$work/err"
status=$?
set -e
[ "$status" -eq 2 ] && grep -q "no-such-scene" "$work/err" || { echo "test_install: bad scene: exit $status" >&2; cat "$work/err" >&2; exit 1; }
