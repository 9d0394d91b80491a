#pragma once
// Why a model breaks, in one line per scene, from its form-limit records (issue 38, item 5): for
// tables that rank models (the league), where a per-run verdict table would not fit.
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace iwb::comparison {

// Over a record's runs of one wall and boundary, per quantity: the runs, those the soil-test set's
// prediction breaks, and these counted by cause (form, calibration, calibration (unchecked):
// comparison/form_limit.hpp).
struct QuantityCauses {
  int runs = 0, predicted_breaks = 0;
  std::map<std::string, int> by_cause;
};
std::map<std::string, QuantityCauses> causes_on(const nlohmann::json& record,
                                                const std::string& wall,
                                                const std::string& boundary);

// "residual_friction: form 3 of 3; total_dilation: form 2, calibration 1 of 3": each quantity the
// prediction breaks, with its breaks counted by cause, the most frequent first;
// "nothing breaks" when the prediction breaks none; empty for no runs.
std::string causes_line(const std::map<std::string, QuantityCauses>& causes);

// The form-limit record of `model` under `dir` (DIR/*/form_limit.json) that has runs on `wall`
// and `boundary`; nullopt when there is none. Records that are not form limits, or are another
// model's, are skipped; one of `model` that check_form_limit_record refuses is an InputError.
std::optional<std::filesystem::path> find_form_limit(const std::filesystem::path& dir,
                                                     const std::string& model,
                                                     const std::string& wall,
                                                     const std::string& boundary);

// A ranking table's cell for `model` (the league): {"record": the record's path or null, "causes":
// causes_line of its runs on this wall and boundary, or "no form-limit record"}.
nlohmann::json form_limit_cell(const std::filesystem::path& dir, const std::string& model,
                               const std::string& wall, const std::string& boundary);

}  // namespace iwb::comparison
