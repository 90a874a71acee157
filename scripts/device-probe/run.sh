#!/usr/bin/env bash
# Builds the device probe (probe.cpp and the project sources it runs) with the machine's own g++
# and the KIT pack.sh made, then runs it through EGL on the machine's GPU. For a GPU machine
# without the Debian packages (scripts/device-check.sh is the check for one with them).
# Usage: run.sh KIT [N,I,R ...]   each a run of the probe: grid side, iterations, timed runs
#                                  (none: the probe's defaults, 1024,100,5)
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
kit=$(cd "${1:?usage: run.sh KIT [N,I,R ...]}" && pwd)
shift
build=$(mktemp -d)
trap 'rm -rf "$build"' EXIT
sources=(scripts/device-probe/probe.cpp
         gpu/context/context.cpp gpu/context/egl.cpp gpu/shader_program.cpp gpu/buffer.cpp
         gpu/heightfield_buffers.cpp gpu/timing.cpp gpu/erosion/thermal.cpp
         reference/erosion/thermal.cpp
         core/grid.cpp core/closest.cpp core/mutant.cpp core/memory.cpp core/names.cpp core/sha256.cpp core/json_keys.cpp
         core/params.cpp core/params/thermal.cpp)
objects=()
pids=()
# At most one compiler a core: on a 2-core CI machine, 17 at once starved the tests ctest ran beside
# this one past their time limits.
cores=$(nproc)
for source in "${sources[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$cores" ]; do sleep 0.1; done
  object="$build/$(echo "$source" | tr / _).o"
  g++ -std=c++20 -O2 -w -DFMT_HEADER_ONLY -DGT_SHADER_DIR="\"$repo/gpu/shaders\"" -DGT_PROJECT_DIR="\"$repo\"" \
      -I"$repo" -I"$kit/include" -I"$kit/glad/include" -c "$repo/$source" -o "$object" &
  pids+=($!)
  objects+=("$object")
done
while [ "$(jobs -rp | wc -l)" -ge "$cores" ]; do sleep 0.1; done
gcc -O2 -I"$kit/glad/include" -c "$kit/glad/src/gl.c" -o "$build/gl.o" &
pids+=($!)
for pid in "${pids[@]}"; do wait "$pid"; done
g++ -o "$build/probe" "${objects[@]}" "$build/gl.o" -L"$kit/lib" -l:libEGL.so.1 -l:libcrypto.so.3 -Wl,-rpath,"$kit/lib"
echo "run.sh: probe built with $(g++ --version | head -1)"
status=0
if [ "$#" -eq 0 ]; then set -- ""; fi
for sizes in "$@"; do
  # shellcheck disable=SC2086 # "N,I,R" becomes the probe's three arguments
  LD_LIBRARY_PATH="$kit/lib:${LD_LIBRARY_PATH:-}" "$build/probe" ${sizes//,/ } || status=$?
done
exit "$status"
