#!/usr/bin/env bash
# Everything before the first run on a fresh Debian 12 machine (as root): the Debian packages,
# the real data sets, a release build in build/release, and `import groundtruth` for Debian's
# Python (a .pth file naming build/release/python in its site-packages).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash datasets/fetch.sh
cmake --preset release
cmake --build --preset release
bash scripts/install-python-path.sh build/release
