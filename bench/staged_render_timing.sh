#!/usr/bin/env bash
# What a staged render of a mesh file costs, whole process (reading,
# staging, drawing, writing the PNG), with the options a user gets by
# default (800x800, 3 x 3 samples, the studio look and its shading), against
# an earlier build's umbra: each round runs every row once, in a shuffled
# order (this machine's speed drifts within a run: a fixed order favours a
# place), and each row's median and quartiles over RUNS rounds are printed:
#   BEFORE=/path/to/old/umbra bench/staged_render_timing.sh [RUNS]   (after ./build.sh test; default 15)
# The models: Khronos's two-cylinder engine (110k triangles) and CGAL's bunny
# subdivided to 1.2M triangles, as GLB.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-15}
build=build
data=$build/bench-data
. bench/timing.sh
require_engine_and_bunny $build
[ -x "${BEFORE:-}" ] || { echo "bench: BEFORE must name an earlier build's umbra" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rows=()
for model in "$engine" "$data/bunny-1M.glb"; do
  rows+=("before $(basename "$model")|$BEFORE render $model -o $out/p.png --size 800x800")
  rows+=("now $(basename "$model")|$build/umbra render $model -o $out/p.png --size 800x800")
done
for ((i = 0; i < runs; i++)); do
  for k in $(shuf -e "${!rows[@]}"); do
    # shellcheck disable=SC2086 # the command is split into words on purpose (no path holds a blank)
    time_once "$out/t-$k.txt" ${rows[$k]#*|}
  done
done
quartile() { awk -v c=1 '{print $c}' "$1" | sort -n | awk -v q="$2" '{a[NR]=$1} END {print a[int((NR - 1) * q) + 1]}'; }
echo "| build, model | wall (s), median | quartiles | peak memory (MiB), median |"
echo "|---|---|---|---|"
for k in "${!rows[@]}"; do
  printf '| %s | %s | %s to %s | %.0f |\n' "${rows[$k]%%|*}" "$(median_of "$out/t-$k.txt" 1)" "$(quartile "$out/t-$k.txt" 0.25)" \
    "$(quartile "$out/t-$k.txt" 0.75)" "$(echo "$(median_of "$out/t-$k.txt" 2) / 1024" | bc -l)"
done
