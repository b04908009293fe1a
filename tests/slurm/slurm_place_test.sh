#!/usr/bin/env bash
# End to end: a small base-placement search run once directly and once as a 4-shard Slurm job
# array plus merge (packaging/slurm/submit-place.sh) on a one-node cluster started here must
# give the same ranking. Prints both wall times.
#
#   slurm_place_test.sh [DEMOPLAN_CLI]     (or DEMOPLAN_CLI in the environment)
#
# Exit: 0 same ranking, 1 different or failed, 77 Slurm cannot start here (ctest skip).
# SLURM_TEST_TIMEOUT (seconds, default 300) bounds the wait for the Slurm run.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
submit="$here/../../packaging/slurm/submit-place.sh"
cli=${1:-${DEMOPLAN_CLI:-}}
[ -n "$cli" ] || { echo "usage: $0 DEMOPLAN_CLI" >&2; exit 2; }
command -v python3 >/dev/null || { echo "slurm test: python3 not found, needed to compare" >&2; exit 77; }
# Absolute: the jobs start in Slurm's working directory, not necessarily this one.
DEMOPLAN_CLI=$(realpath "$(command -v "$cli")")
export DEMOPLAN_CLI
shards=4
place_args=(--task shelf_1 --robot panda --region "0.1:0.5,0.0:0.4,-3.14159:3.14159"
  --samples 8 --seeds 1 --time-limit 5)

work=$(mktemp -d /tmp/demoplan-slurm-test.XXXXXX)
ok=0
# Always stop the cluster; keep the folder (logs, partial results) only when the test failed.
cleanup() {
  "$here/one_node_slurm.sh" stop "$work/cluster"
  if [ "$ok" = 1 ]; then rm -rf "$work"; else echo "kept $work for inspection" >&2; fi
}
trap cleanup EXIT
trap 'exit 1' INT TERM # so that the EXIT trap also runs on Ctrl-C or kill

status=0
conf=$("$here/one_node_slurm.sh" start "$work/cluster") || status=$?
if [ "$status" != 0 ]; then ok=1; exit "$status"; fi # 77: it said why on stderr
eval "$conf"

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

# (a) Directly, unsharded, on every core, as a user without Slurm would run it.
t0=$(now)
"$DEMOPLAN_CLI" place "${place_args[@]}" --jobs "$(nproc)" --out "$work/place-single.json" >/dev/null
single_s=$(elapsed "$t0" "$(now)")

# (b) Through Slurm: the array of shards, then the merge once all have succeeded.
t0=$(now)
read -r array_id merge_id < <("$submit" "$shards" "$work/results" -- "${place_args[@]}")
deadline=$(($(date +%s) + ${SLURM_TEST_TIMEOUT:-300}))
# Done when the merge job has left the queue (finished, failed or cancelled because a shard
# failed); squeue prints nothing for a job it no longer knows.
while [ -n "$(squeue -h -j "$merge_id" 2>/dev/null)" ]; do
  if [ "$(date +%s)" -ge "$deadline" ]; then
    echo "FAIL: Slurm jobs $array_id/$merge_id not done after ${SLURM_TEST_TIMEOUT:-300} s" >&2
    squeue >&2 || true
    exit 1
  fi
  sleep 1
done
slurm_s=$(elapsed "$t0" "$(now)")
if [ ! -s "$work/results/place.json" ]; then
  echo "FAIL: the Slurm run wrote no place.json; its logs:" >&2
  tail -n 5 "$work/results"/*.log >&2 || true
  exit 1
fi

echo "wall time: direct (--jobs $(nproc)) ${single_s} s, Slurm ($shards shards + merge) ${slurm_s} s"

# Same ranking: the same (index, feasible, success_rate, cycle_time_s) in the same order.
python3 - "$work/place-single.json" "$work/results/place.json" <<'EOF'
import json, sys

def ranking(path):
    with open(path) as f:
        return [(c["index"], c["feasible"], c["success_rate"], c["cycle_time_s"])
                for c in json.load(f)["candidates"]]

single, sharded = ranking(sys.argv[1]), ranking(sys.argv[2])
if single != sharded:
    print("FAIL: the rankings differ (index, feasible, success_rate, cycle_time_s)")
    print("direct:", *single, sep="\n  ")
    print("slurm: ", *sharded, sep="\n  ")
    sys.exit(1)
print(f"same ranking of {len(single)} candidates; best: index {single[0][0]}" if single
      else "FAIL: no candidates")
sys.exit(0 if single else 1)
EOF
ok=1
