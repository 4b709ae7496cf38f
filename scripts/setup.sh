#!/usr/bin/env bash
# Installs every dependency from Debian's packages (idempotent, non-interactive)
# and builds the project in Release into ./build.
set -euo pipefail
cd "$(dirname "$0")/.."

PKGS=(build-essential cmake git ccache libmrpt-dev mrpt-apps libeigen3-dev
      libgtest-dev googletest libbenchmark-dev zlib1g-dev
      clang libclang-rt-14-dev    # clang + libFuzzer: scripts/fuzz.sh
      clang-format                # scripts/check_format.sh (.ci/run)
      libceres-dev                # rfir-slam --smooth (graph_smoother_ceres.cpp)
      nlohmann-json3-dev          # JSON outputs (header-only, build time only)
      pybind11-dev python3-dev python3-numpy  # the Python module (docs/python.md)
      python3-matplotlib          # docs/python.md's example (ctest python_docs_example)
      libx11-dev                  # the live view's display check (--gui, mrpt_plugins/view)
      xvfb xauth)                 # xvfb-run: the live view's frame tests, --gui-record headless
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "[setup] installing: ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "[setup] all dependencies already installed"
fi

JOBS=${RFIR_JOBS:-$(nproc)}
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$JOBS"
echo "[setup] build done: programs in build/bin"
