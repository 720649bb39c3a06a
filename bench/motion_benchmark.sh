#!/usr/bin/env bash
# What a motion costs beside one still picture, whole process each, side by
# side in one run: 60 frames at 640x480 to MP4 (umbra render --turntable 60)
# of Open CASCADE's motor part (13,506 triangles, Debian's occt-misc), and
# of CGAL's bunny subdivided to 1.2M triangles with the light orbiting
# (--orbit light), each against one default umbra render of the same model
# at that size (3 x 3 samples at edges, the studio look). Rows alternate in
# each round; medians of RUNS rounds:
#   bench/motion_benchmark.sh [RUNS]   (after ./build.sh test; default 5)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=build
. bench/timing.sh
require_engine_and_bunny $build
part=/usr/share/opencascade/data/stl/motor.stl
[ -f "$part" ] || { echo "bench: $part is missing (apt-get install occt-misc)" >&2; exit 2; }
bunny=$build/bench-data/bunny-1M.glb
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rows=("part: one picture, 640x480|$build/umbra render $part --size 640x480 -o $out/part.png"
      "part: 60 frames to MP4, 640x480|$build/umbra render $part --size 640x480 --turntable 60 -o $out/part.mp4"
      "bunny: one picture, 640x480|$build/umbra render $bunny --size 640x480 -o $out/bunny.png"
      "bunny: 60 frames, light orbiting, to MP4|$build/umbra render $bunny --size 640x480 --turntable 60 --orbit light -o $out/bunny.mp4")
time_rows "$out/t" "$runs"
echo "| what | wall (s), median | peak memory (MiB), median |"
echo "|---|---|---|"
rows_table "$out/t"
for pair in "part 0 1" "bunny 2 3"; do
  read -r name still motion <<< "$pair"
  one=$(median_of "$out/t-$still.txt" 1) sixty=$(median_of "$out/t-$motion.txt" 1)
  printf '\n%s: 60 frames over one picture: %.2f times; a frame: %.2f of a picture'"'"'s process\n' "$name" \
    "$(echo "$sixty / $one" | bc -l)" "$(echo "$sixty / 60 / $one" | bc -l)"
done
