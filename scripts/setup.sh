#!/usr/bin/env bash
# Everything before the first run on a fresh Debian 12 machine (as root): the Debian packages,
# the real data sets, a release build in build/release, and `import groundtruth` for Debian's
# Python (a .pth file naming build/release/python in its site-packages).
# Usage: setup.sh [TARGET ...]   the CMake targets to build; none: all of them (the tests too).
# report.sh builds only what the report runs (the groundtruth executable), then the Python module.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash datasets/fetch.sh
cmake --preset release
if [ "$#" -eq 0 ]; then
  cmake --build --preset release
else
  cmake --build --preset release --target "$@"
fi
# `import groundtruth` once the module is built (report.sh builds it after its report, and says so).
if [ "$#" -eq 0 ] || [[ " $* " == *" gt_python "* ]]; then
  bash scripts/install-python-path.sh build/release
fi
