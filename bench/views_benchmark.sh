#!/usr/bin/env bash
# What many views and their data cost: 12 views of Khronos's two-cylinder
# engine (110k triangles) at 256x256 with every pass (depth, normal, object,
# shadow), side by side with one default umbra render of it at that size
# (its one picture: 3 x 3 samples, the studio look), whole process each.
# And a folder's worth: objects a second for Debian's real models (assimp's
# test models: the engine, Wuson, a spider and a textured box) at 12 views
# of 512x512 with every pass, as umbra render draws a folder.
# Rows alternate in each round; medians of RUNS rounds:
#   bench/views_benchmark.sh [RUNS]   (after ./build.sh; default 7)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-7}
build=build
. bench/timing.sh
require_built $build
require_engine
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
models=("$engine" /usr/share/assimp/models/OFF/Wuson.off /usr/share/assimp/models/STL/Spider_binary.stl
        /usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb)
for m in "${models[@]}"; do [ -f "$m" ] || { echo "bench: $m is missing (apt-get install assimp-testmodels)" >&2; exit 2; }; done
# The folder's row: the models copied into one folder, drawn as umbra
# render draws a folder (worker processes, one per core by default).
mkdir -p "$out/models"
for m in "${models[@]}"; do cp "$m" "$out/models/"; done
rows=("one picture, 256x256|$build/umbra render $engine --size 256x256 -o $out/one.png"
      "12 views + 4 passes, 256x256|$build/umbra render $engine --size 256x256 --views 12 --passes depth,normal,object,shadow -o $out/views"
      "4 models x 12 views + 4 passes, 512x512|$build/umbra render $out/models --views 12 --passes depth,normal,object,shadow --size 512x512 -o $out/folder")
time_rows "$out/t" "$runs"
echo "| what | wall (s), median | peak memory (MiB), median |"
echo "|---|---|---|"
rows_table "$out/t"
one=$(median_of "$out/t-0.txt" 1) views=$(median_of "$out/t-1.txt" 1) folder=$(median_of "$out/t-2.txt" 1)
printf '\n12 views with every pass over one picture: %.2f times; the folder: %.2f objects a second\n' \
  "$(echo "$views / $one" | bc -l)" "$(echo "${#models[@]} / $folder" | bc -l)"
