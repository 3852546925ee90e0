#!/usr/bin/env bash
# make demo: from a fresh clone on Debian 12 to every method compared with the ground truth on the
# default scene (builtin:every-family) and the HTML report of it, saying how long each part took.
#   packages   tools/install-deps.sh demo: what building and running glintlab need, if missing
#   configure  cmake --preset demo: Release without tests and benchmarks, a unity build, in build/demo
#   build      the glintlab binary only
#   tables     the precomputed tables, generated on first use and cached (glintlab info lists them)
#   programs   the GL programs compare draws, compiled on every core (below)
#   compare    every method and the reference: out/demo (metrics, images, worst regions)
#   report     out/demo/report/index.html
# Mesa's llvmpipe compiles a program's machine code when it first draws, on the drawing thread, and
# keeps it in its shader cache (~/.cache/mesa_shader_cache): so the programs are first drawn on a
# tiny film by one glintlab per core, each a share of the methods, and compare then finds them
# compiled. Its images are the same either way (tests compare them bit for bit).
# Usage: tools/demo.sh            JOBS=N sets the build's and the compiles' parallelism (default: nproc)
set -euo pipefail
cd "$(dirname "$0")/.."

jobs=${JOBS:-$(nproc)}
glintlab=build/demo/glintlab
out=out/demo
# 1024 samples per pixel: the reference's noise is then well below the differences the table ranks
# (README, "Set-up": measured).
spp=1024

# Each part's wall time, and the CPU time of everything it ran (this shell's waited-for children,
# /proc/<pid>/stat fields 16 and 17), which says how much of the wall time was the machine's load.
declare -a parts
now() { echo "${EPOCHREALTIME/./}"; }  # microseconds
cpu() {  # microseconds
  local stat fields
  stat=$(</proc/$$/stat)
  read -ra fields <<<"${stat##*) }"
  echo $(((fields[13] + fields[14]) * 1000000 / $(getconf CLK_TCK)))
}
timed() {
  local name=$1 start start_cpu
  shift
  start=$(now)
  start_cpu=$(cpu)
  "$@"
  parts+=("$name $(($(now) - start)) $(($(cpu) - start_cpu))")
}
seconds() { printf '%d.%d' $(($1 / 1000000)) $(($1 / 100000 % 10)); }

# Each worker draws its share of the methods (every material variant of the scene) with bench, and
# the first also the reference's programs; the heaviest modules are spread across the workers.
compile_programs() {
  local methods
  mapfile -t methods < <("$glintlab" methods | sed -n 's/^\([a-z0-9-]*\) — .*/\1/p')
  local -a shares
  for ((i = 0; i < ${#methods[@]}; ++i)); do
    shares[i % jobs]+="${shares[i % jobs]:+,}${methods[i]}"
  done
  local -a pids
  for ((w = 0; w < jobs && w < ${#methods[@]}; ++w)); do
    (
      "$glintlab" bench -q --methods "${shares[w]}" --width 16 --height 9 --bench-frames 1 --warmup 0 >/dev/null
      if [ "$w" -eq $((jobs - 1)) ] || [ "$w" -eq $((${#methods[@]} - 1)) ]; then
        "$glintlab" render -q --reference=1 --no-cache --width 16 --height 9 -o "$out.programs/reference.png" >/dev/null
      fi
    ) &
    pids+=($!)
  done
  local status=0
  for p in "${pids[@]}"; do wait "$p" || status=1; done
  rm -rf "$out.programs"
  return $status
}

timed packages tools/install-deps.sh demo
timed configure cmake --preset demo >/dev/null
timed build cmake --build --preset demo -j "$jobs"
timed tables "$glintlab" info >/dev/null
timed programs compile_programs
timed compare "$glintlab" compare --methods all --spp "$spp" -o "$out"
timed report "$glintlab" report -o "$out/report" "$out"

total=0
total_cpu=0
line=""
for p in "${parts[@]}"; do
  read -r name wall cpu_time <<<"$p"
  total=$((total + wall))
  total_cpu=$((total_cpu + cpu_time))
  line+="${line:+, }$name $(seconds "$wall") s (CPU $(seconds "$cpu_time") s)"
done
echo
echo "glintlab: the report is $out/report/index.html (open it in a browser); images and metrics in $out/"
echo "glintlab: make demo took $(seconds $total) s (CPU $(seconds $total_cpu) s on $(nproc) cores, load now $(cut -d' ' -f1-3 /proc/loadavg)): $line"
