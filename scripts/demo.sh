#!/usr/bin/env bash
# Sets up (scripts/setup.sh), then runs the main job: PS-SLAM on a bundled
# dataset (300 mm readers, 4 tags/m^2, random trajectory), scored against its
# ground truth. Outputs go to out/demo (path.tum, map.txt, path_map.png, ...).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
OUT=${1:-out/demo}
mkdir -p "$OUT"
build/bin/rfir-slam --rawlog datasets/rfid_300mm_4tags_random_90s.rawlog \
  --method ps --seed 1 --out-dir "$OUT"
echo "[demo] outputs in $OUT: $(ls "$OUT" | tr '\n' ' ')"
