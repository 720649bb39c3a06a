#!/usr/bin/env bash
# umbra check --repair against admesh (the STL repair a user would pick
# instead), on every STL file in Debian's packages that the tests install:
# admesh's own example, assimp's test models, Open CASCADE's data and CGAL's.
# Each tool repairs with its defaults (admesh with no option does all its
# fixes: exact and nearby merges, unconnected facets, holes, normals), and
# umbra's check judges both outputs alike: closed (no border, manifold) and
# solid (closed, oriented, outward, crossing nowhere). Times are medians of
# RUNS runs, the two tools taking turns; umbra's includes the check of its
# output that --repair prints.
#
#   bench/repair_comparison.sh [RUNS]     (after ./build.sh; default 3)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
build=build
out=$build/bench-data/repair
mkdir -p "$out"
. bench/timing.sh
require_built $build
command -v admesh >/dev/null || { echo "bench: admesh is missing (./build.sh test installs it)" >&2; exit 2; }

files=()
for f in /usr/share/doc/admesh/examples/*.stl /usr/share/assimp/models/STL/*.[sS][tT][lL] /usr/share/opencascade/data/stl/*.stl \
         $build/cgal-data/data/meshes/*.stl; do
  [ -f "$f" ] && files+=("$f")
done

# verdict FILE: "closed, solid", "closed, not solid" or "open", by umbra's check
verdict() {
  { $build/umbra check --json "$1" 2>/dev/null || true; } | /usr/bin/python3 -c '
import json, sys
line = sys.stdin.readline()
d = json.loads(line) if line else {}
if "error" in d or not d: print("no mesh written")
elif not d["closed"]: print("open (%d border edges)" % d["border_edges"])
else: print("closed, " + ("solid" if d["solid"] else "not solid"))'
}

echo "| file | triangles | admesh: output | admesh: time (s) | umbra: output | umbra: time (s) |"
echo "|---|---|---|---|---|---|"
for f in "${files[@]}"; do
  name=$(basename "$f")
  triangles=$({ $build/umbra check --json --time-limit 0 "$f" 2>/dev/null || true; } | /usr/bin/python3 -c 'import json,sys; print(json.loads(sys.stdin.readline()).get("triangles", "?"))')
  rm -f "$out/admesh.txt" "$out/umbra.txt"
  for ((i = 0; i < runs; i++)); do
    time_once "$out/admesh.txt" admesh "$f" -b "$out/admesh-$name"
    time_once "$out/umbra.txt" $build/umbra check "$f" --repair "$out/umbra-$name"
  done
  echo "| $name | $triangles | $(verdict "$out/admesh-$name") | $(median_of "$out/admesh.txt" 1) | $(verdict "$out/umbra-$name") | $(median_of "$out/umbra.txt" 1) |"
done
