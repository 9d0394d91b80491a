// Python module `iwb_interface` (pybind11) over the C library: numpy arrays in and out, errors as
// exceptions carrying the library's status, message and suggested step factor.
//   m = iwb_interface.Material("hvwe", "data/params/table_5_1_evaluation.toml", kappa_r=1.0)
//   s = m.initial_state(sigma_n_kPa=100, e0=0.8)
//   s, traction, tangent = m.update(s, [0.0, 1e-4, 0.0], thickness=1.0)
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "iwb_interface.h"

namespace py = pybind11;

namespace {

constexpr size_t kMessageSize = 2048;

// The library's error as a Python exception: status, message, step_factor (IWB_ERROR_DOMAIN and
// IWB_ERROR_CONVERGENCE: the fraction of the increment to retry with).
struct MaterialError : std::runtime_error {
  MaterialError(int s, const std::string& m, double f)
      : std::runtime_error(m), status(s), step_factor(f) {}
  int status;
  double step_factor;
};

void check(iwb_status status, const char* message, double step_factor = 1.0) {
  if (status != IWB_OK) throw MaterialError(status, message, step_factor);
}

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

class Material {
 public:
  Material(const std::string& model, const std::string& parameter_file, double kappa_r,
           const std::string& integration) {
    char message[kMessageSize];
    iwb_material* m = nullptr;
    check(iwb_material_create(model.c_str(), parameter_file.c_str(), kappa_r, integration.c_str(),
                              &m, message, kMessageSize),
          message);
    material_.reset(m);
  }

  std::vector<std::string> state_names() const {
    std::vector<std::string> names;
    for (int i = 0; i < iwb_state_size(material_.get()); ++i)
      names.emplace_back(iwb_state_name(material_.get(), i));
    return names;
  }

  std::vector<std::string> initial_inputs() const {
    std::vector<std::string> keys;
    for (int i = 0; i < iwb_initial_input_count(material_.get()); ++i)
      keys.emplace_back(iwb_initial_input_key(material_.get(), i));
    return keys;
  }

  Array initial_state(const py::kwargs& inputs) const {
    std::vector<std::string> keys;
    std::vector<double> values;
    for (const auto& [key, value] : inputs)
      keys.push_back(py::str(key)), values.push_back(value.cast<double>());
    std::vector<const char*> pointers;
    for (const auto& k : keys) pointers.push_back(k.c_str());
    Array state(iwb_state_size(material_.get()));
    char message[kMessageSize];
    check(iwb_initial_state(material_.get(), pointers.data(), values.data(), int(values.size()),
                            state.mutable_data(), message, kMessageSize),
          message);
    return state;
  }

  Array traction(const Array& state) const {
    require_size(state);
    Array t(3);
    char message[kMessageSize];
    check(iwb_traction(material_.get(), state.data(), t.mutable_data(), message, kMessageSize),
          message);
    return t;
  }

  // (state_out, traction, tangent 3x3) after the increment du = (du_n, du_x, du_y) over d_s^v.
  py::tuple update(const Array& state, const Array& du, double thickness) const {
    require_size(state);
    if (du.size() != 3) throw py::value_error("du must hold 3 values (du_n, du_x, du_y)");
    Array out(iwb_state_size(material_.get())), t(3), tangent({3, 3});
    double factor = 1.0;
    char message[kMessageSize];
    check(iwb_update(material_.get(), state.data(), du.data(), thickness, 0.0, nullptr,
                     out.mutable_data(), t.mutable_data(), tangent.mutable_data(), &factor, message,
                     kMessageSize),
          message, factor);
    return py::make_tuple(out, t, tangent);
  }

 private:
  void require_size(const Array& state) const {
    if (state.size() != iwb_state_size(material_.get()))
      throw py::value_error("state must hold " + std::to_string(iwb_state_size(material_.get())) +
                            " values");
  }

  struct Destroy {
    void operator()(iwb_material* m) const { iwb_material_destroy(m); }
  };
  std::unique_ptr<iwb_material, Destroy> material_;
};

}  // namespace

PYBIND11_MODULE(iwb_interface, m) {
  m.doc() =
      "The interface models of the interface workbench (iwb) through its C library "
      "(iwb_interface.h)";
  m.attr("__version__") = iwb_version();
  static py::exception<MaterialError> error(m, "MaterialError");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const MaterialError& e) {
      PyObject* type = error.ptr();
      py::object exception = py::reinterpret_borrow<py::object>(type)(e.what());
      exception.attr("status") = e.status;
      exception.attr("step_factor") = e.step_factor;
      PyErr_SetObject(type, exception.ptr());
    }
  });
  py::class_<Material>(m, "Material")
      .def(py::init<const std::string&, const std::string&, double, const std::string&>(),
           py::arg("model"), py::arg("parameter_file"), py::arg("kappa_r") = 1.0,
           py::arg("integration") = "",
           "integration: TOML text of an [integration] table (e.g. 'scheme = \"euler\"\\nsubsteps "
           "= 4'); '' for the default")
      .def_property_readonly("state_names", &Material::state_names)
      .def_property_readonly("initial_inputs", &Material::initial_inputs)
      .def("initial_state", &Material::initial_state,
           "the initial state from the model's [initial] inputs by keyword")
      .def("traction", &Material::traction, py::arg("state"))
      .def("update", &Material::update, py::arg("state"), py::arg("du"), py::arg("thickness") = 1.0,
           "(state_out, traction (sigma_n, tau_x, tau_y) kPa, tangent d traction / d du) after the "
           "increment du");
}
