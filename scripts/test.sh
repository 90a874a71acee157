#!/usr/bin/env bash
# Set up, then run the whole test suite with ctest (two jobs: CI has two cores), then the same
# unit tests and a fast subset of the cases under AddressSanitizer + UndefinedBehaviorSanitizer
# (preset debug-asan, clang), and every libFuzzer target for a bounded time (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --preset release -j 2
cmake --preset debug-asan
cmake --build --preset debug-asan
ctest --preset debug-asan -j 2
bash scripts/fuzz.sh
