#!/usr/bin/env bash
# Records each case's wall seconds from a report.json into datasets/case-seconds.json, the
# expected times behind the progress lines' ETA, `groundtruth list` and the tier budgets that
# tests/tiers_test.cpp holds (compare/case_seconds.hpp). Run it on a report of every case
# (`groundtruth run '*' -j 1`) from the reference machine: 2 cores, no GPU (llvmpipe), quiet.
# Cases the report does not hold keep their recorded time; cases no longer bundled are dropped.
# Usage: record-case-seconds.sh REPORT.json [MACHINE]   (MACHINE: a line describing it)
set -euo pipefail
cd "$(dirname "$0")/.."
report=${1:?usage: record-case-seconds.sh REPORT.json [MACHINE]}
machine=${2:-"$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), llvmpipe"}
listing=$(mktemp)
trap 'rm -f "$listing"' EXIT
./build/release/groundtruth list --json > "$listing"
/usr/bin/python3 - "$report" "$machine" "$listing" <<'PY'
import json, pathlib, sys
report, machine = json.loads(pathlib.Path(sys.argv[1]).read_text()), sys.argv[2]
listing = json.loads(pathlib.Path(sys.argv[3]).read_text())
target = pathlib.Path("datasets/case-seconds.json")
kept = json.loads(target.read_text())["seconds"] if target.exists() else {}
bundled = {case["name"] for case in listing["cases"]}
measured = {case["name"]: round(case["seconds"], 1) for case in report["cases"]
            if isinstance(case.get("seconds"), (int, float)) and case["seconds"] > 0}
seconds = {name: measured.get(name, kept.get(name)) for name in sorted(bundled) if name in measured or name in kept}
document = {"recorded_on": machine, "from": report["environment"].get("run_started", ""), "seconds": seconds}
target.write_text(json.dumps(document, indent=1, ensure_ascii=False) + "\n")
missing = sorted(bundled - set(seconds))
print(f"record-case-seconds: {len(seconds)} cases in {target}" + (f"; no time for: {', '.join(missing)}" if missing else ""))
PY
