#!/usr/bin/env bash
# Runs the experiments of the papers' tables and figures (rfir-experiments):
# PS-SLAM, PF-SLAM, FastSLAM and dead reckoning on the same simulated data,
# several seeds per row; writes docs/results.md, docs/results.json and
# docs/img/exp_*.png. Builds rfir-experiments first if needed.
#
#   bash scripts/experiments.sh                      # every row, 8 seeds
#   bash scripts/experiments.sh --quick --out-dir /tmp/x # tiny runs (a minute)
#   bash scripts/experiments.sh --rows t41,t42 --seeds 3 --out-dir /tmp/y
#   bash scripts/experiments.sh --jobs 2               # on 2 processes, same results
#   bash scripts/experiments.sh --list               # the row ids
# Environment: RFIR_BUILD_DIR (default ./build), RFIR_JOBS (build jobs).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${RFIR_BUILD_DIR:-build}
JOBS=${RFIR_JOBS:-$(nproc)}

if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$BUILD" -j"$JOBS" --target rfir-experiments

args=("$@")
has_out=0
for a in "${args[@]}"; do
  [ "$a" = "--out-dir" ] || [ "$a" = "--out" ] && has_out=1
  # Their commands would name this script's temporary copy of the INIs.
  if [ "$a" = "--manifest" ] || [ "$a" = "--run" ]; then
    echo "experiments.sh: $a: run $BUILD/bin/rfir-experiments itself" \
      "(with --config-dir config_ini; docs/sweeps.md)" >&2
    exit 2
  fi
done
[ $has_out -eq 1 ] || args+=(--out-dir docs)
# A snapshot of the INIs, as committed (uncommitted edits are not used; files
# git does not track are taken as they are): results.md then matches a commit,
# and a snapshot keeps a long run consistent while the tree is edited.
CFG=$(mktemp -d)
trap 'rm -rf "$CFG"' EXIT
for f in config_ini/*.ini; do
  if git cat-file -e "HEAD:$f" 2>/dev/null; then
    git show "HEAD:$f" > "$CFG/$(basename "$f")"
  else
    cp "$f" "$CFG/"
  fi
done
REV=$(git describe --always --dirty 2>/dev/null || echo unknown)
"$BUILD/bin/rfir-experiments" --config-dir "$CFG" --revision "$REV" \
  --notes apps/rfir-experiments/notes.md "${args[@]}"
