"""The optional packages of the scientific stack (xarray, rasterio, pandas): imported when a feature
needs one, with a message naming the Debian package and pip's when it is missing. The core module
(run, check, algorithms) works without any of them."""

import importlib

# module -> (Debian 12's package, pip's)
_PACKAGES = {
    "xarray": ("python3-xarray", "xarray"),
    "rasterio": ("python3-rasterio", "rasterio"),
    "pandas": ("python3-pandas", "pandas"),
}


def require(module, feature):
    """`module`, imported; ImportError saying that `feature` needs it and how to install it."""
    try:
        return importlib.import_module(module)
    except ImportError:
        debian, pip = _PACKAGES[module]
        raise ImportError(f"{feature} needs {module}: apt install {debian} (for Debian's Python, or a venv made "
                          f"with --system-site-packages), or pip install {pip}") from None


def available(module):
    """Whether `module` imports (without importing the others' features)."""
    try:
        importlib.import_module(module)
        return True
    except ImportError:
        return False
