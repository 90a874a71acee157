"""groundtruth's references behind the Basic Model Interface, under bmipy's method names.

    from groundtruth.bmi import Reference
    model = Reference("erosion.pipe")          # ref<double>; precision="float32" for ref<float>
    model.initialize("case.txt")               # the config file of docs/external-implementations.md
    model.set_value("terrain", heights.ravel())
    model.update()                             # one iteration (a step of the pipe model)
    model.get_value("water", numpy.empty(model.get_var_nbytes("water") // 8))

A framework that drives models through the BMI (landlab, pymt) can step the references this way,
and handing a Reference to groundtruth.check is the protocol's round trip: the harness loads it,
steps it and reads it back as it would anyone's model, and it must pass. Variables are the
algorithm's declared state fields (`groundtruth.algorithms()`, "state"), each on its own grid of
shape (rows, columns) (or (rows, columns, values) for several values a cell), and the input
"iteration" (int32): the iterations behind the state, which update() advances. Time is the
iteration count (time step 1). What the algorithm derives from its input heights beyond the state
is not in the config (see compare/external/reference_bmi.hpp).
"""

import numpy

from . import _core

__all__ = ["Reference"]

ITERATION = "iteration"


class Reference:
    """A stepped algorithm's reference, ref<double> (precision "float64") or ref<float> ("float32")."""

    def __init__(self, algorithm, precision="float64"):
        if precision not in ("float32", "float64"):
            raise _core.InputError(f"precision {precision!r}: float32 (ref<float>) or float64 (ref<double>)")
        self._algorithm, self._precision = algorithm, numpy.dtype(precision)
        self._model = _core.ReferenceModel(algorithm, precision == "float64")

    # --- initialise, run, finalise
    def initialize(self, config_file):
        self._model.initialize(str(config_file))

    def update(self):
        self._model.update()

    def update_until(self, time):
        while self._model.iteration() < time:
            self._model.update()

    def finalize(self):
        pass

    # --- exchange items
    def get_component_name(self):
        return f"groundtruth {self._algorithm} reference ({self._precision.name})"

    def get_output_var_names(self):
        return tuple(self._model.output_names())

    def get_input_var_names(self):
        return tuple(self._model.input_names())

    def get_output_item_count(self):
        return len(self.get_output_var_names())

    def get_input_item_count(self):
        return len(self.get_input_var_names())

    # --- variables
    def _shape(self, name):
        if name == ITERATION:
            return (1,)
        components = self._model.components(name)
        return tuple(self._model.shape()) + ((components,) if components > 1 else ())

    def get_var_type(self, name):
        return "int32" if name == ITERATION else self._precision.name

    def get_var_units(self, name):
        return "1" if name == ITERATION else self._model.units(name)

    def get_var_itemsize(self, name):
        return 4 if name == ITERATION else self._precision.itemsize

    def get_var_nbytes(self, name):
        return self.get_var_itemsize(name) * int(numpy.prod(self._shape(name)))

    def get_var_grid(self, name):
        names = self.get_output_var_names()
        return 0 if name == ITERATION else 1 + names.index(name)

    def get_var_location(self, name):
        return "node"

    # --- time: the iteration count
    def get_current_time(self):
        return float(self._model.iteration())

    def get_start_time(self):
        return 0.0

    def get_end_time(self):
        return float("inf")

    def get_time_step(self):
        return 1.0

    def get_time_units(self):
        return "1"

    # --- values
    def get_value(self, name, dest):
        values = [self._model.iteration()] if name == ITERATION else self._model.get(name)
        dest[:] = numpy.asarray(values).astype(dest.dtype if hasattr(dest, "dtype") else self._precision)
        return dest

    def get_value_ptr(self, name):
        raise NotImplementedError("the reference's state lives in C++: use get_value")

    def set_value(self, name, src):
        if name == ITERATION:
            self._model.set_iteration(int(numpy.ravel(src)[0]))
        else:
            self._model.set(name, numpy.asarray(src, numpy.float64).ravel())

    # --- grids: 0 holds the iteration, 1 + k the k-th field
    def _grid_shape(self, grid):
        return (1,) if grid == 0 else self._shape(self.get_output_var_names()[grid - 1])

    def get_grid_type(self, grid):
        return "scalar" if grid == 0 else "uniform_rectilinear"

    def get_grid_rank(self, grid):
        return len(self._grid_shape(grid))

    def get_grid_size(self, grid):
        return int(numpy.prod(self._grid_shape(grid)))

    def get_grid_shape(self, grid, shape):
        shape[:] = self._grid_shape(grid)
        return shape

    def get_grid_spacing(self, grid, spacing):
        spacing[:] = ((1.0,) if grid == 0 else (*self._model.spacing(), 1.0))[:len(spacing)]
        return spacing

    def get_grid_origin(self, grid, origin):
        origin[:] = 0.0
        return origin
