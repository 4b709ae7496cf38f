#!/usr/bin/env bash
# The live view's tests (tests/gui.cmake, docs/live-view.md).
#   bash tests/gui.sh BIN SRC no-display
#     --gui and --gui-record without a display, and --gui-record on a folder
#     holding frames or one that cannot be created: exit 2, a message naming
#     the option, nothing on stdout, nothing written.
#   bash tests/gui.sh BIN SRC keys
#     under xvfb-run, keys pressed through XTest (tests/gui_keys.py): space
#     pauses (no new frame), s and the right arrow step once each, space
#     resumes, q closes the view and the run still finishes.
#   bash tests/gui.sh BIN SRC slam|localize CHECKER
#     under xvfb-run: the recorded frames show the scene (CHECKER counts the
#     view's colours in them), and the run's outputs are byte-identical with
#     and without the view. Exit 77 (skipped) without xvfb-run, or in the
#     sanitizer build (RFIR_GUI_SANITIZED=1): MRPT's window runs on
#     wxWidgets and Mesa's GL, which are not instrumented and keep
#     allocations past exit.
set -uo pipefail
BIN=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
MODE=$3
DS=$SRC/datasets
root=$(mktemp -d "${TMPDIR:-/tmp}/rfir_gui_XXXXXX")
trap 'rm -rf "$root"' EXIT
cd "$root" || exit 1
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

SLAM_ARGS=(--rawlog "$DS/rfid_300mm_4tags_random_90s.rawlog" -q)
LOC_ARGS=(--rawlog "$DS/ir_loop_spots.rawlog" --emitters "$DS/ir_loop_spots.gt_map.txt" -q)

if [ "$MODE" = no-display ]; then
  for prog in rfir-slam rfir-localize; do
    if [ $prog = rfir-slam ]; then args=("${SLAM_ARGS[@]}"); else args=("${LOC_ARGS[@]}"); fi
    for opt in "--gui" "--gui-record frames"; do
      # shellcheck disable=SC2086
      env -u DISPLAY "$BIN/$prog" "${args[@]}" --out-dir out $opt >stdout 2>stderr
      rc=$?
      [ $rc -eq 2 ] || fail "$prog $opt without a display: exit $rc, not 2"
      grep -q -- "--gui" stderr || fail "$prog $opt: the message does not name --gui: $(cat stderr)"
      [ -s stdout ] && fail "$prog $opt: wrote to stdout"
      [ -e out ] || [ -e frames ] && fail "$prog $opt: wrote files"
      echo "$prog $opt, no display: exit $rc: $(cat stderr)"
      rm -rf out frames stdout stderr
    done
  done
  # A recording folder holding frames of another run, or one that cannot be
  # created: exit 2 naming --gui-record, before any work (display or not).
  mkdir old && touch old/frame_000001.png && touch afile
  for dir in old afile/frames; do
    "$BIN/rfir-slam" "${SLAM_ARGS[@]}" --out-dir out --gui-record $dir >stdout 2>stderr
    rc=$?
    [ $rc -eq 2 ] || fail "--gui-record $dir: exit $rc, not 2"
    grep -q -- "--gui" stderr || fail "--gui-record $dir: the message does not name it"
    [ -e out ] || [ -s stdout ] && fail "--gui-record $dir: wrote something"
    rm -f stdout stderr
    echo "--gui-record $dir: exit $rc: $(cat stderr)"
  done
  exit $((failures > 0))
fi

if [ "${RFIR_GUI_SANITIZED:-0}" = 1 ]; then
  echo "SKIP: the sanitizer build: MRPT's window (wxWidgets, Mesa's GL) is not instrumented"
  exit 77
fi
if ! command -v xvfb-run >/dev/null; then
  echo "SKIP: xvfb-run not found (Debian package xvfb; scripts/setup.sh installs it)"
  exit 77
fi
XVFB=(xvfb-run -a -s "-screen 0 1024x768x24")

frames() { find frames -name 'frame_*.png' 2>/dev/null | wc -l; }
# Waits up to $2 s for at least $1 frames.
wait_frames() {
  for _ in $(seq $((10 * $2))); do
    (($(frames) >= $1)) && return 0
    sleep 0.1
  done
  return 1
}
if [ "$MODE" = keys-inner ]; then  # under xvfb-run (below)
  "$BIN/rfir-slam" --rawlog "$DS/rfid_kidnap.rawlog" -q --out-dir out --gui-record frames \
    --gui-every 5 &
  pid=$!
  wait_frames 3 60 || fail "no frame within 60 s"
  keys() { /usr/bin/python3 "$SRC/tests/gui_keys.py" "$@"; }
  keys space && sleep 1
  n=$(frames) && sleep 2
  (($(frames) == n)) || fail "space did not pause ($n, then $(frames) frames)"
  keys s && wait_frames $((n + 1)) 10 || fail "s did not step"
  keys Right && wait_frames $((n + 2)) 10 || fail "the right arrow did not step"
  sleep 1
  (($(frames) == n + 2)) || fail "one step each: $n, then $(frames) frames"
  keys space && wait_frames $((n + 4)) 20 || fail "space did not resume"
  keys q
  wait $pid || fail "rfir-slam exit $? after q"
  total=$(frames)
  # 2621 instants, one frame every 5: q closed the view before the end.
  ((total < 500)) || fail "q did not close the view ($total frames)"
  [ -s out/path.tum ] && [ -s out/stats.json ] || fail "the run did not finish after q"
  echo "keys: paused at $n frames, stepped twice, resumed, closed at $total frames"
  exit $((failures > 0))
fi
if [ "$MODE" = keys ]; then
  if [ ! -x /usr/bin/python3 ] || ! /sbin/ldconfig -p | grep libXtst.so.6 >/dev/null; then
    echo "SKIP: the key test needs /usr/bin/python3 and libXtst.so.6 (Debian libxtst6)"
    exit 77
  fi
  "${XVFB[@]}" bash "$0" "$BIN" "$SRC" keys-inner
  exit $?
fi

CHECK=$4
if [ "$MODE" = slam ]; then
  prog=rfir-slam args=("${SLAM_ARGS[@]}") items=(particles path truth landmark sensor)
  same=(path.tum map.txt errors.json path_map.png)
else
  prog=rfir-localize args=("${LOC_ARGS[@]}") items=(particles path truth landmark sensor)
  same=(path.tum errors.json path_map.png emitter_health.txt)
fi
"${XVFB[@]}" "$BIN/$prog" "${args[@]}" --out-dir with --gui-record frames --gui-every 50 \
  >with.out 2>with.err || fail "$prog --gui-record: exit $?: $(cat with.err)"
"$BIN/$prog" "${args[@]}" --out-dir without >/dev/null 2>without.err ||
  fail "$prog without the view: exit $?: $(cat without.err)"
for f in "${same[@]}"; do
  cmp -s "with/$f" "without/$f" || fail "$prog: $f differs with the view"
done
# At least the run's length / 50 frames (900 and 1900 instants).
"$CHECK" frames 15 "${items[@]}" || fail "$prog: the frames do not show the scene"
exit $((failures > 0))
