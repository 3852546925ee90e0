#!/usr/bin/env bash
# Runs the libFuzzer targets (docs/fuzzing.md) one after another, niced, for a time budget each.
# Usage: tools/fuzz.sh [all|scene|obj|gltf|png|exr|pyramid|view_script ...] [SECONDS]     (default: all, 600 s each)
# Builds nothing: run `make build-fuzz` (or `cmake --preset fuzz && cmake --build build/fuzz`) first.
# The working corpus grows in build/fuzz/corpus/<target> (seeded from fuzz/corpus/<target>);
# findings are written to build/fuzz/findings/<target>-crash-*, -timeout-*, -oom-*; each run's log
# is build/fuzz/logs/<target>.log. Exit status 1 if any target found something.
# FUZZ_KEEP_GOING=1 fuzzes on past findings (libFuzzer's fork mode, -ignore_crashes/ooms/timeouts):
# for a target with a known, not yet fixed finding, so the budget still explores the rest.
set -uo pipefail
cd "$(dirname "$0")/.."

seconds=600
targets=()
for arg in "$@"; do
  if [[ "$arg" =~ ^[0-9]+$ ]]; then seconds=$arg; elif [[ "$arg" != all ]]; then targets+=("$arg"); fi
done
[ ${#targets[@]} -eq 0 ] && targets=(scene obj gltf png exr pyramid view_script)

status=0
for t in "${targets[@]}"; do
  exe=build/fuzz/fuzz/fuzz_$t
  [ -x "$exe" ] || { echo "fuzz.sh: $exe not built (make build-fuzz)" >&2; exit 2; }
  mkdir -p "build/fuzz/corpus/$t" build/fuzz/findings build/fuzz/logs
  keep_going=()
  [ "${FUZZ_KEEP_GOING:-0}" = 1 ] && keep_going=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
  dict=()
  [ -f "fuzz/dict/$t.dict" ] && dict=(-dict="fuzz/dict/$t.dict")
  echo "fuzz.sh: $t for ${seconds} s"
  touch "build/fuzz/logs/$t.log.start"
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb also caps any single allocation.
  nice -n 10 "$exe" "build/fuzz/corpus/$t" "fuzz/corpus/$t" "${dict[@]}" "${keep_going[@]}" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="build/fuzz/findings/$t-" -print_final_stats=1 >"build/fuzz/logs/$t.log" 2>&1
  rc=$?
  grep -E "^#[0-9]+.*(DONE|pulse|cov:)" "build/fuzz/logs/$t.log" | tail -1
  grep -E "^stat::(number_of_executed_units|peak_rss_mb|new_units_added)" "build/fuzz/logs/$t.log"
  findings=$(find build/fuzz/findings -name "$t-*" -newer "build/fuzz/logs/$t.log.start" 2>/dev/null | wc -l)
  echo "fuzz.sh: $t: exit $rc, $findings new findings"
  if [ $rc -ne 0 ] || [ "$findings" -gt 0 ]; then
    echo "fuzz.sh: $t FOUND SOMETHING (exit $rc): see build/fuzz/logs/$t.log and build/fuzz/findings/" >&2
    status=1
  fi
done
exit $status
