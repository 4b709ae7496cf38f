#!/usr/bin/env bash
# Cross-check on an independent simulator: text logs written by
# scripts/crosscheck/textlog_sim.py (not rfir-sim), imported with rfir-import,
# run with the stock INIs of PF-SLAM, PS-SLAM and FastSLAM, scored with
# rfir-eval (dead reckoning from the rawlog's odometry). Prints one markdown
# row per scenario: mean robot / tag error in mm over the random seeds (PF-SLAM also
# after rfir-slam --smooth), and the kidnap resets summed over the random seeds.
#
#   bash scripts/crosscheck.sh [--seeds N] [--out DIR] [--config-dir DIR] [--scenarios a,b]
# --config-dir defaults to config_ini (the stock INIs as in the source tree);
# relative paths are taken from the repository root.
# Needs python3 and a build (build/bin); RFIR_BUILD_DIR overrides the build.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${RFIR_BUILD_DIR:-build}/bin
SEEDS=3; OUT=out/crosscheck; CFGDIR=config_ini; ONLY=""
while [ $# -gt 0 ]; do
  case $1 in
    --seeds|--out|--config-dir|--scenarios)
      [ $# -ge 2 ] || { echo "crosscheck.sh: $1 needs a value" >&2; exit 2; }
      case $1 in
        --seeds) SEEDS=$2 ;; --out) OUT=$2 ;; --config-dir) CFGDIR=$2 ;; --scenarios) ONLY=$2 ;;
      esac
      shift 2 ;;
    -h|--help) sed -n 2,11p "$0"; exit 0 ;;
    *) echo "crosscheck.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
  esac
done
command -v python3 >/dev/null || { echo "crosscheck.sh: needs python3 (apt-get install python3)" >&2; exit 1; }
for p in rfir-import rfir-slam rfir-eval; do
  [ -x "$BIN/$p" ] || { echo "crosscheck.sh: $BIN/$p missing: build first (bash scripts/demo.sh)" >&2; exit 1; }
done
declare -A SC=(
  [loop60]="--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150"
  [async60]="--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --async"
  [slow60]="--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --async --odom-hz 5"
  [epoch60]="--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --t0 1700000000"
  [rect4]="--layout grid4_rect --density 16 --path random --area 4x4 --duration 150"
  [line100]="--layout line3 --density 100 --path random --area 3x3 --duration 150"
  [rand300]="--layout ring8_300 --density 4 --path random --area 5x5 --duration 200"
  [spin300]="--layout ring8_300 --density 4 --path random --area 5x5 --duration 200 --omega 0.3"
  [big300]="--layout ring8_300 --density 4 --path random --area 30x20 --duration 200"
  [kid60]="--layout ring8_60 --density 16 --path loop --area 3x3 --duration 200 --kidnap 90"
  [kid300]="--layout ring8_300 --density 4 --path random --area 5x5 --duration 200 --kidnap 100"
  [faults60]="--layout ring8_60 --density 16 --path loop --area 3x3 --duration 300 --scale 1.02 --drift 0.005 --slips 3 --dead 2,100,160 --ghost 0.005"
  [faults300]="--layout ring8_300 --density 4 --path random --area 5x5 --duration 300 --scale 1.02 --drift 0.005 --slips 3 --dead 2,100,160 --ghost 0.005"
  [lawn300]="--layout ring8_300 --density 4 --path lawn --area 6x6 --duration 300 --scale 0.98 --drift -0.008 --ghost 0.01"
  [rr60]="--layout ring8_60 --density 16 --path loop --area 3x3 --duration 150 --async --odom-hz 25 --rr-hz 5 --lag 0.02"
  [explore60]="--layout ring8_60 --density 16 --path random --area 10x8 --duration 2400"
)
ORDER="loop60 async60 slow60 epoch60 rect4 line100 rand300 spin300 big300 kid60 kid300 faults60 faults300 lawn300 rr60 explore60"
[ -n "$ONLY" ] && ORDER=${ONLY//,/ }
[[ "$SEEDS" =~ ^[1-9][0-9]*$ ]] || { echo "crosscheck.sh: --seeds must be a positive integer, got '${SEEDS}'" >&2; exit 2; }
for m in pf ps fastslam; do
  [ -f "$CFGDIR/slam_$m.ini" ] || { echo "crosscheck.sh: $CFGDIR/slam_$m.ini missing (--config-dir)" >&2; exit 2; }
done
for sc in $ORDER; do
  [ -n "${SC[$sc]:-}" ] || { echo "crosscheck.sh: unknown scenario '$sc' (known: ${!SC[*]})" >&2; exit 2; }
done
mkdir -p "$OUT"
echo "| scenario | PF-SLAM | PS-SLAM | FastSLAM | PF-SLAM --smooth | dead reckoning | resets PF / PS |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for sc in $ORDER; do
  res="$OUT/$sc.results"; : > "$res"; : > "$OUT/$sc.resets"
  for s in $(seq 1 "$SEEDS"); do
    n="$OUT/${sc}_$s"
    # shellcheck disable=SC2086
    python3 scripts/crosscheck/textlog_sim.py --out "$n" --seed "$s" ${SC[$sc]} >/dev/null
    "$BIN/rfir-import" -q --input "$n.txt" --output "$n.rawlog"
    for m in pf ps fastslam; do
      # PF-SLAM also with the offline smoother (its filter outputs are the same)
      sm=(); [ "$m" = pf ] && sm=(--smooth)
      "$BIN/rfir-slam" --rawlog "$n.rawlog" --method "$m" --config "$CFGDIR/slam_$m.ini" \
        --seed "$s" --out-dir "${n}_$m" "${sm[@]}" > "${n}_$m.log" 2>&1 \
        || { echo "crosscheck.sh: rfir-slam failed, see ${n}_$m.log" >&2; exit 1; }
      # dead reckoning once per log, with pf
      dr=(); [ "$m" = pf ] || dr=(--no-odometry)
      "$BIN/rfir-eval" --json-only "${dr[@]}" --rawlog "$n.rawlog" --path "${n}_$m/path.tum" \
        --gt-path "$n.gt.tum" --map "${n}_$m/map.txt" --gt-map "$n.gt_map.txt" \
        | sed "s/^/$m /" >> "$res"
      [ "$m" = pf ] && "$BIN/rfir-eval" --json-only --no-odometry --rawlog "$n.rawlog" \
        --path "${n}_pf/path_smoothed.tum" --gt-path "$n.gt.tum" \
        --map "${n}_pf/map_smoothed.txt" --gt-map "$n.gt_map.txt" | sed "s/^/smooth /" >> "$res"
      python3 -c 'import json,sys; print(sys.argv[1], json.load(open(sys.argv[2]))["kidnap_resets"])' \
        "$m" "${n}_$m/stats.json" >> "$OUT/$sc.resets"
    done
  done
  python3 - "$sc" "$res" "$OUT/$sc.resets" <<'PY'
import json, sys
acc, resets = {}, {}
for line in open(sys.argv[3]):
    m, n = line.split()
    resets[m] = resets.get(m, 0) + int(n)
for line in open(sys.argv[2]):
    m, j = line.split(" ", 1)
    d = json.loads(j)
    acc.setdefault(m, []).append((d["robot"]["mean_dist"], d["tags"]["mean_dist"]))
    if m == "pf":
        acc.setdefault("dr", []).append((d["dead_reckoning"]["mean_dist"], None))
def cell(k):
    v = acc[k]; r = 1e3 * sum(a for a, _ in v) / len(v)
    if v[0][1] is None: return "%.1f" % r
    return "%.1f / %.1f" % (r, 1e3 * sum(b for _, b in v) / len(v))
print("| %s | %s | %s | %s | %s | %s | %d / %d |" % (sys.argv[1], cell("pf"), cell("ps"), cell("fastslam"),
                                               cell("smooth"), cell("dr"), resets.get("pf", 0),
                                               resets.get("ps", 0)))
PY
done
