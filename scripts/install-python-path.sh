#!/usr/bin/env bash
# Makes `import groundtruth` work in Debian's Python: writes groundtruth.pth, naming BUILD/python
# (where CMake lays out the package), into the first site-packages folder of /usr/bin/python3
# that this user may write (/usr/local/lib/python3.X/dist-packages as root), else into the user's
# own site-packages. Running it again replaces the file. Usage: install-python-path.sh BUILD
set -euo pipefail
build=$(cd "${1:?usage: install-python-path.sh BUILD}" && pwd)
package="$build/python"
if [ ! -f "$package/groundtruth/__init__.py" ]; then
  echo "install-python-path: $package/groundtruth is not built: build the preset first" >&2
  exit 2
fi
python=/usr/bin/python3
folder=$("$python" - <<'PY'
import os, site, sys
candidates = [p for p in site.getsitepackages() if p.startswith("/usr/local")] + [site.getusersitepackages()]
for folder in candidates:
    parent = folder
    while not os.path.exists(parent):
        parent = os.path.dirname(parent)
    if os.access(parent, os.W_OK):
        print(folder)
        sys.exit(0)
sys.exit("no site-packages folder of this Python is writable")
PY
)
mkdir -p "$folder"
printf '%s\n' "$package" > "$folder/groundtruth.pth.tmp"
mv "$folder/groundtruth.pth.tmp" "$folder/groundtruth.pth"
echo "install-python-path: $folder/groundtruth.pth -> $package"
"$python" -c "import groundtruth; print('install-python-path: import groundtruth works,', len(groundtruth.algorithms()), 'algorithms')"
