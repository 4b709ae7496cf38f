#!/usr/bin/env bash
# Regenerates the bundled simulated datasets in datasets/ with build/bin/rfir-sim
# (build it first: scripts/setup.sh, or cmake --build build --target rfir-sim).
# Fixed seeds: the same build writes byte-identical files.
#   bash scripts/make_datasets.sh [OUT_DIR]      (default: datasets)
set -euo pipefail
cd "$(dirname "$0")/.."
SIM="${RFIR_SIM:-build/bin/rfir-sim}"
OUT="${1:-datasets}"
if [ ! -x "$SIM" ]; then
  echo "error: $SIM not found: build rfir-sim first (bash scripts/setup.sh)" >&2
  exit 1
fi
mkdir -p "$OUT"

# name | INI | seed | extra --set overrides
run() {
  local name="$1" ini="$2" seed="$3"
  shift 3
  local sets=()
  for s in "$@"; do sets+=(--set "$s"); done
  echo "[datasets] $name" >&2
  "$SIM" --config "config_ini/$ini.ini" --out-dir "$OUT" --seed "$seed" --name "$name" -q \
    "${sets[@]}"
}

# 300 mm squares, 4 tags/m^2, random path, 90 s of robot time.
run rfid_300mm_4tags_random_90s sim_rfid_300mm_4tags_random 1 simulation.max_duration=90
# PF-SLAM: 60 mm squares, 16 tags/m^2, rectangular loop x3 (180 s).
run rfid_60mm_16tags_loop sim_rfid_60mm_16tags_loop 1
# Kidnapping: the same loop, carried at 100 s back to where it was at 20 s.
run rfid_kidnap sim_kidnap 1
# Range-and-bearing sensor, rectangle with turns at the corners.
run rb_rotation sim_rb_rotation 1
# IR positioning: decoded readings, loop x3 with 70 marked spots.
run ir_loop_spots sim_ir_loop 1
# IR receivers' raw windows (8 kHz, 800 samples), 15 s.
run ir_raw_15s sim_ir_raw 1 simulation.max_duration=15

ls -l "$OUT" >&2
