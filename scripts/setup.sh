#!/usr/bin/env bash
# Everything before the first run on a fresh Debian 12 machine (as root): the Debian packages,
# the real data sets, and a release build in build/release.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash datasets/fetch.sh
cmake --preset release
cmake --build --preset release
