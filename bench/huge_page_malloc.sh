#!/usr/bin/env bash
# What glibc's huge-page malloc buys (tools/huge_page_malloc.hpp): each
# command as umbra runs it, restarted with GLIBC_TUNABLES=glibc.malloc.hugetlb=1,
# against the same command with GLIBC_TUNABLES set empty, which keeps glibc's
# default 4 KiB pages. Whole processes, wall time, peak memory and minor page
# faults (GNU time), rows alternating, medians of RUNS rounds:
#   bench/huge_page_malloc.sh [RUNS]   (after ./build.sh; default 3)
# The kernel must give huge pages on request: `umbra --version` says whether
# umbra restarts itself.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
build=build
data=$build/bench-data
. bench/timing.sh
require_engine_and_bunny $build
subdivided_bunny "$data" 4M
$build/umbra --version | grep '^memory: malloc takes transparent huge pages' >/dev/null ||
  { echo "bench: umbra does not restart with huge pages here: $($build/umbra --version | grep '^memory')" >&2; exit 2; }

commands=(
  "render demo.scene|render scenes/demo.scene -o $data/huge.png"
  "render 2CylinderEngine.glb --antialias 1|render $engine -o $data/huge.png --size 800x800 --antialias 1"
  "render --method raycast 2CylinderEngine.glb --antialias 1|render --method raycast $engine -o $data/huge.png --size 800x800 --antialias 1"
  "render bunny-1M.glb --antialias 1|render $data/bunny-1M.glb -o $data/huge.png --size 800x800 --antialias 1"
  "render bunny-4M.glb --antialias 1|render $data/bunny-4M.glb -o $data/huge.png --size 800x800 --antialias 1"
  "check bunny-1M.glb|check $data/bunny-1M.glb"
)
rows=()
for c in "${commands[@]}"; do
  rows+=("${c%%|*}: huge pages|$build/umbra ${c#*|}")
  rows+=("${c%%|*}: 4 KiB pages|env GLIBC_TUNABLES= $build/umbra ${c#*|}")
done

time_rows "$data/huge" "$runs"
echo "$(nproc) cores; $runs rounds"
echo
echo "| command: malloc's pages | median wall time (s) | median peak memory (MiB) | median minor faults |"
echo "|---|---|---|---|"
for k in "${!rows[@]}"; do
  printf '| %s | %s | %.0f | %s |\n' "${rows[$k]%%|*}" "$(median_of "$data/huge-$k.txt" 1)" \
    "$(echo "$(median_of "$data/huge-$k.txt" 2) / 1024" | bc -l)" "$(median_of "$data/huge-$k.txt" 3)"
done
