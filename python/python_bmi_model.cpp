// A Python object with bmipy's methods as a BmiModel; see python_bmi_model.hpp.
#include "python_bmi_model.hpp"

#include <cstring>
#include <stdexcept>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace gt::python {
namespace {

// The numpy dtype of a BMI type name.
py::dtype dtype_of(const std::string& type) {
  if (type == "float" || type == "float32") return py::dtype("float32");
  if (type == "double" || type == "float64") return py::dtype("float64");
  if (type == "int" || type == "int32") return py::dtype("int32");
  throw std::runtime_error(fmt::format("type '{}': groundtruth reads float, float32, double, float64, int or int32", type));
}

// A py::object owned through a shared pointer whose deleter takes the GIL: copies of the driver's
// options (made without the GIL) then never touch Python's reference counts.
using SharedObject = std::shared_ptr<py::object>;

SharedObject share(py::object object) {
  return SharedObject(new py::object(std::move(object)), [](py::object* owned) {
    py::gil_scoped_acquire gil;
    delete owned;
  });
}

class PythonBmiModel : public BmiModel {
 public:
  PythonBmiModel(py::object model, const std::filesystem::path& config, std::string label)
      : model_(std::move(model)), label_(std::move(label)) {
    call("initialize", config.string());
  }
  ~PythonBmiModel() override {
    py::gil_scoped_acquire gil;
    try {
      if (py::hasattr(model_, "finalize")) model_.attr("finalize")();
    } catch (const py::error_already_set&) {
      // Finalising is the model's last word: a failure there changes no verdict.
    }
    model_ = py::object();
  }

  std::vector<std::string> output_names() override { return names("get_output_var_names"); }
  std::vector<std::string> input_names() override { return names("get_input_var_names"); }

  BmiVariable variable(const std::string& name) override {
    py::gil_scoped_acquire gil;
    return {.name = name,
            .type = py::str(call("get_var_type", name)),
            .units = py::str(call("get_var_units", name)),
            .itemsize = call("get_var_itemsize", name).cast<int>(),
            .nbytes = call("get_var_nbytes", name).cast<long long>(),
            .grid = call("get_var_grid", name).cast<int>()};
  }

  BmiGrid grid(int id) override {
    constexpr int most_dimensions = 8;
    py::gil_scoped_acquire gil;
    BmiGrid grid;
    grid.rank = call("get_grid_rank", id).cast<int>();
    if (grid.rank < 1 || grid.rank > most_dimensions) {
      throw std::runtime_error(fmt::format("{}: get_grid_rank({}) says rank {} (1 to {} are read)", label_, id,
                                           grid.rank, most_dimensions));
    }
    grid.size = call("get_grid_size", id).cast<long long>();
    const auto shape = call("get_grid_shape", id, py::array_t<long long>(grid.rank));
    for (const auto& side : shape) grid.shape.push_back(side.cast<int>());
    const auto spacing = call("get_grid_spacing", id, py::array_t<double>(grid.rank));
    for (const auto& step : spacing) grid.spacing.push_back(step.cast<double>());
    return grid;
  }

  void update() override { call("update"); }

  void get_value(const std::string& name, std::vector<std::byte>& bytes) override {
    py::gil_scoped_acquire gil;
    const py::dtype dtype = dtype_of(py::str(call("get_var_type", name)));
    const auto count = static_cast<py::ssize_t>(bytes.size() / static_cast<std::size_t>(dtype.itemsize()));
    py::array destination(dtype, std::vector<py::ssize_t>{count});
    py::object given = call("get_value", name, destination);
    if (given.is_none()) given = destination;
    const py::array values = py::module_::import("numpy").attr("ascontiguousarray")(given, dtype).attr("ravel")();
    if (static_cast<std::size_t>(values.nbytes()) != bytes.size()) {
      throw std::runtime_error(fmt::format("{}: get_value('{}') gave {} bytes where its get_var_nbytes says {}", label_,
                                           name, values.nbytes(), bytes.size()));
    }
    std::memcpy(bytes.data(), values.data(), bytes.size());
  }

  void set_value(const std::string& name, std::vector<std::byte>& bytes) override {
    py::gil_scoped_acquire gil;
    const py::dtype dtype = dtype_of(py::str(call("get_var_type", name)));
    const auto count = static_cast<py::ssize_t>(bytes.size() / static_cast<std::size_t>(dtype.itemsize()));
    py::array source(dtype, std::vector<py::ssize_t>{count});
    if (static_cast<std::size_t>(source.nbytes()) != bytes.size()) {
      throw std::runtime_error(fmt::format("{}: {} bytes of '{}' are not a whole number of {}-byte items", label_,
                                           bytes.size(), name, dtype.itemsize()));
    }
    std::memcpy(source.mutable_data(), bytes.data(), bytes.size());
    call("set_value", name, source);
  }

  const std::string& label() const override { return label_; }

 private:
  template <class... Args>
  py::object call(const char* method, Args&&... args) {
    py::gil_scoped_acquire gil;
    try {
      if (!py::hasattr(model_, method)) {
        throw std::runtime_error(fmt::format("{} has no method {}, which groundtruth calls (bmipy's names)", label_, method));
      }
      return model_.attr(method)(std::forward<Args>(args)...);
    } catch (py::error_already_set& error) {
      throw std::runtime_error(fmt::format("{}.{} raised {}", label_, method, error.what()));
    } catch (const py::cast_error& error) {
      throw std::runtime_error(fmt::format("{}.{} gave a value of the wrong kind: {}", label_, method, error.what()));
    }
  }

  std::vector<std::string> names(const char* method) {
    py::gil_scoped_acquire gil;
    std::vector<std::string> names;
    for (const auto& name : call(method)) names.push_back(py::str(name));
    return names;
  }

  py::object model_;
  std::string label_;
};

}  // namespace

ExternalModel python_external_model(const py::object& factory, const std::string& label) {
  const SharedObject shared = share(factory);
  return {.label = label,
          .origin = "a Python model, in this process",
          .make = [shared, label](const std::filesystem::path& config) -> std::unique_ptr<BmiModel> {
            py::gil_scoped_acquire gil;
            py::object instance;
            try {
              instance = (*shared)();
            } catch (py::error_already_set& error) {
              throw std::runtime_error(fmt::format("making {} raised {}", label, error.what()));
            }
            return std::make_unique<PythonBmiModel>(std::move(instance), config, label);
          }};
}

}  // namespace gt::python
