"""Bad input from Python: a groundtruth.InputError (a ValueError) carrying the command line's
message, never a crash, and nothing written. Where the command line has the same input (an array
saved as a .npy file, a --set), the two messages are compared word for word."""

import pathlib

import numpy
import pytest

import groundtruth
from conftest import cli_message, cone


def refusal(tmp_path, *args, **kwargs):
    """The InputError message of a Python run, checking it left no report behind."""
    out = tmp_path / "python_report"
    with pytest.raises(groundtruth.InputError) as refused:
        groundtruth.run(*args, out=out, **kwargs)
    assert isinstance(refused.value, ValueError)
    assert not out.exists()
    return str(refused.value)


def cli_refusal_of_array(tmp_path, array, *arguments):
    """The command line's message for the same array saved as heights.npy, its path read as
    'heights' (the name Python gives the array)."""
    path = tmp_path / "heights.npy"
    numpy.save(path, array)
    status, message = cli_message(["run", "--algorithm", "erosion.thermal", "--input", str(path), *arguments,
                                   "--out", str(tmp_path / "cli_report")])
    assert status == 2
    assert not (tmp_path / "cli_report").exists()
    return message.replace(str(path), "heights")


@pytest.mark.parametrize("dtype", ["complex128", "bool"])
def test_an_array_of_a_dtype_the_reader_does_not_take_is_refused_as_on_the_command_line(tmp_path, dtype):
    array = numpy.ones((8, 8), dtype=dtype)
    message = refusal(tmp_path, "erosion.thermal", array)
    assert "unsupported .npy dtype" in message
    assert message == cli_refusal_of_array(tmp_path, array)


def test_integers_float64_cannot_hold_exactly_are_refused(tmp_path):
    array = numpy.full((8, 8), 2**53 + 1, dtype=numpy.int64)
    assert "beyond 2**53" in refusal(tmp_path, "erosion.thermal", array)


@pytest.mark.parametrize("reps", [-1, 101, 1.5, True])
def test_a_repetition_count_that_is_not_0_to_100_is_refused(tmp_path, reps):
    assert "reps" in refusal(tmp_path, "erosion.thermal", cone(8), reps=reps)


def test_an_object_array_is_refused_without_pickling():
    with pytest.raises(groundtruth.InputError, match=r"heights: unsupported \.npy dtype '\|O'"):
        groundtruth.run("erosion.thermal", numpy.array([[1.0, "a"], [2.0, 3.0]], dtype=object))


@pytest.mark.parametrize("shape", [(16,), (4, 4, 4), (0, 5)])
def test_an_array_that_is_not_a_non_empty_grid_is_refused_as_on_the_command_line(tmp_path, shape):
    array = numpy.ones(shape)
    message = refusal(tmp_path, "erosion.thermal", array)
    assert "2-D array" in message
    assert message == cli_refusal_of_array(tmp_path, array)


def test_an_array_of_no_data_only_is_refused(tmp_path):
    array = numpy.full((6, 6), numpy.nan)
    message = refusal(tmp_path, "erosion.thermal", array)
    assert "every cell is no-data" in message
    assert message == cli_refusal_of_array(tmp_path, array)


@pytest.mark.parametrize("name, value", [("talsu_angle", 30.0), ("talus_angle", 95.0), ("iterations", 2.5),
                                         ("neighbourhood", "hex"), ("iterations", float("nan"))])
def test_parameters_are_refused_by_the_declarations_as_on_the_command_line(tmp_path, name, value):
    array = cone(8)
    message = refusal(tmp_path, "erosion.thermal", array, **{name: value})
    text = groundtruth._parameter_text(name, value)
    assert message == cli_refusal_of_array(tmp_path, array, "--set", f"{name}={text}")


@pytest.mark.parametrize("arguments", [dict(backend="tpu"), dict(cell_size=-1.0), dict(cell_size=float("inf")),
                                       dict(cell_size=(1.0,)), dict(cell_size=(1.0, 2.0, 3.0)),
                                       dict(cell_size=(1.0, -2.0)), dict(cell_size=(True, 1.0)),
                                       dict(cell_size="2"), dict(cell_size=(1.0, float("nan"))),
                                       dict(size=(0, 8)), dict(gl="vulkan"), dict(mutant="erosion.thermal.nope"),
                                       dict(talus_angle=[30, 40]), dict(require_gpu=True, backend="cpu")])
def test_bad_options_are_refused(tmp_path, arguments):
    assert refusal(tmp_path, "erosion.thermal", cone(8), **arguments)


def test_a_row_spacing_without_a_column_spacing_is_refused_by_the_driver(tmp_path):
    # The public cell_size=(dx, dy) always gives both; the driver refuses the rows' spacing alone for
    # every caller (a generator's grid would otherwise take 1 m columns silently).
    with pytest.raises(groundtruth.InputError, match=r"cell_size_y \(the rows' spacing\) needs cell_size"):
        groundtruth._core.run_case("noise.simplex2", "", 8, 8, None, 2.0, [], False, "cpu", "egl", "", False, True,
                                   False, False, 0, tmp_path / "report", "test")
    assert not (tmp_path / "report").exists()


def test_a_heightmap_given_to_an_algorithm_that_makes_its_own_field_is_refused(tmp_path):
    assert "makes its own field" in refusal(tmp_path, "cave.endless", cone(8))


def test_a_missing_file_is_refused_naming_it(tmp_path):
    missing = tmp_path / "no_such_dem.tif"
    assert str(missing) in refusal(tmp_path, "erosion.thermal", missing)


def _python_child(script, tmp_path, limit_bytes=None):
    """A fresh interpreter running `script` with this suite's groundtruth, its temporary folder
    under tmp_path/tmp, under an address-space limit when given; the Popen."""
    import os
    import resource
    import subprocess
    import sys

    scratch = tmp_path / "tmp"
    scratch.mkdir(exist_ok=True)
    environment = dict(os.environ, TMPDIR=str(scratch))

    def limited():
        if limit_bytes:
            resource.setrlimit(resource.RLIMIT_AS, (limit_bytes, limit_bytes))

    return subprocess.Popen([sys.executable, "-c", script], env=environment, preexec_fn=limited,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def test_a_broadcast_array_is_weighed_before_it_is_copied(tmp_path):
    # numpy.broadcast_to's view of 60000² cells holds 8 bytes; saving it would expand it to 28.8 GB.
    # Under a 4 GiB address-space limit the module refuses before any copy (it used to reach 7.2 GB).
    script = ("import numpy, groundtruth\n"
              "try:\n"
              "    groundtruth.run('erosion.thermal', numpy.broadcast_to(numpy.float64(1.0), (60000, 60000)))\n"
              "except groundtruth.InputError as error:\n"
              "    print(error)\n")
    child = _python_child(script, tmp_path, limit_bytes=4 << 30)
    out, err = child.communicate(timeout=120)
    assert child.returncode == 0, err
    assert "groundtruth.run: the copy of heights needs about 53.6 GiB (3600000000 cells of heights 60000x60000 x 16 B)" in out
    assert not any((tmp_path / "tmp").iterdir())


def test_a_sigterm_during_a_run_leaves_neither_staging_nor_scratch(tmp_path):
    # A 256² pipe run of 3000 steps takes minutes: ended by SIGTERM once its staging folder exists,
    # the process exits 128 + 15 after removing the staging folder and its temporary folder, as
    # the command line does (Python's default SIGTERM would end it with both left behind).
    import signal
    import time

    out = tmp_path / "work" / "report"
    out.parent.mkdir()
    script = ("import groundtruth\n"
              "from conftest import cone\n"
              f"groundtruth.run('erosion.pipe', cone(256), steps=3000, out={str(out)!r})\n")
    child = _python_child(f"import sys; sys.path.insert(0, {str(pathlib.Path(__file__).parent)!r})\n" + script,
                          tmp_path)
    deadline = time.monotonic() + 120
    staging = out.parent / f".report.groundtruth-staging-{child.pid}"
    while not staging.exists() and child.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    assert staging.exists(), child.communicate()
    child.send_signal(signal.SIGTERM)
    _, err = child.communicate(timeout=60)
    assert child.returncode == 128 + signal.SIGTERM, err
    assert "interrupted by signal 15" in err
    assert list((out.parent).iterdir()) == []
    assert list((tmp_path / "tmp").iterdir()) == []
