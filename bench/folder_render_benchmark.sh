#!/usr/bin/env bash
# Wall time and peak memory of folder renders and checks, which since the
# corpus work draw (and, with --timeout, check) each file in a process of
# its own, against an earlier build (whose folder renders shared one process
# and kept one GL context per thread) when BEFORE names its umbra:
#   bench/folder_render_benchmark.sh [RUNS]           (after ./build.sh; default 5)
#   BEFORE=/tmp/umbra-old/build/umbra bench/folder_render_benchmark.sh
# The folder: Debian's assimp glTF 2 samples (many small files: the case
# where a process and a GL context per file costs the most), rendered with
# the options a user gets by default (800x800, 3 x 3 samples) and small and
# quick (200x200, one sample); and CGAL's data meshes checked with and
# without --timeout. Rows run alternately, RUNS rounds; medians.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=build
data=$build/bench-data
. bench/timing.sh
require_built $build
models=/usr/share/assimp/models/glTF2
[ -d "$models" ] || { echo "bench: $models is missing (./build.sh installs assimp-testmodels)" >&2; exit 2; }
meshes=$build/cgal-data/data/meshes
[ -d "$meshes" ] || { echo "bench: $meshes is missing (build the tests first: ./build.sh test)" >&2; exit 2; }
mkdir -p "$data"

compared_builds $build
rows=()
for b in "${builds[@]}"; do
  exe=${b#*|}
  rows+=("${b%%|*}: render glTF2/ (800x800, default)|$exe render $models -o $data/folder-${b%%|*}")
  rows+=("${b%%|*}: render glTF2/ --size 200x200 --antialias 1|$exe render $models -o $data/folder-small-${b%%|*} --size 200x200 --antialias 1")
done
rows+=("now: check cgal meshes/|$build/umbra check $meshes --time-limit 0")
rows+=("now: check cgal meshes/ --timeout 60|$build/umbra check $meshes --time-limit 0 --timeout 60")

time_rows "$data/folder" "$runs"
echo "$(nproc) cores; $runs rounds; $(find "$models" -type f | wc -l) files in $models, $(ls "$meshes" | wc -l) in $meshes"
echo
echo "| build: command | median wall time (s) | median peak memory (MiB) |"
echo "|---|---|---|"
rows_table "$data/folder"
