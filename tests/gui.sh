#!/usr/bin/env bash
# The live view's tests (tests/gui.cmake, docs/live-view.md).
#   bash tests/gui.sh BIN SRC no-display
#     --gui and --gui-record without a display: exit 2, a message naming
#     --gui, nothing on stdout, nothing written.
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
  exit $((failures > 0))
fi

CHECK=$4
if [ "${RFIR_GUI_SANITIZED:-0}" = 1 ]; then
  echo "SKIP: the sanitizer build: MRPT's window (wxWidgets, Mesa's GL) is not instrumented"
  exit 77
fi
if ! command -v xvfb-run >/dev/null; then
  echo "SKIP: xvfb-run not found (Debian package xvfb; scripts/setup.sh installs it)"
  exit 77
fi
XVFB=(xvfb-run -a -s "-screen 0 1024x768x24")
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
