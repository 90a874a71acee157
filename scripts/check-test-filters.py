#!/usr/bin/env python3
"""Lint: every alternative of a test preset's name filter in CMakePresets.json (exclude or include)
still names a test, and the long tier is one pattern: what the release preset leaves out is what
release-long runs, so that the two together run every test once.

A test renamed or split leaves its old name in the filter, matching nothing, and the test it was
meant to keep out runs after all (CI's debug-asan run once ran the split pipe suite under the
sanitizers, both halves past ctest's limit), or the test meant for the long tier runs nowhere.

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
    by_name = {preset["name"]: preset for preset in presets.get("testPresets", [])}
    for preset in by_name.values():
        for which in ("exclude", "include"):
            pattern = preset.get("filter", {}).get(which, {}).get("name")
            for alternative in pattern.split("|") if pattern else []:
                if not any(re.search(alternative, name) for name in names):
                    unmatched.append(f"{preset['name']} ({which}): {alternative!r} matches none of the {len(names)} tests")
    left_out = by_name["release"]["filter"]["exclude"]["name"]
    long_tier = by_name["release-long"]["filter"]["include"]["name"]
    if left_out != long_tier:
        unmatched.append(f"release leaves out {left_out!r} but release-long runs {long_tier!r}")
    if unmatched:
        print("check-test-filters: a filter names tests that no longer exist, or the tiers differ:", file=sys.stderr)
        for line in unmatched:
            print("  " + line, file=sys.stderr)
        sys.exit(1)
    print(f"check-test-filters: every filter alternative names a test, the long tier is one pattern ({len(names)} tests)")


main()
