#!/usr/bin/env bash
# How umbra stages real models: renders every mesh file of Debian's
# assimp-testmodels, of CGAL's data set and of Open CASCADE's sample parts
# (occt-misc; STEP, IGES and BREP where umbra's CAD module is built) on its own (umbra render MESH,
# 200x200, with the shadow mask) and counts the pictures with a shadow over
# at least 1% of the frame (mask 0: faces turned from the light, or in
# shadow), with no black pixel over 1% of it, with no background seen, with
# under 0.5% of the frame clipped to white, and whose shadowed pixels spread
# over 20 grey levels or more (png_stats.py says how each is measured).
#   bench/staging_survey.sh [OUT_DIR]     (after ./build.sh; default build/staging-survey)
# Files umbra cannot render (glTF 1.0, Draco, point clouds, broken on
# purpose) are counted apart, with their exit status.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-build/staging-survey}
[ -x build/umbra ] || { echo "bench: run ./build.sh first" >&2; exit 2; }
[ -d build/cgal-data/data/meshes ] || { echo "bench: run ./build.sh test first (it unpacks CGAL's data)" >&2; exit 2; }
rm -rf "$out" && mkdir -p "$out"
. bench/timing.sh
cad=()
[[ $(build/umbra formats) == *STEP* ]] && cad=(-o -iname '*.step' -o -iname '*.stp' -o -iname '*.iges' -o -iname '*.igs' -o -iname '*.brep')
{ find /usr/share/assimp/models -type f \( -iname '*.glb' -o -iname '*.gltf' -o -iname '*.obj' -o -iname '*.ply' \
    -o -iname '*.stl' -o -iname '*.3mf' -o -iname '*.off' \); ls build/cgal-data/data/meshes/*.off
  if [ -d /usr/share/opencascade/data ]; then find /usr/share/opencascade/data -type f \( -iname '*.stl' "${cad[@]}" \); fi; } |
  sort > "$out/files.txt"
render_one() {
  local name
  name=$(survey_name "$1")
  timeout 120 build/umbra render "$1" -o "$2/$name.png" --mask "$2/$name.mask.png" --size 200x200 >/dev/null 2>&1
  echo "$? $name"
}
export -f render_one survey_name
xargs -P "$(nproc)" -I{} bash -c 'render_one "$1" "$2"' _ {} "$out" < "$out/files.txt" > "$out/status.txt"
python3 bench/png_stats.py $(awk '$1 == 0 {print "'"$out"'/" $2 ".png"}' "$out/status.txt") > "$out/stats.txt"
echo "$(wc -l < "$out/files.txt") files; exit status: $(awk '{print $1}' "$out/status.txt" | sort | uniq -c | tr -s ' ' | tr '\n' ';')"
awk '{n++; s += $2 >= 0.01; b += $3 < 0.01; g += $4 == 0; c += $5 < 0.005; t += $6 >= 20}
     END {printf "%d rendered: %d (%.1f%%) with a shadow over >= 1%% of the frame, %d (%.1f%%) with no black frame, %d (%.1f%%) with no background\n",
          n, s, 100 * s / n, b, 100 * b / n, g, 100 * g / n;
          printf "%d (%.1f%%) with under 0.5%% of pixels clipped to white, %d (%.1f%%) whose shadowed pixels spread over 20 levels or more\n",
          c, 100 * c / n, t, 100 * t / n}' "$out/stats.txt"
