"""Your own implementation graded from Python (groundtruth.check): the numpy thermal erosion of
examples/python passes and its leaky variant fails the ledger; a model with the BMI's methods is
driven the same way; models that break the rules are refused naming what is wrong; the pytest
helper lists the failing checks."""

import pathlib
import subprocess
import sys
import tempfile

import numpy
import pytest

import groundtruth
import groundtruth.bmi
from groundtruth.testing import assert_matches_reference
from conftest import CLI, readme_block

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"))
from thermal_numpy import thermal_step, thermal_step_leaky  # noqa: E402

VOLCANO = groundtruth.DATASETS / "real" / "volcano.json"


def statuses(result):
    return {check["name"]: check["status"] for check in result.checks}


def test_the_numpy_thermal_erosion_passes_on_the_volcano():
    result = groundtruth.check(thermal_step, "erosion.thermal", VOLCANO, talus_angle=30, iterations=24, quick=True)
    assert result.status == "pass", result.failed() or result.error
    seen = statuses(result)
    # float64 fields: graded against ref<double>, loaded with its states.
    for name in ("parity.shadow.terrain.external_vs_double", "parity.shadow.terrain.multi.external_vs_double",
                 "determinism.external", "mass.relative_drift.external"):
        assert seen[name] == "pass", name
    assert "parity.shadow.terrain.gpu_vs_float" not in seen
    assert any("thermal_step" in note for note in result.notes)
    assert set(result.fields["terrain"]) >= {"cpu", "external"}


def test_the_same_step_in_float32_is_graded_against_ref_float():
    result = groundtruth.check(thermal_step, "erosion.thermal", VOLCANO, dtype="float32", talus_angle=30,
                               iterations=8, quick=True)
    assert result.status == "pass", result.failed() or result.error
    assert statuses(result)["parity.shadow.terrain.external_vs_float"] == "pass"


def test_material_lost_at_the_border_fails_the_ledger_and_the_shadow_step():
    result = groundtruth.check(thermal_step_leaky, "erosion.thermal", VOLCANO, talus_angle=30, iterations=24,
                               quick=True)
    assert result.status == "fail"
    seen = statuses(result)
    assert seen["mass.relative_drift.external"] == "fail"
    assert seen["parity.shadow.terrain.external_vs_double"] == "fail"


class ThermalBmi:
    """A model with bmipy's method names around the numpy step (what a landlab or pymt user has)."""

    def __init__(self):
        self._inner = None

    def initialize(self, config_file):
        self._inner = groundtruth._StepModel(thermal_step, [{"name": "terrain", "unit": "m"}], "float64")
        self._inner.initialize(config_file)

    def __getattr__(self, name):
        return getattr(self._inner, name)


def test_a_model_with_the_bmi_methods_is_graded_the_same_way():
    result = groundtruth.check(ThermalBmi, "erosion.thermal", VOLCANO, talus_angle=30, iterations=8, quick=True)
    assert result.status == "pass", result.failed() or result.error
    assert any("ThermalBmi" in note for note in result.notes)


class WrongUnits(ThermalBmi):
    def get_var_units(self, name):
        return "ft"


class Raising(ThermalBmi):
    def update(self):
        raise RuntimeError("my model gave up")


def wrong_shape(state, params):
    return {"terrain": state["terrain"][1:]}


def test_models_that_break_the_rules_are_refused_or_end_their_case():
    with pytest.raises(groundtruth.InputError, match=r"'terrain': units 'ft', expected 'm'"):
        groundtruth.check(WrongUnits, "erosion.thermal", VOLCANO, iterations=4, quick=True)
    with pytest.raises(groundtruth.InputError, match="is not one"):
        groundtruth.check(thermal_step, "noise.fbm", quick=True)
    with pytest.raises(groundtruth.InputError, match="neither a model"):
        groundtruth.check(42, "erosion.thermal", VOLCANO, quick=True)
    with pytest.raises(groundtruth.InputError, match="float32 or float64"):
        groundtruth.check(thermal_step, "erosion.thermal", VOLCANO, dtype="int16", quick=True)
    raised = groundtruth.check(Raising, "erosion.thermal", VOLCANO, iterations=4, quick=True)
    assert raised.status == "error" and "my model gave up" in raised.error
    shaped = groundtruth.check(wrong_shape, "erosion.thermal", VOLCANO, iterations=4, quick=True)
    assert shaped.status == "error" and "shape" in shaped.error


def test_the_pytest_helper_lists_the_failing_checks():
    assert_matches_reference(thermal_step, "erosion.thermal", VOLCANO, talus_angle=30, iterations=8)
    with pytest.raises(AssertionError, match=r"mass\.relative_drift\.external: .* > bound"):
        assert_matches_reference(thermal_step_leaky, "erosion.thermal", VOLCANO, talus_angle=30, iterations=8)


@pytest.mark.parametrize("precision, versus", [("float64", "double"), ("float32", "float")])
def test_the_reference_behind_the_bmi_passes_its_own_round_trip(precision, versus):
    """The pipe model's reference handed over as an outside model: loaded, stepped and read back
    through the BMI as anyone's model is, it must pass (water and terrain, bit for bit)."""
    reference = groundtruth.bmi.Reference("erosion.pipe", precision)
    result = groundtruth.check(reference, "erosion.pipe", VOLCANO, steps=12, rain_rate=0.002, quick=True)
    assert result.status in ("pass", "inconclusive"), result.failed() or result.error
    seen = statuses(result)
    for field in ("terrain", "water"):
        assert seen[f"parity.shadow.{field}.external_vs_{versus}"] == "pass", field
    # The BMI hands over the state alone: ledger terms that read the model's own records do not apply.
    assert seen["determinism.external"] == "pass"


def test_the_jako_reference_behind_the_bmi_steps_the_hardness_map_it_is_handed():
    """Jákó's hardness map is a read-only field of the state: the harness hands it to an outside
    model with the terrain, so the reference behind the BMI, checked with a banded map, steps that
    map (bit for bit against ref<double>, whose terrain the map changes) and hands it back as set."""
    bands = numpy.repeat([[0.0, 0.5, 1.0, 1.5]], 61, axis=0).repeat(22, axis=1)[:, :87]
    params = dict(iterations=12, talus_angle=20, hardness_talus=0.3, rate=0.5, quick=True)
    reference = groundtruth.bmi.Reference("erosion.thermal_jako")
    result = groundtruth.check(reference, "erosion.thermal_jako", VOLCANO, fields={"hardness": bands}, **params)
    assert result.status == "pass", result.failed() or result.error
    seen = statuses(result)
    for name in ("parity.shadow.terrain.external_vs_double", "parity.shadow.hardness.external_vs_double",
                 "state.hardness.unchanged.external", "state.hardness.unchanged.cpu"):
        assert seen[name] == "pass", name
    numpy.testing.assert_array_equal(result.fields["hardness"]["external"], bands)
    uniform = groundtruth.run("erosion.thermal_jako", VOLCANO, backend="cpu", **params)
    assert numpy.abs(uniform.fields["terrain"]["cpu"] - result.fields["terrain"]["cpu"]).max() > 0.1, \
        "the map should change the terrain, or the parity above would not show that the model read it"


def test_the_readme_examples_run_as_written():
    """The README's Python block, run from the root of the checkout, prints what its comments say; its
    command line, with `groundtruth` and build/release/ this build's, passes."""
    root = pathlib.Path(__file__).resolve().parents[2]
    ran = subprocess.run([sys.executable, "-c", readme_block("python", "Check your own implementation")], cwd=root,
                         capture_output=True, text=True, timeout=600)
    assert ran.returncode == 0, ran.stderr
    lines = ran.stdout.splitlines()
    assert lines[0] == "pass pass"
    assert lines[1].startswith("fail [") and "'mass.relative_drift.external'" in lines[1]
    assert lines[2] == "pass"
    command = readme_block("sh", "Check your own implementation").replace("\\\n", " ").split()
    assert command[:2] == ["groundtruth", "run"]
    build = CLI.parent
    arguments = [word.replace("build/release/", f"{build}/") for word in command[1:]]
    with tempfile.TemporaryDirectory() as scratch:
        finished = subprocess.run([str(CLI), *arguments, "--out", scratch + "/report", "--quiet"], cwd=root,
                                  capture_output=True, text=True, timeout=600)
    assert finished.returncode == 0, finished.stdout + finished.stderr
