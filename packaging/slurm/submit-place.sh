#!/usr/bin/env bash
# Submits a base-placement search as a Slurm job array of SHARDS shards plus the merge job that
# waits for it, and prints the two job ids (array first) on one line.
#
#   submit-place.sh SHARDS RESULTS_DIR [SBATCH-OPTION...] -- PLACE-ARGS...
#
#   SHARDS         number of array tasks, each evaluating 1/SHARDS of the candidates
#   RESULTS_DIR    folder on a file system every node shares; the answer is RESULTS_DIR/place.json
#   SBATCH-OPTION  given to both sbatch calls, e.g. --partition=short --account=lab
#                  --time=1:00:00 (--cpus-per-task=K gives K threads per shard and merge)
#   PLACE-ARGS     `demoplan-cli place` arguments without --shard, --out and --jobs
#
# DEMOPLAN_CLI (default: demoplan-cli on the nodes' PATH) names the CLI the jobs run.
set -euo pipefail

usage() { echo "usage: $0 SHARDS RESULTS_DIR [SBATCH-OPTION...] -- PLACE-ARGS..." >&2; exit 2; }
[ $# -ge 3 ] || usage
shards=$1 results=$2
shift 2
[[ $shards =~ ^[1-9][0-9]*$ ]] || usage
sbatch_opts=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do sbatch_opts+=("$1"); shift; done
[ "${1:-}" = -- ] || usage
shift

here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$results"
results=$(cd "$results" && pwd) # the jobs may start in another directory
# An old answer would look like this run's to whoever waits for place.json.
if [ -e "$results/place.json" ]; then
  echo "$0: $results/place.json exists; use a new folder or remove it" >&2
  exit 2
fi

# --export=ALL: the jobs see this environment (DEMOPLAN_CLI, PATH) plus the two settings.
export_vars="ALL,PLACE_SHARDS=$shards,PLACE_RESULTS=$results"
array_id=$(sbatch --parsable "${sbatch_opts[@]}" --array="1-$shards" --export="$export_vars" \
  --output="$results/place-%a.log" "$here/place.sbatch" "$@")
array_id=${array_id%%;*} # --parsable prints "id;cluster" on multi-cluster setups
# --kill-on-invalid-dep: if a shard fails the merge is cancelled instead of pending forever.
merge_id=$(sbatch --parsable "${sbatch_opts[@]}" --dependency="afterok:$array_id" \
  --kill-on-invalid-dep=yes --export="$export_vars" --output="$results/merge.log" \
  "$here/merge.sbatch")
merge_id=${merge_id%%;*}
echo "$array_id $merge_id"
