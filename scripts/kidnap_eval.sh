#!/usr/bin/env bash
# The kidnap detector measured as a classifier (docs/slam.md, "Kidnapping"):
# false resets per hour of data on the stock simulator INIs without a
# kidnapping, and on the kidnap INIs the detection delay (first reset after
# the put-down) and the recovery time (from the put-down until the robot
# error stays under 2 x the same run's error without the kidnapping for 5 s;
# and, second, under 2 x the error the run had when it was last at the same
# place, the error a robot relocalised against its own map comes back to).
#
#   bash scripts/kidnap_eval.sh                      # 3 seeds, pf and ps
#   bash scripts/kidnap_eval.sh --seeds 1 --methods pf --out-dir /tmp/k
#   bash scripts/kidnap_eval.sh --set kidnap.enabled=false   # rfir-slam --set
#   bash scripts/kidnap_eval.sh --slam-ini-dir /old/config_ini  # another build's INIs
# Environment: RFIR_BIN (default ./build/bin).
set -euo pipefail
cd "$(dirname "$0")/.."
BIN=${RFIR_BIN:-build/bin}
seeds=3
methods="pf ps"
out=""
sets=()
slamIni=config_ini
while (($#)); do
  case "$1" in
    --seeds) seeds="$2"; shift 2 ;;
    --methods) methods="$2"; shift 2 ;;
    --out-dir) out="$2"; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    --slam-ini-dir) slamIni="$2"; shift 2 ;;
    *) echo "kidnap_eval.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[[ -n "$out" ]] || out=$(mktemp -d /tmp/kidnap_eval.XXXXXX)
mkdir -p "$out"
for b in rfir-sim rfir-slam; do
  [[ -x "$BIN/$b" ]] || { echo "kidnap_eval.sh: $BIN/$b not built" >&2; exit 2; }
done

normal="bench_floor_30x20 sim_rfid_300mm_4tags_random sim_rfid_300mm_4tags_random_biased
  sim_rfid_300mm_lawnmower sim_rfid_300mm_rotation sim_rfid_60mm_16tags_loop sim_rfid_60mm_16tags_loop_biased
  sim_rfid_60mm_16tags_random sim_rfid_60mm_100tags_loop sim_rfid_60mm_100tags_random
  sim_rb_rotation sim_rb_norotation"
kidnap="sim_kidnap sim_kidnap_300mm"

# One simulated log per INI and seed (and its unkidnapped twin), then each
# method on it; stats.json lists the reset times.
run() {  # ini seed tag [sim --set ...]
  local ini=$1 seed=$2 tag=$3; shift 3
  local d="$out/$tag/s$seed"
  [[ -f "$d/$ini.rawlog" ]] ||
    "$BIN/rfir-sim" --config "config_ini/$ini.ini" --out-dir "$d" --seed "$seed" -q "$@"
  for m in $methods; do
    "$BIN/rfir-slam" --rawlog "$d/$ini.rawlog" --config "$slamIni/slam_$m.ini" --seed "$seed" \
      --out-dir "$d/$m" -q ${sets[@]+"${sets[@]}"}
  done
}
for s in $(seq 1 "$seeds"); do
  for ini in $normal; do run "$ini" "$s" "$ini"; done
  for ini in $kidnap; do
    run "$ini" "$s" "$ini"
    run "$ini" "$s" "${ini}_ref" --set kidnap.enabled=false
  done
done

python3 - "$out" "$seeds" "$methods" "$normal" "$kidnap" <<'PY' | tee "$out/table.md"
import json, math, sys, re, configparser
out, seeds, methods = sys.argv[1], int(sys.argv[2]), sys.argv[3].split()
normal, kidnap = sys.argv[4].split(), sys.argv[5].split()

def tum(p):
    rows = []
    for l in open(p):
        f = l.split()
        if f and not l.startswith('#'):
            rows.append((float(f[0]), float(f[1]), float(f[2])))
    return rows

def errors(d, ini, m):
    gt = {round(t, 3): (x, y) for t, x, y in tum(f"{d}/{ini}.gt.tum")}
    e = []
    for t, x, y in tum(f"{d}/{m}/path.tum"):
        g = gt.get(round(t, 3))
        if g: e.append((t, math.hypot(x - g[0], y - g[1])))
    return e

def place_errors(gt, e, T):
    """For each time after the kidnapping, the error the same run had when it
    was last at that place before it (nearest ground-truth position, within
    0.1 m; None if it never was): a robot put down where it has been is
    relocalised against the tags it mapped there, so this is the error it
    can be expected to come back to."""
    e = dict((round(t, 3), v) for t, v in e)
    before = [(t, x, y) for t, x, y in gt if t < T and round(t, 3) in e]
    out = {}
    for t, x, y in gt:
        if t < T: continue
        best = min(before, key=lambda b: (b[1] - x) ** 2 + (b[2] - y) ** 2)
        if math.hypot(best[1] - x, best[2] - y) <= 0.1:
            out[round(t, 3)] = e[round(best[0], 3)]
    return out

def recovery(e, down, bound):
    """From the put-down until every error for 5 s is under bound(t, v)."""
    for i, (t, _) in enumerate(e):
        if t < down: continue
        w = [(tt, v) for tt, v in e[i:] if tt <= t + 5]
        if all(v < bound(tt) for tt, v in w): return t - down
    return None

def resets(d, m):
    return json.load(open(f"{d}/{m}/stats.json"))["kidnap_reset_times_s"]

def closures(d, m):
    return json.load(open(f"{d}/{m}/stats.json")).get("loop_closure_times_s", [])

print("| method | false resets / h (normal INIs) | data (h) | INIs with a false reset | loop closures by smoothing |")
print("| --- | --- | --- | --- | --- |")
for m in methods:
    n, hours, bad, lc = 0, 0.0, set(), []
    for ini in normal:
        for s in range(1, seeds + 1):
            d = f"{out}/{ini}/s{s}"
            r = resets(d, m)
            e = errors(d, ini, m)
            n += len(r)
            c = closures(d, m)
            if c: lc.append(f"{ini} seed {s} ({len(c)})")
            hours += (e[-1][0] - e[0][0]) / 3600
            if r: bad.add(f"{ini} ({len(r)})" if seeds == 1 else ini)
    print(f"| {m} | {n / hours:.1f} ({n} resets) | {hours:.2f} | {', '.join(sorted(bad)) or '-'} | "
          f"{', '.join(lc) or '-'} |")
print()
print("| method | kidnap INI | seed | false resets before | detection delay (s) | recovery (s) | recovery to the same place's error (s) | error after, mm (unkidnapped) |")
print("| --- | --- | --- | --- | --- | --- | --- | --- |")
for ini in kidnap:
    c = configparser.ConfigParser(inline_comment_prefixes=None)
    c.read(f"config_ini/{ini}.ini")
    # [kidnap] time counts from the run's start, the clock from start_time
    # (1 s unless the INI says otherwise: docs/simulator.md).
    t0 = float(c["simulation"].get("start_time", "1")) if "simulation" in c else 1.0
    T = t0 + float(c["kidnap"]["time"]); down = T + float(c["kidnap"]["carry_time"])
    for m in methods:
        for s in range(1, seeds + 1):
            d, dr = f"{out}/{ini}/s{s}", f"{out}/{ini}_ref/s{s}"
            r = resets(d, m)
            e, er = errors(d, ini, m), errors(dr, ini, m)
            ref = sum(v for t, v in er if t >= down) / max(1, sum(1 for t, _ in er if t >= down))
            after = [v for t, v in e if t >= down + 15]
            refAfter = [v for t, v in er if t >= down + 15]
            det = [t for t in r if t >= T]
            rec = recovery(e, down, lambda t: 2 * ref)
            # Where the robot was never before (no pose within 0.1 m), no bound.
            place = place_errors(tum(f"{d}/{ini}.gt.tum"), e, T)
            recPlace = recovery(e, down, lambda t: 2 * place.get(round(t, 3), math.inf))
            f = lambda v: "none" if v is None else f"{v:.1f}"
            print(f"| {m} | {ini} | {s} | {sum(1 for t in r if t < T)} | "
                  f"{f(det[0] - down if det else None)} ({len(det)} resets"
                  f"{f', {len(closures(d, m))} closures' if closures(d, m) else ''}) | {f(rec)} | "
                  f"{f(recPlace)} | "
                  f"{1e3 * sum(after) / len(after):.0f} ({1e3 * sum(refAfter) / len(refAfter):.0f}) |")
PY
echo "kidnap_eval.sh: outputs in $out" >&2
