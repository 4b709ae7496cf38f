#!/usr/bin/env bash
# Builds the libFuzzer harnesses of fuzz/ with clang (ASan + UBSan) in
# build-fuzz and runs each for SECONDS (default 60) from its starting corpus in
# fuzz/corpus/<target>. Exits non-zero on any crash, leak, timeout (10 s per
# input) or memory blow-up (2 GB resident, or one allocation above 256 MB); the
# input is left in
# build-fuzz/artifacts/<target>/ and the log in build-fuzz/logs/<target>.log.
#   scripts/fuzz.sh [SECONDS]
#   RFIR_FUZZ_TARGETS="textlog tum" scripts/fuzz.sh 30   (a subset)
# The mutation sequence is fixed by RFIR_FUZZ_SEED (default 1): a slower
# machine runs a prefix of the inputs a faster one ran, so the CI smoke does
# not meet new inputs by chance.
set -euo pipefail
cd "$(dirname "$0")/.."
SECS=${1:-60}
BUILD=${RFIR_FUZZ_BUILD:-build-fuzz}
TARGETS=${RFIR_FUZZ_TARGETS:-textlog import rawlog ini mapfile tum plaintext}
JOBS=${RFIR_JOBS:-$(nproc)}
SEED=${RFIR_FUZZ_SEED:-1}
if ! command -v clang++ >/dev/null; then
  echo "[fuzz] clang++ not found: run scripts/setup.sh (installs clang, libclang-rt-14-dev)" >&2
  exit 2
fi
CC=clang CXX=clang++ cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release \
  -DRFIR_FUZZ=ON -DRFIR_BUILD_TESTS=OFF >/dev/null
cmake --build "$BUILD" -j"$JOBS" --target $(printf 'fuzz_%s ' $TARGETS)

ROOT=$(pwd)
export LSAN_OPTIONS="suppressions=$ROOT/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="suppressions=$ROOT/tests/sanitizers/ubsan.supp:print_stacktrace=1:halt_on_error=1"
# The harnesses' scratch files (a crashing run cannot remove its own).
SCRATCH=$(mktemp -d "$([ -d /dev/shm ] && echo /dev/shm || echo /tmp)/rfir-fuzz.XXXXXX")
trap 'rm -rf "$SCRATCH"' EXIT
export RFIR_FUZZ_TMP="$SCRATCH"
failed=()
for t in $TARGETS; do
  work="$BUILD/corpus/$t" art="$BUILD/artifacts/$t" log="$BUILD/logs/$t.log"
  mkdir -p "$work" "$art" "$(dirname "$log")"
  echo "[fuzz] $t: ${SECS}s"
  # New inputs go to the work corpus (first folder); the starting corpus stays
  # as it is.
  # Inputs are a few KB: one allocation above 256 MB is an unbounded read.
  if "$BUILD/bin/fuzz_$t" -max_total_time="$SECS" -seed="$SEED" -rss_limit_mb=2048 -timeout=10 \
      -malloc_limit_mb=256 \
      -close_fd_mask=3 -print_final_stats=1 -artifact_prefix="$ROOT/$art/" \
      "$ROOT/$work" "$ROOT/fuzz/corpus/$t" >"$log" 2>&1; then
    grep -E '^stat::number_of_executed_units|^stat::average_exec_per_sec' "$log" |
      tr '\n' ' ' | sed "s/^/[fuzz] $t: /; s/\$/\n/"
  else
    echo "[fuzz] $t: FAILED (log $log, input in $art/):" >&2
    grep -E 'ERROR|SUMMARY|==[0-9]+==|runtime error|property violated|round trip' "$log" | head -20 >&2
    failed+=("$t")
  fi
done
if ((${#failed[@]})); then
  echo "[fuzz] failed: ${failed[*]}" >&2
  exit 1
fi
echo "[fuzz] all targets ran ${SECS}s without a crash"
