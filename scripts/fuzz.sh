#!/usr/bin/env bash
# Runs every libFuzzer target of the debug-asan build (AddressSanitizer + UBSan + LeakSanitizer),
# each from its seed corpus in fuzz/corpus/<target>.
#
#   bash scripts/fuzz.sh                 CI: seed 1 and a fixed number of runs per target (about 10 to
#                                        20 s each on CI's machine), so a pass here is a pass there
#   bash scripts/fuzz.sh --seconds N     exploration: a random seed, N seconds a target, and a corpus
#                                        kept under build/debug-asan/fuzz-corpus between runs
#
# A crash, a sanitizer report, a leak, a 2 GB allocation or a 25 s input stops the run with the
# input saved as build/debug-asan/fuzz-artifacts/<target>/<kind>-<hash>: fix the bug, then copy that
# file into fuzz/regressions/<target>/ so that ctest replays it for ever (fuzz.<target>.replay).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=""
if [ "${1:-}" = "--seconds" ]; then seconds="${2:?--seconds needs a number}"; fi
build=build/debug-asan
export ASAN_OPTIONS="detect_leaks=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
shopt -s nullglob
targets=("$build"/fuzz/fuzz_*)
[ ${#targets[@]} -gt 0 ] || { echo "fuzz: no targets in $build/fuzz: build the debug-asan preset first" >&2; exit 2; }
scratch_root=$(mktemp -d)
trap 'rm -rf "$scratch_root"' EXIT

# Runs for CI's fixed budget: decoding an image under the sanitizers takes about 0.1 s (PNG,
# EXR) or 15 ms (TIFF); the other loaders take under 1 ms an input.
runs_for() {
  case "$1" in
    heightmap_png | heightmap_exr) echo 150 ;;
    heightmap_tif) echo 1000 ;;
    *) echo 20000 ;;
  esac
}

for binary in "${targets[@]}"; do
  target="${binary##*/fuzz_}"
  [ -x "$binary" ] || continue
  artifacts="$build/fuzz-artifacts/$target/"
  mkdir -p "$artifacts"
  if [ -n "$seconds" ]; then
    corpus="$build/fuzz-corpus/$target"
    budget=(-max_total_time="$seconds")
    echo "fuzz: $target for $seconds s"
  else
    corpus="$scratch_root/$target"
    budget=(-seed=1 -runs="$(runs_for "$target")")
    echo "fuzz: $target, seed 1, $(runs_for "$target") runs"
  fi
  mkdir -p "$corpus"
  set +e
  "$binary" "${budget[@]}" -rss_limit_mb=2048 -malloc_limit_mb=2048 -timeout=25 -artifact_prefix="$artifacts" \
    -print_final_stats=1 "$corpus" "fuzz/corpus/$target" > "$scratch_root/$target.log" 2>&1
  status=$?
  set -e
  grep -E "^Done|ERROR|SUMMARY|runtime error" "$scratch_root/$target.log" || true
  if [ "$status" -ne 0 ]; then
    tail -n 40 "$scratch_root/$target.log" >&2
    echo "fuzz: $target failed (exit $status); the input is in $artifacts" >&2
    exit 1
  fi
done
echo "fuzz: ${#targets[@]} targets ran clean"
