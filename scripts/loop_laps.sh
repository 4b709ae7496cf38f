#!/usr/bin/env bash
# Where the 60 mm loop's error comes from: rfir-sim on
# config_ini/sim_rfid_60mm_16tags_loop.ini (3 laps), PF-SLAM, PS-SLAM and
# FastSLAM with their stock INIs, rfir-eval --segments 3 (one window per lap).
# Prints a markdown table: mean robot error per lap and over the run, mm,
# averaged over the random seeds, with dead reckoning.
#
#   bash scripts/loop_laps.sh [--seeds N] [--out-dir DIR]
# Runs the stock INIs as they are in config_ini/ (not the build copy);
# relative paths are taken from the repository root.
# Needs python3 and a build (build/bin); RFIR_BUILD_DIR overrides the build.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${RFIR_BUILD_DIR:-build}/bin
SEEDS=12; OUT=out/loop_laps
while [ $# -gt 0 ]; do
  case $1 in
    --seeds|--out-dir|--out)
      [ $# -ge 2 ] || { echo "loop_laps.sh: $1 needs a value" >&2; exit 2; }
      [ "$1" = --seeds ] && SEEDS=$2 || OUT=$2
      shift 2 ;;
    -h|--help) sed -n 2,11p "$0"; exit 0 ;;
    *) echo "loop_laps.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
  esac
done
[[ "$SEEDS" =~ ^[1-9][0-9]*$ ]] || { echo "loop_laps.sh: --seeds must be a positive integer, got '${SEEDS}'" >&2; exit 2; }
command -v python3 >/dev/null || { echo "loop_laps.sh: needs python3 (apt-get install python3)" >&2; exit 1; }
for p in rfir-sim rfir-slam rfir-eval; do
  [ -x "$BIN/$p" ] || { echo "loop_laps.sh: $BIN/$p missing: build first (bash scripts/demo.sh)" >&2; exit 1; }
done
INI=config_ini/sim_rfid_60mm_16tags_loop.ini
mkdir -p "$OUT"
for s in $(seq 1 "$SEEDS"); do
  echo "loop_laps.sh: seed $s of $SEEDS" >&2
  d="$OUT/seed$s"
  "$BIN/rfir-sim" -q --config "$INI" --out-dir "$d" --name run --seed "$s" >/dev/null
  for m in pf ps fastslam; do
    # The source tree's stock INIs (the build's copy is refreshed only by a build).
    "$BIN/rfir-slam" --rawlog "$d/run.rawlog" --out-dir "$d/$m" --method "$m" \
      --config "config_ini/slam_$m.ini" --seed "$s" > "$d/$m.log" 2>&1 \
      || { echo "loop_laps.sh: rfir-slam failed, see $d/$m.log" >&2; exit 1; }
    "$BIN/rfir-eval" --path "$d/$m/path.tum" --gt-path "$d/run.gt.tum" --rawlog "$d/run.rawlog" \
      --segments 3 --json-only --label "$m" > "$d/$m.json"
  done
done
python3 - "$OUT" "$SEEDS" <<'PY'
import json, sys
out, n = sys.argv[1], int(sys.argv[2])
rows = {}
for s in range(1, n + 1):
    for m in ("pf", "ps", "fastslam"):
        j = json.load(open(f"{out}/seed{s}/{m}.json"))
        rows.setdefault(m, []).append(j["segments"]["robot_mean_dist"] + [j["robot"]["mean_dist"]])
        if m == "pf":
            rows.setdefault("dr", []).append(
                j["segments"]["dead_reckoning_mean_dist"] + [j["dead_reckoning"]["mean_dist"]])
names = {"pf": "PF-SLAM", "ps": "PS-SLAM", "fastslam": "FastSLAM 1.0", "dr": "dead reckoning"}
print(f"| robot error, mm, {n} seeds | lap 1 | lap 2 | lap 3 | run |")
print("| --- | ---: | ---: | ---: | ---: |")
for m in ("pf", "ps", "fastslam", "dr"):
    cols = [sum(c) / len(c) * 1e3 for c in zip(*rows[m])]
    print(f"| {names[m]} | " + " | ".join(f"{v:.1f}" for v in cols) + " |")
PY
