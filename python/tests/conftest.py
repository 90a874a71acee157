"""Shared helpers of the Python suite: small terrains made in numpy, the command line beside the
module (for the tests that hold Python's messages against the CLI's), and the float32 rounding
bound of the fields the module hands back."""

import pathlib
import re
import subprocess

import numpy
import pytest

import groundtruth

# The command line built with the module (in <build>/groundtruth, wherever the module is installed).
CLI = groundtruth.COMMAND_LINE

# Fields come back as float32 (.npy files of compare/field_files.hpp), the double reference's as
# float64: each value is the double rounded to nearest, off by at most half an ulp, 2^-24 of its
# magnitude in float32 (none in float64: the reference's own double is stored).
FLOAT32_UNIT_ROUNDOFF = 2.0**-24


def cone(side=32, peak=40.0, cell_size=1.0):
    """A right circular cone on a plane, radius 0.4 of the side, as the case generator makes it."""
    centre = 0.5 * side * cell_size
    coordinates = (numpy.arange(side) + 0.5) * cell_size
    x, y = numpy.meshgrid(coordinates, coordinates)
    distance = numpy.hypot(x - centre, y - centre)
    return numpy.maximum(0.0, peak * (1.0 - distance / (0.4 * side * cell_size)))


def float32_sum_bound(*fields):
    """The most that the sums of these fields can be off from the sums of the doubles they were
    rounded from: half an ulp of each float32 value, nothing for a float64 field."""
    return sum(FLOAT32_UNIT_ROUNDOFF * float(numpy.nansum(numpy.abs(field.astype(numpy.float64))))
               for field in fields if field.dtype == numpy.float32)


def cli_message(arguments):
    """The command line's refusal: its exit status and the message after 'groundtruth: '."""
    finished = subprocess.run([str(CLI), *arguments], capture_output=True, text=True, timeout=300)
    lines = [line for line in finished.stderr.splitlines() if line.startswith("groundtruth: ")]
    return finished.returncode, lines[-1][len("groundtruth: "):] if lines else finished.stderr


@pytest.fixture
def out(tmp_path):
    """A report folder the test keeps (the module writes nothing else)."""
    return tmp_path / "report"


def readme_block(language, title):
    """The README's first code block of `language` under its heading `title` (a step of the
    tutorial, "### 4. Check your own implementation", is found by "Check your own implementation"),
    up to the next heading of that level or above."""
    readme = (pathlib.Path(__file__).resolve().parents[2] / "README.md").read_text()
    level, section, in_code = None, [], False
    for line in readme.splitlines(keepends=True):
        in_code ^= line.startswith("```")
        heading = None if in_code else re.match(r"(#+) (?:\d+\. )?(.*)$", line)
        if level is None:
            if heading and heading.group(2) == title:
                level = len(heading.group(1))
        elif heading and len(heading.group(1)) <= level:
            break
        else:
            section.append(line)
    return "".join(section).split(f"```{language}\n", 1)[1].split("```", 1)[0]
