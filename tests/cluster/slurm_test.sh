#!/usr/bin/env bash
# docs/batch-checks.md's Slurm recipe, run as the page gives it on a real
# Slurm: a one-machine cluster of Debian's slurm-wlm and munge
# (slurm_cluster.sh) takes the page's array job (three tasks here, not 100;
# one core each) over a folder of real model files whose name holds '_',
# and the page's lines put the reports together; they must be the
# one-machine run's, in file order. An array job that renders its shards
# (--shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT) must draw the
# one-machine run's pictures. Exits 77 (skipped, said why) where the
# daemons cannot start.
#
#   slurm_test.sh UMBRA WORK_FOLDER MODEL...
set -uo pipefail
umbra=$1 work=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/slurm_cluster.sh"
meshes="$work/real_models_2"
rm -rf "$work" && mkdir -p "$meshes"
cp "$@" "$meshes/"
trap stop_slurm EXIT
# Not in a subshell: stop_slurm needs what start_slurm sets.
if ! start_slurm "$work/slurm" > "$work/why.txt"; then
  echo "skipped: a Slurm cluster could not start on this machine: $(cat "$work/why.txt")"
  exit 77
fi
export SLURM_CONF="$work/slurm/slurm.conf"

# The Kth sh block of the page's Slurm section, with three tasks for 100,
# one core for 8, and the test's folder for /data/meshes.
recipe() {
  python3 - "$here/../../docs/batch-checks.md" "$1" <<'PY' | sed -e 's/--array=0-99/--array=0-2/' -e 's/seq 0 99/seq 0 2/' \
    -e 's/--cpus-per-task=8/--cpus-per-task=1/' -e "s|/data/meshes|$meshes|"
import re, sys
page = open(sys.argv[1]).read()
section = page[page.index("### Slurm array jobs"):page.index("### Dask")]
print(re.findall(r"```sh\n(.*?)```", section, re.S)[int(sys.argv[2])], end="")
PY
}
recipe 0 > "$work/shards.sh"
recipe 1 > "$work/gather.sh"
grep -q "seq 0 2" "$work/gather.sh" && grep -q "array=0-2" "$work/shards.sh" ||
  { echo "the page's recipe is not as this test reads it:"; cat "$work/shards.sh" "$work/gather.sh"; exit 1; }
# The job finds umbra on its PATH, as a user's does. A task exits 1 where a
# mesh in its part is open, so sbatch --wait's status says little: the
# reports say what ran. 5 minutes is far more than the tasks take.
(cd "$work" && PATH="$(dirname "$umbra"):$PATH" timeout 300 bash "$work/gather.sh")
cat "$work"/reports/*.log 2>/dev/null

# The renders, sharded as the page says.
cat > "$work/render.sh" <<JOB
#!/usr/bin/env bash
#SBATCH --array=0-2
#SBATCH --output=$work/render-%a.log
"$umbra" render --size 160x120 --shard "\$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT" "$meshes" -o "$work/pictures"
JOB
if ! timeout 300 sbatch --wait "$work/render.sh"; then
  echo "the render array job failed:"; cat "$work"/render-*.log; exit 1
fi

"$umbra" check --json "$meshes" > "$work/reports-one-machine.jsonl"
"$umbra" render --size 160x120 "$meshes" -o "$work/pictures-one-machine" > /dev/null
status=0
# The reports put together, in file order as one machine writes them,
# without the seconds each search took.
same_reports=$(python3 - "$work" <<'PY'
import json, pathlib, sys
work = pathlib.Path(sys.argv[1])
def reports(path):
    lines = [json.loads(l) for l in path.read_text().splitlines()]
    for r in lines:
        r.get("self_intersections", {}).pop("seconds", None)
    return lines
gathered, one = reports(work / "all.jsonl"), reports(work / "reports-one-machine.jsonl")
print("yes" if gathered == one and len(one) > 0 else f"no: {len(gathered)} reports gathered, {len(one)} from one machine")
PY
)
if [ "$same_reports" != yes ]; then echo "the shards' reports differ from one machine's: $same_reports"; status=1; fi
for picture in "$work"/pictures-one-machine/*.png; do
  name=$(basename "$picture")
  if ! cmp -s "$picture" "$work/pictures/$name"; then echo "the shards' $name differs from one machine's"; status=1; fi
done
count=$(ls "$work"/pictures/*.png | wc -l)
[ "$count" -eq "$(ls "$work"/pictures-one-machine/*.png | wc -l)" ] || { echo "the shards drew $count pictures"; status=1; }
[ $status -eq 0 ] && echo "Slurm array job of 3 tasks: $count pictures and their reports, as one machine makes them"
exit $status
