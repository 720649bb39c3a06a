#!/usr/bin/env bash
# The pictures of docs/rendering.md's "Directing the picture of a mesh": one
# real model per option, 240x240, from Debian's assimp-testmodels.
#   bench/option_pictures.sh [OUT_DIR]     (after ./build.sh; default docs/images/options)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/images/options}
[ -x build/umbra ] || { echo "bench: run ./build.sh first" >&2; exit 2; }
models=/usr/share/assimp/models
engine=$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
mkdir -p "$out"
picture() {  # NAME MODEL [OPTION...]
  local name=$1 model=$2
  shift 2
  build/umbra render "$model" -o "$out/$name.png" --size 240x240 "$@" 2>/dev/null
}
picture default "$engine"
picture camera "$engine" --camera-azimuth 150 --camera-elevation 15
picture light "$engine" --light-azimuth 60 --light-elevation 35
picture zoom "$engine" --camera-zoom 1.8 --fov 45
picture floor "$engine" --floor '#3c5a78' --background white
picture transparent "$engine" --floor none --background transparent
picture color "$models/OBJ/WusonOBJ.obj" --color orange
picture light-angle "$engine" --light-angle 180
picture catcher "$engine" --floor shadow-catcher --background transparent
picture catcher-opaque "$engine" --floor shadow-catcher
