#!/usr/bin/env bash
# umbra check --report's page at corpus size: 10,000 small meshes (a
# tetrahedron each, every hundredth open) checked into a report without
# pictures, then the page opened in headless Chromium, RUNS times each way:
# as it opens, and sorted by border edges with the open ones alone shown.
# Prints the median milliseconds the page's script took to make its rows,
# sort and filter them (its data-ready-ms), and the check's wall time.
#
#   bench/check_report_benchmark.sh [RUNS]   (default 5; after ./build.sh test)
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/timing.sh
runs=${1:-5}
require_built build
command -v chromium >/dev/null || { echo "bench: needs Debian's chromium (./build.sh test installs it)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/many"
for i in $(seq -w 0 9999); do
  if [ $((10#$i % 100)) -eq 0 ]; then faces="3
3 0 2 1
3 0 1 3
3 0 3 2"; else faces="4
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3"; fi
  printf 'OFF\n4 %s 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n%s\n' "${faces%%$'\n'*}" "${faces#*$'\n'}" > "$work/many/t$i.off"
done
start=$(date +%s.%N)
build/umbra check --brief "$work/many" --report "$work/report.html" --no-pictures > /dev/null 2>&1 || true
echo "umbra check --report of 10,000 meshes: $(echo "$(date +%s.%N) - $start" | bc -l | cut -c1-5) s, page $(du -h "$work/report.html" | cut -f1)"
ready() {
  chromium --headless --no-sandbox --disable-gpu --user-data-dir="$work/profile" --dump-dom \
    "file://$work/report.html$1" 2>/dev/null | grep -o 'data-ready-ms="[0-9]*"' | grep -o '[0-9]*'
}
for ((k = 0; k < runs; k++)); do
  ready "" >> "$work/plain.txt"
  ready "#sort=border-edges&order=descending&verdict=not-closed" >> "$work/sorted.txt"
done
echo "page ready, as it opens: median $(median < "$work/plain.txt") ms; sorted and filtered: median $(median < "$work/sorted.txt") ms ($runs runs, $(nproc) cores)"
