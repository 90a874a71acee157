"""The declarations Python sees are the command line's: every algorithm, every parameter with its
kind, default, range or choices and unit."""

import json
import subprocess

import pytest

import groundtruth
from conftest import CLI, cli_message


def cli_listing():
    finished = subprocess.run([str(CLI), "list", "--json"], capture_output=True, text=True, check=True, timeout=120)
    return json.loads(finished.stdout)["algorithms"]


def test_every_algorithm_of_the_command_line_is_declared_alike():
    assert groundtruth.algorithms() == cli_listing()


@pytest.mark.parametrize("algorithm", [a["name"] for a in groundtruth.algorithms()])
def test_every_default_lies_in_its_declared_range(algorithm):
    for name, spec in groundtruth.parameters(algorithm).items():
        assert spec["name"] == name
        assert spec["unit"] is not None
        if spec["kind"] in ("real", "integer"):
            assert spec["min"] <= spec["default"] <= spec["max"], spec
        elif spec["kind"] == "choice":
            assert spec["default"] in spec["choices"], spec
        else:
            assert spec["kind"] == "boolean" and isinstance(spec["default"], bool), spec


def test_an_unknown_algorithm_is_refused_with_the_command_lines_message(tmp_path):
    status, cli = cli_message(["run", "--algorithm", "erosion.nope", "--size", "8x8", "--out", str(tmp_path / "o")])
    assert status == 2
    with pytest.raises(groundtruth.InputError) as refused:
        groundtruth.parameters("erosion.nope")
    assert str(refused.value) == cli
    with pytest.raises(groundtruth.InputError) as refused:
        groundtruth.run("erosion.nope", size=(8, 8))
    assert str(refused.value) == cli


def test_stepped_algorithms_declare_their_state_once_with_units():
    """The state the stepped runner compares, exports and pictures, as the command line lists it."""
    stepped = {a["name"]: a for a in groundtruth.algorithms() if a["kind"] == "stepped"}
    assert {"erosion.thermal", "erosion.thermal_jako", "erosion.pipe"} <= set(stepped)
    for name, algorithm in stepped.items():
        fields = algorithm["state"]
        assert fields, name
        assert len({f["name"] for f in fields}) == len(fields), name
        for field in fields:
            assert field["unit"] and field["meaning"], (name, field)
            assert field["components"] >= 1, (name, field)
    water = next(f for f in stepped["erosion.pipe"]["state"] if f["name"] == "water")
    assert (water["unit"], water["standard_name"]) == ("m", "surface_water__depth")
    outflow = next(f for f in stepped["erosion.pipe"]["state"] if f["name"] == "outflow")
    assert outflow["extent"] == "cell x pipe" and outflow["component_names"] == ["L", "R", "T", "B"]
    assert all("state" not in a for a in groundtruth.algorithms() if a["kind"] != "stepped")
