#!/usr/bin/env bash
# Peak memory and wall time of `umbra render` of a mesh file on its own,
# against umbra's own ray-cast reference of the same file, and against an
# earlier build when BEFORE names its umbra executable:
#   bench/render_memory_benchmark.sh [RUNS]           (after ./build.sh; default 5)
#   BEFORE=/tmp/umbra-old bench/render_memory_benchmark.sh
# The files: Khronos's two-cylinder engine (110k triangles, open; Debian's
# assimp-testmodels) and the 1.2M-triangle bunny that check_benchmark.sh
# makes (closed), at 800x800; and a scene of two spheres, which shows what
# the GL context alone costs; the engine also at one sample a pixel, with and
# without its shadow mask (--mask), as the issue compares them with the
# reference's. Rows run alternately, RUNS rounds; medians.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=build
data=$build/bench-data
. bench/timing.sh
require_engine_and_bunny $build

compared_builds $build
rows=()
for b in "${builds[@]}"; do
  exe=${b#*|}
  rows+=("${b%%|*}: render two_spheres.scene|$exe render scenes/two_spheres.scene -o $data/mem.png --size 800x800")
  rows+=("${b%%|*}: render 2CylinderEngine.glb|$exe render $engine -o $data/mem.png --size 800x800")
  rows+=("${b%%|*}: render bunny-1M.glb|$exe render $data/bunny-1M.glb -o $data/mem.png --size 800x800")
  rows+=("${b%%|*}: render --antialias 1 2CylinderEngine.glb|$exe render --antialias 1 $engine -o $data/mem.png --size 800x800")
  rows+=("${b%%|*}: render --antialias 1 --mask 2CylinderEngine.glb|$exe render --antialias 1 $engine -o $data/mem.png --mask $data/mask.png --size 800x800")
done
rows+=("raycast: render --method raycast 2CylinderEngine.glb|$build/umbra render --method raycast $engine -o $data/mem.png --size 800x800")
rows+=("raycast: render --method raycast --antialias 1 2CylinderEngine.glb|$build/umbra render --method raycast --antialias 1 $engine -o $data/mem.png --size 800x800")
rows+=("raycast: render --method raycast --antialias 1 --mask 2CylinderEngine.glb|$build/umbra render --method raycast --antialias 1 $engine -o $data/mem.png --mask $data/mask.png --size 800x800")
rows+=("raycast: render --method raycast bunny-1M.glb|$build/umbra render --method raycast $data/bunny-1M.glb -o $data/mem.png --size 800x800")

time_rows "$data/mem" "$runs"
echo "$(nproc) cores; $runs rounds"
echo
echo "| build: command | median peak memory (MiB) | median wall time (s) |"
echo "|---|---|---|"
for k in "${!rows[@]}"; do
  printf '| %s | %.0f | %s |\n' "${rows[$k]%%|*}" "$(echo "$(median_of "$data/mem-$k.txt" 2) / 1024" | bc -l)" \
    "$(median_of "$data/mem-$k.txt" 1)"
done
