#!/usr/bin/env bash
# Usage: test.sh [--long]
# Set up, then run the test suite with ctest (two jobs: CI has two cores) without its long tier
# (the erosion and planet mutants, the droplet and pipe case suites, the device probe's build:
# CMakePresets.json's release-long; --long runs them too, about 7 minutes more), the sharding test
# on a single-node Slurm cluster (scripts/slurm-shards.sh: a job array of 3 shards merged must equal
# the unsharded run; about a minute), then the same unit tests and a fast subset of the cases under
# AddressSanitizer + UndefinedBehaviorSanitizer (preset debug-asan, clang), and every libFuzzer
# target for a bounded time (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
long=""
if [ "${1:-}" = "--long" ]; then long=1; elif [ -n "${1:-}" ]; then echo "usage: test.sh [--long]" >&2; exit 2; fi
bash scripts/setup.sh
ctest --preset release -j 2
if [ -n "$long" ]; then ctest --preset release-long -j 2; fi
trap 'bash scripts/slurm-cluster.sh stop || true' EXIT
bash scripts/slurm-shards.sh 3
bash scripts/slurm-cluster.sh stop
trap - EXIT
cmake --preset debug-asan
cmake --build --preset debug-asan
ctest --preset debug-asan -j 2
bash scripts/fuzz.sh
