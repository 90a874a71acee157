// groundtruth._core: the C++ half of the Python module (python/groundtruth/__init__.py is the
// other). It gives Python the driver's own entry points, so that a run from Python is the run
// `groundtruth run --algorithm ...` makes: the same input readers, parameter declarations, twins,
// checks and report, and the same messages for bad input.
//
//   algorithms_json()            the declarations of every algorithm (compare/algorithm.hpp
//                                algorithm_json), as `groundtruth list --json` gives them
//   algorithm_json(name)         one of them; an unknown name raises InputError listing the known
//   run_case(...)                one ad-hoc case into a report folder; returns the exit status
//                                (0: nothing unexpected failed, 1: something did). With `external`
//                                (a callable returning a model with bmipy's methods) that model is
//                                graded where the GPU twin stands (python_bmi_model.hpp). With
//                                `vary` (name=v1,v2,... each) the case is the base of a sweep
//                                (compare/sweep.hpp: sweep.json, sweep.csv, sweep.html), with `a` and
//                                `b` (name=value each) of an A/B comparison (compare/ab.hpp: ab.json),
//                                as `groundtruth sweep` and `groundtruth ab` make them
//   dataset_dir()                the bundled and fetched data sets (datasets/ of the checkout)
//   command_line()               the `groundtruth` executable built beside this module
//   degrees_to_metres(dlon, dlat, latitude)  a geographic cell's size in metres, (x, y), as the
//                                command line's readers convert it (core/io/dem_formats.hpp)
//   require_memory(count, unit, bytes_each, what)  core/memory.hpp's gate (InputError when the
//                                estimate exceeds what this process may use), for the Python side
//   ReferenceModel(algorithm, double)  a stepped algorithm's reference behind the BMI
//                                (compare/external/reference_bmi.hpp); groundtruth.bmi.Reference
//                                gives it bmipy's method names
//   InputError                   a ValueError carrying the CLI's message (the CLI's exit 2)
//
// The GIL is released while a case runs (an outside Python model takes it for each call); meanwhile a
// SIGTERM (or another ending signal Python leaves at its default) removes the staging folder and the
// caller's scratch folder before the process ends, as on the command line. The driver makes
// and ends its own GL context for the case, so nothing GL outlives a call.
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "compare/ab.hpp"
#include "compare/algorithm.hpp"
#include "compare/driver.hpp"
#include "compare/external/reference_bmi.hpp"
#include "compare/output_folder.hpp"
#include "compare/sweep.hpp"
#include "core/errors.hpp"
#include "core/io/dem_formats.hpp"
#include "core/memory.hpp"
#include "core/mutant.hpp"
#include "gpu/context/context.hpp"
#include "python_bmi_model.hpp"

namespace py = pybind11;

namespace {

gt::Backends parse_backends(const std::string& name) {
  if (name == "cpu") return gt::Backends::cpu;
  if (name == "gpu") return gt::Backends::gpu;
  if (name == "both") return gt::Backends::both;
  throw gt::InputError("backend '" + name + "': expected cpu (references only), gpu, or both");
}

struct CaseCall {
  std::string algorithm;
  std::string input;  // a file path, or empty (a generator's grid, or an algorithm without input)
  int width = 256;
  int height = 256;
  std::optional<double> cell_size;    // metres; none: the file's own (1 m for a generator)
  std::optional<double> cell_size_y;  // the rows' spacing when it differs (needs cell_size)
  std::vector<std::string> assignments;
  bool red_channel = false;
  std::string backend = "both";
  std::string gl = "egl";
  std::string mutant;
  bool require_gpu = false;
  bool quiet = true;
  bool pictures = true;
  bool descriptors = true;
  std::optional<int> reps;  // timed repetitions of each twin; none: the command line's (3 CPU, 5 GPU)
  std::filesystem::path out;
  std::string command_line;
  py::object external;         // None, or a callable returning an outside model (bmipy's methods)
  std::string external_label;  // the name it is shown by
  std::filesystem::path scratch;  // the caller's temporary folder, removed too if a signal ends the process
  std::vector<std::string> vary;  // a sweep: name=v1,v2,... per varied parameter (none: not a sweep)
  bool force = false;             // a sweep of more runs than compare/sweep.hpp's cap
  std::vector<std::string> a;     // an A/B comparison: A's name=value assignments, then B's
  std::vector<std::string> b;
  std::vector<std::string> fields;  // the heightmap's input fields, name=file
};

// The command line refuses these in its option parser (--size, --cell-size): the same limits.
void check_grid_options(const CaseCall& call) {
  constexpr int largest_side = 65536;
  if (call.width < 1 || call.height < 1 || call.width > largest_side || call.height > largest_side) {
    throw gt::InputError(fmt::format("size ({}, {}): expected (width, height) with sides in [1, {}]", call.width,
                                     call.height, largest_side));
  }
  for (const auto& size : {call.cell_size, call.cell_size_y}) {
    if (size && !(std::isfinite(*size) && *size > 0.0)) {
      throw gt::InputError(fmt::format("cell_size {}: expected a positive, finite number of metres", *size));
    }
  }
}

// The call's case as the driver runs it: one ad-hoc case, the base of a sweep, or of an A/B pair.
void set_cases(const CaseCall& call, const gt::AdHocCase& base, gt::DriverOptions& options) {
  const bool ab = !call.a.empty() || !call.b.empty();
  if (ab && !call.vary.empty()) throw gt::InputError("a call is a sweep (vary) or an A/B comparison (a, b), not both");
  if (ab) {
    options.sweep = gt::make_ab(base, call.a, call.b);
  } else if (!call.vary.empty()) {
    options.sweep = gt::make_sweep(base, call.vary, call.force);
  } else {
    options.ad_hoc = base;
  }
}

int run_case(const CaseCall& call) {
  check_grid_options(call);
  gt::DriverOptions options;
  const gt::AdHocCase base{.algorithm = call.algorithm,
                                 .input = call.input,
                                 .width = call.width,
                                 .height = call.height,
                                 .cell_size = call.cell_size.value_or(0.0),
                                 .cell_size_y = call.cell_size_y.value_or(0.0),
                                 .assignments = call.assignments,
                                 .red_channel = call.red_channel,
                                 .fields = call.fields};
  set_cases(call, base, options);
  options.backends = parse_backends(call.backend);
  options.gl = gt::parse_gl_backend(call.gl);
  options.mutant = call.mutant;
  options.require_gpu = call.require_gpu;
  if (options.require_gpu && options.backends == gt::Backends::cpu) {
    throw gt::InputError("require_gpu and backend='cpu' contradict each other: choose one");
  }
  if (call.reps && (*call.reps < 0 || *call.reps > 100)) {
    throw gt::InputError(fmt::format("reps {}: expected 0 (untimed) to 100 timed repetitions", *call.reps));
  }
  if (call.reps) options.cpu_reps = options.gpu_reps = *call.reps;
  options.pictures = call.pictures;
  options.descriptors = call.descriptors;
  options.quiet = call.quiet;
  options.summary = !call.quiet;
  options.out = call.out;
  options.dataset_dir = GT_DATASET_DIR;
  options.command_line = call.command_line;
  if (!call.external.is_none()) options.external_model = gt::python::python_external_model(call.external, call.external_label);
  // A mutant is switched on for the rest of a process (core/mutant.hpp): a Python session goes on
  // after the call, so the switch is put back whatever the run did.
  struct MutantReset {
    ~MutantReset() { gt::set_active_mutant(""); }
  } reset;
  py::gil_scoped_release unlocked;
  const gt::EmbeddedInterruptCleanup interruptible(call.scratch);
  return gt::run_driver(options);
}

}  // namespace

PYBIND11_MODULE(_core, module) {
  module.doc() = "groundtruth's driver (C++): use the groundtruth package, not this module";
  py::register_exception<gt::InputError>(module, "InputError", PyExc_ValueError);

  module.def("algorithms_json", [] {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& algorithm : gt::algorithms()) list.push_back(gt::algorithm_json(algorithm));
    return list.dump();
  });
  module.def("dataset_dir", [] { return std::filesystem::path(GT_DATASET_DIR); });
  module.def("command_line", [] { return std::filesystem::path(GT_COMMAND_LINE); });
  module.def("degrees_to_metres", [](double degrees_longitude, double degrees_latitude, double latitude) {
    const gt::detail::CellSizeMetres cell = gt::detail::degrees_to_metres(degrees_longitude, degrees_latitude, latitude);
    return std::pair<double, double>(cell.x, cell.y);
  });
  module.def("require_memory", [](double count, const std::string& unit, double bytes_each, const std::string& what) {
    gt::require_memory(gt::memory_for(count, unit, bytes_each), what);
  });
  py::class_<gt::ReferenceBmi>(module, "ReferenceModel")
      .def(py::init<std::string, bool>(), py::arg("algorithm"), py::arg("double_precision"))
      .def("initialize", [](gt::ReferenceBmi& model, const std::filesystem::path& config) { model.initialize(config); })
      .def("update", [](gt::ReferenceBmi& model) {
        py::gil_scoped_release unlocked;
        model.update();
      })
      .def("output_names", &gt::ReferenceBmi::output_names)
      .def("input_names", &gt::ReferenceBmi::input_names)
      .def("units", [](const gt::ReferenceBmi& model, const std::string& name) { return model.field(name).unit; })
      .def("components", [](const gt::ReferenceBmi& model, const std::string& name) { return model.field(name).components; })
      .def("shape", [](const gt::ReferenceBmi& model) { return std::vector<int>{model.grid().height, model.grid().width}; })
      .def("spacing", [](const gt::ReferenceBmi& model) {
        return std::vector<double>{model.grid().cell_size_y, model.grid().cell_size_x};
      })
      .def("iteration", &gt::ReferenceBmi::iteration)
      .def("set_iteration", &gt::ReferenceBmi::set_iteration)
      .def("get", [](gt::ReferenceBmi& model, const std::string& name) {
        const std::vector<double> values = model.get(name);
        return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
      })
      .def("set", [](gt::ReferenceBmi& model, const std::string& name,
                     const py::array_t<double, py::array::c_style | py::array::forcecast>& values) {
        model.set(name, std::vector<double>(values.data(), values.data() + values.size()));
      });
  module.def("algorithm_json", [](const std::string& name) { return gt::algorithm_json(gt::find_algorithm(name)).dump(); });
  module.def(
      "run_case",
      [](const std::string& algorithm, const std::string& input, int width, int height,
         std::optional<double> cell_size, std::optional<double> cell_size_y,
         const std::vector<std::string>& assignments, bool red_channel, const std::string& backend,
         const std::string& gl, const std::string& mutant, bool require_gpu, bool quiet, bool pictures,
         bool descriptors, std::optional<int> reps, const std::filesystem::path& out, const std::string& command_line,
         const py::object& external, const std::string& external_label, const std::filesystem::path& scratch,
         const std::vector<std::string>& vary, bool force, const std::vector<std::string>& a,
         const std::vector<std::string>& b, const std::vector<std::string>& fields) {
        return run_case({algorithm, input, width, height, cell_size, cell_size_y, assignments, red_channel, backend, gl, mutant,
                         require_gpu, quiet, pictures, descriptors, reps, out, command_line, external, external_label,
                         scratch, vary, force, a, b, fields});
      },
      py::arg("algorithm"), py::arg("input"), py::arg("width"), py::arg("height"), py::arg("cell_size"), py::arg("cell_size_y"),
      py::arg("assignments"), py::arg("red_channel"), py::arg("backend"), py::arg("gl"), py::arg("mutant"),
      py::arg("require_gpu"), py::arg("quiet"), py::arg("pictures"), py::arg("descriptors"), py::arg("reps"),
      py::arg("out"), py::arg("command_line"), py::arg("external") = py::none(), py::arg("external_label") = "",
      py::arg("scratch") = std::filesystem::path(), py::arg("vary") = std::vector<std::string>(),
      py::arg("force") = false, py::arg("a") = std::vector<std::string>(), py::arg("b") = std::vector<std::string>(),
      py::arg("fields") = std::vector<std::string>());
}
