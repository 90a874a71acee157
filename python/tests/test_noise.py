"""The noise twins from Python: every noise.* algorithm samples its field on the grid asked for,
both twins, with the driver's parity checks, and the samples handed back are the noise's."""

import numpy
import pytest

import groundtruth

NOISE = sorted(a["name"] for a in groundtruth.algorithms() if a["name"].startswith("noise."))


def test_there_is_noise_to_test():
    assert len(NOISE) >= 8


@pytest.mark.parametrize("algorithm", NOISE)
def test_each_noise_samples_its_grid_on_both_twins_and_they_agree(algorithm):
    result = groundtruth.run(algorithm, size=(24, 16))
    assert result.status not in ("fail", "error"), result.failed() or result.error
    value = result.fields["value"]
    assert {"cpu", "gpu"} <= set(value)
    for backend in ("cpu", "gpu"):
        assert value[backend].shape == (16, 24)  # (rows, columns) = (height, width)
        assert numpy.isfinite(value[backend]).all()
        assert value[backend].std() > 0.0, "noise is not constant"
    assert any(check["name"].startswith("parity.") and check["status"] == "pass" for check in result.checks)


@pytest.mark.parametrize("algorithm", ["noise.simplex2", "noise.simplex3", "noise.perlin3"])
def test_a_basis_noise_stays_within_its_unit_amplitude(algorithm):
    # Simplex and improved Perlin noise are scaled to [-1, 1] by their constants (70, 32, and the
    # gradient set's bound); the samples of the double reference stay inside it.
    result = groundtruth.run(algorithm, size=(32, 32), backend="cpu", step=0.37)
    assert numpy.abs(result.fields["value"]["cpu"]).max() <= 1.0


def test_the_step_parameter_moves_the_samples():
    # The origin sample is the same; one step further along x it is the sample of the other run
    # at twice the distance.
    near = groundtruth.run("noise.simplex2", size=(8, 1), backend="cpu", step=0.1).fields["value"]["cpu"]
    far = groundtruth.run("noise.simplex2", size=(8, 1), backend="cpu", step=0.2).fields["value"]["cpu"]
    assert near[0, 0] == far[0, 0]
    numpy.testing.assert_array_equal(near[0, 2::2][:3], far[0, 1:4])
