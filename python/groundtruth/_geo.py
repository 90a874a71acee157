"""Georeferenced heights in and out: an xarray.DataArray or a rasterio dataset as run()'s input, a
Result as an xarray.Dataset or a GeoTIFF with the input's georeferencing.

Conventions:
  rows and columns are the array's as given (row 0 is the first row: north for a GeoTIFF, the
      first y coordinate for a DataArray); nothing is flipped on the way in or out.
  cell size: a DataArray's from its two dimension coordinates (cell centres, evenly spaced: the
      step's magnitude, dx along a row, dy down a column); a rasterio dataset's from its affine
      transform (|a|, |e|; a rotated or sheared grid is refused). An explicit cell_size wins and
      the notes say so. Degrees (a geographic CRS; lat/lon dimensions or a "units" attribute
      naming degrees) become metres at the grid's centre latitude as the command line's readers
      convert them (core/io/dem_formats.hpp degrees_to_metres), and the notes say so.
  no-data: NaN, a DataArray's `_FillValue` or `nodata` attribute (or encoding), a rasterio
      dataset's mask; each masked cell becomes NaN and the notes count them.
  kept: the DataArray's dimension names, coordinates and attributes, a rasterio dataset's
      transform, CRS and no-data value; a result written back carries them.
xarray and rasterio are optional (groundtruth._optional)."""

import numbers
import os
import pathlib

import numpy

from . import _core, _optional
from ._core import InputError

# Relative unevenness of a coordinate's steps still read as one cell size: coordinates written
# in float32 (a netCDF's) carry about 2^-24 relative rounding of the coordinate's magnitude,
# which for a 10^6 m easting is about 0.06 m against 30 m steps, 2·10^-3 of a step.
_STEP_TOLERANCE = 1e-2
_LATITUDE_NAMES = {"lat", "latitude"}
_DEGREE_NAMES = _LATITUDE_NAMES | {"lon", "longitude"}


class Georeference:
    """Where an input's cells lie. dims: (rows' name, columns' name); coords: xarray coordinates to
    put back (dimension and scalar ones, e.g. rioxarray's spatial_ref); attrs: the input's
    attributes; transform: a rasterio Affine of the cell corners, or None; crs: a rasterio CRS,
    WKT text or None; nodata: the input's no-data value (None: NaN only)."""

    def __init__(self, dims=("y", "x"), coords=None, attrs=None, transform=None, crs=None, nodata=None):
        self.dims, self.coords, self.attrs = tuple(dims), dict(coords or {}), dict(attrs or {})
        self.transform, self.crs, self.nodata = transform, crs, nodata

    def __repr__(self):
        return f"<groundtruth.Georeference dims={self.dims} crs={self.crs!r} transform={self.transform!r} nodata={self.nodata!r}>"


def is_dataarray(value):
    return type(value).__name__ == "DataArray" and hasattr(value, "dims") and hasattr(value, "coords")


def is_rasterio_dataset(value):
    return all(hasattr(value, name) for name in ("transform", "crs", "nodata", "read", "count"))


def _step(coordinate, name):
    """The even spacing of a dimension coordinate (a signed step), or None for fewer than 2 values."""
    values = numpy.asarray(coordinate, dtype=numpy.float64)
    if values.size < 2:
        return None
    steps = numpy.diff(values)
    step = float(steps[0])
    if not numpy.all(numpy.isfinite(values)) or step == 0.0:
        raise InputError(f"coordinate {name}: not finite or not increasing/decreasing")
    if numpy.max(numpy.abs(steps - step)) > _STEP_TOLERANCE * abs(step):
        raise InputError(f"coordinate {name}: not evenly spaced (steps {steps.min():.6g} to {steps.max():.6g}); "
                         "resample onto a regular grid first")
    return step


def _in_degrees(array, name):
    units = str(array.coords[name].attrs.get("units", "")).lower() if name in array.coords else ""
    return name.lower() in _DEGREE_NAMES or "degree" in units


def _nodata_of(array):
    for source in (array.attrs, getattr(array, "encoding", {})):
        for key in ("_FillValue", "nodata", "missing_value"):
            if source.get(key) is not None:
                return source[key]
    return None


def _squeezed(array, notes):
    """A DataArray of (y, x), its length-1 leading dimensions (a rioxarray band) dropped."""
    while array.ndim > 2 and array.shape[0] == 1:
        notes.append(f"heights: dimension {array.dims[0]} of length 1 dropped")
        array = array.isel({array.dims[0]: 0}, drop=True)
    if array.ndim != 2:
        raise InputError(f"heights: a DataArray of 2 dimensions (rows, columns), not {array.dims} {array.shape}")
    return array


def _metres(step_x, step_y, centre_latitude, notes, source):
    """A cell of step_x by step_y degrees in metres at the centre latitude, as the command line's
    readers convert it; said in the notes."""
    x, y = _core.degrees_to_metres(abs(step_x), abs(step_y), centre_latitude)
    notes.append(f"geographic {source}: cells {abs(step_x) * 3600:.4g}\" x {abs(step_y) * 3600:.4g}\" converted to "
                 f"metres at centre latitude {centre_latitude:.4f}: {x:.2f} m x {y:.2f} m")
    return x, y


def _cell_size(steps, names, given, notes, source):
    """The cell size run() hands the driver: the caller's, else the steps' magnitudes."""
    known = [abs(step) for step in steps if step is not None]
    if given is not None:
        if known:
            notes.append(f"cell_size={given!r} given: the {source}'s spacing is not used")
        return given
    if len(known) == 2:
        notes.append(f"cell size {known[0]:.6g} m ({names[0]}, columns) by {known[1]:.6g} m ({names[1]}, rows) "
                     f"from the {source}")
        return (known[0], known[1])
    if len(known) == 1:
        notes.append(f"cell size {known[0]:.6g} m from the {source}'s one spaced dimension, taken for both")
        return known[0]
    return None


def from_dataarray(array, cell_size):
    """(heights as numpy, cell size, Georeference, notes) of a DataArray (the module's conventions)."""
    notes = []
    array = _squeezed(array, notes)
    rows_name, columns_name = array.dims
    steps = [_step(array.coords[name], name) if name in array.coords else None for name in (columns_name, rows_name)]
    if cell_size is None and any(_in_degrees(array, name) for name in (rows_name, columns_name)):
        if None in steps or rows_name.lower() not in _LATITUDE_NAMES | {"y"}:
            raise InputError(f"heights: coordinates {rows_name}, {columns_name} are in degrees without a spaced "
                             "latitude on the rows: pass cell_size= in metres, or reproject")
        size = _metres(steps[0], steps[1], float(numpy.mean(array.coords[rows_name])), notes, "coordinates")
    else:
        size = _cell_size(steps, (columns_name, rows_name), cell_size, notes, "coordinates")
    _core.require_memory(float(array.size), f"cells of heights {array.shape[1]}x{array.shape[0]}", 8.0,
                         "groundtruth.run: the DataArray's values")
    values = numpy.asarray(array.values)
    nodata = _nodata_of(array)
    if nodata is not None and not (isinstance(nodata, numbers.Real) and numpy.isnan(nodata)):
        masked = values == nodata
        if numpy.any(masked):
            count = int(numpy.count_nonzero(masked))
            notes.append(f"heights: {count} cell{'s' if count != 1 else ''} equal to the no-data value {nodata} "
                         f"{'are' if count != 1 else 'is'} no-data (NaN)")
            values = numpy.where(masked, numpy.nan, values.astype(numpy.result_type(values.dtype, numpy.float32)))
    attrs = {key: value for key, value in array.attrs.items() if key not in ("_FillValue", "missing_value")}
    crs = attrs.get("crs")
    coords = {name: array.coords[name] for name in array.coords}
    for coordinate in coords.values():
        crs = crs or coordinate.attrs.get("crs_wkt") or coordinate.attrs.get("spatial_ref")
    return values, size, Georeference((rows_name, columns_name), coords, attrs, None, crs, nodata), notes


def from_rasterio(dataset, cell_size, band=1):
    """(heights as a masked numpy array, cell size, Georeference, notes) of an open rasterio dataset."""
    notes = []
    transform = dataset.transform
    if transform.b != 0 or transform.d != 0:
        raise InputError(f"heights: {dataset.name} has a rotated or sheared transform ({transform!r}): "
                         "warp it onto a north-up grid first")
    if cell_size is None and dataset.crs is not None and dataset.crs.is_geographic:
        size = _metres(transform.a, transform.e, transform.f + transform.e * dataset.height / 2, notes, "CRS")
    else:
        size = _cell_size((transform.a, transform.e), ("x", "y"), cell_size, notes, "transform")
    if not 1 <= band <= dataset.count:
        raise InputError(f"heights: {dataset.name} has bands 1 to {dataset.count}, not {band}")
    _core.require_memory(float(dataset.width) * dataset.height, f"cells of heights {dataset.width}x{dataset.height}",
                         8.0, f"groundtruth.run: band {band} of {dataset.name}")
    heights = dataset.read(band, masked=True)
    return heights, size, Georeference(("y", "x"), {}, dict(dataset.tags()), transform, dataset.crs,
                                       dataset.nodata), notes


def from_path(path):
    """The georeferencing of a GeoTIFF the driver reads itself, when rasterio is there (else None:
    a result is then written back without it)."""
    if pathlib.Path(path).suffix.lower() not in (".tif", ".tiff") or not _optional.available("rasterio"):
        return None
    import rasterio
    try:
        with rasterio.open(path) as dataset:
            return Georeference(("y", "x"), {}, dict(dataset.tags()), dataset.transform, dataset.crs, dataset.nodata)
    except rasterio.errors.RasterioIOError:
        return None  # the driver's reader says what is wrong with the file


def _centres(start, step, count):
    return start + step * (numpy.arange(count) + 0.5)


def _dimension_coordinates(georeference, grid):
    """(rows' coordinate values, columns') for a grid of the driver's shape: the input's own where it
    had them, else cell centres from the transform, else from the cell size (origin 0, y down)."""
    rows, columns = int(grid["height"]), int(grid["width"])
    rows_name, columns_name = georeference.dims
    own = georeference.coords
    if rows_name in own and columns_name in own and own[rows_name].size == rows and own[columns_name].size == columns:
        return own[rows_name], own[columns_name]
    transform = georeference.transform
    if transform is not None:
        return _centres(transform.f, transform.e, rows), _centres(transform.c, transform.a, columns)
    return _centres(0.0, float(grid["cell_size_y"]), rows), _centres(0.0, float(grid["cell_size_x"]), columns)


def _transform(georeference, grid):
    """The affine transform of the cell corners a GeoTIFF is written with."""
    from rasterio.transform import Affine
    if georeference.transform is not None:
        return georeference.transform
    y, x = (numpy.asarray(values, dtype=numpy.float64) for values in _dimension_coordinates(georeference, grid))
    dx = float(x[1] - x[0]) if x.size > 1 else float(grid["cell_size_x"])
    dy = float(y[1] - y[0]) if y.size > 1 else float(grid["cell_size_y"])
    return Affine(dx, 0.0, float(x[0]) - dx / 2, 0.0, dy, float(y[0]) - dy / 2)


def to_dataset(result):
    """The result's fields as an xarray.Dataset: a variable per field with dimensions (backend,
    rows, columns[, component]), NaN where a backend has no such field; units and meanings as
    attributes; the input's coordinates and attributes kept."""
    xarray = _optional.require("xarray", "Result.to_xarray")
    georeference = result.georeference or Georeference()
    rows_name, columns_name = georeference.dims
    backends = [backend for backend in ("input", "cpu", "cpu_float", "gpu", "external")
                if any(backend in by_backend for by_backend in result.fields.values())]
    y, x = _dimension_coordinates(georeference, result.grid)
    coords = {name: value for name, value in georeference.coords.items() if name not in (rows_name, columns_name)}
    coords.update({"backend": backends, rows_name: y, columns_name: x})
    variables = {}
    for field, by_backend in result.fields.items():
        shape = next(iter(by_backend.values())).shape
        dtype = numpy.result_type(*(values.dtype for values in by_backend.values()))
        stacked = numpy.full((len(backends), *shape), numpy.nan, dtype=dtype)
        for index, backend in enumerate(backends):
            if backend in by_backend:
                stacked[index] = by_backend[backend]
        dims = ("backend", rows_name, columns_name, f"{field}_component")[:1 + len(shape)]
        info = result.field_info[field]
        attrs = {"units": next(iter(info.values()))["unit"]}
        attrs.update({f"meaning_{backend}": detail["meaning"] for backend, detail in info.items()})
        variables[field] = (dims, stacked, attrs)
    attrs = dict(georeference.attrs)
    if georeference.crs is not None and "crs" not in attrs:  # a rasterio CRS, kept as its WKT
        attrs["crs"] = georeference.crs.to_wkt() if hasattr(georeference.crs, "to_wkt") else str(georeference.crs)
    attrs.update({"case": result.case, "algorithm": result.algorithm, "status": result.status,
                  "notes": "\n".join(result.notes)})
    attrs.update({f"param_{name}": str(value) for name, value in result.params.items()})
    return xarray.Dataset(variables, coords=coords, attrs=attrs)


def write_geotiff(result, path, field, backend, overwrite):
    """Writes one field of one backend as a single-band GeoTIFF with the input's transform, CRS and
    no-data value (a NaN cell becomes that value; NaN when the input had none); atomically (a
    temporary name beside `path`, then renamed). An existing file is replaced only with overwrite."""
    rasterio = _optional.require("rasterio", "Result.to_geotiff")
    if field not in result.fields or backend not in result.fields[field]:
        known = ", ".join(f"{name}[{'/'.join(by_backend)}]" for name, by_backend in result.fields.items())
        raise InputError(f"{result.case} has no field {field!r} of backend {backend!r}; it has: {known or 'none'}")
    values = result.fields[field][backend]
    if values.ndim != 2:
        raise InputError(f"field {field!r} has {values.ndim} dimensions: a GeoTIFF band holds 2")
    path = pathlib.Path(path)
    if path.exists() and not overwrite:
        raise InputError(f"{path} exists: pass overwrite=True to replace it")
    georeference = result.georeference or Georeference()
    nodata = georeference.nodata
    nodata = float("nan") if nodata is None or numpy.isnan(nodata) else float(nodata)
    band = numpy.where(numpy.isnan(values), nodata, values).astype(values.dtype)
    staging = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    profile = {"driver": "GTiff", "height": band.shape[0], "width": band.shape[1], "count": 1,
               "dtype": band.dtype.name, "transform": _transform(georeference, result.grid), "nodata": nodata}
    if georeference.crs is not None:
        profile["crs"] = georeference.crs
    try:
        with rasterio.open(staging, "w", **profile) as output:
            output.write(band, 1)
            output.update_tags(case=result.case, field=field, backend=backend,
                               units=result.field_info[field][backend]["unit"])
        os.replace(staging, path)
    finally:
        staging.unlink(missing_ok=True)
    return path
