#!/usr/bin/env bash
# Runs the programs on the bundled datasets with fixed seeds into OUT, then,
# given a reference folder REF made the same way by an earlier build, checks
# that every output is the same: bytes for every file, except JSON, which is
# compared as parsed values (its layout may change) with the wall-clock
# timings left out. A restructuring must pass this unchanged.
# Usage: compare_outputs.sh OUT [REF [BIN]]   (BIN defaults to build/bin)
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:?usage: compare_outputs.sh OUT [REF [BIN]]}
REF=${2:-}
BIN=$(realpath "${3:-build/bin}")
ROOT=$PWD
# The runs record their command line: run them in one fixed folder so that
# two runs name the same paths, then move the results to OUT.
WORK=/tmp/rfir_compare_outputs
rm -rf "$WORK" && mkdir -p "$WORK" && ln -s "$ROOT/datasets" "$WORK/datasets"
ln -s "$ROOT/config_ini" "$WORK/config_ini"
cd "$WORK"
D=datasets
run() {  # run NAME CMD...: stdout to NAME.stdout, exit code to NAME.rc
    local name=$1
    shift
    set +e
    "$@" > "$name.stdout" 2> "$name.stderr"
    echo $? > "$name.rc"
    set -e
}
for m in pf ps fastslam; do
    smooth=()
    [ "$m" = ps ] && smooth=(--smooth)
    run slam_loop_$m "$BIN/rfir-slam" --rawlog $D/rfid_60mm_16tags_loop.rawlog \
        --method $m --seed 1 --out-dir slam_loop_$m "${smooth[@]}"
done
run slam_300_pf "$BIN/rfir-slam" --rawlog $D/rfid_300mm_4tags_random_90s.rawlog \
    --method pf --seed 1 --out-dir slam_300_pf
run slam_kidnap_ps "$BIN/rfir-slam" --rawlog $D/rfid_kidnap.rawlog --method ps --seed 1 \
    --out-dir slam_kidnap_ps
run slam_rb_fastslam "$BIN/rfir-slam" --rawlog $D/rb_rotation.rawlog --method fastslam \
    --seed 1 --out-dir slam_rb_fastslam
for d in ir_loop_spots ir_raw_15s; do
    run loc_$d "$BIN/rfir-localize" --config config_ini/ir_localize.ini \
        --rawlog $D/$d.rawlog --emitters $D/$d.gt_map.txt --out-dir loc_$d --seed 1
done
run loc_odo "$BIN/rfir-localize" --config config_ini/ir_localize.ini \
    --rawlog $D/ir_loop_spots.rawlog --emitters $D/ir_loop_spots.gt_map.txt \
    --out-dir loc_odo --odometry-only
for ini in sim_faults_combined sim_rb_rotation sim_faults_ir_combined; do
    run sim_$ini "$BIN/rfir-sim" --config config_ini/$ini.ini --out-dir sim_$ini \
        --seed 3 --set simulation.max_duration=40
done
run sim_stock "$BIN/rfir-sim" --config sim_kidnap --out-dir sim_stock --seed 1 \
    --set simulation.max_duration=30
L=$D/rfid_60mm_16tags_loop
run eval_runs "$BIN/rfir-eval" --gt-path $L.gt.tum --gt-map $L.gt_map.txt --rawlog $L.rawlog \
    --run "PF=slam_loop_pf/path.tum,slam_loop_pf/map.txt" \
    --run "PS=slam_loop_ps/path.tum,slam_loop_ps/map.txt" \
    --run "FastSLAM \"q\"=slam_loop_fastslam/path.tum,slam_loop_fastslam/map.txt" \
    --title "loop, seed 1" --plot eval_paths.png --error-plot eval_error.png \
    --json-file eval_runs.json
run eval_one "$BIN/rfir-eval" --path slam_rb_fastslam/path.tum --gt-path $D/rb_rotation.gt.tum \
    --map slam_rb_fastslam/map.txt --gt-map $D/rb_rotation.gt_map.txt \
    --rawlog $D/rb_rotation.rawlog --label 'rb "quoted" \ label'
run eval_ir "$BIN/rfir-eval" --path loc_ir_loop_spots/path.tum \
    --gt-path $D/ir_loop_spots.gt.tum --json-only
run ids_plan "$BIN/rfir-ids" plan --room "0 0 3.2 2.4" --pitch 0.8 --height 1.5 \
    --output ids_plan.txt
run exp_quick "$BIN/rfir-experiments" --quick --rows t41,kidnap --no-figures \
    --config-dir config_ini \
    --revision ref --out-dir exp_quick
rm -f datasets config_ini
cd "$ROOT"
rm -rf "$OUT" && mkdir -p "$(dirname "$OUT")" && mv "$WORK" "$OUT"
[ -n "$REF" ] || exit 0
python3 - "$REF" "$OUT" <<'PY'
import json, os, re, sys
ref, out = sys.argv[1:3]
# Wall-clock measurements: not outputs of the computation.
TIMING = re.compile(r"(^|_)(time_s|seconds|time_ms|step_ms|ms_per_step|total_s)$")
def same(a, b):
    """Equal as JSON values, with the keys in the same order."""
    if isinstance(a, dict) and isinstance(b, dict):
        ka = [k for k in a if not TIMING.search(k)]
        kb = [k for k in b if not TIMING.search(k)]
        return ka == kb and all(same(a[k], b[k]) for k in ka)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b
    return a == b
def parse(text):
    try:
        return True, json.loads(text)
    except ValueError:
        return False, None
def same_text(ta, tb):
    """Bytes, except that lines holding a JSON document compare as values."""
    la, lb = ta.split("\n"), tb.split("\n")
    if len(la) != len(lb):
        return False
    for x, y in zip(la, lb):
        if x == y:
            continue
        okx, vx = parse(x)
        oky, vy = parse(y)
        if not (okx and oky and same(vx, vy)):
            return False
    return True
def files(root):
    for d, _, fs in os.walk(root):
        for f in fs:
            yield os.path.relpath(os.path.join(d, f), root)
bad = 0
a, b = set(files(ref)), set(files(out))
for f in sorted(a ^ b):
    print("only in", ref if f in a else out, f); bad += 1
for f in sorted(a & b):
    # Progress and timings; results.md is results.json's numbers with the
    # timings as a column.
    if f.endswith(".stderr") or f == "exp_quick/results.md":
        continue
    with open(os.path.join(ref, f), "rb") as x, open(os.path.join(out, f), "rb") as y:
        ba, bb = x.read(), y.read()
    if ba == bb:
        continue
    ta, tb = ba.decode("utf-8", "surrogateescape"), bb.decode("utf-8", "surrogateescape")
    if f.endswith(".json"):
        oka, va = parse(ta)
        okb, vb = parse(tb)
        if oka and okb and same(va, vb):
            continue
    elif same_text(ta, tb):
        continue
    print("differs:", f); bad += 1
print(f"compared {len(a & b)} files: {bad} difference(s)")
sys.exit(1 if bad else 0)
PY
