#!/usr/bin/env bash
# Runs docs/tutorial.md as a user would: every ```sh block, in order, as one
# script, from a scratch folder where build/ and datasets/ point at this
# build and the source's datasets. RawLogViewer opens a window, so its line
# is left out (rawlog-edit, which the tutorial runs next, loads the same
# plugin). Then checks what the tutorial says happens: the script succeeds,
# every out/tutorial/... file the page names exists and is not empty,
# except out/tutorial/broken.rawlog, which the failed import must not
# write, and the failed import names the file and line the page shows.
#   bash tests/run_tutorial.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
BUILD=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
page=$SRC/docs/tutorial.md
work=$(mktemp -d "${TMPDIR:-/tmp}/rfir_tutorial_XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
ln -s "$BUILD" build
ln -s "$SRC/datasets" datasets

awk '/^```sh$/ { on = 1; next } /^```$/ { on = 0 } on' "$page" |
  sed 's/^RawLogViewer /echo "(ctest: skipped, needs a display)" RawLogViewer /' > tutorial.sh
grep -q 'rfir-import' tutorial.sh || { echo "FAIL: no sh block found in $page"; exit 1; }
if ! command -v rawlog-edit > /dev/null; then
  echo "note: rawlog-edit not installed (MRPT's mrpt-apps): its line is skipped"
  sed -i 's/^rawlog-edit /echo "(skipped: no rawlog-edit)" rawlog-edit /' tutorial.sh
fi

# In the sanitizer build (scripts/sanitize.sh) MRPT's uninstrumented
# programs get the sanitizer runtimes preloaded, else they cannot load the
# instrumented plugin.
if [ -n "${RFIR_SANITIZER_PRELOAD:-}" ]; then
  sed -i 's/^rawlog-edit /LD_PRELOAD="$RFIR_SANITIZER_PRELOAD" rawlog-edit /' tutorial.sh
fi

failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

if ! bash -euo pipefail tutorial.sh > log.txt 2>&1; then
  cat log.txt
  echo "FAIL: the tutorial's commands stopped (output above)"
  exit 1
fi

# Every file the page names under out/tutorial/.
for f in $(grep -o 'out/tutorial/[A-Za-z0-9_./-]*[A-Za-z0-9_]' "$page" | sort -u); do
  [ "$f" = out/tutorial/broken.rawlog ] && continue
  if [ -d "$f" ]; then continue; fi
  [ -s "$f" ] || fail "the tutorial names $f, which the commands did not write"
done
[ -e out/tutorial/broken.rawlog ] && fail "the failed import wrote out/tutorial/broken.rawlog"
grep -q "rfir-import: error: out/tutorial/broken.txt:28: rfid names reader 'R7', which no 'reader' header record declares" log.txt ||
  fail "the failed import's message is not the one the tutorial shows"
grep -q 'rfir-import exited with 1' log.txt || fail "the failed import did not exit 1"
grep -q 'the same rawlog' log.txt || fail "the CSV conversion did not give the same rawlog"
for m in pf ps fastslam odometry; do
  for f in path.tum map.txt path_map.png error_time.png errors.json stats.json settings.ini scene.3Dscene; do
    [ -s "out/tutorial/$m/$f" ] || fail "rfir-slam --method $m wrote no $f"
  done
done
if command -v rawlog-edit > /dev/null; then
  grep -q 'All sensor labels *: HEADER, ODOMETRY, RFID' log.txt ||
    fail "rawlog-edit --info with the plugin does not list HEADER, ODOMETRY, RFID"
fi

if [ $failures -ne 0 ]; then
  echo "--- output of the tutorial's commands ---"
  cat log.txt
  exit 1
fi
echo "tutorial: every command ran, every file it names was written"
