#!/usr/bin/env bash
# How much harness code each algorithm needs beside the shared runners: the lines of its file in
# compare/algorithms/ (and its registry row), the kind of case it declares, and the lines of the
# runners every algorithm of that kind shares. A new stepped algorithm needs one registry row and
# its own files (its state and steppers in compare/steppers/, its checks in compare/algorithms/);
# everything the stepped runner does (checkpoints, shadow steps, ledgers by backend,
# skips, field export, pictures, timing) it gets from compare/stepped_case.cpp.
set -euo pipefail
cd "$(dirname "$0")/.."
lines() { grep -cv '^\s*\(//.*\)\?$' "$@" | awk -F: '{ s += $NF } END { print s }'; }
printf '%-40s %-10s %s\n' "file (code lines, no comments)" kind lines
for file in compare/algorithms/*.cpp; do
  kind=$( (grep -o 'CaseKind::[a-z]*' "$file" || true) | sed 's/CaseKind:://' | sort -u | paste -sd, -)
  printf '%-40s %-10s %s\n' "$file" "${kind:-helper}" "$(lines "$file")"
done
echo
printf '%-40s %s\n' "state and steppers (an outside model's part)" lines
for file in compare/steppers/*; do printf '%-40s %s\n' "$file" "$(lines "$file")"; done
echo
printf '%-40s %s\n' "shared stepped runner" "$(lines compare/stepper.hpp compare/stepper.cpp compare/stepped_case.hpp compare/stepped_case.cpp)"
printf '%-40s %s\n' "shared generated-field runner" "$(lines compare/field_twin.hpp compare/field_twin.cpp)"
