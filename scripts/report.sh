#!/usr/bin/env bash
# The main job: set up, then `groundtruth report` on the bundled data into reports/latest/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/release/groundtruth report --require-gpu "$@"
