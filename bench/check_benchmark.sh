#!/usr/bin/env bash
# Times `umbra check` against admesh on a mesh of over a million triangles:
# CGAL's bunny00.off (75,408 triangles, from Debian's libcgal-demo) split
# into four twice, 1,206,528 triangles, written as binary STL (which both
# read) and as OBJ. Prints a Markdown table of medians over RUNS runs of wall
# time and peak resident memory (GNU time's %e and %M).
#
#   bench/check_benchmark.sh [RUNS]     (after ./build.sh; default 5 runs)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=build
data=$build/bench-data
mkdir -p "$data"

for tool in /usr/bin/time admesh; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is missing (./build.sh installs it)" >&2; exit 2; }
done
[ -x $build/umbra ] && [ -x $build/bench/make_subdivided_mesh ] || { echo "bench: run ./build.sh first" >&2; exit 2; }

if [ ! -f "$data/bunny-1M.stl" ]; then
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$data" data/meshes/bunny00.off
  $build/bench/make_subdivided_mesh "$data/data/meshes/bunny00.off" "$data/bunny-1M.stl" "$data/bunny-1M.obj" 2
fi

. bench/timing.sh

# measure NAME COMMAND...: runs it $runs times, prints a table row
measure() {
  local name=$1; shift
  rm -f "$data/time.txt"
  for ((i = 0; i < runs; i++)); do time_once "$data/time.txt" "$@"; done
  printf '| %s | %s | %.0f |\n' "$name" "$(median_of "$data/time.txt" 1)" "$(echo "$(median_of "$data/time.txt" 2) / 1024" | bc -l)"
}

echo "mesh: $(stat -c %s "$data/bunny-1M.stl") bytes of binary STL, 1206528 triangles; $runs runs each; $(nproc) cores"
echo
echo "| command | median wall time (s) | median peak memory (MiB) |"
echo "|---|---|---|"
measure "umbra check bunny-1M.stl" $build/umbra check "$data/bunny-1M.stl"
measure "umbra check bunny-1M.stl --time-limit 0 (no self-intersection search)" $build/umbra check "$data/bunny-1M.stl" --time-limit 0
measure "umbra check bunny-1M.obj" $build/umbra check "$data/bunny-1M.obj"
measure "admesh bunny-1M.stl" admesh "$data/bunny-1M.stl"
