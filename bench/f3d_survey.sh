#!/usr/bin/env bash
# f3d's pictures of the files staging_survey.sh rendered, at the same size,
# with f3d's defaults (what a user who reached for it would see), and sheets
# of umbra's and f3d's side by side, 16 pairs a sheet, two a row, to look at together:
#   bench/f3d_survey.sh [SURVEY_DIR]   (after bench/staging_survey.sh; default
#                                       build/staging-survey; needs f3d and Xvfb)
# Writes SURVEY_DIR/f3d/NAME.png, SURVEY_DIR/sheets/sheet-K.png and
# SURVEY_DIR/sheets/sheet-K.txt (the files of sheet K, in order, two a row:
# umbra's picture on the left of each pair, f3d's on the right).
set -euo pipefail
cd "$(dirname "$0")/.."
survey=${1:-build/staging-survey}
for tool in f3d xvfb-run; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is missing (apt-get install f3d xvfb)" >&2; exit 2; }
done
[ -f "$survey/status.txt" ] || { echo "bench: run bench/staging_survey.sh $survey first" >&2; exit 2; }
mkdir -p "$survey/f3d" "$survey/sheets"
. bench/timing.sh
rm -f "$survey"/sheets/sheet-*
# Each file umbra rendered, by the name staging_survey.sh gave its picture.
awk '$1 == 0 {print $2}' "$survey/status.txt" | sort > "$survey/rendered.txt"
while read -r file; do
  name=$(survey_name "$file")
  grep -qx "$name" "$survey/rendered.txt" || continue
  timeout 120 xvfb-run -a f3d --resolution=200,200 --output="$survey/f3d/$name.png" "$file" >/dev/null 2>&1 || true
  echo "$name"
done < "$survey/files.txt" > "$survey/paired.txt"
split -l 16 -d "$survey/paired.txt" "$survey/sheets/sheet-"
for list in "$survey"/sheets/sheet-[0-9]*; do
  mv "$list" "$list.txt"
  args=()
  while read -r name; do args+=("$survey/$name.png" "$survey/f3d/$name.png"); done < "$list.txt"
  python3 bench/side_by_side.py "$list.png" "${args[@]}"
done
echo "$(wc -l < "$survey/paired.txt") files side by side in $(ls "$survey"/sheets/*.png | wc -l) sheets: $survey/sheets"
