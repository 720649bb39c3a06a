#!/usr/bin/env bash
# What a moving light costs `umbra view`: the median frame time of the
# 1.2M-triangle bunny (that check_benchmark.sh makes) at 800x800 under Xvfb,
# one sample a pixel (--antialias 1: a still view would be drawn with the
# staged model's 3 x 3), with the light orbiting and with it paused, rows
# alternating, and against an earlier build when BEFORE names its umbra
# executable:
#   bench/view_orbit_benchmark.sh [RUNS] [FRAMES]   (after ./build.sh; defaults 5, 30)
#   BEFORE=/tmp/umbra-old bench/view_orbit_benchmark.sh
# Each run prints its median over FRAMES - 1 frames (umbra view --frames);
# the table gives the median of the runs' medians, and orbiting over paused.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
frames=${2:-30}
build=build
data=$build/bench-data
command -v xvfb-run >/dev/null || { echo "bench: xvfb-run is missing (apt-get install xvfb)" >&2; exit 2; }
. bench/timing.sh
require_built $build make_subdivided_mesh
subdivided_bunny "$data" 1M

compared_builds $build
rows=()
for b in "${builds[@]}"; do
  rows+=("${b%%|*}, orbiting|${b#*|}|")
  rows+=("${b%%|*}, paused|${b#*|}|--paused")
done
rm -f "$data"/orbit-*.txt
for ((i = 0; i < runs; i++)); do
  for k in "${!rows[@]}"; do
    IFS='|' read -r _ exe flag <<< "${rows[$k]}"
    # shellcheck disable=SC2086 # the flag is empty or one word
    xvfb-run -a -s "-screen 0 1024x1024x24" "$exe" view "$data/bunny-1M.glb" --size 800x800 --antialias 1 --frames "$frames" $flag 2>&1 |
      sed -n 's/.*median \([0-9.]*\) ms.*/\1/p' >> "$data/orbit-$k.txt"
  done
done
echo "$(nproc) cores; $runs rounds of $frames frames"
echo
echo "| build, light | median frame (ms) | orbiting / paused |"
echo "|---|---|---|"
for k in "${!rows[@]}"; do
  ms=$(median < "$data/orbit-$k.txt")
  if ((k % 2 == 0)); then
    printf '| %s | %s | %.2fx |\n' "${rows[$k]%%|*}" "$ms" "$(echo "$ms / $(median < "$data/orbit-$((k + 1)).txt")" | bc -l)"
  else
    printf '| %s | %s | |\n' "${rows[$k]%%|*}" "$ms"
  fi
done
