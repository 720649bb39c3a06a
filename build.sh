#!/usr/bin/env bash
# umbra's whole set-up on a fresh Debian 12 machine: installs the Debian
# packages it needs (only those missing), configures and builds, then
#   ./build.sh demo   renders scenes/demo.scene to build/demo.png
#   ./build.sh test   runs the whole test suite (CTest)
#   ./build.sh        only builds
set -euo pipefail
cd "$(dirname "$0")"

packages=(
  cmake make g++ pkg-config          # toolchain
  python3-glad                       # generates the OpenGL loader at build time
  libglm-dev libpng-dev              # vectors and matrices, PNG output
  libosmesa6-dev                     # headless OpenGL (Mesa llvmpipe)
  libglfw3-dev libgl1-mesa-dri       # umbra view: a window with an OpenGL context
  libimgui-dev                       # umbra view's overlay (Dear ImGui)
  xvfb xauth                         # tests run umbra view in a virtual display
  libcgal-dev libgmp-dev libmpfr-dev # exact predicates, mesh checks and repair
  libopenmesh-dev                    # half-edge meshes for silhouettes
  libgtest-dev python3               # tests (python3 reads the JSON that umbra check writes)
  libbenchmark-dev                   # bench/silhouette_benchmark (Google Benchmark)
  libcgal-demo                       # CGAL's data meshes, for the tests
  admesh time bc                     # bench/check_benchmark.sh: the checker it compares with, timing
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  echo "installing: ${missing[*]}"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build -j"$(nproc)"

case "${1:-}" in
  demo)
    ./build/umbra render scenes/demo.scene -o build/demo.png --mask build/demo-mask.png --explain
    echo "the demo image is at $(pwd)/build/demo.png"
    ;;
  test)
    cd build && ctest --output-on-failure -j"$(nproc)"
    ;;
  "") ;;
  *) echo "usage: ./build.sh [demo|test]" >&2; exit 2 ;;
esac
