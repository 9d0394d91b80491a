#include "soil_test/soil_test.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/run_directory.hpp"

namespace iwb::soil_test {

namespace fs = std::filesystem;

const char* to_string(SoilTestKind k) {
  switch (k) {
    case SoilTestKind::kOedometer:
      return "oedometer";
    case SoilTestKind::kSimpleShear:
      return "simpleshear";
    case SoilTestKind::kCyclicShear:
      return "cyclicshear";
  }
  return "?";
}

SoilTestKind soil_test_kind(const std::string& name, const std::string& where) {
  for (const auto k :
       {SoilTestKind::kOedometer, SoilTestKind::kSimpleShear, SoilTestKind::kCyclicShear})
    if (name == to_string(k)) return k;
  throw InputError(
      fmt::format("{} = '{}': allowed oedometer, simpleshear or cyclicshear", where, name));
}

std::size_t SoilTest::loading_end() const {
  return std::size_t(std::max_element(control.begin(), control.end()) - control.begin());
}

namespace {

nlohmann::json read_manifest(const fs::path& file) {
  if (!fs::exists(file))
    throw InputError(fmt::format("{}: missing (not a soil-test directory)", file.string()));
  return io::read_json_file(file);
}

template <class T>
T require(const nlohmann::json& m, const std::string& key, const fs::path& file, const char* what) {
  if (!m.contains(key))
    throw InputError(fmt::format("{}: missing key '{}' ({})", file.string(), key, what));
  try {
    return m.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(
        fmt::format("{}: key '{}' = {} is not {}", file.string(), key, m.at(key).dump(), what));
  }
}

double require_positive(const nlohmann::json& m, const std::string& key, const fs::path& file,
                        const char* what) {
  const double v = require<double>(m, key, file, what);
  if (!(v > 0.0) || !std::isfinite(v))
    throw InputError(
        fmt::format("{}: key '{}' = {:g} must be positive ({})", file.string(), key, v, what));
  return v;
}

constexpr const char* kTestNames = "\"oedometer\", \"simpleshear\" or \"cyclicshear\"";

void read_header(SoilTest& t, const fs::path& file) {
  const auto m = read_manifest(file);
  if (require<std::string>(m, "kind", file, "\"soiltest\"") != "soiltest")
    throw InputError(
        fmt::format("{}: key 'kind' = {} should be \"soiltest\"", file.string(), m["kind"].dump()));
  const auto test = require<std::string>(m, "test", file, kTestNames);
  if (test == "oedometer") {
    t.kind = SoilTestKind::kOedometer;
    t.sigma0_kPa = require_positive(m, "sigma_v0_kPa", file, "initial vertical stress, kPa");
  } else if (test == "simpleshear" || test == "cyclicshear") {
    t.kind = soil_test_kind(test, file.string() + ": key 'test'");
    t.sigma0_kPa = require_positive(m, "sigma_n0_kPa", file, "initial normal stress, kPa");
    t.boundary =
        driver::parse_boundary_kind(require<std::string>(m, "boundary", file, "\"CNL\" or \"CV\""),
                                    file.string() + ": key 'boundary'");
    if (t.boundary == driver::BoundaryKind::kCNS)
      throw InputError(
          fmt::format("{}: key 'boundary' = \"CNS\": soil tests are CNL or CV", file.string()));
  } else {
    throw InputError(
        fmt::format("{}: key 'test' = \"{}\" should be {}", file.string(), test, kTestNames));
  }
  t.e0 = require_positive(m, "e0", file, "initial void ratio");
  if (m.contains("K0")) t.K0 = require_positive(m, "K0", file, "initial lateral stress ratio");
  t.source = require<std::string>(m, "source", file, "\"dem:<engine>\" or \"synthetic:<model>\"");
  if (m.contains("source_parameters")) t.source_parameters = m["source_parameters"];
  if (m.contains("density") && m["density"].is_string())
    t.specimen = m["density"].get<std::string>();
  if (m.contains("seed") && m["seed"].is_number_integer()) t.seed = m["seed"].get<int>();
  if (m.contains("status") && m["status"] != "complete")
    throw InputError(
        fmt::format("{}: status {} is not \"complete\"", file.string(), m["status"].dump()));
}

// Line of data row i in timeseries.csv: the header is line 1.
std::size_t line_of(std::size_t row) {
  return row + 2;
}

// Cyclic gamma: every row moves (a repeated row has no direction), and it reverses at least once
// (else it is a monotonic test, and the calibration would judge it as one).
void check_cyclic(const SoilTest& t, const fs::path& file) {
  int reversals = 0;
  for (std::size_t i = 1; i < t.rows(); ++i) {
    const double step = t.control[i] - t.control[i - 1];
    if (step == 0.0)
      throw InputError(fmt::format(
          "{}:{}: column 'gamma' = {:g} repeats the row before: cyclic shear moves every row",
          file.string(), line_of(i), t.control[i]));
    if (i > 1 && step * (t.control[i - 1] - t.control[i - 2]) < 0.0) ++reversals;
  }
  if (reversals == 0)
    throw InputError(fmt::format(
        "{}: column 'gamma' never reverses: a cyclic shear test reverses at least once (a "
        "monotonic one is test \"simpleshear\")",
        file.string()));
}

void check_monotonic(const SoilTest& t, const fs::path& file) {
  if (t.kind == SoilTestKind::kCyclicShear) return check_cyclic(t, file);
  const char* column = t.kind == SoilTestKind::kOedometer ? "sigma_v_kPa" : "gamma";
  const std::size_t peak = t.kind == SoilTestKind::kOedometer ? t.loading_end() : t.rows() - 1;
  for (std::size_t i = 1; i < t.rows(); ++i) {
    const bool loading = i <= peak;
    const bool ok = loading ? t.control[i] > t.control[i - 1] : t.control[i] < t.control[i - 1];
    if (!ok)
      throw InputError(
          fmt::format("{}:{}: column '{}' = {:g} after {:g}: the {} must be strictly {} here ({})",
                      file.string(), line_of(i), column, t.control[i], t.control[i - 1],
                      t.kind == SoilTestKind::kOedometer ? "vertical stress" : "shear strain",
                      loading ? "increasing" : "decreasing",
                      t.kind == SoilTestKind::kOedometer
                          ? "one loading branch, then at most one unloading branch"
                          : "monotonic shear"));
  }
}

void read_columns(SoilTest& t, const fs::path& file) {
  if (!fs::exists(file)) throw InputError(fmt::format("{}: missing", file.string()));
  const io::CsvTable table = io::read_csv_table(file);
  const auto need = [&](const std::string& name) { return table.values(name, file.string()); };
  t.e = need("e");
  if (t.kind == SoilTestKind::kOedometer) {
    t.control = need("sigma_v_kPa");
    t.eps_v = need("eps_v");
  } else {
    t.control = need("gamma");
    t.tau_kPa = need("tau_kPa");
    t.sigma_n_kPa = need("sigma_n_kPa");
  }
  if (t.rows() < kMinimumRows)
    throw InputError(fmt::format("{}: {} data rows; a soil test needs at least {}", file.string(),
                                 t.rows(), kMinimumRows));
  for (std::size_t i = 0; i < t.rows(); ++i)
    if (!(t.e[i] > 0.0))
      throw InputError(fmt::format("{}:{}: column 'e' = {:g} is not a void ratio (> 0)",
                                   file.string(), line_of(i), t.e[i]));
  check_monotonic(t, file);
}

std::string timeseries_csv(const SoilTest& t) {
  io::CsvTable table;
  if (t.kind == SoilTestKind::kOedometer) {
    table.columns = {"sigma_v_kPa", "eps_v", "e"};
    for (std::size_t i = 0; i < t.rows(); ++i)
      table.rows.push_back({t.control[i], t.eps_v[i], t.e[i]});
  } else {
    table.columns = {"gamma", "tau_kPa", "sigma_n_kPa", "e"};
    for (std::size_t i = 0; i < t.rows(); ++i)
      table.rows.push_back({t.control[i], t.tau_kPa[i], t.sigma_n_kPa[i], t.e[i]});
  }
  for (const auto& [name, values] : t.extra_columns) {
    table.columns.push_back(name);
    for (std::size_t i = 0; i < t.rows(); ++i) table.rows[i].push_back(values.at(i));
  }
  return table.to_csv(12);
}

}  // namespace

double element_until_gamma(const nlohmann::json& m) {
  if (m.value("cell", "") != "periodic" || m.value("test", "") != "simpleshear") return 0.0;
  const auto& summary = m.value("cell_summary", nlohmann::json::object());
  const auto windows = summary.value("profile_linearity_r2_by_window", nlohmann::json::array());
  if (windows.empty() || summary.value("homogeneous", false)) return 0.0;
  const double travel = m.at("cell_scene").at("resolved").at("shear").at("travel_mm").get<double>();
  const double per_mm = m.at("gamma_reached").get<double>() / travel;
  const double threshold = summary.value("homogeneous_r2_threshold", kHomogeneousCellR2);
  const auto bent = [&](std::size_t k) {
    return k >= windows.size() || windows[k].at("r2").get<double>() < threshold;
  };
  for (std::size_t k = 0; k < windows.size(); ++k)
    if (bent(k) && bent(k + 1))  // localised: not straight again (a lone bent profile is noise)
      return k == 0 ? -1.0 : windows[k - 1].at("u_x_mm_window").get<double>() * per_mm;
  return 0.0;
}

SoilTest read_soil_test(const fs::path& dir) {
  SoilTest t;
  t.name = dir.string();
  read_header(t, dir / "manifest.json");
  read_columns(t, dir / "timeseries.csv");
  t.rows_in_file = t.rows();
  const double until = element_until_gamma(read_manifest(dir / "manifest.json"));
  if (until == 0.0) return t;
  std::size_t keep = 0;
  while (keep < t.rows() && t.control[keep] <= until) ++keep;
  if (until < 0.0 || keep < kMinimumRows)
    throw NotAnElement(fmt::format(
        "{}: the periodic cell's shear localised {}: fewer than {} rows of an element to read",
        dir.string(),
        until < 0.0 ? "from its first profile window" : fmt::format("by gamma {:.3g}", until),
        kMinimumRows));
  t.element_until = until;
  for (auto* v : {&t.control, &t.e, &t.eps_v, &t.tau_kPa, &t.sigma_n_kPa})
    if (v->size() > keep) v->resize(keep);
  return t;
}

void write_soil_test(const SoilTest& t, const fs::path& dir, bool force,
                     const nlohmann::json& extra) {
  io::prepare_run_directory(dir, {"soiltest"}, force);
  write_soil_test_files(t, dir, extra);
}

void write_soil_test_files(const SoilTest& t, const fs::path& dir, const nlohmann::json& extra) {
  nlohmann::json m = extra;
  m["kind"] = "soiltest";
  m["test"] = to_string(t.kind);
  if (t.kind == SoilTestKind::kOedometer) {
    m["sigma_v0_kPa"] = t.sigma0_kPa;
    m["oedometer_path"] = t.loading_end() + 1 < t.rows() ? "loading-unloading" : "loading";
  } else {  // simple or cyclic shear
    m["sigma_n0_kPa"] = t.sigma0_kPa;
    m["boundary"] = driver::to_string(t.boundary);
  }
  m["e0"] = t.e0;
  if (t.K0 > 0.0) m["K0"] = t.K0;
  m["source"] = t.source;
  m["source_parameters"] = t.source_parameters;
  m["conventions"] = {{"signs", "compression positive (sigma, eps_v); tau has the sign of gamma"},
                      {"units", "kPa; strains and void ratio dimensionless"}};
  if (!m.contains("files")) m["files"] = {"timeseries.csv"};
  m["status"] = "complete";
  io::write_atomically(dir / "timeseries.csv", timeseries_csv(t));
  io::write_manifest(dir, m);
}

namespace {

// Row index where gamma first reaches 80 % of the test's last gamma.
std::size_t last_fifth_start(const SoilTest& t) {
  std::size_t i = 0;
  while (i + 1 < t.rows() && t.control[i] < 0.8 * t.control.back()) ++i;
  return i;
}

}  // namespace

bool ends_at_critical_state(const SoilTest& t) {
  const std::size_t i = last_fifth_start(t), j = t.rows() - 1;
  const double ratio_change =
      std::abs(t.tau_kPa[j] / t.sigma_n_kPa[j] - t.tau_kPa[i] / t.sigma_n_kPa[i]);
  return ratio_change < kCriticalRatioChange && std::abs(t.e[j] - t.e[i]) < kCriticalVoidChange;
}

}  // namespace iwb::soil_test
