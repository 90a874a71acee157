"""The erosion twins from Python: each algorithm on a small terrain, the fields handed back
checked against properties the model guarantees, computed here from the arrays (not read from the
driver's checks), beside the driver's own verdict."""

import json

import numpy
import pytest

import groundtruth
from conftest import float32_sum_bound, cone

EROSION = ["erosion.thermal", "erosion.thermal_jako", "erosion.dissolution", "erosion.pipe", "erosion.particle",
           "erosion.beyer", "erosion.layered"]

# Few iterations keep each run under a few seconds on llvmpipe; the properties hold for any count.
SHORT_RUN = {"erosion.thermal": {"iterations": 12}, "erosion.thermal_jako": {"iterations": 12},
             "erosion.dissolution": {"iterations": 12, "rain": 0.02},
             "erosion.pipe": {"steps": 12, "rain_rate": 0.001}, "erosion.particle": {}, "erosion.beyer": {},
             "erosion.layered": {"steps": 12}}


def test_the_erosion_algorithms_are_all_here():
    assert sorted(a["name"] for a in groundtruth.algorithms() if a["name"].startswith("erosion.")) == sorted(EROSION)


@pytest.fixture(scope="module")
def results():
    """Each erosion algorithm once on a 32x24 cone with 2 m cells, both twins."""
    heights = cone(32, peak=30.0, cell_size=2.0)[:24]
    return heights, {name: groundtruth.run(name, heights, cell_size=2.0, **SHORT_RUN[name]) for name in EROSION}


@pytest.mark.parametrize("algorithm", EROSION)
def test_each_twin_runs_and_no_check_fails(results, algorithm):
    _, result = results
    result = result[algorithm]
    assert result.algorithm == algorithm
    assert result.status not in ("fail", "error"), result.failed() or result.error
    assert any(check["name"].startswith("parity.") for check in result.checks)
    assert result.grid["cell_size_x"] == 2.0


@pytest.mark.parametrize("algorithm", EROSION)
def test_the_terrain_comes_back_as_given_and_on_its_grid(results, algorithm):
    heights, result = results
    terrain = result[algorithm].fields["terrain"]
    assert {"cpu", "cpu_float", "gpu"} <= set(terrain)
    # The input field is the array given, rounded to float32, rows as rows: no transposition.
    numpy.testing.assert_array_equal(terrain["input"], heights.astype(numpy.float32))
    # The double reference keeps its precision; the float twins are float32 whatever is stored.
    for backend, dtype in (("cpu", numpy.float64), ("cpu_float", numpy.float32), ("gpu", numpy.float32)):
        assert terrain[backend].shape == heights.shape and terrain[backend].dtype == dtype
        assert numpy.isfinite(terrain[backend]).all()
    assert result[algorithm].field_info["terrain"]["cpu"]["unit"] == "m"


@pytest.mark.parametrize("algorithm", ["erosion.thermal", "erosion.pipe"])
def test_the_double_reference_comes_back_with_more_than_float32_holds(results, algorithm):
    # A widened float32 copy would hold only float32 values. The cone's heights are irrational
    # multiples of its radius, so nearly every non-zero double lies between two floats (float32's
    # spacing near 30 m is 2^-19 m); the plain around it is 0, a float32 value.
    _, result = results
    double = result[algorithm].fields["terrain"]["cpu"]
    raised = double[double != 0.0]
    between_floats = raised != raised.astype(numpy.float32).astype(numpy.float64)
    assert between_floats.mean() > 0.5, f"{between_floats.sum()} of {raised.size} heights are not float32 values"


@pytest.mark.parametrize("algorithm", ["erosion.thermal", "erosion.thermal_jako"])
def test_thermal_erosion_keeps_the_material_and_lowers_the_peak(results, algorithm):
    heights, result = results
    terrain = result[algorithm].fields["terrain"]
    for backend in ("cpu", "gpu"):
        after = terrain[backend]
        # Moving material conserves it: the sums differ by the float32 rounding of both fields
        # plus the twin's own rounding (GPU: float additions, at most 8 per cell per iteration,
        # each within 2^-24 of the running height; 12 iterations).
        twin_rounding = 12 * 8 * 2.0**-24 * float(numpy.abs(heights).sum()) if backend == "gpu" else 0.0
        assert abs(float(after.astype(numpy.float64).sum()) - float(heights.sum())) <= \
            float32_sum_bound(terrain["input"], after) + twin_rounding + 1e-12 * float(numpy.abs(heights).sum())
        # Material only moves downhill: no cell rises above the highest input cell.
        assert after.max() <= numpy.float32(heights.max())
        assert after.max() < heights.max(), "the cone's apex is steeper than any talus angle here"


def test_the_pipe_model_gives_every_state_field_and_the_water_the_rain_brought(results):
    heights, result = results
    result = result["erosion.pipe"]
    fields = result.fields
    assert {"terrain", "water", "sediment", "velocity_x", "velocity_y"} <= set(fields), list(fields)
    for backend in ("cpu", "gpu"):
        assert (fields["water"][backend] >= 0.0).all()
    # Closed borders, no evaporation: the water after is the water before plus the rain,
    # rate x time step x steps on every cell (depths in m; the cells' area is common to all).
    params = result.params
    rain_depth = params["rain_rate"] * params["time_step"] * params["steps"]
    before, after = fields["water"]["input"], fields["water"]["cpu"]
    expected = float(before.astype(numpy.float64).sum()) + rain_depth * heights.size
    assert abs(float(after.astype(numpy.float64).sum()) - expected) <= \
        float32_sum_bound(before, after) + 1e-12 * expected
    assert result.check("mass.water_balance.cpu")["status"] == "pass"
    assert "mass.water_balance.cpu" in result.ledger


def test_dissolution_keeps_terrain_and_dissolved_material_together_and_books_the_water(results):
    heights, result = results
    result = result["erosion.dissolution"]
    fields, params = result.fields, result.params
    assert {"terrain", "water", "dissolved", "evaporated"} <= set(fields), list(fields)
    for backend in ("cpu", "gpu"):
        # Material only moves between the ground and the water: terrain + dissolved keeps its sum
        # (the float twin within the rounding of its ~35 additions a cell and iteration).
        after = fields["terrain"][backend].astype(numpy.float64) + fields["dissolved"][backend]
        scale = float(numpy.abs(heights).sum())
        twin_rounding = params["iterations"] * 35 * 2.0**-24 * scale if backend == "gpu" else 1e-12 * scale
        assert abs(float(after.sum()) - float(heights.sum())) <= \
            float32_sum_bound(fields["terrain"]["input"], fields["terrain"][backend]) + twin_rounding
        # Every drop of rain is either on the ground or booked as evaporated.
        rained = params["rain"] * params["iterations"] * heights.size
        booked = float(fields["water"][backend].astype(numpy.float64).sum() + fields["evaporated"][backend].sum())
        assert abs(booked - rained) <= 1e-5 * rained
    # The flanks lost ground to the water somewhere.
    assert (fields["terrain"]["cpu"] < heights - 1e-6).any()


def test_the_flow_map_is_a_share_of_droplets(results):
    _, result = results
    flow = result["erosion.particle"].fields["flow"]
    for backend in ("cpu", "gpu"):
        assert (flow[backend] >= 0.0).all() and (flow[backend] <= 1.0).all()
        assert flow[backend].max() > 0.0


def test_a_mutant_is_caught_and_lasts_one_call_only():
    heights = cone(16, peak=10.0)
    mutated = groundtruth.run("erosion.pipe", heights, backend="cpu", steps=8, rain_rate=0.001,
                              mutant="erosion.pipe.half_rain")
    assert mutated.check("mass.water_added.cpu")["status"] == "fail"
    clean = groundtruth.run("erosion.pipe", heights, backend="cpu", steps=8, rain_rate=0.001)
    assert clean.check("mass.water_added.cpu")["status"] == "pass"


def test_a_real_dem_by_path_keeps_its_cell_size_and_says_so(tmp_path):
    result = groundtruth.run("erosion.thermal", groundtruth.DATASETS / "real/volcano.json", backend="cpu",
                             iterations=4, out=tmp_path / "report")
    assert result.grid["cell_size_x"] == 10.0
    assert "volcano.json" in result.input
    assert any("10 m cells" in note for note in result.notes)
    # The report stays where it was asked for, with the fields as files.
    assert (result.report / "index.html").exists()
    sidecar = json.loads((result.report / result.case / "fields.json").read_text())
    assert {(entry["field"], entry["backend"]) for entry in sidecar["files"]} == \
        {("terrain", "input"), ("terrain", "cpu"), ("terrain", "cpu_float")}
    for entry in sidecar["files"]:
        for extension in ("npy", "exr"):
            assert (result.report / result.case / f"{entry['stem']}.{extension}").exists()


def test_nan_cells_are_masked_and_said(tmp_path):
    heights = cone(16, peak=10.0)
    heights[3, 4] = numpy.nan
    result = groundtruth.run("erosion.thermal", heights, backend="cpu", iterations=4)
    assert any("1 NaN cells" in note for note in result.notes)
    assert any("1 m assumed" in note for note in result.notes)
    assert numpy.isnan(result.fields["terrain"]["cpu"][3, 4])
    assert numpy.isfinite(numpy.delete(result.fields["terrain"]["cpu"].ravel(), 3 * 16 + 4)).all()


def test_a_cell_size_given_replaces_the_files_and_the_assumed_one():
    dem = groundtruth.run("erosion.thermal", groundtruth.DATASETS / "real/volcano.json", cell_size=5.0,
                          backend="cpu", iterations=1)
    assert dem.grid["cell_size_x"] == 5.0
    assert "cell size set to 5 m by the caller" in dem.notes
    array = groundtruth.run("erosion.thermal", cone(8), cell_size=2.5, backend="cpu", iterations=1)
    assert array.grid["cell_size_x"] == 2.5
    assert not any("assumed" in note for note in array.notes), array.notes


def test_rectangular_cells_are_given_as_dx_dy_along_columns_and_rows():
    heights = cone(16, peak=8.0)[:12]  # 12 rows, 16 columns
    result = groundtruth.run("erosion.pipe", heights, cell_size=(2.0, 3.0), backend="cpu", steps=2)
    assert (result.grid["cell_size_x"], result.grid["cell_size_y"]) == (2.0, 3.0)
    assert "cell size set to 2 m (x, columns) by 3 m (y, rows) by the caller" in result.notes
    square = groundtruth.run("erosion.pipe", heights, cell_size=(2.0, 2.0), backend="cpu", steps=2)
    assert (square.grid["cell_size_x"], square.grid["cell_size_y"]) == (2.0, 2.0)


def test_a_transposed_view_is_taken_as_the_array_it_shows():
    heights = cone(12, peak=5.0)[:, :9]  # 12 rows, 9 columns
    view = heights.T                      # a Fortran-ordered view: 9 rows, 12 columns
    result = groundtruth.run("erosion.thermal", view, backend="cpu", iterations=1)
    numpy.testing.assert_array_equal(result.fields["terrain"]["input"], view.astype(numpy.float32))


@pytest.mark.parametrize("dtype", ["int64", "uint8", "uint16", "int8", "uint64", ">i2", ">f8", ">f4", "float16"])
def test_a_real_dtype_the_reader_does_not_take_is_converted_exactly_and_said(dtype):
    # Whole metres from 0 to 40: exact in every one of these dtypes, so the run must be the one of
    # the same heights as float64, bit for bit.
    heights = numpy.round(cone(16)).astype(dtype)
    converted = groundtruth.run("erosion.thermal", heights, backend="cpu", iterations=3, quick=True)
    plain = groundtruth.run("erosion.thermal", heights.astype(numpy.float64), backend="cpu", iterations=3, quick=True)
    assert any(note.startswith("heights: ") and ("converted" in note or "big-endian" in note)
               for note in converted.notes), converted.notes
    numpy.testing.assert_array_equal(converted.fields["terrain"]["cpu"], plain.fields["terrain"]["cpu"])


def test_a_masked_array_keeps_its_mask_as_no_data():
    heights = numpy.ma.masked_array(cone(16, peak=10.0), mask=numpy.zeros((16, 16), dtype=bool))
    heights[5, 6] = numpy.ma.masked
    result = groundtruth.run("erosion.thermal", heights, backend="cpu", iterations=2, quick=True)
    assert "heights: 1 masked cells are no-data (NaN)" in result.notes
    assert numpy.isnan(result.fields["terrain"]["cpu"][5, 6])
    assert numpy.isfinite(numpy.delete(result.fields["terrain"]["cpu"].ravel(), 5 * 16 + 6)).all()


def test_quick_keeps_the_checks_and_fields_and_drops_pictures_descriptors_and_timings(tmp_path):
    heights = cone(64)
    full = groundtruth.run("erosion.thermal", heights, backend="cpu", iterations=2, out=tmp_path / "full")
    quick = groundtruth.run("erosion.thermal", heights, backend="cpu", iterations=2, quick=True, out=tmp_path / "quick")
    kinds = lambda result: {artifact["kind"] for artifact in result.artifacts}
    assert "field" in kinds(quick) and "image" not in kinds(quick) and "plot" not in kinds(quick)
    assert {"image", "plot"} <= kinds(full)
    assert not any(check["name"].startswith("descriptors.") for check in quick.checks)
    assert not quick.timings.get("cpu_reps")
    # Every check the quick call made is the full call's, with the same value.
    full_values = {check["name"]: check["value"] for check in full.checks}
    for check in quick.checks:
        assert check["value"] == full_values[check["name"]], check["name"]
    numpy.testing.assert_array_equal(quick.fields["terrain"]["cpu"], full.fields["terrain"]["cpu"])


def test_input_fields_reach_the_algorithm_as_arrays_or_files(tmp_path):
    """fields= gives the heightmap its input fields as a case file's "fields" and --field do: an
    array (saved beside the heights) or a path; a field of another size or an unread one is refused
    naming the caller's field, not a temporary file."""
    heights = cone(16, peak=10.0)
    hardness = numpy.zeros_like(heights)
    hardness[:, 8:] = 1.5
    from_array = groundtruth.run("erosion.thermal_jako", heights, backend="cpu", iterations=4, quick=True,
                                 fields={"hardness": hardness})
    assert any("hardness R from the input field 'hardness', 0 .. 1.5" in note for note in from_array.notes)
    numpy.save(tmp_path / "hardness.npy", hardness)
    from_file = groundtruth.run("erosion.thermal_jako", heights, backend="cpu", iterations=4, quick=True,
                                fields={"hardness": tmp_path / "hardness.npy"})
    numpy.testing.assert_array_equal(from_file.fields["terrain"]["cpu"], from_array.fields["terrain"]["cpu"])
    uniform = groundtruth.run("erosion.thermal_jako", heights, backend="cpu", iterations=4, quick=True)
    assert not numpy.array_equal(uniform.fields["terrain"]["cpu"], from_array.fields["terrain"]["cpu"])
    with pytest.raises(groundtruth.InputError, match=r"fields\['hardness'\]|10x10"):
        groundtruth.run("erosion.thermal_jako", heights, backend="cpu", quick=True,
                        fields={"hardness": numpy.zeros((10, 10))})
    with pytest.raises(groundtruth.InputError, match="reads no input field 'profile'"):
        groundtruth.run("erosion.thermal_jako", heights, backend="cpu", quick=True, fields={"profile": hardness})
    with pytest.raises(groundtruth.InputError, match="expected"):
        groundtruth.run("erosion.thermal_jako", heights, backend="cpu", quick=True, fields=["hardness"])
