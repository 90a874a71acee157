"""Sweeps and A/B comparisons from Python: the command line's tables (sweep.json, ab.json) as pandas
DataFrames, the same values for the same runs, and the refusals in Python's words."""

import json
import math
import subprocess
import sys

import numpy
import pytest

import groundtruth
from conftest import CLI, cone, readme_block

pytest.importorskip("pandas")

TALUS = [25, 35, 45]
TIMINGS = {"seconds", "cpu_ms", "gpu_ms"}


@pytest.fixture(scope="module")
def heights():
    return cone(24, peak=30.0)


def test_a_sweep_from_python_is_the_command_lines_table(heights, tmp_path):
    table = groundtruth.sweep("erosion.thermal", heights, vary={"talus_angle": TALUS}, backend="cpu", quick=True,
                              iterations=15, out=tmp_path / "python")
    assert list(table.talus_angle) == TALUS and table.talus_angle.dtype.kind == "i"
    assert list(table.columns[:3]) == ["talus_angle", "case", "outcome"]
    assert not set(table.outcome) & {"fail", "error"}
    assert (tmp_path / "python" / "sweep.html").is_file()
    # The command line's sweep of the same array: every check's value is the same in each run (the
    # references are deterministic); only the timings differ.
    numpy.save(tmp_path / "heights.npy", heights)
    finished = subprocess.run([str(CLI), "sweep", "--algorithm", "erosion.thermal", "--input",
                               str(tmp_path / "heights.npy"), "--vary", "talus_angle=" + ",".join(map(str, TALUS)),
                               "--set", "iterations=15", "--backend", "cpu", "--quiet", "--out", str(tmp_path / "cli")],
                              capture_output=True, text=True, timeout=600)
    assert finished.returncode == 0, finished.stderr
    command_line = json.loads((tmp_path / "cli" / "sweep.json").read_text())
    checks = [name for name in table.columns[3:] if name not in TIMINGS]
    assert checks and "mass.relative_drift.cpu" in checks
    for (_, row), run in zip(table.iterrows(), command_line["runs"]):
        assert int(run["params"]["talus_angle"]) == row["talus_angle"]
        for name in checks:
            expected = run["metrics"].get(name)
            assert (math.isnan(row[name]) and expected is None) or row[name] == expected, name


def test_a_sweep_of_a_descriptor_shows_flatter_slopes_at_lower_talus_angles(heights):
    """Thermal erosion moves material until no slope exceeds the talus angle (docs/erosion.md): the
    cone's flanks (72°) relax towards it, so a lower talus angle leaves a lower mean slope."""
    table = groundtruth.sweep("erosion.thermal", heights, vary={"talus_angle": [10, 40]}, backend="cpu",
                              pictures=False, reps=0, iterations=60)
    flat, steep = table.iloc[0], table.iloc[1]
    assert flat["descriptor.slope_deg.mean"] < steep["descriptor.slope_deg.mean"]


def test_an_ab_comparison_from_python_tables_a_b_and_their_difference(heights):
    table = groundtruth.ab("erosion.thermal", heights, a={"talus_angle": 25}, b={"talus_angle": 45}, backend="cpu",
                           quick=True, iterations=15)
    assert list(table.columns) == ["a", "b", "b_minus_a"]
    assert table.attrs["a"]["assignments"][-1] == "talus_angle=25" and table.attrs["b"]["outcome"] not in ("fail", "error")
    both = table.dropna()
    numpy.testing.assert_array_equal(both.b_minus_a.values, both.b.values - both.a.values)
    # The metrics that moved come first, as ab.html lists them.
    moved = (table.b_minus_a != 0) & table.b_minus_a.notna()
    assert moved.any()
    assert not (moved.values[1:] & ~moved.values[:-1]).any()


def test_a_sweep_or_ab_refuses_what_the_command_line_refuses_in_pythons_words(heights):
    with pytest.raises(groundtruth.InputError, match="vary: a dict"):
        groundtruth.sweep("erosion.thermal", heights, vary={})
    with pytest.raises(groundtruth.InputError, match="none holding a comma"):
        groundtruth.sweep("erosion.thermal", heights, vary={"neighbourhood": ["a,b"]})
    with pytest.raises(groundtruth.InputError, match="pass force=True"):
        groundtruth.sweep("erosion.thermal", heights, vary={"talus_angle": list(range(10, 75)), "strength": [0.5, 1]})
    with pytest.raises(groundtruth.InputError, match="talus_angle"):
        groundtruth.sweep("erosion.thermal", heights, vary={"talus_angle": [30, 400]})
    with pytest.raises(groundtruth.InputError, match="b: a dict"):
        groundtruth.ab("erosion.thermal", heights, a={"talus_angle": 30})
    with pytest.raises(groundtruth.InputError, match="both empty"):
        groundtruth.ab("erosion.thermal", heights, a={}, b={})
    with pytest.raises(groundtruth.InputError, match="A and B are the same variant"):  # the command line's words
        groundtruth.ab("erosion.thermal", heights, a={"talus_angle": 30}, b={"talus_angle": 30})


def test_the_readme_sweep_example_runs_as_written(tmp_path):
    """The README's notebook-style sweep prints one row per talus angle and saves its plot."""
    ran = subprocess.run([sys.executable, "-c", readme_block("python", "Sweep a parameter from Python")], cwd=tmp_path,
                         capture_output=True, text=True, timeout=600)
    assert ran.returncode == 0, ran.stderr
    lines = ran.stdout.splitlines()
    assert lines[0].split() == ["talus_angle", "outcome", "descriptor.slope_deg.mean"]
    rows = [line.split() for line in lines[1:]]
    assert [row[0] for row in rows] == ["10", "15", "20", "25", "30"]
    assert not {row[1] for row in rows} & {"fail", "error"}
    # The lowest angle relaxes most of the volcano's flanks (its mean slope is about 15°), leaving
    # the flattest terrain; from about 30° on few cells exceed the angle and the mean slope barely
    # moves (not monotonically: which cells topple first differs).
    mean_slopes = [float(row[2]) for row in rows]
    assert mean_slopes[0] < min(mean_slopes[1:])
    plot = tmp_path / "talus_sweep.png"
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
