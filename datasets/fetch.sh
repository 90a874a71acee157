#!/usr/bin/env bash
# Fetches the real data of the project's data-sources list into datasets/real/ (git-ignored):
# the four DEMs (volcano.json from the npm package vega-datasets, jacksboro_fault_dem.npz and
# topobathy.npz from the Debian package python-matplotlib-data, elev.tif from the Debian package
# r-cran-terra) and, into datasets/real/meshes/, four ASCII OFF meshes of CGAL's demo data
# (bunny00, elephant, cow, elephant-with-holes from libcgal-demo's data.tar.gz) and, into
# datasets/real/textures/, two images of scikit-image's sample data used as colour drapes
# (astronaut.png, grass.png from the Debian package python3-skimage).
#
# Conventions
#   - Every file is pinned by SHA-256; a mismatch stops the script with an error.
#   - Beside each file: LICENSE.<stem>.txt (the package's copyright notice or licence text) and
#     <stem>.source.json (origin, SHA-256, units, grid or mesh size, licence). A stem may name a
#     subfolder of datasets/real (meshes/bunny00); the companions then lie in that subfolder.
#   - Idempotent: a file already present with the right hash and both companions is kept, so a
#     second run downloads nothing.
#   - Packages are fetched with the ordinary clients (npm pack, apt-get download) and unpacked in
#     a temporary folder, never installed. apt-get download is retried once after apt-get update.
set -euo pipefail

dataset_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
readonly dataset_dir
readonly real_dir="$dataset_dir/real"

readonly npm_spec="vega-datasets@3.2.1"
readonly mpl_deb="python-matplotlib-data=3.6.3-1"
readonly terra_deb="r-cran-terra=1.7-3-1"
readonly cgal_demo_deb="libcgal-demo=5.5.1-2"
# libcgal-demo's doc folder is a link to libcgal-dev's, so its copyright file ships in libcgal-dev.
readonly cgal_dev_deb="libcgal-dev=5.5.1-2"
readonly skimage_deb="python3-skimage=0.19.3-8"
readonly ferret_deb="ferret-datasets=7.6.0-5"
readonly mpl_sample_dir="usr/share/matplotlib/mpl-data/sample_data"
readonly terra_ex_dir="usr/lib/R/site-library/terra/ex"
readonly cgal_data_tar="usr/share/doc/libcgal-dev/data.tar.gz"
readonly cgal_copyright="usr/share/doc/libcgal-dev/copyright"
readonly skimage_data_dir="usr/lib/python3/dist-packages/skimage/data"
readonly ferret_data_dir="usr/share/ferret-vis/data"

readonly volcano_sha=49578c17a2a595a83a393a6da2cc85e3d3d4c93043e942a5e04dc113ca4a8528
readonly jacksboro_sha=d493f50a33e82a4420494c54d1fca1539d177bdc27ab190bc5fe6e92f62fb637
readonly topobathy_sha=0244e03291702df45024dcb5cacbc4f3d4cb30d72dfa7fd371c4ac61c42b4fbf
readonly elev_sha=c6a4967fe5b720499e75a3453e9814f00a416167b8e0926a4c55f5100ae4ddb2
readonly bunny00_sha=ab651cb04955c161efaeb079035a1e5e1f0e0d1f816a2df67beaea68f393ff2b
readonly elephant_sha=be4e1ea68f5f840a3d2ada69d828222e76a57d9e25b21e19a9deacd3f2328e02
readonly cow_sha=1c5a25c3047fc6b14dd0c962d3562b1796671422ab4634f9d46f9f23814cd54a
readonly elephant_with_holes_sha=0262a20c433534623af10f2b8b3aeb9067792486195cac47738bc6abea0cb8d0
readonly astronaut_sha=88431cd9653ccd539741b555fb0a46b61558b301d4110412b5bc28b5e3ea6cb5
readonly etopo60_sha=36b4cb72a01cf4c6dc155e52dca6c4ff148aea5958d056d3136fe2789646c4ad
readonly grass_sha=b6b6022426b38936c43a4ac09635cd78af074e90f42ffa8227ac8b7452d39f89

work_dir="$(mktemp -d)"
readonly work_dir
trap 'rm -rf "$work_dir"' EXIT
# apt-get download runs as the unprivileged _apt user when it can write the folder.
chmod 777 "$work_dir"

fail() {
  echo "fetch.sh: error: $*" >&2
  exit 1
}

sha256_of() {
  sha256sum "$1" | cut -d' ' -f1
}

# licence_of STEM: the path of the stem's licence notice (meshes/cow -> real/meshes/LICENSE.cow.txt).
licence_of() {
  echo "$real_dir/$(dirname "$1")/LICENSE.$(basename "$1").txt"
}

# is_current FILE STEM SHA: the file, its licence and its sidecar are present and the hash matches.
is_current() {
  [[ -f "$real_dir/$1" && -f "$(licence_of "$2")" && -f "$real_dir/$2.source.json" ]] &&
    [[ "$(sha256_of "$real_dir/$1")" == "$3" ]]
}

check_sha() {
  local actual
  actual="$(sha256_of "$1")"
  [[ "$actual" == "$2" ]] || fail "$1: SHA-256 is $actual, expected $2 (the package changed?)"
}

# install_file SOURCE FILE STEM SHA LICENSE_SOURCE: verifies SOURCE, then copies it and its licence
# into datasets/real (through a temporary name, so an interrupted copy leaves no partial file).
install_file() {
  local partial
  partial="$real_dir/$(dirname "$2")/.$(basename "$2").partial"
  check_sha "$1" "$4"
  cp "$1" "$partial"
  mv "$partial" "$real_dir/$2"
  cp "$5" "$(licence_of "$3")"
}

# apt_fetch PKG=VERSION: downloads the .deb into the work folder (once) and unpacks it there.
apt_fetch() {
  local package="${1%%=*}"
  [[ -d "$work_dir/$package" ]] && return
  if ! (cd "$work_dir" && apt-get download -q "$1"); then
    echo "fetch.sh: apt-get download $1 failed; running apt-get update and retrying once" >&2
    apt-get update -q
    (cd "$work_dir" && apt-get download -q "$1")
  fi
  mkdir "$work_dir/$package"
  dpkg-deb --fsys-tarfile "$work_dir/${package}"_*.deb | tar -x -C "$work_dir/$package"
}

# write_sidecar STEM: writes the JSON read from stdin to datasets/real/STEM.source.json.
write_sidecar() {
  cat >"$real_dir/$1.source.json"
}

fetch_volcano() {
  is_current volcano.json volcano "$volcano_sha" && { echo "volcano.json: up to date"; return; }
  (cd "$work_dir" && npm pack --silent --ignore-scripts "$npm_spec" >/dev/null)
  tar -x -C "$work_dir" -f "$work_dir"/vega-datasets-*.tgz \
    package/data/volcano.json package/package.json package/datapackage.json package/README.md
  # The npm package ships no LICENSE file: the notice is assembled from what it does ship.
  python3 - "$work_dir/package" >"$work_dir/volcano-license.txt" <<'EOF'
import json, pathlib, sys
package = pathlib.Path(sys.argv[1])
manifest = json.loads((package / "package.json").read_text())
catalog = json.loads((package / "datapackage.json").read_text())
volcano = next(r for r in catalog["resources"] if r["path"] == "volcano.json")
readme = (package / "README.md").read_text()
print(f"{manifest['name']} {manifest['version']}: package.json \"license\": {manifest['license']}")
print("Data package licences:", ", ".join(l["title"] for l in catalog.get("licenses", [])))
print()
print(readme[readme.index("## License"):].split("\n## ")[0].strip())
print()
print("datapackage.json, resource volcano.json:")
print(volcano["description"])
for source in volcano.get("sources", []):
    print(f"Source: {source['title']} <{source['path']}>")
EOF
  install_file "$work_dir/package/data/volcano.json" volcano.json volcano "$volcano_sha" \
    "$work_dir/volcano-license.txt"
  write_sidecar volcano <<EOF
{
  "file": "volcano.json",
  "origin": {"package": "npm:$npm_spec", "path": "package/data/volcano.json"},
  "sha256": "$volcano_sha",
  "licence": {"name": "BSD-3-Clause (vega-datasets); data from R's datasets::volcano", "notice": "LICENSE.volcano.txt"},
  "description": "Maunga Whau (Mt Eden), Auckland, digitised from a topographic map by Ross Ihaka",
  "format": "JSON {width, height, values[row-major]}",
  "grid": {"width": 87, "height": 61, "cell_size": "10 m (approximate, per the package)"},
  "units": {"horizontal": "m", "vertical": "m"},
  "values": {"min": 94, "max": 195},
  "no_data": "none"
}
EOF
  echo "volcano.json: fetched"
}

fetch_jacksboro() {
  is_current jacksboro_fault_dem.npz jacksboro_fault_dem "$jacksboro_sha" &&
    { echo "jacksboro_fault_dem.npz: up to date"; return; }
  apt_fetch "$mpl_deb"
  install_file "$work_dir/python-matplotlib-data/$mpl_sample_dir/jacksboro_fault_dem.npz" \
    jacksboro_fault_dem.npz jacksboro_fault_dem "$jacksboro_sha" \
    "$work_dir/python-matplotlib-data/usr/share/doc/python-matplotlib-data/copyright"
  write_sidecar jacksboro_fault_dem <<EOF
{
  "file": "jacksboro_fault_dem.npz",
  "origin": {"package": "deb:$mpl_deb", "path": "$mpl_sample_dir/jacksboro_fault_dem.npz"},
  "sha256": "$jacksboro_sha",
  "licence": {"name": "matplotlib licence (PSF-based, BSD-compatible)", "notice": "LICENSE.jacksboro_fault_dem.txt"},
  "description": "Jacksboro fault, Tennessee (USGS DEM as shipped with matplotlib)",
  "format": "npz: elevation int16 (344 rows, 403 cols), row 0 north; dx dy xmin xmax ymin ymax float64 scalars",
  "grid": {"width": 403, "height": 344, "cell_size": "dx = dy = 1/1200 degree (3 arc-seconds)",
           "longitude": [-84.41375, -84.07791666666667], "latitude": [36.44625, 36.73291666666667]},
  "units": {"horizontal": "degree (WGS84 longitude/latitude)", "vertical": "m"},
  "values": {"min": 236, "max": 1076},
  "no_data": "none"
}
EOF
  echo "jacksboro_fault_dem.npz: fetched"
}

fetch_topobathy() {
  is_current topobathy.npz topobathy "$topobathy_sha" && { echo "topobathy.npz: up to date"; return; }
  apt_fetch "$mpl_deb"
  install_file "$work_dir/python-matplotlib-data/$mpl_sample_dir/topobathy.npz" \
    topobathy.npz topobathy "$topobathy_sha" \
    "$work_dir/python-matplotlib-data/usr/share/doc/python-matplotlib-data/copyright"
  write_sidecar topobathy <<EOF
{
  "file": "topobathy.npz",
  "origin": {"package": "deb:$mpl_deb", "path": "$mpl_sample_dir/topobathy.npz"},
  "sha256": "$topobathy_sha",
  "licence": {"name": "matplotlib licence (PSF-based, BSD-compatible)", "notice": "LICENSE.topobathy.txt"},
  "description": "Vancouver Island and the Strait of Georgia, topography and bathymetry",
  "format": "npz: topo float32 (91 rows, 120 cols), row 0 south; longitude float32 (120), latitude float32 (91)",
  "grid": {"width": 120, "height": 91,
           "cell_size": "longitude 2 arc-minutes; latitude 0.02229 to 0.02144 degree (Mercator rows)",
           "longitude": [234.0167, 237.9834], "latitude": [48.0164, 49.9842]},
  "units": {"horizontal": "degree (longitude east of Greenwich, latitude)", "vertical": "m (negative below sea level)"},
  "values": {"min": -1437, "max": 2205},
  "no_data": "none"
}
EOF
  echo "topobathy.npz: fetched"
}

fetch_luxembourg() {
  is_current elev.tif elev "$elev_sha" && { echo "elev.tif: up to date"; return; }
  apt_fetch "$terra_deb"
  install_file "$work_dir/r-cran-terra/$terra_ex_dir/elev.tif" elev.tif elev "$elev_sha" \
    "$work_dir/r-cran-terra/usr/share/doc/r-cran-terra/copyright"
  write_sidecar elev <<EOF
{
  "file": "elev.tif",
  "origin": {"package": "deb:$terra_deb", "path": "$terra_ex_dir/elev.tif"},
  "sha256": "$elev_sha",
  "licence": {"name": "GPL-3+", "notice": "LICENSE.elev.txt"},
  "description": "Luxembourg elevation (example raster of the R package terra)",
  "format": "GeoTIFF int16, LZW, 1 channel; CRS EPSG:4326 (GTModelTypeGeoKey 2 = geographic)",
  "grid": {"width": 95, "height": 90, "cell_size": "1/120 degree (30 arc-seconds), ModelPixelScale tag 33550",
           "origin": "top-left corner 5.741667 E, 50.191667 N (ModelTiepoint tag 33922)"},
  "units": {"horizontal": "degree (WGS84)", "vertical": "m"},
  "values": {"min": 141, "max": 547, "valid_cells": 4608, "cells": 8550},
  "no_data": "-32768 (GDAL_NODATA tag 42113)"
}
EOF
  echo "elev.tif: fetched"
}

# cgal_mesh_notice NAME: the licence notice of one CGAL demo mesh, on stdout: what applies to
# data/meshes, the Stanford credit for the bunny, then libcgal-demo's copyright file as shipped.
cgal_mesh_notice() {
  echo "$1.off from $cgal_demo_deb, $cgal_data_tar, member data/meshes/$1.off."
  echo "The file carries no copyright notice of its own; per the copyright file below (upstream"
  echo "LICENSE), such CGAL files are licensed under Creative Commons CC0 1.0."
  if [[ "$1" == bunny00 ]]; then
    echo "The bunny is the Stanford Bunny of the Stanford 3D Scanning Repository, Stanford University"
    echo "Computer Graphics Laboratory (https://graphics.stanford.edu/data/3Dscanrep/): credit Stanford."
  fi
  echo
  echo "Copyright file of $cgal_demo_deb (its doc folder links to libcgal-dev's; shipped by $cgal_dev_deb):"
  echo
  cat "$work_dir/libcgal-dev/$cgal_copyright"
}

# fetch_cgal_mesh NAME SHA VERTICES FACES DESCRIPTION TOPOLOGY: one mesh of CGAL's demo data into
# datasets/real/meshes/NAME.off, with its licence notice and sidecar.
fetch_cgal_mesh() {
  local name="$1" sha="$2"
  is_current "meshes/$name.off" "meshes/$name" "$sha" && { echo "meshes/$name.off: up to date"; return; }
  apt_fetch "$cgal_demo_deb"
  apt_fetch "$cgal_dev_deb"
  tar -x -z -C "$work_dir" -f "$work_dir/libcgal-demo/$cgal_data_tar" "data/meshes/$name.off"
  cgal_mesh_notice "$name" >"$work_dir/$name-license.txt"
  install_file "$work_dir/data/meshes/$name.off" "meshes/$name.off" "meshes/$name" "$sha" \
    "$work_dir/$name-license.txt"
  write_sidecar "meshes/$name" <<EOF
{
  "file": "meshes/$name.off",
  "origin": {"package": "deb:$cgal_demo_deb", "path": "$cgal_data_tar", "member": "data/meshes/$name.off"},
  "sha256": "$sha",
  "licence": {"name": "CC0 1.0 (CGAL files without a notice of their own)", "notice": "LICENSE.$name.txt"},
  "description": "$5",
  "format": "ASCII OFF, triangles",
  "mesh": {"vertices": $3, "faces": $4, "topology": "$6"},
  "units": "none (model coordinates)"
}
EOF
  echo "meshes/$name.off: fetched"
}

# skimage_texture_notice NAME: the licence notice of one scikit-image sample image, on stdout: the
# docstring of skimage.data.NAME (which states the image's own licence and origin), then the
# package's copyright file as shipped.
skimage_texture_notice() {
  echo "$1.png from $skimage_deb, $skimage_data_dir/$1.png."
  echo "Its licence and origin, as the docstring of skimage.data.$1 ($skimage_data_dir/_fetchers.py) states them:"
  echo
  python3 - "$work_dir/python3-skimage/$skimage_data_dir/_fetchers.py" "$1" <<'EOF'
import ast, sys
tree = ast.parse(open(sys.argv[1]).read())
print(next(ast.get_docstring(f) for f in tree.body if isinstance(f, ast.FunctionDef) and f.name == sys.argv[2]))
EOF
  echo
  echo "Copyright file of $skimage_deb:"
  echo
  cat "$work_dir/python3-skimage/usr/share/doc/python3-skimage/copyright"
}

# fetch_skimage_texture NAME SHA CHANNELS LICENCE DESCRIPTION: one scikit-image sample image into
# datasets/real/textures/NAME.png, with its licence notice and sidecar.
fetch_skimage_texture() {
  local name="$1" sha="$2"
  is_current "textures/$name.png" "textures/$name" "$sha" && { echo "textures/$name.png: up to date"; return; }
  apt_fetch "$skimage_deb"
  skimage_texture_notice "$name" >"$work_dir/$name-license.txt"
  install_file "$work_dir/python3-skimage/$skimage_data_dir/$name.png" "textures/$name.png" "textures/$name" "$sha" \
    "$work_dir/$name-license.txt"
  write_sidecar "textures/$name" <<EOF
{
  "file": "textures/$name.png",
  "origin": {"package": "deb:$skimage_deb", "path": "$skimage_data_dir/$name.png"},
  "sha256": "$sha",
  "licence": {"name": "$4", "notice": "LICENSE.$name.txt"},
  "description": "$5",
  "format": "PNG, 8 bits per channel, $3",
  "image": {"width": 512, "height": 512, "row_0": "top"},
  "use": "colour drape of render.terrain (drape = $name): u east, v south, row 0 at the north edge"
}
EOF
  echo "textures/$name.png: fetched"
}

mkdir -p "$real_dir/meshes" "$real_dir/textures"
# ETOPO 1° global relief (issue 13: generated planets beside the Earth).
fetch_etopo60() {
  is_current etopo60.cdf etopo60 "$etopo60_sha" && { echo "etopo60.cdf: up to date"; return; }
  apt_fetch "$ferret_deb"
  install_file "$work_dir/ferret-datasets/$ferret_data_dir/etopo60.cdf" etopo60.cdf etopo60 "$etopo60_sha" \
    "$work_dir/ferret-datasets/usr/share/doc/ferret-datasets/copyright"
  write_sidecar etopo60 <<EOF
{
  "file": "etopo60.cdf",
  "origin": {"package": "deb:$ferret_deb", "path": "$ferret_data_dir/etopo60.cdf"},
  "sha256": "$etopo60_sha",
  "licence": {"name": "Ferret licence (NOAA PMEL); ETOPO5 data public domain (NOAA NGDC)", "notice": "LICENSE.etopo60.txt"},
  "description": "ETOPO 1 degree global relief, land and sea floor (Ferret's packaging of NOAA's ETOPO5)",
  "format": "netCDF-3 classic; variable ROSE float32, fill -1e34; coordinate variables ETOPO60X, ETOPO60Y",
  "grid": {"width": 360, "height": 180, "cell_size": "1 degree",
           "longitude": [20.5, 379.5], "latitude": [-89.5, 89.5], "row_order": "south row first"},
  "units": {"horizontal": "degree (longitude east, latitude north)", "vertical": "m"},
  "values": {"min": -7473, "max": 5731, "area_weighted_ocean_fraction": 0.710},
  "no_data": "-1e34 (none in the file)"
}
EOF
  echo "etopo60.cdf: fetched"
}

fetch_volcano
fetch_jacksboro
fetch_topobathy
fetch_luxembourg
fetch_etopo60
# The topology as groundtruth check-mesh measures it (tests/mesh_checks_test.cpp pins it).
fetch_cgal_mesh bunny00 "$bunny00_sha" 37706 75408 \
  "Stanford bunny (Stanford 3D Scanning Repository) as shipped in CGAL's demo data" \
  "closed 2-manifold, genus 0, consistently oriented outward, no self-intersections"
fetch_cgal_mesh elephant "$elephant_sha" 2775 5558 "elephant" \
  "closed 2-manifold, genus 3 (Euler characteristic -4), consistently oriented outward, no self-intersections"
fetch_cgal_mesh cow "$cow_sha" 2904 5804 "cow" \
  "closed 2-manifold, genus 0, consistently oriented; 101 pairs of faces cross (self-intersections)"
fetch_cgal_mesh elephant-with-holes "$elephant_with_holes_sha" 2798 4463 "elephant, open (holes in the surface)" \
  "open: 1353 boundary edges in 106 loops, genus 3 (Euler characteristic -110); 173 pairs of faces cross"
fetch_skimage_texture astronaut "$astronaut_sha" "RGB" "public domain (NASA; no known copyright restrictions)" \
  "Eileen Collins, NASA astronaut (NASA Great Images), as shipped in scikit-image's sample data"
fetch_skimage_texture grass "$grass_sha" "gray" "CC0 1.0" \
  "grass (DeviantArt linolafett, cropped to 512x512 and converted to gray by scikit-image)"
