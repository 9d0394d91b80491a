#include "comparison/presentation/report.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>

#include "common/errors.hpp"
#include "comparison/presentation/band_figures.hpp"
#include "comparison/presentation/cell_glance.hpp"
#include "comparison/presentation/column_section.hpp"
#include "comparison/presentation/cyclic_figures.hpp"
#include "comparison/presentation/figure.hpp"
#include "comparison/presentation/html.hpp"
#include "comparison/presentation/verdict_table.hpp"
#include "comparison/replay/dem_run.hpp"
#include "comparison/replay/metrics.hpp"
#include "comparison/replay/quantities.hpp"
#include "comparison/verdicts/cyclic_verdicts.hpp"
#include "io/csv_table.hpp"
#include "io/json_file.hpp"
#include "io/output_directory.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;

namespace {

// The DEM's seed band of one quantity (mean - SD, mean + SD per row), from the comparison's
// seed_band.csv; empty without seeds.
std::vector<std::pair<double, double>> seed_band(const std::optional<io::CsvTable>& seeds,
                                                 const std::string& mean_col,
                                                 const std::string& sd_col) {
  std::vector<std::pair<double, double>> band;
  if (!seeds) return band;
  const auto& t = *seeds;
  for (const auto& r : t.rows)
    band.push_back(
        {r[t.column(mean_col)] - r[t.column(sd_col)], r[t.column(mean_col)] + r[t.column(sd_col)]});
  return band;
}

// Lines of the variants, the seed band under them and the DEM drawn last, thick and black, so
// that no model curve hides it.
std::string dem_on_top_plot(const Figure& f, std::size_t variants, bool band) {
  const std::string data = gnuplot_string(f.name + ".csv");
  std::string plot = "plot ";
  if (band)
    plot += fmt::format(
        "{} using 1:{}:{} skip 1 with filledcurves fc rgb '#d8d8d8' fs solid 0.6 title 'DEM, mean "
        "± SD over seeds', ",
        data, variants + 3, variants + 4);
  for (std::size_t v = 0; v < variants; ++v)
    plot += fmt::format("{} using 1:{} skip 1 with lines lw 1.5 title {}, ", data, v + 3,
                        gnuplot_string(f.titles[v + 1]));
  return plot + fmt::format("{} using 1:2 skip 1 {} title 'DEM (this run)'", data, kReferenceStyle);
}

// One figure of `column` (tau, sigma_n or u_n) against u_x: the DEM and the variants `shown`
// (the predicted, the tau-only and the jointly fitted one: every variant's numbers are in the
// tables, and six curves hide each other and the DEM).
Figure versus_u_x(const std::string& name, const std::string& what, const std::string& dem_col,
                  const std::string& model_col, const io::CsvTable& curves,
                  const nlohmann::json& variants, const std::vector<std::size_t>& shown,
                  const std::vector<std::pair<double, double>>& band) {
  Figure f{name, what + " against u_x", "u_x (mm)", what, {}, {"DEM"}, "", ""};
  f.data.columns = {"u_x_mm", "dem"};
  const std::size_t nv = shown.size();
  std::vector<int> column_of(variants.size(), -1);  // variant index -> its series, or -1
  for (std::size_t k = 0; k < nv; ++k) {
    column_of[shown[k]] = int(k) + 2;
    f.data.columns.push_back(fmt::format("variant_{}", shown[k]));
    f.titles.push_back(variants[shown[k]]["label"].get<std::string>());
  }
  f.data.columns.insert(f.data.columns.end(), {"dem_seed_low", "dem_seed_high"});
  const int vc = curves.column("variant"), xc = curves.column("u_x_mm");
  const int dc = curves.column(dem_col), mc = curves.column(model_col);
  // compare.csv lists each variant's rows in DEM row order: the k-th row of variant v is DEM row k
  std::vector<std::vector<double>> rows;
  std::vector<std::size_t> next(variants.size(), 0);
  for (const auto& r : curves.rows) {
    const std::size_t v = std::size_t(r[vc]);
    if (v == 0) {
      rows.push_back(std::vector<double>(nv + 4, NAN));
      rows.back()[0] = r[xc];
      rows.back()[1] = r[dc];
      if (rows.size() <= band.size())
        std::tie(rows.back()[nv + 2], rows.back()[nv + 3]) = band[rows.size() - 1];
    }
    if (column_of[v] >= 0 && next[v] < rows.size())
      rows[next[v]][std::size_t(column_of[v])] = r[mc];
    ++next[v];
  }
  f.data.rows = rows;
  f.plot = dem_on_top_plot(f, nv, !band.empty());
  return f;
}

Figure velocity_profile(const io::CsvTable& prof, const nlohmann::json& summary) {
  Figure f{"velocity_profile",
           "DEM velocity profile (last window)",
           "vx / v_wall",
           "z / d50",
           {},
           {},
           "",
           ""};
  double last = -INFINITY;
  for (const auto& r : prof.rows) last = std::max(last, r[prof.column("u_x_mm_window")]);
  f.data.columns = {"vx_over_vwall", "z_over_d50"};
  for (const auto& r : prof.rows)
    if (r[prof.column("u_x_mm_window")] == last)
      f.data.rows.push_back({r[prof.column("vx_over_vwall")], r[prof.column("z_over_d50")]});
  f.titles = {fmt::format("u_x = {:.2f} mm", last)};
  f.extra = "set xrange [-0.1:1.1]\n";
  if (summary.contains("wall_band_d50") && summary["wall_band_d50"].is_number())
    f.extra += fmt::format(
        "set arrow from -0.1,{0} to 1.1,{0} nohead dt 2 lw 2 lc rgb '#cc0000'\n"
        "set label 'wall band' at 0.02,{0} offset 0,0.7 tc rgb '#cc0000'\n",
        summary["wall_band_d50"].get<double>());
  if (summary.contains("plate_band_d50") && summary["plate_band_d50"].is_number() &&
      !f.data.rows.empty())
    f.extra += fmt::format(
        "set arrow from -0.1,{0} to 1.1,{0} nohead dt 3 lw 2 lc rgb '#0055cc'\n"
        "set label 'plate band' at 0.75,{0} offset 0,0.7 tc rgb '#0055cc'\n",
        f.data.rows.back()[1] - summary["plate_band_d50"].get<double>());
  return f;
}

std::string metrics_table(const nlohmann::json& cmp) {
  // a cyclic run's last fifth is the end of its path, not a residual (issue 59)
  const bool cyclic =
      !cmp["variants"].empty() && cmp["variants"][0]["metrics"].contains(end_friction_key(true));
  const char* end_key = end_friction_key(cyclic);
  std::string h =
      "<table><tr><th>variant</th><th>kappa_r</th><th>d_s (mm)</th><th>RMSE tau (kPa)</th>"
      "<th>peak tau/sigma_n<br>model (DEM)</th><th>" +
      std::string(cyclic ? "end of path" : "residual") +
      "<br>model (DEM)</th>"
      "<th>u_x at peak (mm)<br>model (DEM)</th><th>RMSE u_n (mm)</th><th>RMSE sigma_n "
      "(kPa)</th><th>status</th></tr>\n";
  auto num = [](const nlohmann::json& j, const char* fmt_) {
    return j.is_number() ? fmt::format(fmt::runtime(fmt_), j.get<double>()) : std::string("-");
  };
  for (const auto& v : cmp["variants"]) {
    const auto& m = v["metrics"];
    h += fmt::format(
        "<tr><td>{}</td><td>{:.3f}</td><td>{:.2f}</td><td>{}</td><td>{} ({})</td><td>{} ({})</td>"
        "<td>{} ({})</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
        escape_html(v["label"]), v["kappa_r"].get<double>(), v["d_s_mm"].get<double>(),
        num(m["rmse_tau_kPa"], "{:.2f}"), num(m["peak_friction"]["model"], "{:.3f}"),
        num(m["peak_friction"]["dem"], "{:.3f}"), num(m[end_key]["model"], "{:.3f}"),
        num(m[end_key]["dem"], "{:.3f}"), num(m["u_x_at_peak_mm"]["model"], "{:.2f}"),
        num(m["u_x_at_peak_mm"]["dem"], "{:.2f}"), num(m["rmse_u_n_mm"], "{:.4f}"),
        num(m["rmse_sigma_n_kPa"], "{:.2f}"), escape_html(v["status"]));
  }
  return h + "</table>\n";
}

// summary.json's keys as a reader names them, with units (src/dem/analysis/summary.cpp defines
// them).
struct SummaryRow {
  const char* key;
  const char* name;
  const char* unit;
  const char* when_null;  // what a null means
};

const std::vector<SummaryRow>& summary_rows() {
  static const std::vector<SummaryRow> r = {
      {"peak_friction", "peak friction tau/sigma_n", "", ""},
      {"u_x_at_peak_mm", "displacement to the peak", "mm", ""},
      {"residual_friction", "residual friction (mean of the last fifth)", "", ""},
      {"residual_is", "residual", "", ""},
      {"/residual_test/to_go_at_window_centre",
       "what the decay fitted from the peak has still to go at the last fifth's centre", "",
       "none: too few rows"},
      {"/residual_test/window_drift", "drift of the last fifth's half-grain block means", "",
       "none: too few rows"},
      {"end_of_path_friction", "end-of-path friction (a cyclic run: mean of the last fifth)", "",
       ""},
      {"dilation_mm", "total dilation u_n", "mm", ""},
      {"dilatancy_angle_deg", "dilatancy angle (last fifth)", "deg", ""},
      {"/dilatancy_rate_at_peak/rate", "dilatancy rate d u_n / d u_x within d50 / 2 of the peak",
       "", "none: too short a run"},
      {"/dilatancy_rate_at_peak/ci95", "its 95 % half-width over blocks of d50 / 8", "",
       "none: too short a run"},
      {"sigma_n_mean_kPa", "mean normal stress", "kPa", ""},
      {"sigma_n_max_relative_deviation", "largest deviation of sigma_n from the target", "", ""},
      {"shear_mode", "where the specimen shears", "", ""},
      {"wall_band_d50", "wall band thickness", "d50", "none: the far field moves with the wall"},
      {"band_thickness_d50", "band thickness, 0.9 to 0.1 of the wall layer's speed", "d50",
       "none: shear not localised at the wall"},
      {"band_thickness_erfc_fit_d50", "band thickness, erfc fit", "d50",
       "none: no wall band to fit"},
      {"plate_band_d50", "band under the plate", "d50", "none: no shear under the plate"},
      {"far_field_speed", "far-field speed / first layer's speed", "", ""},
      {"wall_share_of_velocity_drop", "wall band's share of the velocity drop", "", ""},
      {"wall_slip", "wall slip (1 - first layer's speed / wall speed)", "", ""},
      {"e_band", "void ratio in the band", "", "none: no porosity profile"},
  };
  return r;
}

std::string summary_table(const nlohmann::json& s) {
  std::string h = "<table><tr><th>quantity</th><th>value</th></tr>";
  for (const auto& r : summary_rows()) {
    // a key, or a JSON pointer into one of summary.json's objects
    const nlohmann::json::json_pointer at(r.key[0] == '/' ? r.key : std::string("/") + r.key);
    if (!s.contains(at)) continue;
    const auto& v = s.at(at);
    const std::string unit = *r.unit ? std::string(" ") + r.unit : "";
    const std::string text = v.is_number()   ? fmt::format("{:.4g}{}", v.get<double>(), unit)
                             : v.is_string() ? v.get<std::string>()
                                             : std::string(r.when_null);
    h += fmt::format("<tr><th>{}</th><td>{}</td></tr>", escape_html(r.name), escape_html(text));
  }
  h += "</table>\n";
  if (s.contains("definitions")) {
    h += "<p>Definitions: ";
    for (const auto& [k, d] : s["definitions"].items())
      h += fmt::format("<em>{}</em>: {}. ", escape_html(k), escape_html(d.get<std::string>()));
    h += "</p>\n";
  }
  return h;
}

// The hypothesis checks of a `--runs` set: verdicts and their tables, as hypotheses.json has them.
// A table of strings of hypotheses.json (columns, rows) as HTML.
std::string html_table(const nlohmann::json& t) {
  std::string s = "<table><tr>";
  for (const auto& col : t["columns"]) s += "<th>" + escape_html(col) + "</th>";
  s += "</tr>\n";
  for (const auto& row : t["rows"]) {
    s += "<tr>";
    for (const auto& cell : row) s += "<td>" + escape_html(cell) + "</td>";
    s += "</tr>\n";
  }
  return s + "</table>\n";
}

std::string hypotheses_section(const fs::path& file, const nlohmann::json& h) {
  std::string s =
      fmt::format("<section><h2>Hypothesis checks over {} DEM runs</h2>\n<p>From {}.</p>\n",
                  h["runs"].size(), escape_html(file.string()));
  for (const auto& c : h["checks"]) {
    s += fmt::format("<h3>{}</h3>\n<p>Assumption: {}.</p>\n<p><strong>Verdict:</strong> {}</p>\n",
                     escape_html(c["title"]), escape_html(c["assumption"]),
                     escape_html(c["verdict"]));
    if (c.contains("group_table")) s += html_table(c["group_table"]);
    s += html_table(c["table"]);
    if (c.contains("notes")) s += "<p>" + escape_html(c["notes"]) + "</p>\n";
  }
  return s + "</section>\n";
}

std::string table_html(const Table& t) {
  nlohmann::json j = {{"columns", t.columns}, {"rows", t.rows}};
  return html_table(j);
}

// The files a `--runs` set writes beside its comparison directories.
bool set_file(const fs::path& p) {
  const auto n = p.filename().string();
  return fs::exists(p.parent_path() / "hypotheses.json") &&
         (n == "hypotheses.json" || n == "hypotheses.md" || n == "manifest.json" ||
          n == "pooled_scatter.json" || n == io::kLedgerFileName);
}

struct ReportInputs {
  std::vector<fs::path> compare_dirs;
  std::vector<fs::path> column_runs;  // `iwb column` run directories (column_section.hpp)
  std::vector<fs::path> hypotheses;   // hypotheses.json of the sets the directories came from
};

// Comparison directories as given, a set directory (OUT of `iwb compare --runs`) as its runs,
// and the set's own files (as `OUT/*` passes them) as the set's marker.
ReportInputs resolve(const std::vector<fs::path>& paths) {
  ReportInputs in;
  auto add_unique = [](std::vector<fs::path>& v, const fs::path& p) {
    for (const auto& q : v)
      if (fs::weakly_canonical(q) == fs::weakly_canonical(p)) return;
    v.push_back(p);
  };
  for (const auto& given : paths) {
    auto p = given.lexically_normal();
    if (p.filename().empty()) p = p.parent_path();  // "OUT/run/": its parent is OUT
    if (is_column_run(p)) {
      add_unique(in.column_runs, p);
    } else if (fs::is_directory(p) && fs::exists(p / "compare.json")) {
      add_unique(in.compare_dirs, p);
      if (fs::exists(p.parent_path() / "hypotheses.json"))
        add_unique(in.hypotheses, p.parent_path() / "hypotheses.json");
    } else if (fs::is_directory(p) && fs::exists(p / "hypotheses.json")) {
      add_unique(in.hypotheses, p / "hypotheses.json");
      const auto set = io::read_json_file(p / "hypotheses.json");  // outlives the loop
      for (const auto& r : set["runs"])
        add_unique(in.compare_dirs, p / r["name"].get<std::string>());
    } else if (fs::is_regular_file(p) && set_file(p)) {
      add_unique(in.hypotheses, p.parent_path() / "hypotheses.json");
    } else {
      throw InputError(
          fmt::format("{}: neither a directory of `iwb compare` (compare.json), a set of "
                      "`iwb compare --runs` (hypotheses.json) nor a run of `iwb column`",
                      p.string()));
    }
  }
  return in;
}

// One comparison directory's section: its verdicts first, then the figures, every variant's
// metrics, the DEM's derived quantities and the provenance.
struct Section {
  std::string html;
  std::vector<fs::path> figures;
};

nlohmann::json read_comparison(const fs::path& dir) {
  if (!fs::exists(dir / "compare.json"))
    throw InputError(
        fmt::format("{}: no compare.json (not a directory of `iwb compare`)", dir.string()));
  auto cmp = io::read_json_file(dir / "compare.json");
  if (!cmp.contains("verdicts"))
    throw InputError(
        fmt::format("{}: made by an earlier iwb without verdicts; run `iwb compare` again",
                    (dir / "compare.json").string()));
  return cmp;
}

// Everything one comparison's section shows, read and checked before anything is written, so
// that a report is written whole or not at all.
struct LoadedComparison {
  fs::path dir, dem_dir;
  nlohmann::json cmp, manifest, dem_manifest, summary;
  io::CsvTable curves, profiles;
  std::optional<io::CsvTable> seeds;
  // a cyclic run's program and the DEM's travel at each row (src/cycles/)
  std::optional<cycles::Program> program;
  std::vector<double> travel_mm;
  std::string dem_status() const { return dem_manifest.value("status", std::string("?")); }
};

// Files the comparison recorded a hash of (`iwb compare` since issue 15) must still have it.
void check_hashes(const LoadedComparison& c) {
  if (!c.manifest.contains("sha256")) return;
  for (const auto& [name, sha] : c.manifest["sha256"].items())
    if (io::sha256_hex(io::read_file(c.dir / name)) != sha.get<std::string>())
      throw InputError(fmt::format(
          "{}: changed since `iwb compare` wrote it (sha256 differs from {}'s; truncated?)",
          (c.dir / name).string(), (c.dir / "manifest.json").string()));
}

// A variant the model completed has a row for every DEM row: fewer means compare.csv was cut.
void check_curves(const LoadedComparison& c) {
  const fs::path file = c.dir / "compare.csv";
  const std::size_t dem_rows = io::read_csv_table(c.dem_dir / "timeseries.csv").rows.size();
  const int vc = c.curves.column("variant");
  if (vc < 0) throw InputError(fmt::format("{}: no column 'variant'", file.string()));
  for (const auto& v : c.cmp["variants"]) {
    const auto index = std::size_t(io::json_field<int>(v, "/index", c.dir / "compare.json"));
    const auto rows =
        std::size_t(std::count_if(c.curves.rows.begin(), c.curves.rows.end(),
                                  [&](const auto& r) { return std::size_t(r[vc]) == index; }));
    if (v.value("status", "") == "complete" && rows != dem_rows)
      throw InputError(fmt::format("{}: variant {} has {} rows, the DEM run {} (truncated?)",
                                   file.string(), index, rows, dem_rows));
  }
}

LoadedComparison load_comparison(const fs::path& dir) {
  LoadedComparison c;
  c.dir = dir;
  c.cmp = read_comparison(dir);
  c.manifest = io::read_json_file(dir / "manifest.json");
  const auto status = io::json_field<std::string>(c.manifest, "/status", dir / "manifest.json");
  if (status != "complete")
    throw InputError(
        fmt::format("{}: the comparison's status is '{}'; a report shows finished comparisons only "
                    "(run `iwb compare` again)",
                    (dir / "manifest.json").string(), status));
  check_hashes(c);
  c.curves = io::read_csv_table(dir / "compare.csv");
  if (fs::exists(dir / "seed_band.csv")) c.seeds = io::read_csv_table(dir / "seed_band.csv");
  c.dem_dir = io::json_field<std::string>(c.cmp, "/dem/dir", dir / "compare.json");
  c.dem_manifest = io::read_json_file(c.dem_dir / "manifest.json");
  c.summary = io::read_json_file(c.dem_dir / "summary.json");
  c.profiles = io::read_csv_table(c.dem_dir / "profiles.csv");
  check_curves(c);
  if (c.cmp.contains("cyclic") && !c.cmp["cyclic"].is_null()) {  // null: a monotonic run
    const auto dem = load_dem_run(c.dem_dir, true);
    c.program = cyclic_program(dem);
    if (!c.program)
      throw InputError(fmt::format("{}: judged as cyclic, but the DEM run's scene {} has no cycles",
                                   (dir / "compare.json").string(), c.dem_dir.string()));
    c.travel_mm = cyclic_travel(dem);
  }
  return c;
}

// A DEM run compared with --allow-partial (failed, interrupted, implausible) is shown, but marked
// where nobody can miss it: in the glance table and above its section.
std::string dem_status_warning(const LoadedComparison& c) {
  if (c.dem_status() == "complete") return "";
  return fmt::format(
      "<p class=\"breaks\">Warning: the DEM run {} did not complete (status: {}); it was compared "
      "with --allow-partial and its numbers are not a result.</p>\n",
      escape_html(c.dem_dir.string()), escape_html(c.dem_status()));
}

std::string verdict_section(const nlohmann::json& cmp) {
  const Table cycles = cyclic_verdict_table(cmp);
  std::string h;
  if (!cycles.rows.empty())
    h += "<h3>Verdicts per cycle</h3>\n" + table_html(cycles) +
         "<p>Each DEM value is the mean over the cell's seeds at that cycle with its 95 % "
         "t-interval; the model's relative error in brackets.</p>\n<h3>Verdicts on the whole "
         "path (the monotonic quantities)</h3>\n";
  else
    h += "<h3>Verdicts</h3>\n";
  h += table_html(verdict_table(cmp)) + "<ul>";
  for (const auto& f : verdict_findings(cmp)) h += "<li>" + escape_html(f) + "</li>";
  return h + fmt::format(
                 "</ul><p>Fit weights: {}. Relative errors against max(|DEM|, a floor); "
                 "<em>within DEM scatter</em>: over the tolerance by less than the half-width of "
                 "the 95 % Student's t-interval of the DEM's seed mean (t<sub>0.975, n-1</sub> "
                 "SD/&radic;n).</p>\n",
                 escape_html(cmp["fit"]["algorithm"].get<std::string>()));
}

// Where the model's shear zone sits against the DEM's band: the predicted and the fitted d_s, with
// the model's u_n along the run.
std::vector<ShearZoneMark> shear_zone_marks(const nlohmann::json& cmp, const io::CsvTable& curves) {
  const auto& vs = cmp["variants"];
  std::vector<ShearZoneMark> marks;
  for (const auto& [which, label] :
       {std::pair{"predicted_variant", "d_s predicted"}, {"fitted_variant", "d_s fitted"}})
    if (cmp["verdicts"].contains(which)) {
      const std::size_t v = cmp["verdicts"][which].get<std::size_t>();
      ShearZoneMark m{label,
                      vs[v]["d_s_mm"].get<double>() / cmp["dem"]["d50_mm"].get<double>(),
                      {},
                      {},
                      cmp["dem"]["e0_band"].get<double>()};
      for (const auto& r : curves.rows)
        if (std::size_t(r[curves.column("variant")]) == v)
          m.u_x_mm.push_back(r[curves.column("u_x_mm")]),
              m.u_n_mm.push_back(r[curves.column("u_n_model_mm")]);
      marks.push_back(std::move(m));
    }
  return marks;
}

// The section's figures: tau, u_n and sigma_n along u_x (a cyclic run: its loops, cycle by
// cycle), the velocity profile and the band's figures with the model's shear zones.
std::vector<Figure> comparison_figures(const LoadedComparison& c) {
  const auto& [dir, dem_dir, cmp, manifest, dem_manifest, summary, curves, profiles, seeds, program,
               travel_mm] = c;
  const auto& vs = cmp["variants"];
  std::vector<std::size_t> shown;
  for (const char* which : {"predicted_variant", "tau_only_variant", "fitted_variant"})
    if (cmp["verdicts"].contains(which)) shown.push_back(cmp["verdicts"][which].get<std::size_t>());
  std::vector<Figure> figs;
  if (program)  // loops drawn over one another along u_x would hide every cycle
    figs = cyclic_figures(cmp, curves, travel_mm, *program, shown);
  else
    figs = {versus_u_x("tau_ux", "tau (kPa)", "tau_dem_kPa", "tau_model_kPa", curves, vs, shown,
                       seed_band(seeds, "tau_mean_kPa", "tau_sd_kPa")),
            versus_u_x("un_ux", "u_n (mm), dilation positive", "u_n_dem_mm", "u_n_model_mm", curves,
                       vs, shown, seed_band(seeds, "u_n_mean_mm", "u_n_sd_mm")),
            versus_u_x("sigman_ux", "sigma_n (kPa)", "sigma_n_dem_kPa", "sigma_n_model_kPa", curves,
                       vs, shown, seed_band(seeds, "sigma_n_mean_kPa", "sigma_n_sd_kPa"))};
  figs.push_back(velocity_profile(profiles, summary));
  for (auto& f : band_figures(dem_dir, shear_zone_marks(cmp, curves))) figs.push_back(std::move(f));
  return figs;
}

// Figures go to `staging` (the report's files directory while it is built); the page links them
// where they will be, under `files`.
Section comparison_section(const LoadedComparison& c, std::size_t k,
                           const io::StagedDirectory& files, const fs::path& html) {
  const auto& [dir, dem_dir, cmp, manifest, dem_manifest, summary, curves, profiles, seeds, program,
               travel_mm] = c;
  const std::string fig_name = fmt::format("{}-{}", k, dir.filename().string());
  const fs::path fig_dir = files.path() / fig_name;
  fs::create_directories(fig_dir);
  std::vector<Figure> figs = comparison_figures(c);
  std::vector<std::string> notes(figs.size());
  for (std::size_t i = 0; i < figs.size(); ++i)
    if (figs[i].name == "sigman_ux" && cmp["dem"]["boundary"] == "CNL")
      notes[i] =
          ". Under CNL every model follows the DEM's measured sigma_n by construction: its curves "
          "lie under the DEM's";
  Section out;
  std::string& body = out.html;
  body += fmt::format("<section id=\"run-{}\"><h2>{} against {} ({} engine, {})</h2>\n", k,
                      escape_html(cmp["model"].get<std::string>()), escape_html(dem_dir.string()),
                      escape_html(cmp["dem"]["engine"].get<std::string>()),
                      escape_html(cmp["dem"]["boundary"].get<std::string>()));
  body += fmt::format(
      "<p>Wall R_n = {:.3g}, d50 = {:g} mm, initial sigma_n = {:.1f} kPa, band void ratio e0 = "
      "{:.3f}. "
      "The model is driven along the DEM's own path: {}.</p>\n",
      cmp["dem"]["R_n"].get<double>(), cmp["dem"]["d50_mm"].get<double>(),
      cmp["dem"]["sigma_n0_kPa"].get<double>(), cmp["dem"]["e0_band"].get<double>(),
      escape_html(cmp["replay"]["normal_control"].get<std::string>()));
  body += dem_status_warning(c) + verdict_section(cmp) + "<div class=\"figures\">\n";
  for (std::size_t i = 0; i < figs.size(); ++i) {
    const auto svg = draw(figs[i], fig_dir);
    out.figures.push_back(svg);
    body += fmt::format(
        "<figure>{}<figcaption>{}{} (data: {})</figcaption></figure>\n", inline_svg(svg),
        escape_html(figs[i].title), escape_html(notes[i]),
        escape_html(fs::relative(files.final_path() / fig_name / (figs[i].name + ".csv"),
                                 html.parent_path())
                        .string()));
  }
  body += "</div>\n<h3>Every variant</h3>\n" + metrics_table(cmp);
  body += "<h3>DEM derived quantities</h3>\n" + summary_table(summary);
  body +=
      fmt::format("<details><summary>Provenance: DEM manifest</summary><pre>{}</pre></details>\n",
                  escape_html(dem_manifest.dump(2)));
  body += fmt::format(
      "<details><summary>Provenance: comparison "
      "manifest</summary><pre>{}</pre></details></section>\n",
      escape_html(manifest.dump(2)));
  return out;
}

// One line per comparison: per quantity, the predicted and the fitted verdict as marks.
std::string glance_table(const std::vector<LoadedComparison>& comparisons) {
  auto mark = [](const nlohmann::json& verdicts, const std::string& key) {
    for (const auto& v : verdicts)
      if (v["quantity"] == key)
        return v["verdict"] == "holds"    ? std::string("<span class=\"holds\">✔</span>")
               : v["verdict"] == "breaks" ? std::string("<span class=\"breaks\">✘</span>")
               : v["verdict"] == "within DEM scatter"
                   ? std::string("<span class=\"scatter\">≈</span>")
                   : std::string("–");
    return std::string("");
  };
  std::string h = "<table><tr><th>run</th><th>boundary</th><th>DEM status</th>";
  for (const auto& q : quantity_table()) h += fmt::format("<th>{}</th>", escape_html(q.name));
  h += "</tr>\n";
  for (std::size_t k = 0; k < comparisons.size(); ++k) {
    const auto& cmp = comparisons[k].cmp;
    const std::string status = comparisons[k].dem_status();
    const auto& p =
        cmp["variants"][cmp["verdicts"]["predicted_variant"].get<std::size_t>()]["verdicts"];
    const auto& f =
        cmp["variants"][cmp["verdicts"]["fitted_variant"].get<std::size_t>()]["verdicts"];
    h += fmt::format(
        "<tr><td><a href=\"#run-{}\">{}</a></td><td>{}</td><td{}>{}</td>", k,
        escape_html(
            fs::path(cmp["dem"]["dir"].get<std::string>()).lexically_normal().filename().string()),
        escape_html(cmp["dem"]["boundary"].get<std::string>()),
        status == "complete" ? "" : " class=\"breaks\"", escape_html(status));
    for (const auto& q : quantity_table()) {
      const std::string a = mark(p, q.key), b = mark(f, q.key);
      h += a.empty() ? "<td></td>" : fmt::format("<td>{} · {}</td>", a, b);
    }
    h += "</tr>\n";
  }
  return h +
         "</table>\n<p>Each cell: predicted · fitted (joint fit). ✔ holds, ✘ breaks, ≈ misses the "
         "tolerance "
         "by less than the DEM's seed scatter, – the model did not reach the end; blank: not "
         "judged under "
         "this boundary condition.</p>\n";
}

// Cyclic runs judged by more than one model (an -igs model and its plain counterpart): their
// per-cycle verdicts side by side, one table per DEM run.
std::string models_beside(const std::vector<LoadedComparison>& comparisons) {
  std::vector<std::pair<std::string, std::vector<nlohmann::json>>> by_run;
  for (const auto& c : comparisons) {
    if (!c.program) continue;
    const std::string run = fs::weakly_canonical(c.dem_dir).string();
    auto it =
        std::find_if(by_run.begin(), by_run.end(), [&](const auto& g) { return g.first == run; });
    if (it == by_run.end()) by_run.push_back({run, {}}), it = by_run.end() - 1;
    it->second.push_back(c.cmp);
  }
  std::string h;
  for (const auto& [run, cmps] : by_run)
    if (cmps.size() > 1)
      h +=
          fmt::format("<h3>{}</h3>\n", escape_html(cmps.front()["dem"]["dir"].get<std::string>())) +
          table_html(cyclic_models_table(cmps));
  if (h.empty()) return h;
  return "<section><h2>Cyclic verdicts, model beside model</h2>\n<p>Each cell: the model's value "
         "(its error against the DEM's seed mean) and its verdict.</p>\n" +
         h + "</section>\n";
}

}  // namespace

std::vector<fs::path> write_report(const std::vector<fs::path>& paths, const fs::path& html) {
  io::require_file_destination(html, "-o");
  // every input read and checked before anything is written
  const auto [compare_dirs, column_runs, hypotheses] = resolve(paths);
  std::vector<LoadedComparison> comparisons;
  for (const auto& dir : compare_dirs) comparisons.push_back(load_comparison(dir));
  for (const auto& run : column_runs) require_column_run(run);
  std::vector<nlohmann::json> sets;
  for (const auto& h : hypotheses) sets.push_back(io::read_json_file(h));

  if (html.has_parent_path()) fs::create_directories(html.parent_path());
  io::StagedDirectory files(html.parent_path() / (html.stem().string() + "_files"), "report-files");
  std::vector<fs::path> figures;
  std::vector<nlohmann::json> cmps;
  for (const auto& c : comparisons) cmps.push_back(c.cmp);
  std::string body;
  if (!comparisons.empty())
    body = "<section><h2>Verdicts at a glance: one row per cell</h2>\n" +
           cell_glance_html(cell_rows(cmps)) + "</section>\n<section><h2>Runs at a glance</h2>\n" +
           glance_table(comparisons) + "</section>\n" + models_beside(comparisons);
  for (std::size_t i = 0; i < hypotheses.size(); ++i)
    body += hypotheses_section(hypotheses[i], sets[i]);
  // a section's page and its figures, named where they will be once the files are committed
  const auto add = [&](const auto& section) {
    body += section.html;
    for (const auto& svg : section.figures)
      figures.push_back(files.final_path() / fs::relative(svg, files.path()));
  };
  for (std::size_t k = 0; k < comparisons.size(); ++k)
    add(comparison_section(comparisons[k], k, files, html));
  for (std::size_t k = 0; k < column_runs.size(); ++k) {
    const auto name = fmt::format("column-{}-{}", k, column_runs[k].filename().string());
    add(column_section(column_runs[k], files.path() / name,
                       fs::relative(files.final_path() / name, html.parent_path()).string()));
  }
  const std::string page = html_page(
      "iwb validation report",
      fmt::format("<p>Generated {} by iwb {}. Compression positive, u_n &gt; 0 is dilation, kPa "
                  "and mm. Figures are also "
                  "in {} as SVG and PNG, each with its data (CSV) and gnuplot script.</p>\n{}",
                  io::utc_timestamp(), IWB_VERSION,
                  escape_html(files.final_path().filename().string()), body));
  files.commit();
  io::write_atomically(html, page);
  return figures;
}

}  // namespace iwb::comparison
