"""Georeferenced heights in and out: a GeoTIFF through rasterio, run() and back to a GeoTIFF; a
DataArray's coordinates as the cell size and its attributes into the result's Dataset; the checks
as a table. Each property is computed here from the files and arrays, not read from the driver."""

import math

import numpy
import pytest

import groundtruth
from conftest import cone

rasterio = pytest.importorskip("rasterio")
xarray = pytest.importorskip("xarray")
pytest.importorskip("pandas")
from rasterio.crs import CRS  # noqa: E402
from rasterio.transform import from_origin  # noqa: E402

NODATA = -9999.0
# UTM zone 33N, with rectangular cells: 30 m across a row (x), 20 m down a column (y).
TRANSFORM = from_origin(500000.0, 4200000.0, 30.0, 20.0)
CRS_UTM33 = CRS.from_epsg(32633)


def dem_with_a_hole():
    """A 24x32 cone (peak 40 m) with a 4x5 block of no-data cells off its centre."""
    heights = cone(32, peak=40.0, cell_size=1.0)[:24].astype(numpy.float32)
    hole = numpy.zeros(heights.shape, bool)
    hole[3:7, 20:25] = True
    return numpy.where(hole, NODATA, heights).astype(numpy.float32), hole


@pytest.fixture
def geotiff(tmp_path):
    heights, hole = dem_with_a_hole()
    path = tmp_path / "dem.tif"
    with rasterio.open(path, "w", driver="GTiff", height=heights.shape[0], width=heights.shape[1], count=1,
                       dtype="float32", crs=CRS_UTM33, transform=TRANSFORM, nodata=NODATA) as output:
        output.write(heights, 1)
    return path, hole


def test_a_geotiff_round_trips_through_rasterio_run_and_a_geotiff(geotiff, tmp_path):
    path, hole = geotiff
    with rasterio.open(path) as dataset:
        result = groundtruth.run("erosion.thermal", dataset, backend="cpu", quick=True, iterations=20)
    # backend="cpu" runs the references alone: the GPU's checks are skipped, none fails.
    assert result.status not in ("fail", "error") and not result.failed(), result.failed() or result.error
    # The transform's |a| and |e| are the cell size the driver used, and the notes say where they came from.
    assert (result.grid["cell_size_x"], result.grid["cell_size_y"]) == (30.0, 20.0)
    assert any("30 m (x, columns) by 20 m (y, rows) from the transform" in note for note in result.notes)
    assert any(f"{hole.sum()} masked cells are no-data" in note for note in result.notes)
    written = result.to_geotiff(tmp_path / "eroded.tif", field="terrain", backend="cpu")
    with rasterio.open(written) as back:
        assert back.transform == TRANSFORM
        assert back.crs == CRS_UTM33
        assert back.nodata == NODATA
        band = back.read(1, masked=True)
        tags = back.tags()
    numpy.testing.assert_array_equal(numpy.ma.getmaskarray(band), hole)
    eroded = result.fields["terrain"]["cpu"]
    numpy.testing.assert_array_equal(numpy.isnan(eroded), hole)
    numpy.testing.assert_array_equal(band.filled(numpy.nan), eroded.astype(band.dtype))
    assert tags["field"] == "terrain" and tags["backend"] == "cpu" and tags["units"] == "m"
    assert CRS.from_wkt(result.to_xarray().attrs["crs"]) == CRS_UTM33


def test_a_written_geotiff_is_never_overwritten_unasked(geotiff, tmp_path):
    path, _ = geotiff
    result = groundtruth.run("erosion.thermal", str(path), backend="cpu", quick=True, iterations=4)
    # A path's georeferencing is read beside the driver's own reading of the file.
    assert result.georeference.transform == TRANSFORM and result.georeference.crs == CRS_UTM33
    before = path.read_bytes()
    with pytest.raises(groundtruth.InputError, match="exists: pass overwrite=True"):
        result.to_geotiff(path)
    assert path.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dem.tif"]  # no staging file left behind
    result.to_geotiff(path, backend="cpu_float", overwrite=True)
    with rasterio.open(path) as back:
        assert back.dtypes == ("float32",) and back.transform == TRANSFORM


def test_a_rotated_raster_is_refused(tmp_path):
    rotated = tmp_path / "rotated.tif"
    with rasterio.open(rotated, "w", driver="GTiff", height=8, width=8, count=1, dtype="float32", crs=CRS_UTM33,
                       transform=rasterio.Affine(30.0, 5.0, 0.0, 0.0, -30.0, 0.0)) as output:
        output.write(numpy.ones((8, 8), numpy.float32), 1)
    with rasterio.open(rotated) as dataset, pytest.raises(groundtruth.InputError, match="rotated or sheared"):
        groundtruth.run("erosion.thermal", dataset, backend="cpu", quick=True)


LUXEMBOURG = groundtruth.DATASETS / "real" / "elev.tif"  # 30" cells, EPSG:4326, GDAL_NODATA -32768


def test_a_geographic_raster_gets_the_command_lines_metres_whichever_way_it_comes():
    """The real Luxembourg DEM in degrees, as a path (the driver's GeoTIFF reader converts), as an
    open rasterio dataset and as a DataArray of lat/lon: the same cell size in metres, the same
    no-data cells, the conversion said in the notes."""
    by_path = groundtruth.run("erosion.thermal", LUXEMBOURG, backend="cpu", quick=True, iterations=2)
    with rasterio.open(LUXEMBOURG) as dataset:
        assert dataset.crs.is_geographic
        by_dataset = groundtruth.run("erosion.thermal", dataset, backend="cpu", quick=True, iterations=2)
        band = dataset.read(1, masked=True)
        transform = dataset.transform
    latitude = transform.f + transform.e * (numpy.arange(band.shape[0]) + 0.5)
    longitude = transform.c + transform.a * (numpy.arange(band.shape[1]) + 0.5)
    array = xarray.DataArray(band.filled(-32768).astype(numpy.float32), dims=("lat", "lon"),
                             coords={"lat": latitude, "lon": longitude}, attrs={"nodata": -32768})
    by_array = groundtruth.run("erosion.thermal", array, backend="cpu", quick=True, iterations=2)
    expected = (by_path.grid["cell_size_x"], by_path.grid["cell_size_y"])
    assert 590 < expected[0] < 610 and 915 < expected[1] < 925  # 30" x 30" at 49.8 N, as heightmap_io_test says
    for result in (by_dataset, by_array):
        assert (result.grid["cell_size_x"], result.grid["cell_size_y"]) == pytest.approx(expected, rel=1e-12)
        assert any("converted to metres at centre latitude 49.8" in note for note in result.notes), result.notes
        numpy.testing.assert_array_equal(numpy.isnan(result.fields["terrain"]["input"]),
                                         numpy.isnan(by_path.fields["terrain"]["input"]))
    assert numpy.isnan(by_path.fields["terrain"]["input"]).sum() == 3942


def anisotropic_dataarray():
    """24 rows x 32 columns, 3 m along x (increasing), 2 m along y (decreasing: north up), in UTM
    metres, with _FillValue -1 in two cells."""
    heights = cone(32, peak=20.0, cell_size=1.0)[:24]
    heights[0, 0] = heights[5, 9] = -1.0
    x = 700000.0 + 3.0 * (numpy.arange(32) + 0.5)
    y = 5300000.0 - 2.0 * (numpy.arange(24) + 0.5)
    return xarray.DataArray(heights, dims=("y", "x"), coords={"y": y, "x": x},
                            attrs={"crs": "EPSG:32633", "_FillValue": -1.0, "long_name": "elevation", "units": "m"})


def test_a_dataarray_with_anisotropic_coordinates_gives_the_cell_size_and_comes_back():
    array = anisotropic_dataarray()
    result = groundtruth.run("erosion.thermal", array, backend="cpu", quick=True, iterations=10)
    assert (result.grid["cell_size_x"], result.grid["cell_size_y"]) == (3.0, 2.0)
    assert any("cell size 3 m (x, columns) by 2 m (y, rows) from the coordinates" in note for note in result.notes)
    assert any("2 cells equal to the no-data value -1.0 are no-data" in note for note in result.notes)
    dataset = result.to_xarray()
    assert list(dataset.backend.values) == ["input", "cpu", "cpu_float"]
    assert dataset.terrain.dims == ("backend", "y", "x")
    numpy.testing.assert_array_equal(dataset.x.values, array.x.values)
    numpy.testing.assert_array_equal(dataset.y.values, array.y.values)
    assert dataset.attrs["crs"] == "EPSG:32633" and dataset.attrs["long_name"] == "elevation"
    assert dataset.attrs["case"] == result.case and dataset.attrs["param_iterations"] == "10"
    assert dataset.terrain.attrs["units"] == "m" and "ref<double>" in dataset.terrain.attrs["meaning_cpu"]
    numpy.testing.assert_array_equal(dataset.terrain.sel(backend="cpu").values, result.fields["terrain"]["cpu"])
    no_data = numpy.isnan(dataset.terrain.sel(backend="input").values)
    assert no_data.sum() == 2 and no_data[0, 0] and no_data[5, 9]


def test_a_dataarray_in_degrees_without_latitudes_or_unevenly_spaced_is_refused():
    degrees = xarray.DataArray(numpy.ones((6, 6)), dims=("row", "lon"), coords={"lon": numpy.arange(6) * 0.01})
    with pytest.raises(groundtruth.InputError, match="in degrees without a spaced latitude"):
        groundtruth.run("erosion.thermal", degrees, backend="cpu", quick=True)
    uneven = xarray.DataArray(numpy.ones((6, 6)), dims=("y", "x"),
                              coords={"y": numpy.arange(6.0), "x": [0.0, 1.0, 2.0, 3.5, 4.5, 5.5]})
    with pytest.raises(groundtruth.InputError, match="coordinate x: not evenly spaced"):
        groundtruth.run("erosion.thermal", uneven, backend="cpu", quick=True)


def test_the_checks_table_holds_each_check_with_its_bound():
    result = groundtruth.run("erosion.thermal", cone(16), backend="cpu", quick=True, iterations=8)
    table = result.checks_table()
    assert list(table.index) == [check["name"] for check in result.checks]
    assert list(table.columns) == ["status", "value", "bound", "loose_bound", "expected", "reason"]
    for check in result.checks:
        row = table.loc[check["name"]]
        assert row.status == check["status"]
        if "threshold" in check:
            assert row.bound == check["threshold"]
        else:
            assert math.isnan(row.bound)
    drift = table.loc["mass.relative_drift.cpu"]
    assert drift.status == "pass" and drift.value <= drift.bound and drift.reason
    skipped = table[table.status == "skip"]
    assert len(skipped) and all(skipped.reason != "")  # a skipped check says why
