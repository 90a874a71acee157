#!/usr/bin/env bash
# Set up, then run the whole test suite with ctest (two jobs: CI has two cores), the sharding test
# on a single-node Slurm cluster (scripts/slurm-shards.sh: a job array of 3 shards merged must equal
# the unsharded run; about a minute), then the same unit tests and a fast subset of the cases under
# AddressSanitizer + UndefinedBehaviorSanitizer (preset debug-asan, clang), and every libFuzzer
# target for a bounded time (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
ctest --preset release -j 2
trap 'bash scripts/slurm-cluster.sh stop || true' EXIT
bash scripts/slurm-shards.sh 3
bash scripts/slurm-cluster.sh stop
trap - EXIT
cmake --preset debug-asan
cmake --build --preset debug-asan
ctest --preset debug-asan -j 2
bash scripts/fuzz.sh
