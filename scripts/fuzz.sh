#!/usr/bin/env bash
# Runs every libFuzzer target of the debug-asan build (AddressSanitizer + UBSan) for a bounded time
# each: SECONDS (first argument, default 20). Each starts from its seed corpus in
# fuzz/corpus/<target>; what it discovers goes to a scratch corpus under build/debug-asan, never into
# the repository. A crash, a sanitizer report, a leak, a 2 GB allocation or a 25 s input stops the
# run with the input saved as build/debug-asan/fuzz-artifacts/<target>/<kind>-<hash>: fix the bug,
# then copy that file into fuzz/regressions/<target>/ so that ctest replays it for ever.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
build=build/debug-asan
export ASAN_OPTIONS="detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
shopt -s nullglob
targets=("$build"/fuzz/fuzz_*)
if [ ${#targets[@]} -eq 0 ]; then
  echo "fuzz: no targets in $build/fuzz: build the debug-asan preset first" >&2
  exit 2
fi
for binary in "${targets[@]}"; do
  target="${binary##*/fuzz_}"
  scratch="$build/fuzz-corpus/$target"
  artifacts="$build/fuzz-artifacts/$target/"
  mkdir -p "$scratch" "$artifacts"
  echo "fuzz: $target for $seconds s"
  "$binary" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=25 \
    -artifact_prefix="$artifacts" -print_final_stats=1 "$scratch" "fuzz/corpus/$target" 2>&1 | tail -n 12
  status=${PIPESTATUS[0]}
  if [ "$status" -ne 0 ]; then
    echo "fuzz: $target failed (exit $status); the input is in $artifacts" >&2
    exit 1
  fi
done
echo "fuzz: ${#targets[@]} targets ran $seconds s each without a finding"
