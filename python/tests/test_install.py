"""The module as users install it: the wheel (python/make_wheel.py) in a venv, its metadata, a venv
without the system's packages, another Python version, and the optional packages missing."""

import os
import pathlib
import shutil
import subprocess
import sys
import zipfile

import pytest

import groundtruth
from conftest import readme_block

# ctest runs the suite in the venv that python.venv_install made from the wheel (python/CMakeLists.txt)
# and names both; a developer's plain pytest run from the build tree has neither.
INSTALLED_IN = os.environ.get("GT_INSTALLED_IN")
WHEEL = pathlib.Path(os.environ["GT_WHEEL"]) if "GT_WHEEL" in os.environ else None
needs_wheel = pytest.mark.skipif(WHEEL is None, reason="GT_WHEEL unset: run through ctest, which builds the wheel")


@pytest.mark.skipif(INSTALLED_IN is None, reason="GT_INSTALLED_IN unset: not run in ctest's venv")
def test_the_suite_imports_the_module_the_wheel_installed_in_its_venv():
    venv = pathlib.Path(INSTALLED_IN).resolve()
    assert pathlib.Path(sys.prefix).resolve() == venv
    package = pathlib.Path(groundtruth.__file__).resolve().parent
    assert venv in package.parents, f"groundtruth imported from {package}, not from the venv {venv}"
    assert pathlib.Path(groundtruth._core.__file__).resolve().parent == package
    # Installed elsewhere, it still finds this build's command line and data sets.
    assert groundtruth.COMMAND_LINE.is_file() and os.access(groundtruth.COMMAND_LINE, os.X_OK)
    assert (groundtruth.DATASETS / "expectations.txt").is_file()


@needs_wheel
def test_the_readmes_install_lines_work_in_a_fresh_venv(tmp_path):
    """The README's two lines, run as written in an empty folder (build/release/ being this build)."""
    lines = [line.split("#")[0].strip() for line in readme_block("sh", "Sweep a parameter from Python").splitlines()]
    lines = [line for line in lines if line]
    assert lines[0] == "/usr/bin/python3 -m venv --system-site-packages env"
    assert lines[1].startswith("env/bin/pip install --no-index build/release/python/dist/groundtruth-")
    build = WHEEL.parents[2]
    for line in lines:
        finished = subprocess.run(["bash", "-c", line.replace("build/release/", f"{build}/")], cwd=tmp_path,
                                  capture_output=True, text=True, timeout=300)
        assert finished.returncode == 0, f"{line}: {finished.stderr}"
    imported = subprocess.run([str(tmp_path / "env/bin/python"), "-c", "import groundtruth; print(groundtruth.__file__)"],
                              capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert imported.returncode == 0, imported.stderr
    assert pathlib.Path(imported.stdout.strip()).resolve().is_relative_to((tmp_path / "env").resolve())


@needs_wheel
def test_the_wheel_declares_its_python_numpy_and_the_optional_extras():
    with zipfile.ZipFile(WHEEL) as wheel:
        names = wheel.namelist()
        info = f"groundtruth-{groundtruth.__version__}.dist-info"
        metadata = wheel.read(f"{info}/METADATA").decode()
        record = wheel.read(f"{info}/RECORD").decode()
    assert any(name.startswith("groundtruth/_core.") and name.endswith(".so") for name in names)
    assert f"Requires-Python: =={sys.version_info[0]}.{sys.version_info[1]}.*" in metadata.splitlines()
    assert "Requires-Dist: numpy" in metadata.splitlines()
    for extra in ("xarray", "rasterio", "pandas"):
        assert f'Requires-Dist: {extra}; extra == "{extra}"' in metadata.splitlines()
    # Every file of the package is listed with its hash, as pip checks.
    assert all(f"{name}," in record for name in names if not name.endswith("/RECORD"))


@needs_wheel
def test_a_venv_without_the_system_packages_installs_it_and_says_numpy_is_missing(tmp_path):
    """Offline, a venv without the system's packages cannot get numpy (nor pytest); the wheel still
    installs (without its dependencies) and the import says what to install."""
    venv = tmp_path / "bare"
    subprocess.run([sys._base_executable, "-m", "venv", str(venv)], check=True, timeout=300)
    subprocess.run([str(venv / "bin/pip"), "install", "--quiet", "--no-index", "--no-deps", "--no-cache-dir",
                    "--disable-pip-version-check", str(WHEEL)], check=True, timeout=300)
    imported = subprocess.run([str(venv / "bin/python"), "-c", "import groundtruth"], capture_output=True, text=True,
                              timeout=300, cwd=tmp_path)
    assert imported.returncode != 0
    assert "groundtruth needs numpy: apt install python3-numpy" in imported.stderr
    assert list((venv / "lib").glob("python3.*/site-packages/groundtruth/_core.*.so"))


def test_another_python_version_is_refused_naming_both(tmp_path):
    """The module as built for Python 3.99 (its _build.py says so), imported by this one."""
    package = pathlib.Path(groundtruth.__file__).resolve().parent
    copy = tmp_path / "groundtruth"
    shutil.copytree(package, copy, ignore=shutil.ignore_patterns("__pycache__"))
    (copy / "_build.py").write_text(f"PYTHON_VERSION = (3, 99)\nVERSION = {groundtruth.__version__!r}\n")
    imported = subprocess.run([sys.executable, "-c", "import groundtruth"], capture_output=True, text=True, timeout=300,
                              cwd=tmp_path, env=dict(os.environ, PYTHONPATH=str(tmp_path)))
    assert imported.returncode != 0
    running = f"{sys.version_info[0]}.{sys.version_info[1]}"
    assert "was built for Python 3.99, and this is Python " + running in imported.stderr


def test_without_xarray_rasterio_and_pandas_runs_work_and_features_name_the_package(tmp_path):
    """The optional packages hidden (None in sys.modules makes their import fail): a run still works;
    each feature that needs one says which Debian package (and pip's) to install."""
    script = """
import sys
for name in ("xarray", "rasterio", "pandas"):
    sys.modules[name] = None
import numpy, groundtruth
result = groundtruth.run("erosion.thermal", numpy.outer(numpy.arange(12.0), numpy.ones(12)), backend="cpu", quick=True)
print(result.check("mass.relative_drift.cpu")["status"])
for call in (result.to_xarray, result.checks_table, lambda: result.to_geotiff("x.tif"),
             lambda: groundtruth.sweep("erosion.thermal", vary={"talus_angle": [30, 40]})):
    try:
        call()
    except ImportError as error:
        print(error)
"""
    ran = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300, cwd=tmp_path)
    assert ran.returncode == 0, ran.stderr
    lines = ran.stdout.splitlines()
    assert lines[0] == "pass"
    assert lines[1].startswith("Result.to_xarray needs xarray: apt install python3-xarray")
    assert lines[2].startswith("Result.checks_table needs pandas: apt install python3-pandas")
    assert lines[3].startswith("Result.to_geotiff needs rasterio: apt install python3-rasterio")
    assert lines[4].startswith("groundtruth.sweep needs pandas: apt install python3-pandas")
    assert not (tmp_path / "x.tif").exists()
