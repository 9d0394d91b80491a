#include "tradeoff/plan_parameters.hpp"

#include "io/json_file.hpp"
#include "io/run_directory.hpp"
#include "validation/parameter_choice.hpp"

namespace iwb::tradeoff {

namespace {

// The first of `files`, else the set `iwb validate` would choose for the reference run.
io::ParameterSet first_parameters(const PlanOptions& opt, const std::vector<std::string>& files,
                                  std::string& why) {
  if (!files.empty()) {
    why = "given with --params";
    return io::read_parameter_set(files.front());
  }
  const auto summary = io::read_json_file(reference_run(opt) / "summary.json");
  const auto scene = dem::parse_scene(io::read_file(opt.scene_file), opt.scene_file.string());
  return validation::parameters_for(io::parameter_sets({}), scene,
                                    summary["residual_friction"].get<double>(), why);
}

}  // namespace

nlohmann::json run_plan_from_files(PlanOptions opt, const std::vector<std::string>& files) {
  load_scene_to_plan(opt.scene_file);  // every value and [requirements] checked first
  opt.params = first_parameters(opt, files, opt.params_why);
  for (std::size_t k = 1; k < files.size(); ++k)
    opt.other_calibrations.push_back(io::read_parameter_set(files[k]));
  return run_plan(opt);
}

}  // namespace iwb::tradeoff
