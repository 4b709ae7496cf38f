#!/usr/bin/env bash
# Runs the IR positioning experiments of thesis chapter 5 in simulation
# (rfir-ir-experiments: rfir_sim data, the rfir-localize code path, rfir_eval
# scores) and writes docs/results_ir.md and docs/img/ir_*.png. Then shows the
# command-line route on one data set: rfir-sim -> rfir-localize (and its
# odometry-only mode) -> outputs in $WORK/cli.
#
#   bash scripts/experiments_ir.sh                  # all, 5 seeds (~20 min on 2 cores)
#   bash scripts/experiments_ir.sh --quick --out-dir /tmp/ir   # smoke test (~3 min)
#   bash scripts/experiments_ir.sh --only config,height --seeds 3
# Environment: RFIR_BUILD_DIR (default ./build), RFIR_JOBS (build jobs),
# RFIR_WORK (scratch, default /tmp/rfir-ir-experiments).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${RFIR_BUILD_DIR:-build}
JOBS=${RFIR_JOBS:-$(nproc)}
WORK=${RFIR_WORK:-/tmp/rfir-ir-experiments}

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD" -j"$JOBS" --target rfir-ir-experiments rfir-sim rfir-localize rfir-ids

args=("$@")
out=""
for ((i = 0; i < ${#args[@]}; i++)); do
  if [ "${args[$i]}" = "--out-dir" ] || [ "${args[$i]}" = "--out" ]; then
    [ $((i + 1)) -lt ${#args[@]} ] || { echo "experiments_ir.sh: --out-dir needs a folder" >&2; exit 2; }
    out=${args[$((i + 1))]}
  fi
done
[ -n "$out" ] || { out=docs; args+=(--out-dir docs); }

# The source tree's INIs, as they are now (even if nothing was rebuilt).
"$BUILD/bin/rfir-ir-experiments" --config-dir config_ini --work-dir "$WORK" \
  --notes apps/rfir-ir-experiments/results_notes.md "${args[@]}"

# The same thing through the programs, on one data set.
cli="$WORK/cli"
mkdir -p "$cli"
"$BUILD/bin/rfir-ids" plan --room "0 0 3.2 2.4" --pitch 0.8 --height 1.5 --output "$cli/planned_emitters.txt"
"$BUILD/bin/rfir-sim" --config config_ini/sim_ir_loop.ini --out-dir "$cli" --name loop --seed 1 -q
echo "[experiments_ir] command-line run (seed 1, lattice room):"
# Each prints its error table on stdout (also in OUT/errors.json).
"$BUILD/bin/rfir-localize" --config config_ini/ir_localize.ini --rawlog "$cli/loop.rawlog" \
  --emitters "$cli/loop.gt_map.txt" --out-dir "$cli/mcl" --seed 1
"$BUILD/bin/rfir-localize" --config config_ini/ir_localize.ini --rawlog "$cli/loop.rawlog" \
  --emitters "$cli/loop.gt_map.txt" --out-dir "$cli/odometry" --odometry-only
echo "[experiments_ir] results: $out/results_ir.md"
