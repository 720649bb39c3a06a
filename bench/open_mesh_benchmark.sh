#!/usr/bin/env bash
# What a mesh that is not a closed 2-manifold costs to shadow, end to end:
# `umbra render` at 512x512 of a ~300,000-triangle closed mesh (a bumpy torus
# made by bench/make_mesh_variants) and of its variants with 3 small holes, a
# patch wound the other way, a non-manifold fin, two interpenetrating
# components and repeated faces, each with the auto plan (z-pass here, no
# caps) and with --method zfail (every cap drawn). Runs interleave the meshes,
# so all share the machine's load; the table gives medians and their ratio to
# the closed mesh. Then a model of 576 open tubes (110,592 triangles) at
# 800x800 against umbra's own CPU ray-cast reference and the per-triangle
# volumes the renderer used before (timed once: about 20 s).
#
#   bench/open_mesh_benchmark.sh [RUNS]     (after ./build.sh; default 5 runs)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
build=build
data=$build/bench-data/variants
. bench/timing.sh
require_built $build make_mesh_variants

for tool in /usr/bin/time bc; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is missing (./build.sh installs it)" >&2; exit 2; }
done
mkdir -p "$data"
[ -f "$data/parts.obj" ] || $build/bench/make_mesh_variants "$data" >/dev/null
variants=(closed holes reversed fin two duplicates parts)
for v in "${variants[@]}"; do
  printf 'light 0.6 0.8 1.8\ntriangle -1 -1 -1  1 -1 -1  1 1 -1\ntriangle -1 -1 -1  1 1 -1  -1 1 -1\nmesh %s.obj\n' "$v" \
    > "$data/$v.scene"
done
rm -f "$data"/*.times

for ((r = 0; r < runs; r++)); do
  for v in closed holes reversed fin two duplicates; do
    for method in auto zfail; do
      time_once "$data/$v-$method.times" $build/umbra render "$data/$v.scene" -o "$data/out.png" --size 512x512 --method $method
    done
  done
  for method in auto zfail raycast; do
    time_once "$data/parts-$method.times" $build/umbra render "$data/parts.scene" -o "$data/out.png" --size 800x800 --method $method
  done
done
time_once "$data/parts-triangles.times" $build/umbra render "$data/parts.scene" -o "$data/out.png" --size 800x800 --method triangles

# the path --explain gives the mesh, in its own words
path_of() {
  $build/umbra render "$data/$1.scene" -o "$data/out.png" --size 64x64 --explain 2>/dev/null |
    sed -n 's/^    mesh (line 4): \(.*\) ([0-9]* triangles).*/\1/p'
}
ratio() { printf '%.2f' "$(echo "$1 / $2" | bc -l)"; }
mib() { printf '%.0f' "$(echo "$1 / 1024" | bc -l)"; }

echo "$runs runs each, medians; $(nproc) cores; time in s, peak memory in MiB; ratios to the closed mesh"
echo
echo "| mesh (512x512) | how umbra casts it | auto: time | ratio | memory | ratio | zfail: time | ratio | memory | ratio |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for v in closed holes reversed fin two duplicates; do
  row="| $v | $(path_of $v) |"
  for method in auto zfail; do
    t=$(median_of "$data/$v-$method.times" 1) m=$(median_of "$data/$v-$method.times" 2)
    t0=$(median_of "$data/closed-$method.times" 1) m0=$(median_of "$data/closed-$method.times" 2)
    row="$row $t | $(ratio "$t" "$t0") | $(mib "$m") | $(ratio "$m" "$m0") |"
  done
  echo "$row"
done
echo
echo "576 open tubes, 110,592 triangles ($(path_of parts)), 800x800:"
echo
echo "| method | time (s) | ratio to raycast | peak memory (MiB) |"
echo "|---|---|---|---|"
t_ref=$(median_of "$data/parts-raycast.times" 1)
for method in auto zfail raycast triangles; do
  t=$(median_of "$data/parts-$method.times" 1) m=$(median_of "$data/parts-$method.times" 2)
  echo "| $method | $t | $(ratio "$t" "$t_ref") | $(mib "$m") |"
done
