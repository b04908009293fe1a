#!/usr/bin/env bash
# Cells end to end (issue 15, docs/benchmarks.md): for each example cell and seed, synth --cell
# with 3 random picks, then calibrate, extract, evaluate, plan (--seed 1), validate and export.
# One JSON line per run in OUT/results.jsonl, a summary table on stdout.
# Usage: scripts/cell_end_to_end.sh [OUT] [SEEDS] [CELLS]   (defaults: /tmp/cell_e2e, "1..10", both)
set -uo pipefail
cd "$(dirname "$0")/.."
CLI="${DEMOPLAN_CLI:-build/app/demoplan-cli}"
OUT="${1:-/tmp/cell_e2e}"
SEEDS="${2:-$(seq 1 10)}"
CELLS="${3:-ur5_workbench iiwa_shelf}"
DATA=(--data-dir resources/gtamp)
mkdir -p "$OUT"
: > "$OUT/results.jsonl"
# The JSON a step printed, or null when it failed before printing any.
json_or_null() { if [ -s "$1" ]; then cat "$1"; else echo null; fi; }
for cell in $CELLS; do
  for seed in $SEEDS; do
    d="$OUT/$cell/$seed"
    rm -rf "$d" && mkdir -p "$d"
    c="resources/cells/$cell.json"
    "$CLI" synth "${DATA[@]}" --cell "$c" --picks 3 --seed "$seed" --out "$d" --json > "$d/synth.out" 2> "$d/synth.err"; s1=$?
    "$CLI" calibrate "$d/calibration.mp4" --board "$d/board.json" --out "$d/cam.json" --json > "$d/calibrate.out" 2> "$d/calibrate.err"; s2=$?
    "$CLI" extract "$d/video.mp4" --camera "$d/cam.json" --scene "$d/scene.json" --out "$d/demo.json" --json > "$d/extract.out" 2> "$d/extract.err"; s3=$?
    "$CLI" evaluate "${DATA[@]}" "$d/demo.json" --truth "$d/truth.json" --json > "$d/evaluate.out" 2> "$d/evaluate.err"; s4=$?
    "$CLI" plan "${DATA[@]}" --cell "$c" --demo "$d/demo.json" --seed 1 --out "$d/p.json" --json > "$d/plan.out" 2> "$d/plan.err"; s5=$?
    "$CLI" validate "${DATA[@]}" "$d/p.json" --cell "$c" --demo "$d/demo.json" --json > "$d/validate.out" 2> "$d/validate.err"; s6=$?
    "$CLI" export "${DATA[@]}" "$d/p.json" --cell "$c" --format csv --out "$d/x.csv" > /dev/null 2> "$d/export.err"; s7=$?
    echo "{\"cell\": \"$cell\", \"seed\": $seed, \"exit\": {\"synth\": $s1, \"calibrate\": $s2, \"extract\": $s3, \"evaluate\": $s4, \"plan\": $s5, \"validate\": $s6, \"export\": $s7}, \"synth\": $(json_or_null "$d/synth.out"), \"calibrate\": $(json_or_null "$d/calibrate.out"), \"truth\": $(cat "$d/camera_truth.json" 2>/dev/null || echo null), \"evaluate\": $(json_or_null "$d/evaluate.out"), \"plan\": $(json_or_null "$d/plan.out"), \"validate\": $(json_or_null "$d/validate.out")}" | tr -d '\n' >> "$OUT/results.jsonl"
    echo >> "$OUT/results.jsonl"
    echo "$cell seed $seed: synth $s1 calibrate $s2 extract $s3 evaluate $s4 plan $s5 validate $s6 export $s7" >&2
  done
done
python3 - "$OUT/results.jsonl" <<'PY'
import json, statistics, sys
runs = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
steps = ["synth", "calibrate", "extract", "evaluate", "plan", "validate", "export"]
def med(xs): return statistics.median(xs) if xs else float("nan")
for cell in sorted({r["cell"] for r in runs}):
    rs = [r for r in runs if r["cell"] == cell]
    print(f"{cell}: {len(rs)} runs")
    print("  succeeded  " + ", ".join(f"{s} {sum(r['exit'][s] == 0 for r in rs)}" for s in steps))
    cal = [(r["calibrate"], r["truth"]) for r in rs if r["calibrate"] and r["truth"]]
    rms = [c["rms_px"] for c, t in cal]
    fx = [abs(c["fx"] - t["intrinsics"]["fx"]) / t["intrinsics"]["fx"] * 100 for c, t in cal]
    print(f"  calibration RMS px median {med(rms):.3f} max {max(rms, default=float('nan')):.3f}; "
          f"fx error % median {med(fx):.3f} max {max(fx, default=float('nan')):.3f}")
    ev = [r["evaluate"] for r in rs if r["evaluate"]]
    print(f"  events precision min {min((e['event_precision'] for e in ev), default=float('nan')):.3f} "
          f"recall min {min((e['event_recall'] for e in ev), default=float('nan')):.3f}; "
          f"median translation error mm (median over runs) {med([e['median_translation_error_mm'] for e in ev]):.2f}, "
          f"rotation deg {med([e['median_rotation_error_deg'] for e in ev]):.2f}")
    pl = [r["plan"]["planning_time_s"] for r in rs if r["plan"] and "planning_time_s" in r["plan"]]
    print(f"  planning time s median {med(pl):.2f}")
    va = [r["validate"]["valid"] for r in rs if r["validate"]]
    print(f"  paths valid {sum(va)}/{len(rs)}")
PY
