#pragma once
// The total Sobol indices of an interface model's element test (issue 17; seed 4.3.1, Tables
// 4.3-4.7): every material parameter of the model's tables is normal about its value in the
// parameter file with one coefficient of variation (the seed's sensitivity study takes COV 0.05 and
// 0.1), the element test is monotonic simple shear under CNL, CNS or CV, and the quantities of
// interest are its peak, path-averaged and end friction tau/sigma_n, its end normal strain and
// normal stress.
#include <functional>
#include <map>
#include <string>

#include "assessment/sobol.hpp"
#include "assessment/uncertainty.hpp"
#include "driver/control.hpp"
#include "models/registry.hpp"

namespace iwb::assessment {

struct ElementSensitivityOptions {
  models::ModelInputs inputs;  // the parameter file: the distributions' means
  double cov = 0.1;
  std::map<std::string, double>
      cov_of;  // per parameter key, instead of cov (the seed's starred ones)
  // key -> (factor, other): the parameter follows another, key = factor x other, and is not varied
  // itself (the seed's Table 4.6 samples e_c0 only, e_i0 = 1.2 e_c0 and e_d0 = 0.379 e_c0)
  std::map<std::string, std::pair<double, std::string>> ties;
  driver::BoundaryKind boundary = driver::BoundaryKind::kCNL;
  double sigma_n_kPa = 100.0;
  double e0 = 0.0;                     // for a model with a void ratio; ignored by one without
  double K_kPa_per_unit_strain = 0.0;  // CNS
  double gamma = 0.1;
  int increments = 200;
  int samples = 1000;  // N: the runs are N (k + 2)
  unsigned seed = 1;
  int threads = 0;  // runs at once; 0: every core
  std::function<void(long done, long total)> progress;
};

// The parameters varied: the tables' material entries (phi_c included) with a non-zero value (a
// zero, such as no cohesion, has no spread to give) that are not tied to another, each with `cov`
// or its own in `cov_of`. InputError for a key of `cov_of` that is not varied, or a tie naming a
// parameter the model lacks.
std::vector<Distribution> varied_parameters(
    const models::ModelSpec& spec, const models::ModelInputs& inputs, double cov,
    const std::map<std::string, double>& cov_of = {},
    const std::map<std::string, std::pair<double, std::string>>& ties = {});

SobolResult element_sensitivity(const models::ModelSpec& spec,
                                const ElementSensitivityOptions& options);

// The CV of each quantity when the parameters named in `distributions` (keys of the model's tables)
// follow them and the others keep the file's values (seed 4.3.2, Table 4.8); options.samples Latin
// hypercube samples. InputError naming a key the model does not have.
UncertaintyResult element_uncertainty(const models::ModelSpec& spec,
                                      const ElementSensitivityOptions& options,
                                      const std::vector<Distribution>& distributions);

}  // namespace iwb::assessment
