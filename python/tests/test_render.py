"""The renderers and the mesh checks from Python: a mesh file or an array in, the reference
rasterizer and the GL pipeline compared by the driver's image checks."""

import numpy
import pytest

import groundtruth
from conftest import cli_message, cone

BUNNY = groundtruth.DATASETS / "real/meshes/bunny00.off"
ELEPHANT_WITH_HOLES = groundtruth.DATASETS / "real/meshes/elephant-with-holes.off"


def assert_twins_agree(result):
    assert result.status not in ("fail", "error"), result.failed() or result.error
    assert any(check["name"].endswith("gpu_vs_cpu") for check in result.checks)


def test_a_heightmap_of_a_mesh_seen_from_above():
    result = groundtruth.run("render.heightmap_from_mesh", BUNNY, width=48, height=40)
    assert_twins_agree(result)
    height = result.fields["height"]
    for backend in ("cpu", "gpu"):
        assert height[backend].shape == (40, 48)
        # 1 - z' lies in [0, 1]: the box's top is 1, uncovered texels 0, and the bunny covers some.
        assert height[backend].min() >= 0.0 and height[backend].max() <= 1.0
        assert 0.0 < (height[backend] > 0.0).mean() < 1.0


def test_a_phong_shaded_mesh_comes_back_as_its_colour_channels():
    result = groundtruth.run("render.phong", BUNNY, width=48, height=40)
    assert_twins_agree(result)
    assert {"red", "green", "blue"} <= set(result.fields)
    for channel in ("red", "green", "blue"):
        for backend in ("cpu", "gpu"):
            values = result.fields[channel][backend]
            assert values.shape == (40, 48)
            # 8-bit levels / 255: every value is a whole number of 255ths.
            levels = values.astype(numpy.float64) * 255.0
            assert numpy.abs(levels - numpy.round(levels)).max() < 1e-3


def test_a_terrain_given_as_an_array_is_drawn_as_a_solid():
    result = groundtruth.run("render.terrain", cone(24, peak=6.0), width=64, height=48)
    assert_twins_agree(result)
    assert result.check("mesh.closed.cpu")["status"] == "pass"


def test_the_material_drape_needs_the_layered_ground(tmp_path):
    # drape = material colours by the layered ground's surface, which only erode = layered makes:
    # without it the case is refused (exit 2 on the command line), naming the remedy.
    for erode in ("none", "pipe"):
        with pytest.raises(groundtruth.InputError) as refused:
            groundtruth.run("render.terrain", cone(16, peak=3.0), width=32, height=24, drape="material", erode=erode)
        assert "erode = layered" in str(refused.value)
    path = tmp_path / "heights.npy"
    numpy.save(path, cone(16, peak=3.0))
    status, message = cli_message(["run", "--algorithm", "render.terrain", "--input", str(path), "--set",
                                   "drape=material", "--out", str(tmp_path / "cli_report")])
    assert status == 2
    assert "drape = material" in message and "erode = layered" in message
    assert not (tmp_path / "cli_report").exists()


def surface_colour(result, backend):
    """Mean (red, green, blue) over the pixels the solid covers (the background is 0)."""
    image = numpy.stack([result.fields[channel][backend] for channel in ("red", "green", "blue")], axis=-1)
    covered = image.sum(axis=-1) > 0.0
    assert covered.mean() > 0.2
    return image[covered].mean(axis=0)


def test_the_material_drape_colours_the_surface_by_its_material():
    # A gentle cone (peak 3 over a radius of 9.6 cells: 17°, under the rock blend's 30° and every
    # repose angle, so one step moves little) under pure sand, pale yellow (0.93, 0.83, 0.56), and
    # under scree, a near grey mix of sand, gravel, stones and boulders (0.54, 0.53, 0.51). Seen from
    # high above, most covered pixels are the lit surface (the skirts are rock in both): the sand's
    # picture is brighter and far yellower (red - blue) than the scree's, which stays near grey.
    colours = {}
    for soil in ("sand", "scree"):
        result = groundtruth.run("render.terrain", cone(24, peak=3.0), width=64, height=48, elevation_deg=70.0,
                                 erode="layered", drape="material", layered_soil=soil, layered_steps=1)
        assert_twins_agree(result)
        colours[soil] = {backend: surface_colour(result, backend) for backend in ("cpu", "gpu")}
    for backend in ("cpu", "gpu"):
        sand, scree = colours["sand"][backend], colours["scree"][backend]
        assert sand[0] - sand[2] > 0.15, sand
        assert abs(scree[0] - scree[2]) < 0.05, scree
        assert sand.sum() > scree.sum() + 0.2, (sand, scree)


def test_the_mesh_checks_find_the_holes_of_a_mesh_with_holes():
    closed = groundtruth.run("mesh.check", BUNNY)
    holed = groundtruth.run("mesh.check", ELEPHANT_WITH_HOLES)
    assert closed.check("mesh.closed.input")["status"] == "pass"
    assert holed.check("mesh.closed.input")["status"] == "fail"


def test_a_heightmap_is_not_a_mesh(tmp_path):
    path = tmp_path / "heights.npy"
    numpy.save(path, cone(8))
    try:
        groundtruth.run("mesh.check", path)
    except groundtruth.InputError as refused:
        assert str(path) in str(refused)
    else:
        raise AssertionError("a .npy heightmap was taken as a mesh")
