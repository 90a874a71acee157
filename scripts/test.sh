#!/usr/bin/env bash
# Set up, then run the whole test suite with ctest (two jobs: CI has two cores).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --preset release -j 2
