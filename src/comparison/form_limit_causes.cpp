#include "comparison/form_limit_causes.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <vector>

#include "comparison/form_limit.hpp"
#include "io/json_file.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;
using nlohmann::json;

std::map<std::string, QuantityCauses> causes_on(const json& record, const std::string& wall,
                                                const std::string& boundary) {
  std::map<std::string, QuantityCauses> out;
  for (const auto& run : record.value("runs", json::array())) {
    if (run.value("wall", "") != wall || run.value("boundary", "") != boundary) continue;
    for (const auto& [quantity, q] : run["quantities"].items()) {
      auto& c = out[quantity];
      ++c.runs;
      if (q["soil_test_predicted"]["verdict"] != "breaks") continue;
      ++c.predicted_breaks;
      ++c.by_cause[cause_if_breaks(q)];
    }
  }
  return out;
}

std::string causes_line(const std::map<std::string, QuantityCauses>& causes) {
  if (causes.empty()) return "";
  std::vector<std::string> parts;
  for (const auto& [quantity, c] : causes) {
    if (c.predicted_breaks == 0) continue;
    std::vector<std::pair<std::string, int>> order(c.by_cause.begin(), c.by_cause.end());
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    std::string line;
    for (const auto& [cause, n] : order)
      line += fmt::format("{}{} {}", line.empty() ? "" : ", ", cause, n);
    parts.push_back(fmt::format("{}: {} of {}", quantity, line, c.runs));
  }
  if (parts.empty()) return "nothing breaks";
  std::string line;
  for (const auto& p : parts) line += (line.empty() ? "" : "; ") + p;
  return line;
}

std::optional<fs::path> find_form_limit(const fs::path& dir, const std::string& model,
                                        const std::string& wall, const std::string& boundary) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (fs::exists(e.path() / "form_limit.json")) files.push_back(e.path() / "form_limit.json");
  std::sort(files.begin(), files.end());  // the same record on every machine
  for (const auto& f : files) {
    const auto j = io::read_json_file(f);
    if (io::json_optional<std::string>(j, "/kind", f) != "form_limit" ||
        io::json_optional<std::string>(j, "/model", f) != model)
      continue;
    check_form_limit_record(j, f);  // an edited record is refused, not half read (issue 60)
    if (!causes_on(j, wall, boundary).empty()) return f;
  }
  return std::nullopt;
}

json form_limit_cell(const fs::path& dir, const std::string& model, const std::string& wall,
                     const std::string& boundary) {
  const auto record = find_form_limit(dir, model, wall, boundary);
  if (!record) return {{"record", nullptr}, {"causes", "no form-limit record"}};
  return {{"record", record->string()},
          {"causes", causes_line(causes_on(io::read_json_file(*record), wall, boundary))}};
}

}  // namespace iwb::comparison
