#!/usr/bin/env bash
# How many files of a corpus each tool draws, side by side: umbra (one folder
# run, a JSON record a file) and f3d 1.3 (Debian's, with its Assimp and
# Open CASCADE modules, one process a file, as a user would script it), over
# every regular file of Debian's assimp-testmodels by default. A file counts
# as drawn by umbra where its record says "drawn", and by f3d where f3d
# exits 0 having written a picture that shows something (not one colour:
# f3d writes a blank picture of a file it reads nothing from). Per
# extension, and in all:
#   bench/format_coverage.sh [FOLDER]   (after ./build.sh test; needs f3d and Xvfb)
set -euo pipefail
cd "$(dirname "$0")/.."
folder=${1:-/usr/share/assimp/models}
build=build
. bench/timing.sh
require_built $build
for tool in f3d xvfb-run /usr/bin/python3; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is missing (apt-get install f3d xvfb python3-pil)" >&2; exit 2; }
done
[ -d "$folder" ] || { echo "bench: $folder is missing (apt-get install assimp-testmodels)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$build/umbra" render "$folder" -o "$out/umbra" --size 64x64 --json --timeout 60 > "$out/umbra.jsonl" 2>/dev/null || true
find "$folder" -type f | sort > "$out/files.txt"
mkdir -p "$out/f3d"
# One X server for every f3d run; each file's picture named by its line.
xvfb-run -a bash -c '
  n=0
  while IFS= read -r file; do
    n=$((n + 1))
    if timeout 60 f3d --output="$1/f3d/$n.png" --resolution=64,64 "$file" >/dev/null 2>&1; then echo "$n"; fi
  done < "$1/files.txt" > "$1/f3d-exited-0.txt"' _ "$out"
/usr/bin/python3 - "$out" <<'PYTHON'
import collections, json, os, sys
from PIL import Image
out = sys.argv[1]
files = open(os.path.join(out, "files.txt")).read().splitlines()
umbra = {json.loads(line)["path"]: json.loads(line)["status"] for line in open(os.path.join(out, "umbra.jsonl"))}
f3d_ok = {int(n) for n in open(os.path.join(out, "f3d-exited-0.txt")).read().split()}
def shows_something(n):
    path = os.path.join(out, "f3d", f"{n}.png")
    if not os.path.exists(path):
        return False
    extrema = Image.open(path).convert("RGB").getextrema()
    return any(lo != hi for lo, hi in extrema)
rows = collections.defaultdict(lambda: [0, 0, 0, 0])
for n, path in enumerate(files, 1):
    ext = os.path.splitext(path)[1].lower() or "(none)"
    row = rows[ext]
    row[0] += 1
    row[1] += umbra.get(path) == "drawn"
    row[2] += n in f3d_ok and shows_something(n)
    row[3] += path in umbra
print("| extension | files | umbra draws | f3d 1.3 draws | umbra's records |")
print("|---|---|---|---|---|")
total = [0, 0, 0, 0]
for ext, row in sorted(rows.items(), key=lambda item: (-item[1][0], item[0])):
    if row[1] or row[2]:
        print(f"| {ext} | {row[0]} | {row[1]} | {row[2]} | {row[3]} |")
    total = [a + b for a, b in zip(total, row)]
print(f"| all {len(rows)} extensions | {total[0]} | {total[1]} | {total[2]} | {total[3]} |")
PYTHON
