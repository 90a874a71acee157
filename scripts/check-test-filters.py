#!/usr/bin/env python3
"""Lint: every alternative of a test preset's exclude filter in CMakePresets.json still names a test.

A test renamed or split leaves its old name in the filter, matching nothing, and the test it was
meant to keep out runs after all (CI's debug-asan run once ran the split pipe suite under the
sanitizers, both halves past ctest's limit).

    scripts/check-test-filters.py BUILD_DIR   the tests `ctest --test-dir BUILD_DIR -N` lists
                                              (ctest: Lint.TestFilters, on the release build)
"""
import json
import pathlib
import re
import subprocess
import sys


def test_names(build):
    listing = subprocess.run(["ctest", "--test-dir", build, "-N"], check=True, capture_output=True, text=True).stdout
    return [m.group(1) for m in (re.match(r"\s*Test\s+#\d+: (\S+)", line) for line in listing.splitlines()) if m]


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check-test-filters.py BUILD_DIR")
    names = test_names(sys.argv[1])
    if not names:
        sys.exit("check-test-filters: ctest listed no tests")
    presets = json.loads((pathlib.Path(__file__).resolve().parent.parent / "CMakePresets.json").read_text())
    unmatched = []
    for preset in presets.get("testPresets", []):
        pattern = preset.get("filter", {}).get("exclude", {}).get("name")
        for alternative in pattern.split("|") if pattern else []:
            if not any(re.search(alternative, name) for name in names):
                unmatched.append(f"{preset['name']}: {alternative!r} matches none of the {len(names)} tests")
    if unmatched:
        print("check-test-filters: an exclude filter names tests that no longer exist:", file=sys.stderr)
        for line in unmatched:
            print("  " + line, file=sys.stderr)
        sys.exit(1)
    print(f"check-test-filters: every exclude alternative names a test ({len(names)} tests)")


main()
