#!/usr/bin/env bash
# umbra against f3d, the viewer a user would reach for instead: whole
# processes (reading, drawing and writing the PNG), wall time and peak memory
# (GNU time), rows alternating, medians of RUNS rounds:
#   bench/f3d_comparison.sh [RUNS]   (after ./build.sh; default 3; needs f3d and Xvfb)
# The models: Khronos's two-cylinder engine (110k triangles; Debian's
# assimp-testmodels), CGAL's bunny subdivided to 1.2M and 4.8M triangles,
# each as GLB, and assimp's textured spider (OBJ, with its JPEG maps), at
# 800x800. umbra stages each (floor, light, camera) and draws its exact
# shadow: by default one sample a pixel and 3 x 3 exact rays at its edge
# pixels, once with one sample alone (--antialias 1) and once with 3 x 3 at
# every pixel (--antialias-all, the default before edges); f3d 1.3 draws the
# model alone, unshadowed, one sample a pixel, into an Xvfb display started
# once for the whole run (so its start is not counted).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
build=build
data=$build/bench-data
for tool in f3d Xvfb /usr/bin/time; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is missing (apt-get install f3d xvfb time)" >&2; exit 2; }
done

. bench/timing.sh
require_engine_and_bunny $build
subdivided_bunny "$data" 4M

display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 1024x1024x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1

models=("engine|$engine" "bunny 1.2M|$data/bunny-1M.glb" "bunny 4.8M|$data/bunny-4M.glb"
        "spider (textured)|/usr/share/assimp/models/OBJ/spider.obj")
rows=()
for m in "${models[@]}"; do
  name=${m%%|*} file=${m#*|}
  rows+=("$name: umbra render|$build/umbra render $file -o $data/f3d-cmp.png --size 800x800")
  rows+=("$name: umbra render --antialias 1|$build/umbra render $file -o $data/f3d-cmp.png --size 800x800 --antialias 1")
  rows+=("$name: umbra render --antialias-all|$build/umbra render $file -o $data/f3d-cmp.png --size 800x800 --antialias-all")
  rows+=("$name: f3d, no shadow|env DISPLAY=$display f3d --output=$data/f3d-cmp.png --resolution=800,800 $file")
done
time_rows "$data/f3d" "$runs"
echo "$(nproc) cores; $runs rounds"
echo
echo "| model: program | median wall time (s) | median peak memory (MiB) |"
echo "|---|---|---|"
rows_table "$data/f3d"
