#!/usr/bin/env bash
# Scale benchmark: umbra check and umbra render on a scan of over a million
# triangles, side by side with admesh (the checker a user would pick
# instead), and umbra check over a folder of real meshes with one job and
# with every core. All rows come from one run; each is the median of RUNS
# runs of wall time and peak resident memory (GNU time's %e and %M), the rows
# taken in turn in each round.
#
# The mesh: CGAL's bunny00.off (75,408 triangles, from Debian's libcgal-demo)
# with each triangle split into four, twice (1,206,528 triangles) and three
# times (4,826,112), written as binary STL (which both tools read), OBJ and
# glTF binary (GLB).
# The folder: CGAL's 143 data meshes.
#
#   bench/check_benchmark.sh [RUNS] [render]   (after ./build.sh; default 5 rounds)
# With `render`, only admesh and the two renders run: rounds of three rows,
# so that admesh and the 1.2M render run next to each other.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
only=${2:-}
[ -z "$only" ] || [ "$only" = render ] || { echo "usage: bench/check_benchmark.sh [RUNS] [render]" >&2; exit 2; }
build=build
data=$build/bench-data
mkdir -p "$data"

for tool in /usr/bin/time admesh; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is missing (./build.sh installs it)" >&2; exit 2; }
done

. bench/timing.sh
require_built $build make_subdivided_mesh
subdivided_bunny "$data" 1M
subdivided_bunny "$data" 4M
# The folder the last two rows check: every one of CGAL's data meshes
# (subdivided_bunny takes only the bunny from the archive).
[ "$only" = render ] || tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$data" data/meshes
# The bunny just above a floor under one light, as in the bundled mesh scenes,
# inside the cube [-1,1]^3 that scenes are made for.
for size in 1M 4M; do
  cat >"$data/bunny-$size.scene" <<SCENE
light 0.5 0.9 1.8
material floor diffuse 0.7 0.7 0.72
triangle -1 -1 -1   1 -1 -1   1 1 -1 material floor
triangle -1 -1 -1   1 1 -1   -1 1 -1 material floor
mesh bunny-$size.obj scale 1.5 rotate 1 0 0 90 translate 0 0 -0.25
SCENE
done

# The rows, each "NAME|COMMAND". Every round runs each row once, in this
# order, so that a shared machine's drift from fast to slow spreads over all
# rows alike instead of landing on whichever ran last.
rows=(
  "admesh bunny-1M.stl|admesh $data/bunny-1M.stl"
  "umbra check bunny-1M.stl|$build/umbra check $data/bunny-1M.stl"
  "umbra check bunny-1M.stl --jobs 1 (one core)|$build/umbra check --jobs 1 $data/bunny-1M.stl"
  "umbra check bunny-1M.stl --time-limit 0 (no self-intersection search)|$build/umbra check --time-limit 0 $data/bunny-1M.stl"
  "umbra check bunny-1M.obj|$build/umbra check $data/bunny-1M.obj"
  "umbra check bunny-1M.glb|$build/umbra check $data/bunny-1M.glb"
  "umbra render bunny-1M.scene, 800x800|$build/umbra render $data/bunny-1M.scene -o $data/bunny-1M.png --size 800x800"
  "umbra render bunny-4M.scene, 800x800|$build/umbra render $data/bunny-4M.scene -o $data/bunny-4M.png --size 800x800"
  "umbra check --jobs 1 on CGAL's 143 data meshes|$build/umbra check --jobs 1 $data/data/meshes"
  "umbra check --jobs $(nproc) on CGAL's 143 data meshes|$build/umbra check $data/data/meshes"
)
# The rows `render` keeps (their numbers stay, as the ratios below name them).
if [ "$only" = render ]; then
  for k in "${!rows[@]}"; do
    case $k in 0 | 6 | 7) ;; *) unset "rows[$k]" ;; esac
  done
fi
rm -f "$data"/time-*.txt
for ((i = 0; i < runs; i++)); do
  # The 1.2M inputs read once, untimed, so that the kernel's cache holds
  # them for every row alike (admesh, first in each round, read them cold
  # after the 4.8M render in some rounds).
  cat "$data"/bunny-1M.* >/dev/null
  for k in "${!rows[@]}"; do
    # shellcheck disable=SC2086 # the command is split into words on purpose (no path holds a blank)
    time_once "$data/time-$k.txt" ${rows[$k]#*|}
  done
done

echo "$(nproc) cores; $runs rounds; bunny-1M.stl is $(stat -c %s "$data/bunny-1M.stl") bytes"
echo
echo "| command | median wall time (s) | median peak memory (MiB) |"
echo "|---|---|---|"
rows_table "$data/time"
# ratio A B [COLUMN]: the median over the rounds of row A's figure over row
# B's in the same round (wall time, or COLUMN 2 for memory): a slow spell of
# the machine then weighs on both sides of each ratio alike.
ratio() {
  paste -d' ' "$data/time-$1.txt" "$data/time-$2.txt" |
    awk -v c="${3:-1}" '{printf "%.4f\n", $c / $(c + NF / 2)}' | median | awk '{printf "%.2f", $1}'
}
# ratio_row NAME A B [COLUMN]: a table row, where both rows ran
ratio_row() {
  [ -n "${rows[$2]+x}" ] && [ -n "${rows[$3]+x}" ] || return 0
  echo "| $1 | $(ratio "$2" "$3" "${4:-1}") |"
}
echo
echo "| ratio (median of the rounds' ratios) | measured |"
echo "|---|---|"
ratio_row "umbra check / admesh, time (1.2M triangles, STL)" 1 0
ratio_row "umbra check / admesh, memory" 1 0 2
ratio_row "umbra check, every core / one core" 1 2
ratio_row "umbra check without the self-intersection search / admesh, time" 3 0
ratio_row "umbra render (1.2M, OBJ, 800x800) / admesh, time" 6 0
ratio_row "umbra render (1.2M) / admesh, memory" 6 0 2
ratio_row "umbra render, 4.8M / 1.2M triangles, time" 7 6
ratio_row "umbra check on a folder, --jobs $(nproc) / --jobs 1, time" 9 8
