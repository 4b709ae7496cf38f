#!/usr/bin/env bash
# Sets up (scripts/setup.sh), then runs the whole GoogleTest suite with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --test-dir build --output-on-failure -j"${RFIR_JOBS:-$(nproc)}"
