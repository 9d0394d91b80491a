#include "comparison/verdicts/form_limit_causes.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <vector>

#include "common/errors.hpp"
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

std::string wall_name(double R_n, double d50_mm) {
  return fmt::format("R_n {:g}, d50 {:g} mm", R_n, d50_mm);
}

std::string cause_of(const std::string& verdict, const std::string& cause_if_breaks) {
  return verdict == "breaks" ? cause_if_breaks : "";
}

std::string cause_if_breaks(const json& q) {
  if (q.contains("cause_if_breaks")) return q["cause_if_breaks"].get<std::string>();
  return q["form_limit"]["verdict"] == "breaks" ? "form" : "calibration (unchecked)";
}

void check_form_limit_record(const json& record, const fs::path& file) {
  const auto& runs = io::json_array(record, "/runs", file);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto run = fmt::format("/runs/{}", i);
    if (io::json_object(record, run, file).contains("dir"))
      io::json_field<std::string>(record, run + "/dir", file);
    io::json_field<std::string>(record, run + "/wall", file);
    io::json_field<std::string>(record, run + "/boundary", file);
    for (const auto& q : io::json_object(record, run + "/quantities", file).items()) {
      const auto at = fmt::format("{}/quantities/{}", run, q.key());
      for (const char* variant : {"soil_test_predicted", "form_limit"})
        io::json_field<std::string>(record, fmt::format("{}/{}/verdict", at, variant), file);
      io::json_optional<std::string>(record, at + "/cause_if_breaks", file);
    }
  }
}

json read_form_limit(const fs::path& file, const std::string& model) {
  const auto j = io::read_json_file(file);
  if (io::json_optional<std::string>(j, "/kind", file).value_or("") != "form_limit" ||
      !j.contains("runs"))
    throw InputError(
        fmt::format("--form-limit {}: not a form-limit record (iwb form-limit's "
                    "form_limit.json)",
                    file.string()));
  const auto of = io::json_optional<std::string>(j, "/model", file);
  if (of != model)
    throw InputError(fmt::format("--form-limit {}: a form limit of {}, not of {}", file.string(),
                                 of.value_or("?"), model));
  check_form_limit_record(j, file);
  return j;
}

std::map<std::string, std::string> form_limit_causes(const json& record, const fs::path& dem_dir,
                                                     double R_n, double d50_mm,
                                                     const std::string& boundary) {
  const json* match = nullptr;
  for (const auto& r : record["runs"]) {
    const fs::path d = r.value("dir", "");
    if (fs::exists(d) && fs::exists(dem_dir) && fs::equivalent(d, dem_dir)) {
      match = &r;
      break;
    }
    if (!match && r.value("wall", "") == wall_name(R_n, d50_mm) &&
        r.value("boundary", "") == boundary)
      match = &r;
  }
  std::map<std::string, std::string> out;
  if (match)
    for (const auto& [key, q] : (*match)["quantities"].items()) out[key] = cause_if_breaks(q);
  return out;
}

}  // namespace iwb::comparison
