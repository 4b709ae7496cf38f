#!/usr/bin/env bash
# Sets up (scripts/setup.sh), then runs the main job (scripts/demo_run.sh):
# PF-SLAM, PS-SLAM, its --smooth and FastSLAM side by side with the odometry
# on a bundled loop dataset; one table, one picture. Outputs go to out/demo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
OUT=${1:-out/demo}
bash scripts/demo_run.sh "$OUT"
echo "[demo] outputs in $OUT: $(ls "$OUT" | tr '\n' ' ')"
