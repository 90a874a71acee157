#!/usr/bin/env bash
# The one prepared check for a machine with a GPU (issue 35): what only a device can tell, in one
# short script, so that a few lent minutes are enough.
#   1. a release build with every core (the tests too);
#   2. the GPU-relevant tests (every test whose name says Gpu, Gl, Shader, Phong, RngParity or
#      BlockLayout), all cores at once;
#   3. the quick tier of the cases on the hardware EGL device, every GPU half required
#      (--gl egl --require-gpu: a case whose GPU half cannot run is an error, not a skip);
#   4. the performance table at SIZES (default 256,1024) on that device, its rows printed beside the
#      published ones (Mei 2007 Table 1, Hydra Tables 5.1-5.6, Šťava 2008; compare/benchmark_table.cpp).
# Reports go to $OUT (the device tool's folder) or device-check/: quick/ and bench/, and the log of
# each step. It also runs on llvmpipe, slowly (DEVICE_CHECK_SIZES=256 keeps it to minutes there):
# a script that has not run here is not one to spend a lent device on.
# Expected on a 16-core machine with one GPU: build ~3 min, tests ~1 min, quick tier ~1 min, table
# ~1 min at 256 and 1024: under 8 minutes. It needs the project's Debian packages (scripts/
# install-deps.sh); on a GPU machine without them and without a package registry, as the lent
# NVIDIA machines are, run scripts/device-probe/ instead (docs/fast-feedback.md).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-device-check}
sizes=${DEVICE_CHECK_SIZES:-256,1024}
cores=$(nproc)
mkdir -p "$out"
step() { echo "device-check: $1 ($(date -u +%H:%M:%S))"; }

step "build with $cores cores"
cmake --preset release > "$out/configure.log"
cmake --build --preset release -j "$cores" > "$out/build.log"

step "GPU-relevant tests"
ctest --preset release -j "$cores" -R 'Gpu|GlContext|Shader|Phong|RngParity|BlockLayout' --output-on-failure \
  > "$out/ctest.log" || { tail -40 "$out/ctest.log"; exit 1; }
tail -3 "$out/ctest.log"

step "quick tier on the EGL device, GPU halves required"
./build/release/groundtruth run --quick --gl egl --require-gpu -j 2 --out "$out/quick" > "$out/quick.log" \
  || { tail -40 "$out/quick.log"; exit 1; }
tail -1 "$out/quick.log"

step "performance table at $sizes"
./build/release/groundtruth bench --sizes "$sizes" --gl egl --quiet --out "$out/bench" > "$out/bench.log"
cat "$out/bench.log"
step "done: reports in $out/quick and $out/bench"
