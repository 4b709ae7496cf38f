#!/usr/bin/env bash
# The layers point one way (docs/architecture.md): read the library graph from
# CMake (--graphviz, a configure of its own, nothing built) and fail when a
# library links one of its own layer or above, or when a folder of apps/
# declares a library or holds more than one source file (a program folder
# holds its main and command line).
#   scripts/check_layers.sh [work dir]      (default: a temporary folder)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
WORK=${1:-$(mktemp -d)}
[ $# -ge 1 ] || trap 'rm -rf "$WORK"' EXIT
mkdir -p "$WORK"

# Layer of each library, lowest first. Equal numbers may not link each other.
declare -A RANK=(
  [rfir_models]=1 [rfir_observations]=2 [rfir_io]=3 [rfir_maps]=3 [rfir_slam]=4 [rfir_ir]=4
  [rfir_appcommon]=5 [rfir_sim]=6 [rfir_eval]=6 [rfir_localize_core]=7
  [rfir_plain]=6 [rfir_slamapp]=7 [rfir_evalapp]=7 [rfir_experiments]=7 [rfir_bench]=7 [rfir_irexp]=8 [rfir_mrpt_plugin]=8 [rfir_python]=9
  [rfir_view]=8
)

cmake -S "$ROOT" -B "$WORK/build" -DRFIR_BUILD_TESTS=OFF \
  --graphviz="$WORK/rfir.dot" >"$WORK/configure.log" 2>&1 ||
  { cat "$WORK/configure.log" >&2; echo "check_layers: configure failed" >&2; exit 1; }

fail=0
edges=0
while read -r from to; do
  [[ -n "${RANK[$from]:-}" && "$to" == rfir_* && "$to" != rfir_tclap && "$to" != rfir_json ]] || continue
  edges=$((edges + 1))
  if [[ -z "${RANK[$to]:-}" ]]; then
    echo "check_layers: $from links $to, which has no layer in scripts/check_layers.sh" >&2
    fail=1
  elif ((RANK[$to] >= RANK[$from])); then
    echo "check_layers: $from (layer ${RANK[$from]}) links $to (layer ${RANK[$to]})" >&2
    fail=1
  fi
done < <(sed -n 's|.*// \([^ ]*\) -> \([^ ]*\)$|\1 \2|p' "$WORK/rfir.dot")

for lib in "${!RANK[@]}"; do
  # The Python module is built only where pybind11 is found (RFIR_WITH_PYTHON).
  [[ $lib == rfir_python ]] && ! grep -q "pybind11_DIR:PATH=/" "$WORK/build/CMakeCache.txt" && continue
  # The live view is built only with MRPT's gui module (RFIR_WITH_GUI).
  [[ $lib == rfir_view ]] && grep -q "live view (--gui): OFF" "$WORK/configure.log" && continue
  grep -q "label = \"$lib[\\\"]" "$WORK/rfir.dot" ||
    { echo "check_layers: library $lib is not in the build graph" >&2; fail=1; }
done
if grep -rlE '^\s*(rfir_)?add_library\(' "$ROOT"/apps --include=CMakeLists.txt; then
  echo "check_layers: the program folders above declare a library" >&2
  fail=1
fi
# A program folder holds one source file, its main with its command line.
for dir in "$ROOT"/apps/*/; do
  n=$(find "$dir" -name '*.cpp' -o -name '*.h' | wc -l)
  ((n <= 1)) || { echo "check_layers: $dir holds $n source files, not only its main" >&2; fail=1; }
done
if grep -rnE 'include_directories\([^)]*apps/' "$ROOT"/mrpt_plugins "$ROOT"/observations \
    --include=CMakeLists.txt; then
  echo "check_layers: a library includes a program folder" >&2
  fail=1
fi
((fail == 0)) && echo "check_layers: $edges edges between the libraries, all downwards"
exit $fail
