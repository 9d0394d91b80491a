// The C interface (iwb_interface.h) over the workbench's models and stress-point integrator. Every
// entry point catches everything: errors become status codes and a message in the caller's
// buffer. The tangent is the derivative of the integrated increment: the increment integrated on
// dual numbers once per component of du (common/scalar.hpp carries one derivative).
#include "c_api/iwb_interface.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "element/element_test_file.hpp"
#include "integration/stress_point_integrator.hpp"
#include "io/parameter_file.hpp"
#include "io/toml_reader.hpp"
#include "models/registry.hpp"

struct iwb_material {
  const iwb::models::ModelSpec* spec = nullptr;
  iwb::models::ModelInputs inputs;
  std::unique_ptr<iwb::models::Model> model;
  iwb::integration::IntegratorSettings settings;
  std::vector<std::string> state_names;
};

namespace {

using iwb::models::StateVector;
using iwb::models::StateVectorT;

void copy_message(const std::string& text, char* message, size_t size) {
  if (message == nullptr || size == 0) return;
  const size_t n = std::min(text.size(), size - 1);
  std::memcpy(message, text.data(), n);
  message[n] = '\0';
}

// Runs `body`, turning every exception into a status and its message.
template <class Body>
iwb_status guarded(char* message, size_t size, Body&& body) {
  try {
    body();
    copy_message("", message, size);
    return IWB_OK;
  } catch (const iwb::InputError& e) {
    copy_message(e.what(), message, size);
    return IWB_ERROR_INPUT;
  } catch (const iwb::DomainError& e) {
    copy_message(e.what(), message, size);
    return IWB_ERROR_DOMAIN;
  } catch (const iwb::ConvergenceError& e) {
    copy_message(e.what(), message, size);
    return IWB_ERROR_CONVERGENCE;
  } catch (const std::exception& e) {
    copy_message(e.what(), message, size);
    return IWB_ERROR_INTERNAL;
  } catch (...) {
    copy_message("unknown error", message, size);
    return IWB_ERROR_INTERNAL;
  }
}

void require(bool condition, const std::string& why) {
  if (!condition) throw iwb::InputError(why);
}

std::unique_ptr<iwb_material> make_material(const char* model, iwb::models::ModelInputs inputs,
                                            double kappa_r, const char* integration) {
  require(model != nullptr, "model name is NULL");
  auto m = std::make_unique<iwb_material>();
  m->spec = &iwb::models::find_model(model);
  const auto& support = m->spec->declaration.roughness;
  if (m->spec->uses_roughness) {
    require(kappa_r > 0.0 && kappa_r <= 1.0, fmt::format("kappa_r = {:g} outside (0, 1]", kappa_r));
    inputs.roughness.scheme = support.default_scheme;
    inputs.roughness.kappa_r = kappa_r;
  } else {
    require(
        kappa_r == 1.0,
        fmt::format("model '{}' is a continuum model and takes no wall roughness: give kappa_r = 1 "
                    "(given {:g})",
                    model, kappa_r));
  }
  if (integration != nullptr && *integration != '\0')
    m->settings = iwb::element::parse_integrator_settings(
        iwb::io::parse_toml_text(integration, "integration"), "integration");
  m->inputs = std::move(inputs);
  m->model =
      m->spec->make(m->inputs);  // validates the parameters (InputError naming file, key, value)
  m->state_names = m->model->state_names();
  return m;
}

iwb_status create(char* message, size_t size, iwb_material** out,
                  const std::function<std::unique_ptr<iwb_material>()>& make) {
  if (out != nullptr) *out = nullptr;
  return guarded(message, size, [&] {
    require(out != nullptr, "out is NULL");
    *out = make().release();
  });
}

// d(traction)/d(strain component j) of the integrated increment, by one pass on dual numbers.
StateVector derivative_of_increment(const iwb_material& m, const StateVector& s,
                                    const iwb::models::InterfaceStrain& d, int j,
                                    StateVector& values) {
  using iwb::Dual;
  const double c[3] = {d.eps_n, d.gamma_x, d.gamma_y};
  Dual x[3];
  for (int i = 0; i < 3; ++i) x[i] = i == j ? iwb::make_variable(c[i]) : Dual(c[i]);
  iwb::integration::IntegrationCounters counters;
  double first_step = 1.0;
  const StateVectorT<Dual> start = s.cast<Dual>();
  const auto end = iwb::integration::integrate_increment<Dual>(*m.model, start, {x[0], x[1], x[2]},
                                                               m.settings, counters, first_step);
  StateVector derivative(end.size());
  values.resize(end.size());
  for (int i = 0; i < end.size(); ++i) {
    values(i) = iwb::value_of(end(i));
    derivative(i) = iwb::derivative_of(end(i));
  }
  return derivative;
}

void write_traction(const iwb_material& m, const StateVector& s, double* traction) {
  const auto t = m.model->stress(s);
  traction[0] = t.sigma_n, traction[1] = t.tau_x, traction[2] = t.tau_y;
}

StateVector state_of(const iwb_material& m, const double* values) {
  return Eigen::Map<const Eigen::VectorXd>(values, m.model->state_size());
}

}  // namespace

extern "C" {

const char* iwb_version(void) {
  return IWB_VERSION;
}

iwb_status iwb_material_create(const char* model, const char* parameter_file, double kappa_r,
                               const char* integration, iwb_material** out, char* message,
                               size_t message_size) {
  return create(message, message_size, out, [&] {
    require(parameter_file != nullptr, "parameter_file is NULL");
    iwb::models::ModelInputs inputs;
    inputs.tables = iwb::io::load_parameter_file(parameter_file);
    inputs.source = parameter_file;
    return make_material(model, std::move(inputs), kappa_r, integration);
  });
}

iwb_status iwb_material_create_from_values(const char* model, const char* const* keys,
                                           const double* values, int n, double kappa_r,
                                           const char* integration, iwb_material** out,
                                           char* message, size_t message_size) {
  return create(message, message_size, out, [&] {
    require(n >= 0 && (n == 0 || (keys != nullptr && values != nullptr)), "keys or values is NULL");
    iwb::models::ModelInputs inputs;
    inputs.source = "<iwb_material_create_from_values>";
    for (int i = 0; i < n; ++i) {
      require(keys[i] != nullptr, fmt::format("key {} is NULL", i));
      const std::string key = keys[i];
      const auto dot = key.find('.');
      require(dot != std::string::npos && dot > 0 && dot + 1 < key.size(),
              fmt::format("key '{}' is not \"table.key\" (e.g. \"hypoplastic.phi_c_deg\")", key));
      inputs.tables[key.substr(0, dot)][key.substr(dot + 1)] = values[i];
    }
    return make_material(model, std::move(inputs), kappa_r, integration);
  });
}

void iwb_material_destroy(iwb_material* material) {
  delete material;
}

int iwb_state_size(const iwb_material* material) {
  return material ? material->model->state_size() : 0;
}

const char* iwb_state_name(const iwb_material* material, int i) {
  if (material == nullptr || i < 0 || i >= int(material->state_names.size())) return nullptr;
  return material->state_names[i].c_str();
}

int iwb_monotonic_only(const iwb_material* material) {
  return material != nullptr && material->spec->declaration.monotonic_only ? 1 : 0;
}

int iwb_initial_input_count(const iwb_material* material) {
  return material ? int(material->spec->declaration.initial.size()) : 0;
}

const char* iwb_initial_input_key(const iwb_material* material, int i) {
  if (material == nullptr || i < 0 || i >= iwb_initial_input_count(material)) return nullptr;
  return material->spec->declaration.initial[i].key.c_str();
}

iwb_status iwb_initial_state(const iwb_material* material, const char* const* keys,
                             const double* values, int n, double* state, char* message,
                             size_t message_size) {
  return guarded(message, message_size, [&] {
    require(material != nullptr && state != nullptr, "material or state is NULL");
    require(n >= 0 && (n == 0 || (keys != nullptr && values != nullptr)), "keys or values is NULL");
    toml::table initial;
    for (int i = 0; i < n; ++i) {
      require(keys[i] != nullptr, fmt::format("key {} is NULL", i));
      initial.insert_or_assign(keys[i], values[i]);
    }
    const auto init = iwb::element::parse_initial_state(initial, material->spec->name,
                                                        material->inputs, "initial state");
    const auto s = material->model->initial_state(init);
    std::copy(s.data(), s.data() + s.size(), state);
  });
}

iwb_status iwb_traction(const iwb_material* material, const double* state, double traction[3],
                        char* message, size_t message_size) {
  return guarded(message, message_size, [&] {
    require(material != nullptr && state != nullptr && traction != nullptr,
            "material, state or traction is NULL");
    write_traction(*material, state_of(*material, state), traction);
  });
}

iwb_status iwb_update(const iwb_material* material, const double* state_in, const double du[3],
                      double thickness, double dt, const double* external, double* state_out,
                      double traction[3], double* tangent, double* step_factor, char* message,
                      size_t message_size) {
  (void)dt;        // no model of the workbench reads time yet (issue 19)
  (void)external;  // nor temperature or suction: their increments will travel with the stretching
  if (step_factor != nullptr) *step_factor = 1.0;
  const iwb_status status = guarded(message, message_size, [&] {
    require(material != nullptr && state_in != nullptr && du != nullptr && state_out != nullptr &&
                traction != nullptr,
            "material, state_in, du, state_out or traction is NULL");
    require(thickness > 0.0, fmt::format("thickness d_s^v = {:g} must be positive", thickness));
    const StateVector s = state_of(*material, state_in);
    // A model whose law is in displacement (hyperbolic, mortara, api-tz) turns strains back into
    // displacements by the d_s it was made with (ModelInputs::shear_zone_mm), so it is given the
    // strain over that d_s: its response in displacement is then exact whatever the caller's
    // thickness, which it does not depend on (over `thickness` it scaled by d_s / thickness).
    const double h =
        material->spec->declaration.displacement_based ? material->inputs.shear_zone_mm : thickness;
    const iwb::models::InterfaceStrain d{du[0] / h, du[1] / h, du[2] / h};
    StateVector end;
    if (tangent == nullptr) {
      iwb::integration::IntegrationCounters counters;
      double first_step = 1.0;
      end = iwb::integration::integrate_increment<double>(*material->model, s, d,
                                                          material->settings, counters, first_step);
    } else {
      // The traction is linear in the state (every model's stress() selects and signs components),
      // so the derivative of the traction is the traction of the state's derivative.
      for (int j = 0; j < 3; ++j) {
        const StateVector ds = derivative_of_increment(*material, s, d, j, end);
        double column[3];
        write_traction(*material, ds, column);
        for (int i = 0; i < 3; ++i) tangent[3 * i + j] = column[i] / h;
      }
    }
    if (const auto why = material->model->domain_violation(end); !why.empty())
      throw iwb::DomainError(why);
    material->model->flush_negligible_components(end);
    std::copy(end.data(), end.data() + end.size(), state_out);
    write_traction(*material, end, traction);
  });
  if ((status == IWB_ERROR_DOMAIN || status == IWB_ERROR_CONVERGENCE) && step_factor != nullptr)
    *step_factor = 0.5;
  if (status != IWB_OK && material != nullptr && state_in != nullptr && state_out != nullptr &&
      state_out != state_in)
    std::copy(state_in, state_in + material->model->state_size(),
              state_out);  // the caller retries from here
  return status;
}

}  // extern "C"
