# Shell helpers the benchmark scripts source: the check that the build is
# there, the builds to compare, GNU time's wall time and peak memory of one
# command, and medians.

# require_built BUILD TOOL...: exits unless ./build.sh has made BUILD/umbra
# and each BUILD/bench/TOOL
require_built() {
  local build=$1 tool; shift
  for tool in umbra "${@/#/bench/}"; do
    [ -x "$build/$tool" ] || { echo "bench: run ./build.sh first ($build/$tool is missing)" >&2; exit 2; }
  done
}

# compared_builds BUILD: sets the array `builds` to "now|BUILD/umbra" and,
# when BEFORE names an earlier build's umbra, "before|$BEFORE"
compared_builds() {
  builds=("now|$1/umbra")
  [ -n "${BEFORE:-}" ] && builds+=("before|$BEFORE")
  return 0
}

# median of the numbers on stdin
median() { sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

# time_once OUT COMMAND...: runs it once, appends "SECONDS KILOBYTES FAULTS"
# (wall time, peak memory, minor page faults) to OUT
time_once() {
  local out=$1; shift
  /usr/bin/time -f "%e %M %R" -o "$out.last" "$@" >/dev/null 2>&1 || true
  # the last line: GNU time puts "Command exited with non-zero status" before it
  tail -n 1 "$out.last" >> "$out"
}

# column N of FILE's lines, as a median
median_of() { awk -v c="$2" '{print $c}' "$1" | median; }

# time_rows PREFIX RUNS: runs every "NAME|COMMAND" of the array `rows` once a
# round, rows alternating, RUNS rounds; row k's figures go to PREFIX-k.txt
time_rows() {
  local prefix=$1 runs=$2 i k
  rm -f "$prefix"-*.txt
  for ((i = 0; i < runs; i++)); do
    for k in "${!rows[@]}"; do
      # shellcheck disable=SC2086 # the command is split into words on purpose (no path holds a blank)
      time_once "$prefix-$k.txt" ${rows[$k]#*|}
    done
  done
}

# rows_table PREFIX: a markdown row per row of `rows`, its name, median wall
# time (s) and median peak memory (MiB) from PREFIX-k.txt
rows_table() {
  local k
  for k in "${!rows[@]}"; do
    printf '| %s | %s | %.0f |\n' "${rows[$k]%%|*}" "$(median_of "$1-$k.txt" 1)" \
      "$(echo "$(median_of "$1-$k.txt" 2) / 1024" | bc -l)"
  done
}

# require_engine: sets `engine` to Khronos's two-cylinder engine (110k
# triangles, open) from Debian's assimp-testmodels, or exits
require_engine() {
  engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
  [ -f "$engine" ] || { echo "bench: $engine is missing (./build.sh installs assimp-testmodels)" >&2; exit 2; }
}

# subdivided_bunny DATA SIZE: makes DATA/bunny-SIZE.{stl,obj,glb} unless there,
# CGAL's bunny subdivided to SIZE 1M (1.2M triangles) or 4M (4.8M)
subdivided_bunny() {
  local data=$1 size=$2 level
  [ -f "$data/bunny-$size.glb" ] && return
  level=$([ "$size" = 1M ] && echo 2 || echo 3)
  mkdir -p "$data"
  tar xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$data" data/meshes/bunny00.off
  build/bench/make_subdivided_mesh "$data/data/meshes/bunny00.off" "$data/bunny-$size.stl" "$data/bunny-$size.obj" \
    "$data/bunny-$size.glb" "$level"
}

# require_engine_and_bunny BUILD: `engine` set (require_engine), BUILD's
# bench tools there, and BUILD/bench-data/bunny-1M.* made unless there
require_engine_and_bunny() {
  require_engine
  require_built "$1" make_subdivided_mesh
  subdivided_bunny "$1/bench-data" 1M
}

# survey_name FILE: the name bench/staging_survey.sh and bench/f3d_survey.sh
# give FILE's pictures: its path under the data set's folder, / as _
survey_name() {
  echo "$1" | sed 's|^/usr/share/assimp/models/||; s|^build/cgal-data/data/meshes/|cgal/|; s|^/usr/share/opencascade/data/|occt/|; s|/|_|g'
}
