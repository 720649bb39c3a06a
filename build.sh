#!/usr/bin/env bash
# umbra's whole set-up on a fresh Debian 12 machine: installs the Debian
# packages it needs (only those missing: for the demo, what building and
# rendering need; for a plain build, the Python module's too; for the tests,
# the rest), configures and builds, then
#   ./build.sh demo   renders scenes/demo.scene to build/demo.png
#   ./build.sh test   runs the whole test suite (CTest)
#   ./build.sh sanitize   builds into build-sanitize/ with AddressSanitizer and
#                         UndefinedBehaviorSanitizer and runs the whole suite
#   ./build.sh fuzz [SEC] builds the libFuzzer targets with clang into
#                         build-fuzz/ and runs each for SEC seconds (default 60)
#   ./build.sh fuzz-libraries [SEC]   the same for the fuzzer that reaches
#                         Assimp's and Open CASCADE's readers too (not run by
#                         CI: their bugs are theirs)
#   ./build.sh        only builds
set -euo pipefail
cd "$(dirname "$0")"
case "${1:-}" in  # before anything is installed
  demo|test|sanitize|fuzz|fuzz-libraries|"") ;;
  *) echo "usage: ./build.sh [demo|test|sanitize|fuzz [SECONDS]|fuzz-libraries [SECONDS]]" >&2; exit 2 ;;
esac

# What building umbra and rendering with it need: all that ./build.sh demo
# installs, so that a first run is quick.
packages=(
  cmake ninja-build g++ pkg-config   # toolchain
  python3-glad                       # generates the OpenGL loader at build time
  libglm-dev libpng-dev              # vectors and matrices, PNG output
  libjpeg62-turbo-dev                # pictures written as JPEG (libjpeg-turbo); the texture benchmark
  libopenexr-dev                     # a view's depth and normals as float OpenEXR (--passes)
  libosmesa6-dev                     # headless OpenGL (Mesa llvmpipe) through OSMesa
  libegl-dev libegl-mesa0            # headless OpenGL through EGL: a GPU, or Mesa's software device
  libglfw3-dev libgl1-mesa-dri       # umbra view: a window with an OpenGL context
  libimgui-dev                       # umbra view's overlay (Dear ImGui)
  libstb-dev                         # texture maps (stb_image), the contact sheet's label font (stb_easy_font)
  libcgal-dev libgmp-dev libmpfr-dev # exact predicates, mesh checks and repair
  libeigen3-dev                      # the repair's hole filling: CGAL's fairing solves with Eigen
  libopenmesh-dev                    # half-edge meshes for silhouettes
  libembree-dev                      # the ray-cast reference's hierarchy (Embree 3)
  libtbb-dev                         # the self-intersection search on every core
  libfast-float-dev                  # fast, exact number parsing in the mesh readers
  libcli11-dev                       # every command's options (CLI11)
  nlohmann-json3-dev                 # umbra check --json (nlohmann/json)
  libtinygltf-dev                    # glTF 2.0 and GLB meshes (tinygltf)
  lib3mf-dev libzip-dev              # 3MF meshes (lib3mf; its pkg-config names libzip)
)
# The Python module umbra (docs/python.md): built and installed by a plain
# ./build.sh and by ./build.sh test (python, below).
python_packages=(python3-dev pybind11-dev python3-numpy)
# Animations (--turntable to .mp4, .webp or .gif): each library optional in
# CMake, so that the demo builds without them; built in by a plain
# ./build.sh and by ./build.sh test, sanitize and fuzz (motion, below).
motion_packages=(
  libavcodec-dev libavformat-dev libswscale-dev  # H.264 video in MP4 (Debian's libavcodec encodes it with libx264)
  libwebp-dev                                    # animated WebP (libwebp's mux library)
  libgif-dev                                     # GIF (giflib)
)
# The formats umbra does not parse itself, optional in CMake like the
# encoders, built in by a plain ./build.sh and the tests.
format_packages=(
  libassimp-dev                      # 3DS, Collada, FBX, Blender, LightWave, glTF 1.0, Draco glTF, ... (Assimp)
  libocct-data-exchange-dev libocct-modeling-algorithms-dev  # STEP, IGES and BREP, tessellated (Open CASCADE)
)
# What the tests, benchmarks, sanitizers and fuzzers need besides: installed
# by ./build.sh test, sanitize and fuzz.
test_packages=(
  xvfb xauth                         # tests run umbra view in a virtual display
  libgtest-dev python3               # tests (python3 reads the JSON that umbra check writes)
  libbenchmark-dev                   # bench/silhouette_benchmark (Google Benchmark)
  libcgal-demo                       # CGAL's data meshes, for the tests
  assimp-testmodels                  # exporters' real files (glTF, 3MF, OBJ, PLY, STL), for the tests
  occt-misc                          # Open CASCADE's CAD parts as STL (the repair fills their holes)
  gltfpack                           # the tests read its quantised glTF output
  admesh time bc                     # bench/check_benchmark.sh: the checker it compares with, timing
  clang libclang-rt-14-dev           # ./build.sh fuzz: libFuzzer
  gnuplot-nox                        # umbra bench --plot
  parallel                           # docs/batch-checks.md: sharded checks with GNU parallel (tested)
  python3-pytest python3-pil         # the Python module's tests (pytest), reading the command's pictures (Pillow)
  python3-distributed                # docs/batch-checks.md: the Dask recipe (tested)
  mypy                               # the Python module's type stubs, type-checked (tested)
  slurm-wlm munge                    # docs/batch-checks.md: the Slurm recipe, on a cluster the test starts (tested)
  chromium                           # umbra check --report's page, opened in a real browser (tested)
  ffmpeg                             # ffprobe reads back the MP4 videos umbra writes (tested)
)
case "${1:-}" in
  test|sanitize|fuzz|fuzz-libraries) packages+=("${test_packages[@]}" "${motion_packages[@]}" "${format_packages[@]}") ;;
  "") packages+=("${motion_packages[@]}" "${format_packages[@]}") ;;
esac
# Whether this command builds the Python module: not the demo, which renders
# with umbra alone, nor the sanitizers' and fuzzers' builds (configured below
# without it).
python=OFF
case "${1:-}" in
  test|"") python=ON; packages+=("${python_packages[@]}") ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
sudo=""
[ "$(id -u)" -eq 0 ] || sudo=sudo
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Configures a build folder: with Ninja where the folder is new, which
# compiles a target's files without waiting for the libraries it links,
# where CMake's make files wait for them (a fresh build here: 176 s against
# 192 s, docs/performance.md "Building"). A folder configured before keeps
# its generator.
configure() {
  local folder=$1 generator=()
  shift
  [ -f "$folder/CMakeCache.txt" ] || generator=(-G Ninja)
  cmake "${generator[@]}" -S . -B "$folder" "$@"
}

# Mesa allocates for the life of the process; leaks are not what these look for.
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
case "${1:-}" in
  sanitize)
    # -O1 and line tables only: AddressSanitizer asks for -O1 or more, its
    # reports need only file and line, and CGAL's templates compile in half
    # the time so (the whole build: 522 s against 999 s at -O2 -g).
    # The Python module is left out: a sanitized shared object needs its
    # runtime preloaded into python3.
    configure build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DUMBRA_PYTHON=OFF -DCMAKE_CXX_FLAGS="$sanitizers" \
      -DCMAKE_C_FLAGS="$sanitizers" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
      -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
    cmake --build build-sanitize -j"$(nproc)"
    # The GL tests run once, on the platform auto picks: OSMesa and EGL share
    # Mesa's driver, and only the plain build runs them again on OSMesa.
    cd build-sanitize && ctest --output-on-failure -j"$(nproc)" --label-exclude osmesa
    exit
    ;;
  fuzz|fuzz-libraries)
    seconds="${2:-60}"
    CC=clang CXX=clang++ configure build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DUMBRA_FUZZERS=ON -DUMBRA_PYTHON=OFF \
      -DUMBRA_BUILD_TESTS=OFF -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link $sanitizers" -DCMAKE_C_FLAGS="$sanitizers"
    rm -rf build-fuzz/corpus build-fuzz/crashes && mkdir -p build-fuzz/crashes
    if [ "$1" = fuzz ]; then
      targets=(scene mesh cameras)
      cmake --build build-fuzz -j"$(nproc)" --target scene_fuzzer mesh_fuzzer cameras_fuzzer mesh_seed
      # Seed corpus: the bundled scenes; transforms.json files (fuzz/seeds/cameras/);
      # and the bundled meshes, fuzz/seeds/mesh/ (glTF, GLB, 3MF) and the mesh
      # regressions behind their format byte (written by mesh_seed).
      mkdir -p build-fuzz/corpus/scene build-fuzz/corpus/mesh build-fuzz/corpus/cameras
      cp scenes/*.scene fuzz/regressions/scene/* build-fuzz/corpus/scene/ 2>/dev/null || true
      cp fuzz/seeds/cameras/* fuzz/regressions/cameras/* build-fuzz/corpus/cameras/ 2>/dev/null || true
      build-fuzz/fuzz/mesh_seed build-fuzz/corpus/mesh scenes/meshes/* fuzz/seeds/mesh/* fuzz/regressions/mesh/*
    else
      targets=(library)
      cmake --build build-fuzz -j"$(nproc)" --target library_fuzzer mesh_seed
      # Seeds: the small files of Assimp's test models and Open CASCADE's
      # data (the inputs are cut at 8 KiB), and the library regressions.
      mkdir -p build-fuzz/corpus/library
      find /usr/share/assimp/models /usr/share/opencascade/data fuzz/regressions/library -type f -size -8k -print0 |
        xargs -0 build-fuzz/fuzz/mesh_seed --every-reader build-fuzz/corpus/library
    fi
    for target in "${targets[@]}"; do
      echo "fuzzing the $target input for $seconds s"
      "build-fuzz/fuzz/${target}_fuzzer" -max_total_time="$seconds" -max_len=8192 -timeout=20 -rss_limit_mb=4096 \
        -print_final_stats=1 -artifact_prefix="build-fuzz/crashes/$target-" "build-fuzz/corpus/$target" 2>&1 |
        grep -E "^(Done|stat::number|stat::new|==|SUMMARY)|ERROR|Test unit written|terminate called|what\(\)|runtime error" || true
      if compgen -G "build-fuzz/crashes/$target-*" > /dev/null; then
        echo "the $target fuzzer found a crash: build-fuzz/crashes/ (add it to fuzz/regressions/ once fixed)" >&2
        exit 1
      fi
    done
    exit
    ;;
esac

# The tests and benchmarks only for ./build.sh test, whose packages they need.
tests=OFF
[ "${1:-}" = test ] && tests=ON
# Debug information as line tables only (-g1): backtraces and perf still name
# file and line, and CGAL's templates compile in three quarters of the time
# (docs/performance.md, "Building").
release="-O2 -g1 -DNDEBUG"
configure build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DUMBRA_BUILD_TESTS=$tests -DUMBRA_PYTHON=$python \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$release" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$release"
cmake --build build -j"$(nproc)"
# The Python module where Debian's python3 finds it (docs/python.md):
# /usr/local/lib/python3.X/dist-packages/umbra.
if [ "$python" = ON ]; then
  $sudo cmake --install build --component python > /dev/null
fi

case "${1:-}" in
  demo)
    ./build/umbra render scenes/demo.scene -o build/demo.png --mask build/demo-mask.png --explain
    echo "the demo image is at $(pwd)/build/demo.png"
    ;;
  test)
    cd build && ctest --output-on-failure -j"$(nproc)"
    ;;
  "") ;;
esac
