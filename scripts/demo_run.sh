#!/usr/bin/env bash
# The demo's runs (scripts/demo.sh sets up first; the DemoBar test runs this
# alone): PF-SLAM, PS-SLAM (and its offline smoothing, --smooth) and FastSLAM
# with their stock INIs and seed 1 on a bundled dataset where revisits matter
# (60 mm readers, 16 tags/m^2, a rectangle driven three times), scored side by
# side with the odometry alone against the ground truth. Writes into OUT: the
# table (demo_table.txt, also printed), demo.json, demo_paths.png (every path
# and the truth), demo_error_time.png, and each method's outputs in OUT/<m>/.
# Usage: demo_run.sh [OUT [BIN]]   (defaults: out/demo, build/bin)
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=${1:-out/demo}
BIN=${2:-build/bin}
DATA=datasets/rfid_60mm_16tags_loop
SEED=1
mkdir -p "$OUT"
for m in pf ps fastslam; do
  smooth=()
  [ "$m" = ps ] && smooth=(--smooth)
  "$BIN/rfir-slam" --rawlog "$DATA.rawlog" --method "$m" --seed "$SEED" \
    --out-dir "$OUT/$m" "${smooth[@]}" > /dev/null 2> "$OUT/rfir-slam_$m.log"
done
# The table, then one JSON line (also in demo.json): keep the table.
"$BIN/rfir-eval" --gt-path "$DATA.gt.tum" --gt-map "$DATA.gt_map.txt" \
  --rawlog "$DATA.rawlog" \
  --run "PF-SLAM=$OUT/pf/path.tum,$OUT/pf/map.txt" \
  --run "PS-SLAM=$OUT/ps/path.tum,$OUT/ps/map.txt" \
  --run "FastSLAM=$OUT/fastslam/path.tum,$OUT/fastslam/map.txt" \
  --run "PS-SLAM smoothed=$OUT/ps/path_smoothed.tum,$OUT/ps/map_smoothed.txt" \
  --title "rfid_60mm_16tags_loop, seed $SEED" \
  --plot "$OUT/demo_paths.png" --error-plot "$OUT/demo_error_time.png" \
  --json-file "$OUT/demo.json" | sed '$d' > "$OUT/demo_table.txt"
cat "$OUT/demo_table.txt"
