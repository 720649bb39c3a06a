#!/usr/bin/env bash
# Scale benchmark: umbra check and umbra render on a scan of over a million
# triangles, side by side with admesh (the checker a user would pick
# instead), and umbra check over a folder of real meshes with one job and
# with every core. All rows come from one run; each is the median of RUNS
# runs of wall time and peak resident memory (GNU time's %e and %M).
#
# The mesh: CGAL's bunny00.off (75,408 triangles, from Debian's libcgal-demo)
# with each triangle split into four, twice (1,206,528 triangles) and three
# times (4,826,112), written as binary STL (which both tools read), OBJ and
# glTF binary (GLB).
# The folder: CGAL's 143 data meshes.
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

if [ ! -f "$data/bunny-4M.glb" ]; then
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$data" data/meshes
  for level in 2 3; do
    size=$([ $level = 2 ] && echo 1M || echo 4M)
    $build/bench/make_subdivided_mesh "$data/data/meshes/bunny00.off" "$data/bunny-$size.stl" "$data/bunny-$size.obj" \
      "$data/bunny-$size.glb" $level
  done
fi
# The bunny over a floor under one light, as in the bundled mesh scenes.
for size in 1M 4M; do
  cat >"$data/bunny-$size.scene" <<SCENE
light 0.5 0.9 1.8
material floor diffuse 0.7 0.7 0.72
triangle -1 -1 -1   1 -1 -1   1 1 -1 material floor
triangle -1 -1 -1   1 1 -1   -1 1 -1 material floor
mesh bunny-$size.obj scale 1.5 rotate 1 0 0 90 translate 0 0 -0.4
SCENE
done

. bench/timing.sh

# measure NAME COMMAND...: runs it $runs times; prints a table row and keeps
# the medians in $seconds and $mib for the ratios below.
measure() {
  local name=$1; shift
  rm -f "$data/time.txt"
  for ((i = 0; i < runs; i++)); do time_once "$data/time.txt" "$@"; done
  seconds=$(median_of "$data/time.txt" 1)
  mib=$(echo "$(median_of "$data/time.txt" 2) / 1024" | bc -l)
  printf '| %s | %s | %.0f |\n' "$name" "$seconds" "$mib"
}
ratio() { echo "scale=2; $1 / $2" | bc -l; }

echo "$(nproc) cores; $runs runs each; bunny-1M.stl is $(stat -c %s "$data/bunny-1M.stl") bytes"
echo
echo "| command | median wall time (s) | median peak memory (MiB) |"
echo "|---|---|---|"
measure "admesh bunny-1M.stl" admesh "$data/bunny-1M.stl"; admesh_s=$seconds admesh_mib=$mib
measure "umbra check bunny-1M.stl" $build/umbra check "$data/bunny-1M.stl"; check_s=$seconds check_mib=$mib
measure "umbra check bunny-1M.stl --jobs 1 (one core)" $build/umbra check --jobs 1 "$data/bunny-1M.stl"; check1_s=$seconds
measure "umbra check bunny-1M.stl --time-limit 0 (no self-intersection search)" $build/umbra check --time-limit 0 "$data/bunny-1M.stl"; topology_s=$seconds
measure "umbra check bunny-1M.obj" $build/umbra check "$data/bunny-1M.obj"
measure "umbra check bunny-1M.glb" $build/umbra check "$data/bunny-1M.glb"
measure "umbra render bunny-1M.scene, 800x800" $build/umbra render "$data/bunny-1M.scene" -o "$data/bunny-1M.png" --size 800x800; render1_s=$seconds render1_mib=$mib
measure "umbra render bunny-4M.scene, 800x800" $build/umbra render "$data/bunny-4M.scene" -o "$data/bunny-4M.png" --size 800x800; render4_s=$seconds
measure "umbra check --jobs 1 on CGAL's 143 data meshes" $build/umbra check --jobs 1 "$data/data/meshes"; folder1_s=$seconds
measure "umbra check --jobs $(nproc) on CGAL's 143 data meshes" $build/umbra check "$data/data/meshes"; folderN_s=$seconds
echo
echo "| ratio | measured |"
echo "|---|---|"
echo "| umbra check / admesh, time (1.2M triangles, STL) | $(ratio "$check_s" "$admesh_s") |"
echo "| umbra check / admesh, memory | $(ratio "$check_mib" "$admesh_mib") |"
echo "| umbra check, every core / one core | $(ratio "$check_s" "$check1_s") |"
echo "| umbra check without the self-intersection search / admesh, time | $(ratio "$topology_s" "$admesh_s") |"
echo "| umbra render (1.2M, OBJ, 800x800) / admesh, time | $(ratio "$render1_s" "$admesh_s") |"
echo "| umbra render (1.2M) / admesh, memory | $(ratio "$render1_mib" "$admesh_mib") |"
echo "| umbra render, 4.8M / 1.2M triangles, time | $(ratio "$render4_s" "$render1_s") |"
echo "| umbra check on a folder, --jobs $(nproc) / --jobs 1, time | $(ratio "$folderN_s" "$folder1_s") |"
