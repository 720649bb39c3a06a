#!/usr/bin/env bash
# How smooth each way of antialiasing draws edges, against a 16 x 16
# reference: each model staged at 400x400 (its scene saved, so that every
# picture sees the same stage), the ray-cast reference drawn from that scene
# at 1600x1600 with 4 x 4 rays a pixel and box-filtered down by 4
# (bench/antialias_error.py), then the mean error of its edge pixels, in
# levels of 255, for one sample a pixel, 3 x 3 samples everywhere (the GL's
# frame drawn 3 times larger), the default (3 x 3 exact rays at edge pixels
# alone, or everywhere for a mesh finer than the picture's pixels), 4 x 4,
# and the ray-cast reference's own 3 x 3 at edges:
#   bench/antialias_quality.sh   (after ./build.sh; about two minutes here)
# The models: Khronos's two-cylinder engine, CGAL's bunny subdivided to 1.2M
# triangles (drawn flat at this size) and assimp's textured spider (OBJ).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
data=$build/bench-data
. bench/timing.sh
require_engine_and_bunny $build
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for model in "$engine" "$data/bunny-1M.glb" /usr/share/assimp/models/OBJ/spider.obj; do
  name=$(basename "${model%.*}")
  # The saved scene names the mesh by its path from the scene's folder.
  "$build/umbra" render "$model" --size 400x400 --save-scene "$out/$name.scene" -o "$out/staged.png" >/dev/null 2>&1
  "$build/umbra" render "$out/$name.scene" --size 1600x1600 --method raycast --antialias 4 --antialias-all \
    -o "$out/$name-reference.png" >/dev/null 2>&1
  draw() { "$build/umbra" render "$out/$name.scene" --size 400x400 -o "$out/$name-$1.png" "${@:2}" >/dev/null 2>&1; }
  draw "1-sample" --antialias 1
  draw "3x3-everywhere" --antialias 3 --antialias-all
  draw "default" --antialias 3
  draw "4x4" --antialias 4
  draw "raycast-3x3-at-edges" --antialias 3 --method raycast
  echo "## $name"
  (cd "$out" && python3 "$OLDPWD/bench/antialias_error.py" "$name-reference.png" 4 "$name-1-sample.png" \
    "$name-3x3-everywhere.png" "$name-default.png" "$name-4x4.png" "$name-raycast-3x3-at-edges.png")
done
