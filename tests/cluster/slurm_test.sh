#!/usr/bin/env bash
# docs/batch-checks.md's Slurm recipe, run on a real Slurm: a one-machine
# cluster of Debian's slurm-wlm and munge (slurm_cluster.sh) takes an array
# job of three tasks, each checking and rendering its shard of a folder of
# real model files (--shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT);
# the shards' reports and pictures together must be the one-machine run's.
# Exits 77 (skipped, said why) where the daemons cannot start.
#
#   slurm_test.sh UMBRA WORK_FOLDER MODEL...
set -uo pipefail
umbra=$1 work=$2
shift 2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/slurm_cluster.sh"
rm -rf "$work" && mkdir -p "$work/meshes"
cp "$@" "$work/meshes/"
trap stop_slurm EXIT
# Not in a subshell: stop_slurm needs what start_slurm sets.
if ! start_slurm "$work/slurm" > "$work/why.txt"; then
  echo "skipped: a Slurm cluster could not start on this machine: $(cat "$work/why.txt")"
  exit 77
fi
export SLURM_CONF="$work/slurm/slurm.conf"

# The recipe, as docs/batch-checks.md gives it.
cat > "$work/shard.sh" <<JOB
#!/usr/bin/env bash
#SBATCH --array=0-2
#SBATCH --output=$work/task-%a.log
shard=\$SLURM_ARRAY_TASK_ID/\$SLURM_ARRAY_TASK_COUNT
"$umbra" check --json --shard "\$shard" "$work/meshes" > "$work/reports-\$SLURM_ARRAY_TASK_ID.jsonl"
"$umbra" render --size 160x120 --shard "\$shard" "$work/meshes" -o "$work/pictures"
JOB
# sbatch --wait returns once every task has ended; 5 minutes is far more than they take.
if ! timeout 300 sbatch --wait "$work/shard.sh"; then
  echo "the array job failed:"; cat "$work"/task-*.log; exit 1
fi
cat "$work"/task-*.log

"$umbra" check --json "$work/meshes" > "$work/reports-one-machine.jsonl"
"$umbra" render --size 160x120 "$work/meshes" -o "$work/pictures-one-machine" > /dev/null
status=0
# The reports, in file order, without the seconds each search took.
same_reports=$(python3 - "$work" <<'PY'
import json, pathlib, sys
work = pathlib.Path(sys.argv[1])
def reports(files):
    lines = [json.loads(l) for f in files for l in f.read_text().splitlines()]
    for r in lines:
        r.get("self_intersections", {}).pop("seconds", None)
    return sorted(lines, key=lambda r: r["path"])
shards = reports(sorted(work.glob("reports-[0-9]*.jsonl")))
one = reports([work / "reports-one-machine.jsonl"])
print("yes" if shards == one and len(one) > 0 else f"no: {len(shards)} reports from the shards, {len(one)} from one machine")
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
