"""The README's five-minute tutorial, run as written: every shell block marked
`<!-- run as written by python/tests/test_readme_tutorial.py -->` is taken from the README, each of
its commands run from the root of the checkout with this build's `groundtruth` first on PATH, and
held to the exit status its comment states (`# exit N`) and to what the tutorial's text says will
be seen. The README writes its reports under /tmp/gt/; the test puts them in a temporary folder
instead, so nothing is written anywhere else."""

import os
import pathlib
import re
import shlex
import subprocess

import pytest

from conftest import CLI

ROOT = pathlib.Path(__file__).resolve().parents[2]
MARKER = "<!-- run as written by python/tests/test_readme_tutorial.py"
README_OUT = "/tmp/gt/"


def tutorial_commands():
    """Each marked block's commands in order: (command line, expected exit status)."""
    readme = (ROOT / "README.md").read_text()
    commands = []
    for part in readme.split(MARKER)[1:]:
        block = part.split("```sh\n", 1)[1].split("```", 1)[0]
        assert part.split("```sh\n", 1)[0].count("\n") == 1, "the marker stands right above its block"
        for line in block.replace("\\\n", " ").splitlines():
            if not line.strip():
                continue
            command, _, comment = line.partition("#")
            status = re.match(r"\s*exit (\d)\b", comment)
            assert status, f"every command states its exit status (# exit N): {line}"
            commands.append((command.strip(), int(status.group(1))))
    return commands


COMMANDS = tutorial_commands()


def test_the_tutorial_has_its_steps():
    words = [shlex.split(command) for command, _ in COMMANDS]
    assert all(word[0] == "groundtruth" for word in words), "the tutorial runs groundtruth alone"
    subcommands = [word[1] for word in words]
    assert subcommands.count("run") >= 3 and "list" in subcommands and "stats" in subcommands
    for word in words:
        if word[1] == "run":
            out = word[word.index("--out") + 1]
            assert out.startswith(README_OUT), f"every report goes under {README_OUT}: {out}"


def test_the_readme_stays_a_guide():
    """A user's guide that fits a sitting (issue 37): tasks first, theory in docs/. Under 250 lines,
    the tutorial within its first 120, and every docs/ page it links exists."""
    readme = (ROOT / "README.md").read_text()
    lines = readme.splitlines()
    assert len(lines) < 250, f"the README has {len(lines)} lines: move details to docs/"
    tutorial = next(number for number, line in enumerate(lines) if line.startswith("## A five-minute tutorial"))
    assert tutorial < 120, f"the tutorial starts at line {tutorial + 1}"
    for page in set(re.findall(r"\]\((docs/[^)#]+)", readme)):
        assert (ROOT / page).is_file(), f"the README links {page}, which does not exist"


@pytest.fixture(scope="module")
def ran(tmp_path_factory):
    """Every command of the tutorial, in order, into one temporary folder: {out folder or
    subcommand: what the terminal showed, stdout then stderr}."""
    scratch = tmp_path_factory.mktemp("tutorial")
    environment = dict(os.environ, PATH=f"{CLI.parent}{os.pathsep}{os.environ.get('PATH', '')}")
    results = {}
    for command, expected in COMMANDS:
        line = command.replace(README_OUT, f"{scratch}/")
        finished = subprocess.run(["bash", "-c", line], cwd=ROOT, env=environment, capture_output=True,
                                  text=True, timeout=300)
        assert finished.returncode == expected, f"{command}: exit {finished.returncode}\n{finished.stdout}{finished.stderr}"
        words = shlex.split(command)
        key = words[words.index("--out") + 1][len(README_OUT):] if "--out" in words else words[1]
        results[key] = finished.stdout + finished.stderr
    results["folder"] = scratch
    return results


def test_the_quick_tier_passes(ran):
    """Step 1: two cases, two passes, and the report's four files."""
    listed = ran["list"]
    assert "erosion.thermal.spec.example_3x3" in listed and "quick" in listed and "talus_angle" in listed
    assert "2 cases: 2 pass, 0 warn" in ran["thermal"]
    for file in ("index.html", "report.md", "report.json", "junit.xml"):
        assert (ran["folder"] / "thermal" / file).is_file(), file


def test_a_failure_names_its_checks(ran):
    """Step 2: the mutant's run exits 1 (checked above); the terminal and report.md name the failing
    checks the tutorial quotes, with value and bound; the listed failure is marked expected."""
    terminal = ran["mutant"]
    assert "mass.relative_drift.cpu = 1.44339 (bound 3.83126e-16)" in terminal
    report = (ran["folder"] / "mutant" / "report.md").read_text()
    for check in ("mass.relative_drift.cpu", "spec.cells.cpu"):
        assert re.search(rf"\| {re.escape(check)} \|[^\n]*\*\*fail\*\*", report), check
    holes = ran["holes"]
    assert "cave.marching_cubes.solid.block12 (expected failure)" in holes
    assert "mesh.closed.cpu" in holes
    assert "**fail** (expected)" in (ran["folder"] / "holes" / "report.md").read_text()


def test_your_own_dem_runs(ran):
    """Step 3: stats measures the DEM; the ad-hoc run says what it read and writes its fields."""
    assert "hypsometric integral" in ran["stats"]
    said = ran["mine"]
    assert "3942 cells invalid" in said and "598.56 m x 921.45 m" in said and "int16" in said
    case = ran["folder"] / "mine" / "adhoc.erosion.thermal.elev"
    for file in ("fields.json", "terrain_input.npy", "terrain_cpu.npy", "terrain_cpu_float.npy", "terrain_cpu.exr"):
        assert (case / file).is_file(), file
    assert (ran["folder"] / "mine" / "report.md").is_file()


def test_your_own_outputs_are_graded(ran):
    """Step 4's outputs to judge: the float mesh passes (exit 0, checked above), the flipped
    triangle and the bright patch fail the checks the text names, compare-mesh names the topology."""
    assert "mesh.oriented.candidate = 3 (bound 0)" in ran["flipped"]
    assert "image.share_beyond_tolerance_outside_edges.candidate_vs_cpu" in ran["patch"]
    assert "spec.phong_quad.candidate" in ran["patch"]
    assert "watertight_and_oriented (true against false)" in ran["compare-mesh"]
    assert "1 pass" in ran["my_mesh"]
