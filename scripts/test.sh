#!/usr/bin/env bash
# Runs every test: sets up (installs what is missing, builds), then CTest.
#   bash scripts/test.sh
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
cd "$here/build"
ctest --output-on-failure -j "$(nproc)"
