#!/usr/bin/env bash
# The main job: set up (building only the groundtruth executable, not the tests), then `groundtruth
# report` on the bundled data into reports/latest/: the quick and report tiers of the cases and the
# benchmark at its smallest size; then the Python module (`import groundtruth`), which the report
# does not need, so that the report comes first. Arguments go to `groundtruth report`, e.g.
# `bash scripts/report.sh --full` for every case, every benchmark size and the mutants. The exit
# status is the report's.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh groundtruth
status=0
./build/release/groundtruth report --require-gpu "$@" || status=$?
echo "report.sh: the report is in reports/latest/index.html; now building the Python module (import groundtruth)" >&2
cmake --build --preset release --target gt_python gt_python_wheel
bash scripts/install-python-path.sh build/release
exit "$status"
