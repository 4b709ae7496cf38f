#!/usr/bin/env bash
# IR cross-check on an independent simulator: text logs written by
# scripts/crosscheck/ir_textlog_sim.py (not rfir-sim), imported with
# rfir-import, localized with rfir-localize and the stock ir_localize.ini.
# Prints one markdown row per scenario and seed: robot error (mm) from the
# first estimate (the first unique ID) on, mean and max, and the same from
# 10 s later (after the start transient, docs/ir.md).
#
#   bash scripts/crosscheck_ir.sh [--seeds N] [--out DIR]
# Needs python3 and a build (build/bin); RFIR_BUILD_DIR overrides the build.
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${RFIR_BUILD_DIR:-build}/bin
SEEDS=3; OUT=out/crosscheck_ir
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    --seeds|--out)
      [ $# -ge 2 ] || { echo "crosscheck_ir.sh: $1 needs a value" >&2; exit 2; }
      case "$1" in --seeds) SEEDS=$2 ;; --out) OUT=$2 ;; esac; shift 2 ;;
    *) echo "crosscheck_ir.sh: unknown option '$1' (try --help)" >&2; exit 2 ;;
  esac
done
[[ "$SEEDS" =~ ^[1-9][0-9]*$ ]] || { echo "crosscheck_ir.sh: --seeds must be a positive integer, got '${SEEDS}'" >&2; exit 2; }
command -v python3 >/dev/null || { echo "crosscheck_ir.sh: needs python3" >&2; exit 1; }
for p in rfir-import rfir-localize; do
  [ -x "$BIN/$p" ] || { echo "crosscheck_ir.sh: $BIN/$p missing: build first (bash scripts/demo.sh)" >&2; exit 1; }
done
declare -A SC=(
  [clean]=""
  [faults]="--failed 2 --moved 0.25 --wrong-code 0.01 --volt-outliers 0.005"
)
mkdir -p "$OUT"
echo "| scenario | seed | first estimate (s) | mean / max (mm) | from 10 s later: mean / max (mm) |"
echo "| --- | --- | --- | --- | --- |"
for sc in clean faults; do
  for s in $(seq 1 "$SEEDS"); do
    n="$OUT/${sc}_$s"
    # shellcheck disable=SC2086
    python3 scripts/crosscheck/ir_textlog_sim.py --out "$n" --seed "$s" ${SC[$sc]} >/dev/null
    "$BIN/rfir-import" -q --input "$n.txt" --output "$n.rawlog"
    "$BIN/rfir-localize" -q --rawlog "$n.rawlog" --emitters "$n.emitters.txt" \
      --config config_ini/ir_localize.ini --seed "$s" --out-dir "${n}_loc" \
      || { echo "crosscheck_ir.sh: rfir-localize failed on $n" >&2; exit 1; }
    python3 - "$sc" "$s" "${n}_loc/path.tum" "$n.gt.tum" <<'PY'
import bisect, math, sys
def load(p):
    out = []
    for l in open(p):
        if l.startswith("#") or not l.strip(): continue
        v = [float(x) for x in l.split()]
        out.append((v[0], v[1], v[2]))
    return out
est, gt = load(sys.argv[3]), load(sys.argv[4])
ts = [g[0] for g in gt]
err = []
for t, x, y in est:
    g = gt[min(bisect.bisect_left(ts, t - 1e-6), len(gt) - 1)]
    err.append((t, 1e3 * math.hypot(x - g[1], y - g[2])))
late = [e for t, e in err if t >= err[0][0] + 10]
print("| %s | %s | %.1f | %.1f / %.0f | %.1f / %.0f |" % (
    sys.argv[1], sys.argv[2], err[0][0], sum(e for _, e in err) / len(err),
    max(e for _, e in err), sum(late) / len(late), max(late)))
PY
  done
done
