#include "calibration/simulate.hpp"

#include <fmt/core.h>

#include <cmath>

#include "common/errors.hpp"
#include "driver/element_test.hpp"

namespace iwb::calibration {

namespace {

// Largest step of the control inside one driver increment. Hypoplastic rates are rate
// independent and the integrator is adaptive (rtol below), so the increment size only sets how
// often the mixed control is solved: one increment per data row suffices up to these steps.
constexpr double kMaxShearStrainStep = 0.05;
constexpr double kMaxLogStressStep = 0.25;  // ln(sigma_i / sigma_{i-1})
constexpr double kIntegratorTolerance = 1e-7;

int increments_between(const soil_test::SoilTest& t, std::size_t i) {
  const double step = t.kind == soil_test::SoilTestKind::kOedometer
                          ? std::abs(std::log(t.control[i] / t.control[i - 1])) / kMaxLogStressStep
                          : std::abs(t.control[i] - t.control[i - 1]) / kMaxShearStrainStep;
  return std::max(1, int(std::ceil(step)));
}

driver::Path path_along(const soil_test::SoilTest& t) {
  driver::Path path;
  const driver::BoundaryCondition bc{t.boundary, 0.0};
  for (std::size_t i = 1; i < t.rows(); ++i) {
    const int n = increments_between(t, i);
    if (t.kind == soil_test::SoilTestKind::kOedometer)
      path.push_back(driver::oedometric_path(t.control[i - 1], t.control[i], n).front());
    else
      path.push_back({fmt::format("row {}", i), t.control[i] - t.control[i - 1], 0.0, bc.row(), n});
  }
  return path;
}

void record(Simulated& out, const models::Model& model, const driver::HistoryRow& row) {
  const auto s = model.stress(row.state);
  out.e.push_back(model.void_ratio(row.state));
  out.eps_v.push_back(-row.eps_n);  // compression positive
  out.tau_kPa.push_back(s.tau_x);
  out.sigma_n_kPa.push_back(s.sigma_n);
}

}  // namespace

double initial_K0(const soil_test::SoilTest& test, const std::string& model_name,
                  const models::ModelInputs& inputs) {
  return test.K0 > 0.0 ? test.K0 : models::offer(models::find_model(model_name), inputs, {}).K0;
}

Simulated simulate(const soil_test::SoilTest& test, const std::string& model_name,
                   const models::ModelInputs& inputs) {
  Simulated out;
  std::unique_ptr<models::Model> model;
  models::StateVector initial;
  try {
    model = models::find_model(model_name).make(inputs);
    models::InitialState start{test.sigma0_kPa, initial_K0(test, model_name, inputs), test.e0};
    start.delta_along_compression = true;  // the cell was consolidated vertically (soil_cell.hpp)
    initial = model->initial_state(start);
  } catch (const InputError& e) {
    out.status = fmt::format("refused: {}", e.what());
    return out;
  }
  driver::RunSettings settings;
  settings.integrator.rtol = kIntegratorTolerance;
  const auto result = driver::run_element_test(*model, initial, path_along(test), settings);
  out.status = result.status;
  // The row that ends each segment is the model's value at the next data row.
  record(out, *model, result.rows.front());
  for (std::size_t k = 1; k < result.rows.size(); ++k) {
    const bool last_of_segment =
        k + 1 == result.rows.size() || result.rows[k + 1].segment != result.rows[k].segment;
    if (last_of_segment && (result.complete() || k + 1 < result.rows.size()))
      record(out, *model, result.rows[k]);
  }
  return out;
}

}  // namespace iwb::calibration
