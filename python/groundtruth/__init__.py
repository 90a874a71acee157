"""groundtruth from Python: every algorithm's twins and checks on numpy arrays.

    import groundtruth
    result = groundtruth.run("erosion.pipe", heights, cell_size=10, steps=300, backend="gpu")
    result.status                        # the case's outcome: pass, warn, inconclusive, skip, fail, error
    result.fields["terrain"]["gpu"]      # float32 array (rows, columns), NaN where there is no data;
                                         # the double reference's ("cpu") fields are float64
    result.ledger                        # the case's mass.* checks: name -> value
    result.checks                        # every check with its value, bounds, outcome and error model

A call is the ad-hoc case `groundtruth run --algorithm A --input F --set k=v ...` makes, run in this
process by the same driver: the same input readers, parameter declarations, twins (the reference
in double and float, the GPU version), checks, fields and report, and for bad input the same
message as the command line's, raised as groundtruth.InputError (a ValueError).

Inputs (`heights`):
  a 2-D numpy array (rows, columns) of int16, int32, float32 or float64, NaN cells no-data
      (handed to the driver as the .npy file it reads; `cell_size` in metres, a number for square
      cells or (dx, dy) for rectangular ones, dx along a row (columns, x) and dy down a column
      (rows, y); 1 m assumed and said in `result.notes` when not given). Other real dtypes are converted and the conversion said in
      `result.notes`: other integers (int8, uint8, uint16, uint32, int64, uint64) to float64 when
      every value is exact in it (|v| <= 2**53, else refused), float16 to float32, big-endian
      arrays to little-endian. A numpy masked array's masked cells are no-data (NaN). Booleans,
      complex numbers and objects are refused;
  a path to any file the command line's --input takes (a DEM, an image, a mesh, a .npy volume);
  an xarray.DataArray or an open rasterio dataset: georeferenced heights (groundtruth._geo: the
      coordinates or the transform give the cell size, fill values are no-data, and
      result.to_xarray() / result.to_geotiff() hand the fields back with the input's
      georeferencing);
  None: a generator's `size` grid (noise), or nothing for algorithms that make their own field.
Parameters are keyword arguments named as `groundtruth.parameters(algorithm)` declares them.
Fields come from the case's fields-as-data files: result.fields[field][backend], backends "input",
"cpu" (reference, double), "cpu_float" and "gpu"; result.field_info holds each one's unit and
meaning. With `out`, the whole report (index.html, report.json, pictures, meshes, EXR and .npy
fields) stays in that folder and result.artifacts lists its files with their kind and caption;
without, it is written to a temporary folder that is removed on return.

groundtruth.sweep(algorithm, heights, vary={name: [values]}) and groundtruth.ab(algorithm,
heights, a={...}, b={...}) are the command line's `sweep` and `ab`, returning their tables as pandas
DataFrames; result.checks_table() is a case's checks as one. xarray, rasterio and pandas are
optional: a feature that needs one says which package to install.
"""

import json
import numbers
import os
import pathlib
import sys
import tempfile

from ._build import PYTHON_VERSION as _BUILT_FOR, VERSION as __version__

if tuple(sys.version_info[:2]) != tuple(_BUILT_FOR):
    raise ImportError(f"groundtruth {__version__} was built for Python {_BUILT_FOR[0]}.{_BUILT_FOR[1]}, and this is "
                      f"Python {sys.version_info[0]}.{sys.version_info[1]} ({sys.executable}): run it with Python "
                      f"{_BUILT_FOR[0]}.{_BUILT_FOR[1]}, or build it for this one (cmake --preset release "
                      f"-DGT_PYTHON={sys.executable}; docs/python.md)")
try:
    import numpy
except ImportError:
    raise ImportError("groundtruth needs numpy: apt install python3-numpy (for Debian's Python, or a venv made with "
                      "--system-site-packages), or pip install numpy") from None

from . import _core, _geo, _optional, _tables
from ._core import InputError
from ._geo import Georeference

__all__ = ["COMMAND_LINE", "DATASETS", "Georeference", "InputError", "Result", "ab", "algorithms", "check", "parameters", "run",
           "sweep"]

# The data sets of the checkout the module was built from: bundled ones and those
# datasets/fetch.sh brought (e.g. DATASETS / "real/volcano.json").
DATASETS = pathlib.Path(_core.dataset_dir())
# The `groundtruth` command line built with this module (a sweep's page, a whole report).
COMMAND_LINE = pathlib.Path(_core.command_line())


def algorithms():
    """Every algorithm's declaration: name, summary, source, input kind and parameters."""
    return json.loads(_core.algorithms_json())


def parameters(algorithm):
    """The parameter declarations of `algorithm` by name: kind, default, min and max (or choices),
    unit and description. An unknown algorithm raises InputError naming the known ones."""
    return {spec["name"]: spec for spec in json.loads(_core.algorithm_json(algorithm))["params"]}


class Result:
    """One case's outcome, checks, ledger, timings and fields (see the module's documentation)."""

    def __init__(self, case, fields, field_info, grid, report, georeference=None):
        self.case = case["name"]
        self.algorithm = case["algorithm"]
        self.status = case["status"]
        self.error = case.get("error", "")
        self.input = case["input"]
        self.notes = case.get("notes", [])
        self.params = case["params"]
        self.checks = case["checks"]
        self.timings = case.get("timings", {})
        self.ledger = {check["name"]: check["value"] for check in self.checks if check["name"].startswith("mass.")}
        self.fields = fields
        self.field_info = field_info
        self.grid = grid
        self.report = report
        # Where the input's cells lie (a DataArray's coordinates and attributes, a rasterio dataset's
        # transform, CRS and no-data value), for to_xarray and to_geotiff; None for a bare array.
        self.georeference = georeference
        # What the case wrote (pictures, meshes, field files, plots) with its kind and caption; paths
        # in the report folder, so only with `out` (a temporary report is gone on return).
        self.artifacts = [] if report is None else [
            {"path": report / path, **detail} for path, detail in zip(case["artifacts"], case["artifact_details"])]

    def check(self, name):
        """The check called `name`; KeyError naming the case's checks when it has none of that name."""
        for check in self.checks:
            if check["name"] == name:
                return check
        raise KeyError(f"{self.case} has no check {name!r}; it has: {', '.join(c['name'] for c in self.checks)}")

    def failed(self):
        """The checks whose outcome is fail."""
        return [check for check in self.checks if check["status"] == "fail"]

    def checks_table(self):
        """The checks as a pandas DataFrame indexed by name: status, value, bound, loose_bound,
        expected and reason (needs pandas)."""
        return _tables.checks_frame(self.checks)

    def to_xarray(self):
        """The fields as an xarray.Dataset: one variable per field over (backend, rows, columns), the
        backends input, cpu, cpu_float, gpu (those the case has; NaN where a field lacks one), units
        and meanings as attributes, the input's coordinates and attributes kept (needs xarray)."""
        return _geo.to_dataset(self)

    def to_geotiff(self, path, field="terrain", backend="cpu", overwrite=False):
        """Writes field[backend] as a GeoTIFF with the input's transform, CRS and no-data value,
        atomically; refuses to replace an existing file unless overwrite (needs rasterio). Returns
        the path."""
        return _geo.write_geotiff(self, path, field, backend, overwrite)

    def __repr__(self):
        fields = ", ".join(f"{name}[{'/'.join(backends)}]" for name, backends in self.fields.items())
        return f"<groundtruth.Result {self.case}: {self.status}, {len(self.checks)} checks, fields {fields or 'none'}>"


def _parameter_text(name, value):
    """A keyword argument as the command line's --set text, parsed by the same declarations."""
    if isinstance(value, (bool, numpy.bool_)):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    if isinstance(value, str):
        return value
    raise InputError(f"parameter {name}: a number, a bool or a string, not {type(value).__name__}")


# The dtypes the driver's .npy reader takes as they are (core/io/dem_formats.hpp).
_READ_AS_IS = {"<i2", "<i4", "<f4", "<f8"}
# The largest integer magnitude float64 holds exactly.
_EXACT_IN_FLOAT64 = 2 ** 53


def _cell_sizes(cell_size):
    """`cell_size` as the driver's (columns' spacing, rows' spacing or None): a number of metres for
    square cells, (dx, dy) for rectangular ones, None for the input's own."""
    if cell_size is None:
        return None, None
    if isinstance(cell_size, (bool, numpy.bool_)) or isinstance(cell_size, str):
        raise InputError(f"cell_size {cell_size!r}: expected metres, a number or (dx, dy)")
    if isinstance(cell_size, numbers.Real):
        return float(cell_size), None
    try:
        dx, dy = cell_size
    except (TypeError, ValueError):
        raise InputError(f"cell_size {cell_size!r}: expected metres, a number or (dx, dy)") from None
    for size in (dx, dy):
        if isinstance(size, (bool, numpy.bool_)) or not isinstance(size, numbers.Real):
            raise InputError(f"cell_size {cell_size!r}: expected metres, a number or (dx, dy)")
    return float(dx), float(dy)


def _readable(array):
    """`array` in a dtype the driver reads, and what was done to it (a list of notes)."""
    notes = []
    array = numpy.asanyarray(array)  # no copy: a broadcast view keeps its few bytes until weighed
    if array.ndim == 2 and not array.dtype.hasobject:
        # Saving makes a contiguous copy and a conversion may make another (8 B a cell at most
        # each): weighed before either, as the driver weighs a file before reading it.
        _core.require_memory(float(array.size), f"cells of heights {array.shape[1]}x{array.shape[0]}", 16.0,
                             "groundtruth.run: the copy of heights")
    if numpy.ma.isMaskedArray(array):
        masked = int(numpy.count_nonzero(numpy.ma.getmaskarray(array)))
        if masked:
            notes.append(f"heights: {masked} masked cells are no-data (NaN)")
        wide = numpy.float32 if array.dtype in (numpy.float16, numpy.float32) else numpy.float64
        array = numpy.ma.getdata(array.astype(wide).filled(numpy.nan))
    array = numpy.asarray(array)
    kind = array.dtype.kind
    if array.dtype.hasobject:  # never saved: numpy would pickle it
        raise InputError(f"heights: unsupported .npy dtype '{array.dtype.str}' (supported: <i2 <i4 <f4 <f8)")
    if kind not in "iuf":  # booleans, complex: the driver's reader refuses them in the command line's words
        return array, notes
    if array.dtype.byteorder == ">":
        notes.append(f"heights: big-endian {array.dtype.str} read as little-endian")
        array = array.astype(array.dtype.newbyteorder("<"))
    if array.dtype.str in _READ_AS_IS:
        return array, notes
    if kind == "f":  # float16: float32 holds every value
        notes.append(f"heights: {array.dtype.name} converted to float32 (exact)")
        return array.astype("<f4"), notes
    if array.size and max(abs(int(array.min())), abs(int(array.max()))) > _EXACT_IN_FLOAT64:
        raise InputError(f"heights: {array.dtype.name} values beyond 2**53 have no exact float64: scale them first")
    notes.append(f"heights: {array.dtype.name} converted to float64 (exact)")
    return array.astype("<f8"), notes


def _save_heights(heights, folder, stem="heights"):
    """Writes an array as the .npy file the driver reads (C order); returns the path and the notes
    of what was converted."""
    array, notes = _readable(heights)
    path = folder / f"{stem}.npy"
    numpy.save(path, numpy.ascontiguousarray(array), allow_pickle=False)
    return path, notes


def _load_fields(case_folder):
    """The case's fields-as-data files (compare/field_files.hpp) as arrays, with their sidecar."""
    sidecar = case_folder / "fields.json"
    if not sidecar.exists():
        return {}, {}, {}
    described = json.loads(sidecar.read_text())
    fields, info = {}, {}
    for entry in described["files"]:
        fields.setdefault(entry["field"], {})[entry["backend"]] = numpy.load(case_folder / (entry["stem"] + ".npy"))
        info.setdefault(entry["field"], {})[entry["backend"]] = {"unit": entry["unit"], "meaning": entry["meaning"]}
    return fields, info, described.get("grid", {})


def _georeferenced(heights, cell_size):
    """(heights, cell size, Georeference or None, notes): a DataArray's or a rasterio dataset's
    values and spacing (groundtruth._geo's conventions), a GeoTIFF path's georeferencing, or the
    input as given."""
    if _geo.is_dataarray(heights):
        return _geo.from_dataarray(heights, cell_size)
    if _geo.is_rasterio_dataset(heights):
        return _geo.from_rasterio(heights, cell_size)
    if isinstance(heights, (str, os.PathLike)):
        return heights, cell_size, _geo.from_path(heights), []
    return heights, cell_size, None, []


def _drive(algorithm, heights, read, *, _call, cell_size=None, backend="both", size=(256, 256), red_channel=False,
           mutant=None, require_gpu=False, gl="egl", out=None, quiet=True, pictures=True, descriptors=True, reps=None,
           quick=False, fields=None, _external=None, _external_label="", _vary=(), _force=False, _a=(), _b=(),
           **params):
    """Runs the driver once (one case, a sweep's runs or an A/B pair) on `heights` into `out` or a
    temporary report folder, and returns read(report folder, Georeference, notes) before that
    folder is removed. `_call` is the Python call as the report's command line shows it; _vary,
    _force, _a and _b make it a sweep or an A/B pair (the underscores keep them apart from the
    algorithm's parameters)."""
    if quick:
        pictures, descriptors, reps = False, False, 0
    if reps is not None and (isinstance(reps, bool) or not isinstance(reps, numbers.Integral)):
        raise InputError(f"reps {reps!r}: expected a whole number of timed repetitions (0: untimed) or None")
    assignments = [f"{name}={_parameter_text(name, value)}" for name, value in params.items()]
    heights, cell_size, georeference, notes = _georeferenced(heights, cell_size)
    width, height = size
    with tempfile.TemporaryDirectory(prefix="groundtruth-") as scratch:
        scratch = pathlib.Path(scratch)
        saved = None
        if heights is None:
            input_path = ""
        elif isinstance(heights, (str, os.PathLike)):
            input_path = os.fspath(heights)
        else:
            saved, conversions = _save_heights(heights, scratch)
            notes += conversions
            input_path = str(saved)
        field_files, saved_fields = _field_files(fields, scratch, notes)
        report = pathlib.Path(out) if out is not None else scratch / "report"
        command = f"{_call}({algorithm!r}, backend={backend!r}{''.join(', ' + a for a in assignments)})"
        try:
            _core.run_case(algorithm, input_path, int(width), int(height), *_cell_sizes(cell_size), assignments,
                           bool(red_channel), backend, gl, mutant or "", bool(require_gpu), bool(quiet),
                           bool(pictures), bool(descriptors), None if reps is None else int(reps), report, command,
                           _external, _external_label, scratch, list(_vary), bool(_force), list(_a), list(_b),
                           field_files)
        except InputError as error:
            # The driver names the file it read; the caller gave an array. A Python call forces a
            # sweep with an argument, not an option.
            message = str(error).replace(str(saved), "heights") if saved else str(error)
            for path, label in saved_fields.items():
                message = message.replace(path, label)
            raise InputError(message.replace("pass --force", "pass force=True")) from None
        return read(report, georeference, notes)


def _field_files(fields, folder, notes):
    """The input fields ({name: array or path}) as the driver's name=file list, arrays saved to
    `folder` as the heights are, and {saved file: what the caller called it} for messages."""
    if fields is None:
        return [], {}
    if not isinstance(fields, dict):
        raise InputError(f"fields {fields!r}: expected {{name: array or path}}, as a case file's \"fields\"")
    files, saved = [], {}
    for name, values in fields.items():
        if not isinstance(name, str) or not name or "=" in name or "/" in name:
            raise InputError(f"fields: {name!r} is not a field name (`groundtruth.parameters` lists the fields an "
                             "algorithm reads)")
        if isinstance(values, (str, os.PathLike)):
            files.append(f"{name}={os.fspath(values)}")
        else:
            path, conversions = _save_heights(values, folder, f"field_{name}")
            notes += [f"field {name}: {conversion}" for conversion in conversions]
            files.append(f"{name}={path}")
            saved[str(path)] = f"fields[{name!r}]"
    return files, saved


def run(algorithm, heights=None, **kwargs):
    """Runs `algorithm` on `heights` as one ad-hoc case and returns its Result.

    heights: a numpy array, a path, None (see the module's documentation), an xarray.DataArray
    (its coordinates give the cell size; _FillValue/nodata cells are no-data; its dimensions,
    coordinates and attributes come back in result.to_xarray()) or an open rasterio dataset (band
    1; its transform gives the cell size, its mask the no-data; result.to_geotiff writes a field
    back with its transform, CRS and no-data value). A GeoTIFF path's georeferencing is kept too
    when rasterio is installed.
    Keyword arguments: cell_size (metres, or (dx, dy)); backend: "cpu" (the references, double and
    float), "gpu", or "both" (the twins and every check between them). size: (width, height) of a
    generator's grid. red_channel: take a colour image file's red channel as height. mutant: a
    registered deliberate bug (`groundtruth mutants --list`) for this call only. require_gpu: a
    missing GL context makes the case `error` rather than `skip`. gl: "egl" or "osmesa". out: a
    folder to keep the report in (written atomically; an existing report there is replaced).
    quiet: no progress lines on stderr and no summary on stdout (the notes of decisions taken for
    you are printed on stderr either way, and are in result.notes).
    Cost: pictures=False draws no pictures of the fields (the fields, checks and report stay),
    descriptors=False computes no terrain descriptors (nor their checks), reps sets the timed
    repetitions of each twin (0: untimed, one run each; None: 3 CPU, 5 GPU), and quick=True is all
    three cheap (pictures=False, descriptors=False, reps=0) for a notebook loop or a property test.
    fields: the heightmap's input fields, {name: array or path} of its size (erosion.thermal_jako's
    hardness, erosion.layered's profile, vegetation and obstacle), as `--field` gives them.
    Every other keyword is a parameter of the algorithm (`parameters(algorithm)`).
    Bad input raises InputError with the command line's message.
    """
    def read(report, georeference, notes):
        case = json.loads((report / "report.json").read_text())["cases"][0]
        case["notes"] = notes + case.get("notes", [])
        fields, field_info, grid = _load_fields(report / case["name"])
        return Result(case, fields, field_info, grid, report if kwargs.get("out") is not None else None, georeference)
    return _drive(algorithm, heights, read, _call="groundtruth.run", **kwargs)


def _values_text(name, values):
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise InputError(f"vary[{name!r}]: a list of values, not {values!r}")
    values = [_parameter_text(name, value) for value in values]
    if not values or any("," in value for value in values):
        raise InputError(f"vary[{name!r}]: one value or more, none holding a comma")
    return f"{name}={','.join(values)}"


def sweep(algorithm, heights=None, vary=None, *, force=False, **kwargs):
    """Runs `algorithm` on `heights` for every combination of the `vary` values ({name: [values]})
    as `groundtruth sweep --vary` does, and returns its table (sweep.json) as a pandas DataFrame:
    one row per run with the varied parameters, case, outcome, seconds, cpu_ms, gpu_ms, every
    check's value and every descriptor of ref<double>'s result (descriptor.<group>.<name>); NaN
    where a run has none. More than 64 runs need force=True. The other keywords are run()'s
    (quick=True per run, out= keeps sweep.html with its plots); needs pandas."""
    _optional.require("pandas", "groundtruth.sweep")
    if not isinstance(vary, dict) or not vary:
        raise InputError("vary: a dict of parameter name -> list of values, e.g. {'talus_angle': [30, 35, 40]}")
    texts = [_values_text(name, values) for name, values in vary.items()]
    return _drive(algorithm, heights, lambda report, *_: _tables.sweep_frame(report), _call="groundtruth.sweep",
                  _vary=texts, _force=force, **kwargs)


def ab(algorithm, heights=None, a=None, b=None, **kwargs):
    """Runs two variants of `algorithm` on `heights`, A with the parameters `a` ({name: value}) and
    B with `b`, as `groundtruth ab` does, and returns its table (ab.json) as a pandas DataFrame
    indexed by metric with columns a, b and b_minus_a, the metrics that moved first; frame.attrs
    holds each side's case, assignments and outcome. The other keywords are run()'s; needs pandas."""
    _optional.require("pandas", "groundtruth.ab")
    sides = []
    for side, values in (("a", a), ("b", b)):
        if not isinstance(values, dict):
            raise InputError(f"{side}: a dict of parameter name -> value, e.g. {{'talus_angle': 30}}")
        sides.append([f"{name}={_parameter_text(name, value)}" for name, value in values.items()])
    if not sides[0] and not sides[1]:
        raise InputError("a and b are both empty: give B (or A) a parameter that differs")
    return _drive(algorithm, heights, lambda report, *_: _tables.ab_frame(report), _call="groundtruth.ab",
                  _a=sides[0], _b=sides[1], **kwargs)


class _StepModel:
    """bmipy's methods over a plain step function, `step(state, params) -> state`: the state a dict
    of the algorithm's declared fields (numpy arrays (rows, columns), or (rows, columns, values) for
    a field of several values a cell), params the case's parameters plus "iteration" (iterations
    behind the state) and "spacing" ((dy, dx) in the grid's unit)."""

    def __init__(self, step, fields, dtype):
        self._step, self._fields, self._dtype = step, {f["name"]: f for f in fields}, numpy.dtype(dtype)
        self._state, self._params, self._shape, self._spacing, self._iteration = {}, {}, (0, 0), (1.0, 1.0), 0

    def initialize(self, config_file):
        entries = {}
        for line in pathlib.Path(config_file).read_text().splitlines():
            if line and not line.startswith("#") and " " in line:
                key, value = line.split(" ", 1)
                entries[key] = _tables.typed_value(value)
        self._shape = (int(entries.pop("rows")), int(entries.pop("columns")))
        self._spacing = (float(entries.pop("spacing_y")), float(entries.pop("spacing_x")))
        for key in ("algorithm", "case", "horizontal_unit"):
            entries.pop(key, None)
        self._params = entries
        self._state = {name: numpy.zeros(self._field_shape(name), self._dtype) for name in self._fields}

    def _field_shape(self, name):
        components = self._fields[name].get("components", 1)
        return self._shape if components == 1 else (*self._shape, components)

    def update(self):
        params = dict(self._params, iteration=self._iteration, spacing=self._spacing)
        given = self._step({name: values.copy() for name, values in self._state.items()}, params)
        if not isinstance(given, dict) or set(given) != set(self._fields):
            raise ValueError(f"the step function returned {type(given).__name__}"
                             f"{' with keys ' + ', '.join(map(str, given)) if isinstance(given, dict) else ''}; "
                             f"expected a dict of {', '.join(self._fields)}")
        for name, values in given.items():
            values = numpy.asarray(values)
            if values.shape != self._field_shape(name):
                raise ValueError(f"the step function returned {name} of shape {values.shape}, "
                                 f"expected {self._field_shape(name)}")
            self._state[name] = values.astype(self._dtype)
        self._iteration += 1

    def finalize(self):
        self._state = {}

    def get_output_var_names(self):
        return tuple(self._fields)

    def get_input_var_names(self):
        return (*self._fields, "iteration")

    def get_var_type(self, name):
        return "int32" if name == "iteration" else self._dtype.name

    def get_var_units(self, name):
        return "1" if name == "iteration" else self._fields[name]["unit"]

    def get_var_itemsize(self, name):
        return 4 if name == "iteration" else self._dtype.itemsize

    def get_var_nbytes(self, name):
        return 4 if name == "iteration" else self._state[name].nbytes

    def get_var_grid(self, name):
        return 0 if name == "iteration" else 1 + list(self._fields).index(name)

    def _grid_shape(self, grid):
        return (1,) if grid == 0 else self._field_shape(list(self._fields)[grid - 1])

    def get_grid_rank(self, grid):
        return len(self._grid_shape(grid))

    def get_grid_size(self, grid):
        return int(numpy.prod(self._grid_shape(grid)))

    def get_grid_shape(self, grid, shape):
        shape[:] = self._grid_shape(grid)
        return shape

    def get_grid_spacing(self, grid, spacing):
        spacing[:] = (1.0,) if grid == 0 else (*self._spacing, 1.0)[:len(spacing)]
        return spacing

    def get_value(self, name, dest):
        dest[:] = numpy.ravel(self._iteration if name == "iteration" else self._state[name])
        return dest

    def set_value(self, name, src):
        if name == "iteration":
            self._iteration = int(numpy.ravel(src)[0])
        else:
            self._state[name] = numpy.asarray(src, self._dtype).reshape(self._field_shape(name)).copy()


def _model_factory(model, algorithm, dtype):
    """A callable returning the model to grade, and the name it is shown by: a class (a BMI model's:
    a fresh instance a case), an object with the BMI's methods (itself), or a step function
    (wrapped in _StepModel)."""
    if isinstance(model, type):
        return model, model.__name__
    if hasattr(model, "update") and hasattr(model, "get_value"):
        return (lambda: model), type(model).__name__
    if not callable(model):
        raise InputError(f"{type(model).__name__} is neither a model with the BMI's methods (update, get_value, ...) "
                         "nor a step function step(state, params) -> state")
    if numpy.dtype(dtype).name not in ("float32", "float64"):
        raise InputError(f"dtype {dtype!r}: a step function's fields are float32 or float64")
    fields = json.loads(_core.algorithm_json(algorithm)).get("state", [])
    return (lambda: _StepModel(model, fields, dtype)), getattr(model, "__name__", type(model).__name__)


def check(model, algorithm, heights=None, *, dtype="float64", **kwargs):
    """Grades your own implementation of a stepped algorithm (erosion) where groundtruth's GPU twin
    stands, and returns the Result: the same shadow steps against the reference (ref<float> for
    float32 fields, ref<double> for float64), ledgers and determinism, its checks named by the
    backend "external" (e.g. parity.shadow.terrain.external_vs_double, mass.relative_drift.external).

    model: an object or class with the Basic Model Interface's methods under bmipy's names
      (initialize(config_file), update(), get_value(name, dest), set_value(name, src),
      get_output_var_names(), get_input_var_names(), get_var_type/units/itemsize/nbytes/grid(name),
      get_grid_rank/size(grid), get_grid_shape(grid, shape), get_grid_spacing(grid, spacing)), whose
      variables are the algorithm's declared state (`algorithms()`, "state"); or a plain step
      function step(state, params) -> state over dicts of numpy arrays, its fields of `dtype`
      (params: the case's parameters, "iteration" and "spacing" (dy, dx)). The config file handed to
      initialize() is docs/external-implementations.md's.
    The other arguments are run()'s (heights, cell_size, quick, out, ...). The model runs in this
    process: a model whose variables do not match raises InputError naming each mismatch; one that
    raises while it steps ends the case as `error` with its message.
    """
    factory, label = _model_factory(model, algorithm, dtype)
    return run(algorithm, heights, _external=factory, _external_label=label, **kwargs)
