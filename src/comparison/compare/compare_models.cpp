#include "comparison/compare/compare_models.hpp"

#include <fmt/core.h>

#include "common/errors.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace {

std::vector<ComparisonInputs> inputs_per_model(const CompareOptions& options,
                                               const std::vector<std::string>& models) {
  if (models.size() > 1 && !options.form_limit.empty())
    throw InputError("--form-limit: a form-limit record is one model's; give one --model with it");
  std::vector<ComparisonInputs> each;
  for (const auto& model : models) {
    for (const auto& earlier : each)
      if (earlier.options.model == model)
        throw InputError(fmt::format("--model {}: given twice", model));
    auto opt = options;
    opt.model = model;
    opt.out = models.size() > 1 ? options.out / model : options.out;
    io::require_new_run_directory(opt.out, {"comparison"}, opt.force);
    each.push_back(read_comparison_inputs(opt));
  }
  return each;
}

}  // namespace

ModelComparisons compare_models(const CompareOptions& options,
                                const std::vector<std::string>& models) {
  ModelComparisons out;
  for (const auto& in : inputs_per_model(options, models)) {
    out.results.push_back(run_comparison(in));
    out.dirs.push_back(in.options.out);
  }
  return out;
}

}  // namespace iwb::comparison
