#pragma once
// Why a model breaks, from its form-limit records (issue 38, item 5): a record read and checked,
// the cause of each break on a run, and one line per scene for tables that rank models (the
// league), where a per-run verdict table would not fit. Below the form limit that writes the
// records (form_limit.hpp), so that compare reads them without depending on the fit (issue 58).
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace iwb::comparison {

// Over a record's runs of one wall and boundary, per quantity: the runs, those the soil-test set's
// prediction breaks, and these counted by cause (form, calibration, calibration (unchecked):
// comparison/causes/form_limit.hpp).
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

// The record itself, as its readers take it (iwb compare --form-limit, --runs, the league).

// How a form-limit record names a wall: "R_n 0.5, d50 2 mm".
std::string wall_name(double R_n, double d50_mm);

// The form-limit record `file` (form_limit.json) read for `model`: InputError naming the file
// when it is not one, or is another model's (a form limit says nothing of another model's form),
// or when check_form_limit_record refuses it.
nlohmann::json read_form_limit(const std::filesystem::path& file, const std::string& model);

// A form-limit record read from `file`, checked where its readers take it (form_limit_verdicts,
// causes_on): runs[] of objects with a wall, a boundary and (if any) a dir as strings, and per
// quantity the verdicts soil_test_predicted and form_limit as strings. InputError "FILE: key
// '/runs/0/wall' = 3: should be a string" (issue 60), never nlohmann's type_error.
void check_form_limit_record(const nlohmann::json& record, const std::filesystem::path& file);

// Per quantity, the cause a "breaks" of the soil-test set's prediction has on a run of this wall
// and boundary in `record` (the run itself when the record holds it, else the first run of its
// wall and boundary); empty when the record has no such run.
std::map<std::string, std::string> form_limit_causes(const nlohmann::json& record,
                                                     const std::filesystem::path& dem_dir,
                                                     double R_n, double d50_mm,
                                                     const std::string& boundary);

// The cause a record's quantity gives a "breaks": its cause_if_breaks; for a record written before
// the soil tests judged the set, "form" where the form limit breaks it, else "calibration
// (unchecked)".
std::string cause_if_breaks(const nlohmann::json& quantity);

// A verdict's cause: `cause_if_breaks` for "breaks", empty for every other verdict.
std::string cause_of(const std::string& verdict, const std::string& cause_if_breaks);

}  // namespace iwb::comparison
