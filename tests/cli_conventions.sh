#!/usr/bin/env bash
# Every program in BIN (every rfir-* there, found at run time: a new program
# without an entry below fails) is run, each time in a fresh empty working
# directory, with --help, --version, no argument, an unknown option, malformed
# numbers and a missing required option. Checks the exit codes (0, 0, then 2:
# every command-line error), that a bad number is reported naming its option,
# and that nothing was written: the directory stays empty and no file under
# SRC/docs changes. Then the other command-line errors (an unknown value, an
# unknown stock INI, an unknown subcommand, ...: exit 2 naming the option; an
# INI file's own bad value: exit 1 naming the file), bad --set edits in every
# program that takes --set (exit 2, the message names the edit), the output
# names rfir-slam and rfir-localize share, -q on short real runs (nothing on
# stdout, nothing but warnings on stderr), and --set / --seed of the
# experiment programs on tiny real runs.
#   bash tests/cli_conventions.sh BIN SRC [basic|options|all]
# basic: the first part; options: the rest (two ctests, run in parallel).
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

BASE[rfir-plain-ps]="--input $SRC/tests/data/textlog/rfid_short.txt --output out.tum"
INT[rfir-plain-ps]=--particles
REAL[rfir-plain-ps]=-
MISSING[rfir-plain-ps]="--output out.tum"

BASE[rfir-bench]="--quick --no-realtime --out-dir out"
INT[rfir-bench]=--updates
REAL[rfir-bench]=--realtime-seconds
MISSING[rfir-bench]=-

docs_hash() { (cd "$SRC" && find docs -type f -print0 | sort -z | xargs -0 sha256sum); }
before=$(docs_hash)

# run NAME EXPECT ARGS...: EXPECT is an exit code (0, 1; 2 is every
# command-line error); the run is in a fresh empty directory; prints the
# failure on a mismatch.
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
  if [ $code -ne "$expect" ]; then
    fail "$what: exit $code, expected $expect: $(head -c 400 "$root/stderr")"
  fi
  if [ -n "$(ls -A "$wd")" ]; then
    fail "$what: wrote into the working directory: $(ls -A "$wd" | head -5 | tr '\n' ' ')"
  fi
  rm -rf "$wd"
}

basic_checks() {
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
    run "$prog" 2
    grep -q "^usage:" <<<"$last_err" || fail "$prog without arguments: no usage on stderr"
    run "$prog" 2 "${base[@]}" --no-such-option
    grep -q -- "--no-such-option" <<<"$last_err" ||
      fail "$prog --no-such-option: the message does not name it: $last_err"
    run "$prog" 2 "${base[@]}" -Z
    if [ "${INT[$prog]}" != - ]; then
      for v in "${ints[@]}"; do
        run "$prog" 2 "${base[@]}" "${INT[$prog]}" "$v"
        grep -q -- "${INT[$prog]}" <<<"$last_err" ||
          fail "$prog ${INT[$prog]} '$v': the message does not name the option: $last_err"
      done
    fi
    if [ "${REAL[$prog]}" != - ]; then
      for v in "${reals[@]}"; do
        val=$v
        [ "${REAL[$prog]}" = --start ] && val="0 0 $v"
        run "$prog" 2 "${base[@]}" "${REAL[$prog]}" "$val"
        grep -q -- "${REAL[$prog]}" <<<"$last_err" ||
          fail "$prog ${REAL[$prog]} '$val': the message does not name the option: $last_err"
      done
    fi
    if [ "${MISSING[$prog]}" != - ]; then
      read -r -a missing <<<"${MISSING[$prog]}"
      run "$prog" 2 "${missing[@]}"
    fi
  done
  [ $n -ge 9 ] || fail "found only $n programs in $BIN"
  value_checks
}

# value_checks: command-line errors past the option names, each PROGRAM ARGS
# with a text the message must hold: exit 2, nothing written. Then the same
# key made bad in an INI file: exit 1, naming the file.
value_checks() {
  local R=$DS/rfid_60mm_16tags_loop.rawlog IR=$DS/ir_loop_spots.rawlog
  local GT=$DS/rfid_kidnap.gt.tum
  local cases=(
    "--method|rfir-slam --rawlog $R --out-dir out --method foo"
    "--config: 'nosuch'|rfir-slam --rawlog $R --out-dir out --config nosuch"
    "--set slam.robot_particles=abc: [slam] robot_particles|rfir-slam --rawlog $R --out-dir out --set slam.robot_particles=abc"
    "--set slam.no_such_key=1|rfir-slam --rawlog $R --out-dir out --config slam_ps --set slam.no_such_key=1"
    "--config: 'nosuch'|rfir-localize --rawlog $IR --out-dir out --config nosuch"
    "--set localization.num_particles=abc|rfir-localize --rawlog $IR --out-dir out --set localization.num_particles=abc"
    "--config: 'nosuch'|rfir-sim --config nosuch --out-dir out"
    "--name|rfir-sim --config sim_kidnap --out-dir out --name a/b"
    "--bogus|rfir-ids --bogus"
    "unknown command 'bogus'|rfir-ids bogus"
    "--codes|rfir-ids encode --codes 9,3"
    "--room|rfir-ids plan --room 0,0,1"
    "--full|rfir-bench --out-dir out"
    "--quick and --full|rfir-bench --quick --full --out-dir out"
    "--methods|rfir-bench --quick --methods foo --out-dir out"
    "--config-dir|rfir-bench --quick --config-dir nosuch --out-dir out"
    "--kind|rfir-eval --path $GT --gt-path $GT --kind foo"
    "--gt-path|rfir-eval --path $GT"
    "--run|rfir-eval --run foo --gt-path $GT"
    "--path-format|rfir-eval --path $GT --gt-path $GT --path-format foo"
    "--start|rfir-eval --path $GT --gt-path $GT --path-format mrpt"
    "--rows|rfir-experiments --quick --rows nosuch --out-dir out"
    "--config-dir|rfir-experiments --quick --rows t31_16 --out-dir out --config-dir nosuch"
    "--only|rfir-ir-experiments --quick --only nosuch --out-dir out"
    "--motion|rfir-plain-ps --input $SRC/tests/data/textlog/rfid_short.txt --motion 1,2,3"
    "--lossy|rfir-import --input $SRC/tests/data/textlog/full.txt --output out.rawlog --lossy"
  )
  local item said args
  for item in "${cases[@]}"; do
    said=${item%%|*}
    read -r -a args <<<"${item#*|}"
    for i in "${!args[@]}"; do [ "${args[$i]}" = 0,0,1 ] && args[$i]="0 0 1"; done
    run "${args[@]:0:1}" 2 "${args[@]:1}"
    grep -qF -- "$said" <<<"$last_err" ||
      fail "${args[*]}: the message does not say '$said': $last_err"
    grep -q "config_ini/" <<<"$last_err" &&
      fail "${args[*]}: the message names a stock INI: $last_err"
  done
  # A bad value in an INI file is the file's error (exit 1), named by it,
  # also beside a good --set edit.
  sed 's/^robot_particles.*/robot_particles = abc/' "$CFG/slam_pf.ini" >"$root/bad_pf.ini"
  for extra in "" "--set slam.resample_ess=0.5"; do
    # shellcheck disable=SC2086
    run rfir-slam 1 --rawlog "$R" --out-dir out --config "$root/bad_pf.ini" $extra
    grep -qF "$root/bad_pf.ini: [slam] robot_particles" <<<"$last_err" ||
      fail "rfir-slam --config bad_pf.ini $extra: the message does not name the file: $last_err"
  done
  # A ground truth that is not TUM (here MRPT rbpf-slam's path layout) is the
  # file's error, found before the run (nothing written).
  printf '0 0 0 0 0 0 0 1.0\n1 0.1 0 0 0.2 0 0 1.1\n2 0.2 0 0 0.3 0 0 1.2\n' >"$root/rbpf.txt"
  run rfir-slam 1 --rawlog "$R" --out-dir out --method odometry --gt-path "$root/rbpf.txt"
  grep -qF "log_estimated_path.txt" <<<"$last_err" ||
    fail "rfir-slam --gt-path rbpf.txt: the message does not say what it looks like: $last_err"
  run rfir-localize 1 --rawlog "$IR" --out-dir out --emitters "$DS/ir_loop_spots.gt_map.txt" \
    --gt-path "$root/rbpf.txt"
  grep -qF "not a TUM path" <<<"$last_err" ||
    fail "rfir-localize --gt-path rbpf.txt: the message does not say it is not TUM: $last_err"
}

# quiet_run PROGRAM ARGS...: a short real run in a fresh directory: exit 0,
# something written, nothing on stdout, nothing on stderr but warnings.
quiet_run() {
  local prog=$1
  shift
  local wd
  wd=$(mktemp -d "$root/wd_XXXXXX")
  (cd "$wd" && timeout 120 "$BIN/$prog" "$@" >"$root/stdout" 2>"$root/stderr")
  local code=$?
  local what="$prog $*"
  [ $code -eq 0 ] || fail "$what: exit $code: $(head -c 400 "$root/stderr")"
  [ -s "$root/stdout" ] && fail "$what: printed on stdout: $(head -c 200 "$root/stdout")"
  grep -v -i "warning" "$root/stderr" | grep -q . &&
    fail "$what: printed on stderr: $(head -c 200 "$root/stderr")"
  [ -n "$(ls -A "$wd")" ] || fail "$what: wrote nothing"
  rm -rf "$wd"
}

# exp_run PROGRAM DIR ARGS...: an experiment program with -q into $root/DIR.
exp_run() {
  local prog=$1 d=$2
  shift 2
  (cd "$root" && timeout 300 "$BIN/$prog" -q --out-dir "$d" "$@" >"$root/stdout" 2>"$root/stderr") ||
    fail "$prog $*: exit $?: $(head -c 300 "$root/stderr")"
  [ -s "$root/stdout" ] && fail "$prog -q $*: printed on stdout"
}

# results.json of $root/DIR without what changes from run to run (times, the
# command line, the edits).
numbers() {
  sed -E 's/"(command|wall_seconds|ms_per_step|max_step_ms|total_s|ini_edits)":(\[[^]]*\]|"[^"]*"|[^,]*),?//g' \
    "$root/$1/results.json"
}
ir_md() { sed '/^Run time:/d' "$root/$1/results_ir.md" 2>/dev/null; }

# --set: a malformed edit, an unknown section, an unknown key and a bad value
# (each EDIT@WORD: the message must name WORD and the edit) exit 2 before any
# work, writing nothing, in every program that takes --set.
bad_set_checks() {
  declare -A SETS
  SETS[rfir-slam]="slam_particles=5@slam_particles nosuch.k=1@nosuch
    slam.no_such_key=1@no_such_key slam.robot_particles=abc@robot_particles"
  SETS[rfir-localize]="localization=5@localization nosuch.k=1@nosuch
    localization.no_such_key=1@no_such_key localization.num_particles=1.5@num_particles"
  SETS[rfir-sim]="speed=0.3@speed nosuch.k=1@nosuch trajectory.no_such_key=1@no_such_key
    trajectory.speed=abc@speed"
  SETS[rfir-experiments]="slam_particles=5@slam_particles nosuch.k=1@nosuch
    slam.no_such_key=1@no_such_key trajectory.speed=abc@speed kidnap.enabled=true@kidnap
    slam:trajectory.speed=1@trajectory"
  SETS[rfir-ir-experiments]="localization=5@localization nosuch.k=1@nosuch
    trajectory.no_such_key=1@no_such_key localization.num_particles=abc@num_particles"
  SETS[rfir-bench]="slam_particles=5@slam_particles nosuch.k=1@nosuch
    tagmap.no_such_key=1@no_such_key trajectory.speed=abc@speed
    slam.robot_particles=50@robot_particles"
  for prog in "${!SETS[@]}"; do
    [ -x "$BIN/$prog" ] || { fail "$prog: not built"; continue; }
    read -r -a base <<<"${BASE[$prog]}"
    for item in ${SETS[$prog]}; do
      edit=${item%@*} word=${item##*@}
      run "$prog" 2 "${base[@]}" --set "$edit"
      grep -q -- "$word" <<<"$last_err" ||
        fail "$prog --set '$edit': the message does not name '$word': $last_err"
      grep -qF -- "--set $edit" <<<"$last_err" ||
        fail "$prog --set '$edit': the message does not name the edit: $last_err"
    done
  done
}

# -q on short real runs of every program but the experiment ones (below).
quiet_checks() {
  quiet_run rfir-slam --rawlog "$DS/rfid_60mm_16tags_loop.rawlog" --out-dir out --method pf \
    --set slam.robot_particles=30 -q
  quiet_run rfir-localize --rawlog "$DS/ir_raw_15s.rawlog" --emitters "$DS/ir_raw_15s.gt_map.txt" \
    --out-dir out --set localization.num_particles=200 -q
  quiet_run rfir-sim --config "$CFG/sim_kidnap.ini" --out-dir out \
    --set simulation.max_duration=5 -q
  quiet_run rfir-eval --path "$DS/rfid_kidnap.gt.tum" --gt-path "$DS/rfid_kidnap.gt.tum" \
    --json-file out.json -q
  quiet_run rfir-import --input "$SRC/tests/data/textlog/full.txt" --output out.rawlog -q
  quiet_run rfir-ids plan --room "0 0 3.2 2.4" --output out.txt -q
  local bench=(--quick --no-realtime --m 100 --n 10 --methods ps --updates 5 --rounds 1
    --set tagmap.num_particles=20)
  quiet_run rfir-bench "${bench[@]}" --out-dir out -q
  exp_run rfir-bench bench "${bench[@]}"
  grep -qE '"ini_edits": ?\["tagmap\.num_particles=20"\]' "$root/bench/benchmark.json" ||
    fail "rfir-bench --set: not in benchmark.json's ini_edits"
}

# --set and --seed reach the runs. rfir-experiments: a simulation edit (10 s
# runs: 101 steps each) and a first seed, recorded in results.json and
# results.md; the same command again gives the same numbers, a SLAM edit
# other ones. rfir-ir-experiments: --seed 1 is the default, --seed 3 and a
# localization edit give other numbers, recorded in the header.
experiment_checks() {
  local ex=(--quick --rows t31_16 --no-figures --set simulation.max_duration=10)
  exp_run rfir-experiments e1 "${ex[@]}" --seed 3
  exp_run rfir-experiments e2 "${ex[@]}" --seed 3
  exp_run rfir-experiments e3 "${ex[@]}" --seed 3 --set slam.robot_particles=5
  local j
  j=$(cat "$root/e1/results.json" 2>/dev/null)
  grep -qF '"seeds":[3],' <<<"$j" || fail "rfir-experiments --seed 3: seeds not [3] in results.json"
  grep -qF '"ini_edits":["simulation.max_duration=10"]' <<<"$j" ||
    fail "rfir-experiments --set: not in results.json's ini_edits"
  [ "$(grep -o '"steps":[0-9]*' <<<"$j" | sort -u)" = '"steps":101' ] ||
    fail "rfir-experiments --set simulation.max_duration=10: not 101 steps per run"
  grep -qF '`simulation.max_duration=10`' "$root/e1/results.md" ||
    fail "rfir-experiments --set: not in the results.md header"
  [ "$(numbers e1)" = "$(numbers e2)" ] || fail "rfir-experiments: the same command, other numbers"
  [ "$(numbers e1)" != "$(numbers e3)" ] ||
    fail "rfir-experiments --set slam.robot_particles=5: the same numbers"

  local ir=(--quick --only rotation)
  exp_run rfir-ir-experiments i1 "${ir[@]}"
  exp_run rfir-ir-experiments i2 "${ir[@]}" --seed 1
  exp_run rfir-ir-experiments i3 "${ir[@]}" --seed 3
  exp_run rfir-ir-experiments i4 "${ir[@]}" --seed 3 --set localization.num_particles=300
  [ "$(ir_md i1)" = "$(ir_md i2)" ] || fail "rfir-ir-experiments --seed 1 is not the default"
  [ "$(ir_md i1 | sed 's/seed 1/seed 3/')" != "$(ir_md i3 | sed 's/ --seed 3//')" ] ||
    fail "rfir-ir-experiments --seed 3: the same numbers as seed 1"
  grep -qF -- "--seed 3," "$root/i3/results_ir.md" ||
    fail "rfir-ir-experiments --seed 3: not in the header"
  grep -qF "Loop with rotations, seed 3" "$root/i3/results_ir.md" ||
    fail "rfir-ir-experiments --seed 3: the figure is not seed 3's"
  # Past the header (which names the edit): the tables differ.
  [ "$(ir_md i3 | sed 1,4d)" != "$(ir_md i4 | sed 1,4d)" ] ||
    fail "rfir-ir-experiments --set localization.num_particles=300: the same numbers"
  grep -qF -- "--set localization.num_particles=300" "$root/i4/results_ir.md" ||
    fail "rfir-ir-experiments --set: not in the header"
}

# rfir-slam and rfir-localize: the same option and output names where they do
# the same thing: --gt-path (default: <stem>.gt.tum beside the rawlog),
# errors.json, path_map.png, error_time.png. rfir-localize scores against a
# --gt-path that is not beside the rawlog.
shared_name_checks() {
  local prog
  for prog in rfir-slam rfir-localize; do
    grep -q -- "--gt-path" <<<"$("$BIN/$prog" --help)" || fail "$prog --help: no --gt-path"
  done
  mkdir -p "$root/alone"
  cp "$DS/ir_raw_15s.rawlog" "$root/alone/"
  (cd "$root" && "$BIN/rfir-slam" -q --rawlog "$DS/rfid_60mm_16tags_loop.rawlog" \
    --out-dir slam --method odometry &&
    "$BIN/rfir-localize" -q --rawlog alone/ir_raw_15s.rawlog --out-dir loc \
      --emitters "$DS/ir_raw_15s.gt_map.txt" --gt-path "$DS/ir_raw_15s.gt.tum" \
      --set localization.num_particles=200) >/dev/null 2>"$root/stderr" ||
    fail "slam / localize runs: $(head -c 300 "$root/stderr")"
  local f
  for f in errors.json path_map.png error_time.png path.tum stats.json settings.ini; do
    [ -s "$root/slam/$f" ] || fail "rfir-slam: no $f"
    [ -s "$root/loc/$f" ] || fail "rfir-localize: no $f"
  done
}

option_checks() {
  shared_name_checks
  bad_set_checks
  quiet_checks
  experiment_checks
}

case ${3:-all} in
  basic) basic_checks ;;
  options) option_checks ;;
  all) basic_checks; option_checks ;;
  *) echo "usage: cli_conventions.sh BIN SRC [basic|options|all]" >&2; exit 2 ;;
esac

[ "$(docs_hash)" = "$before" ] || fail "a file under $SRC/docs changed"
echo "cli_conventions (${3:-all}): $failures failure(s)"
[ $failures -eq 0 ]
