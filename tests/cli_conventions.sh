#!/usr/bin/env bash
# Every program in BIN (every rfir-* there, found at run time: a new program
# without an entry below fails) is run, each time in a fresh empty working
# directory, with --help, --version, an unknown option, malformed numbers and
# a missing required option. Checks the exit codes (0, 0, then non-zero), that
# a bad number is reported naming its option, and that nothing was written:
# the directory stays empty and no file under SRC/docs changes.
#   bash tests/cli_conventions.sh BIN SRC
set -uo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
DS=$SRC/datasets
CFG=$SRC/config_ini
root=$(mktemp -d "${TMPDIR:-/tmp}/rfir_cli_XXXXXX")
trap 'rm -rf "$root"' EXIT
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# Per program: a command line with every required option, which would do real
# work and write into the working directory (the base of the bad-value runs);
# an integer option, a real-valued option ('-' for none); a command line
# missing a required option.
declare -A BASE INT REAL MISSING
BASE[rfir-sim]="--config $CFG/sim_kidnap.ini --out-dir out"
INT[rfir-sim]=--seed
REAL[rfir-sim]=-
MISSING[rfir-sim]="--config $CFG/sim_kidnap.ini"

BASE[rfir-import]="--input $SRC/tests/data/textlog/full.txt --output out.rawlog"
INT[rfir-import]=-
REAL[rfir-import]=-
MISSING[rfir-import]="--input $SRC/tests/data/textlog/full.txt"

BASE[rfir-slam]="--rawlog $DS/rfid_60mm_16tags_loop.rawlog --out-dir out --method odometry"
INT[rfir-slam]=--seed
REAL[rfir-slam]=--start
MISSING[rfir-slam]="--rawlog $DS/rfid_60mm_16tags_loop.rawlog"

BASE[rfir-localize]="--rawlog $DS/ir_loop_spots.rawlog --out-dir out --odometry-only"
INT[rfir-localize]=--seed
REAL[rfir-localize]=-
MISSING[rfir-localize]="--out-dir out"

BASE[rfir-eval]="--path $DS/rfid_kidnap.gt.tum --gt-path $DS/rfid_kidnap.gt.tum --json-file out.json"
INT[rfir-eval]=--segments
REAL[rfir-eval]=-
MISSING[rfir-eval]="--json-file out.json"

BASE[rfir-ids]="plan --room 0,0,3.2,2.4 --output out.txt"
INT[rfir-ids]=--unique-codes
REAL[rfir-ids]=--pitch
MISSING[rfir-ids]="--output out.txt"

BASE[rfir-experiments]="--quick --rows t31_16 --out-dir out"
INT[rfir-experiments]=--seeds
REAL[rfir-experiments]=-
MISSING[rfir-experiments]="--quick --rows t31_16"

BASE[rfir-ir-experiments]="--quick --only config --out-dir out"
INT[rfir-ir-experiments]=--seeds
REAL[rfir-ir-experiments]=-
MISSING[rfir-ir-experiments]="--quick --only config"

BASE[rfir-bench]="--quick --no-realtime --out-dir out"
INT[rfir-bench]=--updates
REAL[rfir-bench]=--realtime-seconds
MISSING[rfir-bench]=-

docs_hash() { (cd "$SRC" && find docs -type f -print0 | sort -z | xargs -0 sha256sum); }
before=$(docs_hash)

# run NAME EXPECT ARGS...: EXPECT is 0 or "nonzero"; the run is in a fresh
# empty directory; prints the failure and returns 1 on a mismatch.
last_err=""
run() {
  local prog=$1 expect=$2
  shift 2
  local wd
  wd=$(mktemp -d "$root/wd_XXXXXX")
  local code
  (cd "$wd" && timeout 60 "$BIN/$prog" "$@" >"$root/stdout" 2>"$root/stderr")
  code=$?
  last_err=$(cat "$root/stderr")
  local what="$prog $*"
  if [ "$expect" = 0 ] && [ $code -ne 0 ]; then
    fail "$what: exit $code, expected 0: $(head -c 400 "$root/stderr")"
  elif [ "$expect" != 0 ] && { [ $code -eq 0 ] || [ $code -ge 124 ]; }; then
    fail "$what: exit $code, expected an error exit (1 or 2)"
  fi
  if [ -n "$(ls -A "$wd")" ]; then
    fail "$what: wrote into the working directory: $(ls -A "$wd" | head -5 | tr '\n' ' ')"
  fi
  rm -rf "$wd"
}

ints=(abc -3 1.5 5e2 nan "" 99999999999999999999999)
reals=(abc nan -inf 1e400)
n=0
for exe in "$BIN"/rfir-*; do
  [ -f "$exe" ] && [ -x "$exe" ] || continue
  prog=$(basename "$exe")
  n=$((n + 1))
  if [ -z "${BASE[$prog]+x}" ]; then
    fail "$prog: no entry in tests/cli_conventions.sh (every program must have one)"
    continue
  fi
  read -r -a base <<<"${BASE[$prog]}"
  # rfir-ids' --room is one argument with blanks; written with commas above.
  for i in "${!base[@]}"; do [ "${base[$i]}" = 0,0,3.2,2.4 ] && base[$i]="0 0 3.2 2.4"; done
  run "$prog" 0 --help
  grep -q -i "usage" "$root/stdout" || fail "$prog --help: no usage on stdout"
  run "$prog" 0 --version
  run "$prog" nonzero "${base[@]}" --no-such-option
  run "$prog" nonzero "${base[@]}" -Z
  if [ "${INT[$prog]}" != - ]; then
    for v in "${ints[@]}"; do
      run "$prog" nonzero "${base[@]}" "${INT[$prog]}" "$v"
      grep -q -- "${INT[$prog]}" <<<"$last_err" ||
        fail "$prog ${INT[$prog]} '$v': the message does not name the option: $last_err"
    done
  fi
  if [ "${REAL[$prog]}" != - ]; then
    for v in "${reals[@]}"; do
      val=$v
      [ "${REAL[$prog]}" = --start ] && val="0 0 $v"
      run "$prog" nonzero "${base[@]}" "${REAL[$prog]}" "$val"
      grep -q -- "${REAL[$prog]}" <<<"$last_err" ||
        fail "$prog ${REAL[$prog]} '$val': the message does not name the option: $last_err"
    done
  fi
  if [ "${MISSING[$prog]}" != - ]; then
    read -r -a missing <<<"${MISSING[$prog]}"
    run "$prog" nonzero "${missing[@]}"
  fi
done

[ $n -ge 9 ] || fail "found only $n programs in $BIN"
[ "$(docs_hash)" = "$before" ] || fail "a file under $SRC/docs changed"
echo "cli_conventions: $n programs, $failures failure(s)"
[ $failures -eq 0 ]
