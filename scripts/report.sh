#!/usr/bin/env bash
# The main job: set up (building only the groundtruth executable and the Python module, not the
# tests), then `groundtruth report` on the bundled data into reports/latest/: the quick and report
# tiers of the cases and the benchmark at its smallest size. Arguments go to `groundtruth report`,
# e.g. `bash scripts/report.sh --full` for every case, every benchmark size and the mutants.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh groundtruth gt_python
./build/release/groundtruth report --require-gpu "$@"
