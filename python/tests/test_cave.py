"""The cave meshers from Python: seed 004's marching tetrahedra (closed, oriented, manifold on a
solid block, on both twins), the dropped marching cubes (holes: the seed's reason to drop it) and
the endless cave, with their mesh checks."""

import json

import numpy

import groundtruth

SMALL_BLOCK = {"size_x": 10, "size_y": 8, "size_z": 6}


def test_marching_tetrahedra_closes_a_solid_block_on_both_twins():
    result = groundtruth.run("cave.marching_tetrahedra", **SMALL_BLOCK)
    assert result.status not in ("fail", "error"), result.failed() or result.error
    for backend in ("cpu", "gpu"):
        for property_ in ("closed", "manifold", "oriented"):
            assert result.check(f"mesh.{property_}.{backend}")["status"] == "pass"
    assert result.check("parity.topology.gpu_vs_float")["status"] == "pass"
    assert result.params["size_x"] == 10


def test_marching_cubes_leaves_holes_that_the_checks_see():
    # Midpoint marching cubes without disambiguation: the seed dropped it for its cracks.
    result = groundtruth.run("cave.marching_cubes", backend="cpu", **SMALL_BLOCK)
    assert result.check("mesh.closed.cpu")["status"] == "fail"
    assert result.check("mesh.holes.cpu")["value"] > 0


def test_the_endless_cave_runs_by_default_and_its_seams_hold():
    result = groundtruth.run("cave.endless", size_x=8, size_y=8, size_z=8, slabs=4)
    assert result.status not in ("fail", "error"), result.failed() or result.error
    assert result.params["solid"] is False
    # The density over the path's box: the 8-cell big cube and 4 slabs along +x, in samples (nz, ny, nx).
    assert result.fields["density"]["cpu"].shape == (9, 9, 13)
    for backend in ("cpu", "gpu"):
        seams = result.check(f"seams.unmatched_border_edges.{backend}")
        assert seams["status"] == "pass" and seams["value"] == 0


def test_the_density_comes_back_as_a_volume_that_meshes_again(tmp_path):
    first = groundtruth.run("cave.marching_tetrahedra", backend="cpu", out=tmp_path / "noise", **SMALL_BLOCK)
    density = first.fields["density"]
    samples = (SMALL_BLOCK["size_z"] + 1, SMALL_BLOCK["size_y"] + 1, SMALL_BLOCK["size_x"] + 1)  # (nz, ny, nx)
    assert density["cpu"].shape == density["cpu_float"].shape == samples
    sidecar = json.loads((first.report / first.case / "fields.json").read_text())
    assert all(entry["formats"] == ["exr", "npy"] for entry in sidecar["files"])
    assert density["cpu"].min() < first.params["threshold"] < density["cpu"].max(), "the block holds rock and air"
    # The file is the volume an ad-hoc run takes as input; meshed again, it is read back exactly.
    again = groundtruth.run("cave.marching_tetrahedra", first.report / first.case / "density_cpu_float.npy",
                            backend="cpu")
    numpy.testing.assert_array_equal(again.fields["density"]["input"], density["cpu_float"])
    assert again.check("mesh.closed.cpu")["status"] == "pass"
    # With out=, the meshes are among the artifacts, at their place in the report.
    meshes = [artifact["path"] for artifact in first.artifacts if artifact["path"].suffix == ".ply"]
    assert meshes and all(path.is_file() for path in meshes)
    assert again.artifacts == [], "no out=: no files to point to"
