#!/usr/bin/env bash
# Runs the full benchmark (rfir-bench) and writes its results into the docs:
# docs/img/bench_time_vs_M.png, bench_time_vs_N.png, bench_memory_vs_N.png,
# the results section of docs/benchmark.md (between
# the RESULTS markers). Builds rfir-bench first if needed. The full run sweeps
# N up to 1,000,000 tags: building those states takes several minutes per
# case and round, and needs about 8 GB of free memory (PS-SLAM's 1M-tag state;
# FastSLAM's 5.8 GB at N = 100,000 is freed before).
#
#   bash scripts/bench.sh                 # full run (rfir-bench --full), updates docs/
#   bash scripts/bench.sh --quick         # smoke run (seconds), docs untouched
#   bash scripts/bench.sh --out-dir /tmp/b  # full run, results in /tmp/b only
# Other options are passed to rfir-bench (see rfir-bench --help); without
# --quick the script passes --full.
# Environment: RFIR_BUILD_DIR (default ./build), RFIR_JOBS (build jobs),
# RFIR_BENCH_NO_BUILD=1 (use the rfir-bench already built).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${RFIR_BUILD_DIR:-build}
JOBS=${RFIR_JOBS:-$(nproc)}

out=""
quick=0
args=()
while (($#)); do
  case "$1" in
    --out-dir|--out) out="$2"; shift 2 ;;
    --quick) quick=1; args+=(--quick); shift ;;
    --full) shift ;;
    *) args+=("$1"); shift ;;
  esac
done
[ $quick -eq 1 ] || args+=(--full)

if [ "${RFIR_BENCH_NO_BUILD:-0}" != 1 ]; then
  if [ ! -f "$BUILD/CMakeCache.txt" ]; then
    cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=Release
  fi
  cmake --build "$BUILD" -j"$JOBS" --target rfir-bench
fi

update_docs=0
if [ -z "$out" ]; then
  if [ $quick -eq 1 ]; then out=$(mktemp -d /tmp/rfir_bench_XXXXXX); else out=docs; update_docs=1; fi
fi
mkdir -p "$out/img"
tmp=$(mktemp -d /tmp/rfir_bench_run_XXXXXX)
trap 'rm -rf "$tmp"' EXIT

# The source tree's INIs, as they are now (even if rfir-bench was not rebuilt).
"$BUILD/bin/rfir-bench" --config-dir config_ini --out-dir "$tmp" "${args[@]}" | tee "$tmp/table.txt"

cp "$tmp"/bench_*.png "$out/img/"
if [ $update_docs -eq 1 ]; then
  cp "$tmp/benchmark.json" "$BUILD/benchmark.json"
  doc=docs/benchmark.md
  grep -q '^<!-- RESULTS BEGIN' "$doc" || { echo "[bench] $doc has no RESULTS markers" >&2; exit 1; }
  # Replace what lies between the markers with the new tables.
  awk -v res="$tmp/results.md" '
    /^<!-- RESULTS BEGIN/ { print; while ((getline l < res) > 0) print l; skip = 1; next }
    /^<!-- RESULTS END/ { skip = 0 }
    !skip { print }' "$doc" > "$tmp/benchmark.md"
  cp "$tmp/benchmark.md" "$doc"
  echo "[bench] wrote $doc and docs/img/bench_*.png; JSON in $BUILD/benchmark.json"
else
  cp "$tmp/benchmark.json" "$out/benchmark.json"
  cp "$tmp/results.md" "$out/results.md"
  cp "$tmp/table.txt" "$out/table.txt"
  echo "[bench] results in $out (results.md, table.txt, benchmark.json, img/)"
fi
