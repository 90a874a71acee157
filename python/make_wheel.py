#!/usr/bin/env python3
"""Packs the built package folder (build/<preset>/python/groundtruth: the pure-Python files and
_core's shared library) as a wheel for the Python that runs this script, with `wheel pack`
(Debian's python3-wheel), so that

    pip install --no-index build/release/python/dist/groundtruth-*.whl

installs it into a venv or a conda environment of that Python version offline.

The wheel is for this machine, not one to publish: _core links the system's libraries
(OpenImageIO, Mesa, CGAL's GMP, ...) and names this checkout's data sets and command line, so its
platform tag is the plain linux_<arch>, never manylinux. It requires numpy; xarray, rasterio and
pandas are extras (the features that need them say so when they are missing).

usage: make_wheel.py PACKAGE_DIR VERSION WHEEL   WHEEL: the file to write, named as PEP 427 says
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

SUMMARY = "Grades terrain and cave graphics algorithms (GPU twins, your own implementations) against exact references"
EXTRAS = {"xarray": ["xarray"], "rasterio": ["rasterio"], "pandas": ["pandas"], "test": ["pytest"]}


def metadata(version):
    lines = ["Metadata-Version: 2.1", "Name: groundtruth", f"Version: {version}", f"Summary: {SUMMARY}",
             f"Requires-Python: =={sys.version_info[0]}.{sys.version_info[1]}.*", "Requires-Dist: numpy"]
    for extra, requirements in EXTRAS.items():
        lines.append(f"Provides-Extra: {extra}")
        lines += [f'Requires-Dist: {requirement}; extra == "{extra}"' for requirement in requirements]
    return "\n".join(lines) + "\n"


def wheel_file(tag):
    return f"Wheel-Version: 1.0\nGenerator: groundtruth python/make_wheel.py\nRoot-Is-Purelib: false\nTag: {tag}\n"


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: make_wheel.py PACKAGE_DIR VERSION WHEEL")
    package, version, wheel = pathlib.Path(sys.argv[1]), sys.argv[2], pathlib.Path(sys.argv[3])
    name_parts = wheel.name[:-len(".whl")].split("-")
    if len(name_parts) != 5 or name_parts[:2] != ["groundtruth", version]:
        sys.exit(f"make_wheel: {wheel.name} is not groundtruth-{version}-<python>-<abi>-<platform>.whl")
    tag = "-".join(name_parts[2:])
    with tempfile.TemporaryDirectory(prefix="groundtruth-wheel-") as scratch:
        tree = pathlib.Path(scratch) / f"groundtruth-{version}"
        shutil.copytree(package, tree / "groundtruth", ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        info = tree / f"groundtruth-{version}.dist-info"
        info.mkdir()
        (info / "METADATA").write_text(metadata(version))
        (info / "WHEEL").write_text(wheel_file(tag))
        packed = pathlib.Path(scratch) / "dist"
        packed.mkdir()
        subprocess.run([sys.executable, "-m", "wheel", "pack", str(tree), "-d", str(packed)], check=True,
                       stdout=subprocess.DEVNULL)
        made = list(packed.glob("*.whl"))
        if [path.name for path in made] != [wheel.name]:
            sys.exit(f"make_wheel: wheel pack made {[path.name for path in made]}, expected {wheel.name}")
        wheel.parent.mkdir(parents=True, exist_ok=True)
        # One wheel in the folder, so that the README's glob names it: an earlier version's goes.
        for old in wheel.parent.glob("groundtruth-*.whl"):
            if old.name != wheel.name:
                old.unlink()
        staged = wheel.with_name(wheel.name + ".tmp")
        shutil.copyfile(made[0], staged)
        staged.replace(wheel)


main()
