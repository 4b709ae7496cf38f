#!/usr/bin/env bash
# Sets up (scripts/setup.sh), then runs the main job on a bundled dataset.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "[demo] main job not available yet"
