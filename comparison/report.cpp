#include "comparison/report.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "comparison/figure.hpp"
#include "io/csv_table.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;

namespace {

std::string escape_html(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

// One figure of `column` (tau, sigma_n or u_n) against u_x: the DEM and every variant.
Figure versus_u_x(const std::string& name, const std::string& what, const std::string& dem_col,
                  const std::string& model_col, const io::CsvTable& curves, const nlohmann::json& variants) {
  Figure f{name, what + " against u_x", "u_x (mm)", what, {}, {"DEM"}, "", ""};
  f.data.columns = {"u_x_mm", "dem"};
  std::size_t nv = variants.size();
  for (std::size_t v = 0; v < nv; ++v) {
    f.data.columns.push_back(fmt::format("variant_{}", v));
    f.titles.push_back(variants[v]["label"].get<std::string>());
  }
  const int vc = curves.column("variant"), xc = curves.column("u_x_mm");
  const int dc = curves.column(dem_col), mc = curves.column(model_col);
  // compare.csv lists each variant's rows in DEM row order: the k-th row of variant v is DEM row k
  std::vector<std::vector<double>> rows;
  std::vector<std::size_t> next(nv, 0);
  for (const auto& r : curves.rows) {
    const std::size_t v = std::size_t(r[vc]);
    if (v == 0) {
      rows.push_back(std::vector<double>(nv + 2, NAN));
      rows.back()[0] = r[xc];
      rows.back()[1] = r[dc];
    }
    if (next[v] < rows.size()) rows[next[v]][v + 2] = r[mc];
    ++next[v];
  }
  f.data.rows = rows;
  return f;
}

Figure velocity_profile(const fs::path& dem_dir, const nlohmann::json& summary) {
  Figure f{"velocity_profile", "DEM velocity profile (last window)", "vx / v_wall", "z / d50", {}, {}, "", ""};
  const auto prof = io::read_csv_table(dem_dir / "profiles.csv");
  double last = -INFINITY;
  for (const auto& r : prof.rows) last = std::max(last, r[prof.column("u_x_mm_window")]);
  f.data.columns = {"vx_over_vwall", "z_over_d50"};
  for (const auto& r : prof.rows)
    if (r[prof.column("u_x_mm_window")] == last) f.data.rows.push_back({r[prof.column("vx_over_vwall")], r[prof.column("z_over_d50")]});
  f.titles = {fmt::format("u_x = {:.2f} mm", last)};
  f.extra = "set xrange [-0.1:1.1]\n";
  if (summary.contains("wall_band_d50") && summary["wall_band_d50"].is_number())
    f.extra += fmt::format("set arrow from -0.1,{0} to 1.1,{0} nohead dt 2 lw 2 lc rgb '#cc0000'\n"
                           "set label 'wall band' at 0.02,{0} offset 0,0.7 tc rgb '#cc0000'\n",
                           summary["wall_band_d50"].get<double>());
  if (summary.contains("plate_band_d50") && summary["plate_band_d50"].is_number() && !f.data.rows.empty())
    f.extra += fmt::format("set arrow from -0.1,{0} to 1.1,{0} nohead dt 3 lw 2 lc rgb '#0055cc'\n"
                           "set label 'plate band' at 0.75,{0} offset 0,0.7 tc rgb '#0055cc'\n",
                           f.data.rows.back()[1] - summary["plate_band_d50"].get<double>());
  return f;
}

std::string inline_svg(const fs::path& svg) {
  std::string s = io::read_file(svg);
  const auto start = s.find("<svg");
  return start == std::string::npos ? s : s.substr(start);
}

std::string metrics_table(const nlohmann::json& cmp) {
  std::string h = "<table><tr><th>variant</th><th>kappa_r</th><th>d_s (mm)</th><th>RMSE tau (kPa)</th>"
                  "<th>peak tau/sigma_n<br>model (DEM)</th><th>residual<br>model (DEM)</th>"
                  "<th>u_x at peak (mm)<br>model (DEM)</th><th>RMSE u_n (mm)</th><th>RMSE sigma_n (kPa)</th><th>status</th></tr>\n";
  auto num = [](const nlohmann::json& j, const char* fmt_) {
    return j.is_number() ? fmt::format(fmt::runtime(fmt_), j.get<double>()) : std::string("-");
  };
  for (const auto& v : cmp["variants"]) {
    const auto& m = v["metrics"];
    h += fmt::format("<tr><td>{}</td><td>{:.3f}</td><td>{:.2f}</td><td>{}</td><td>{} ({})</td><td>{} ({})</td>"
                     "<td>{} ({})</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                     escape_html(v["label"]), v["kappa_r"].get<double>(), v["d_s_mm"].get<double>(),
                     num(m["rmse_tau_kPa"], "{:.2f}"), num(m["peak_friction"]["model"], "{:.3f}"),
                     num(m["peak_friction"]["dem"], "{:.3f}"), num(m["residual_friction"]["model"], "{:.3f}"),
                     num(m["residual_friction"]["dem"], "{:.3f}"), num(m["u_x_at_peak_mm"]["model"], "{:.2f}"),
                     num(m["u_x_at_peak_mm"]["dem"], "{:.2f}"), num(m["rmse_u_n_mm"], "{:.4f}"),
                     num(m["rmse_sigma_n_kPa"], "{:.2f}"), escape_html(v["status"]));
  }
  return h + "</table>\n";
}

std::string summary_table(const nlohmann::json& s) {
  std::string h = "<table>";
  for (const auto& [k, v] : s.items()) {
    if (k == "definitions" || k == "cycles") continue;
    h += fmt::format("<tr><th>{}</th><td>{}</td></tr>", escape_html(k),
                     v.is_number_float() ? fmt::format("{:.4g}", v.get<double>()) : escape_html(v.dump()));
  }
  return h + "</table>\n";
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

std::string hypotheses_section(const fs::path& file) {
  const auto h = nlohmann::json::parse(io::read_file(file));
  std::string s = fmt::format("<section><h2>Hypothesis checks over {} DEM runs</h2>\n<p>From {}.</p>\n", h["runs"].size(),
                              escape_html(file.string()));
  for (const auto& c : h["checks"]) {
    s += fmt::format("<h3>{}</h3>\n<p>Assumption: {}.</p>\n<p><strong>Verdict:</strong> {}</p>\n",
                     escape_html(c["title"]), escape_html(c["assumption"]), escape_html(c["verdict"]));
    if (c.contains("group_table")) s += html_table(c["group_table"]);
    s += html_table(c["table"]);
    if (c.contains("notes")) s += "<p>" + escape_html(c["notes"]) + "</p>\n";
  }
  return s + "</section>\n";
}

// The files a `--runs` set writes beside its comparison directories.
bool set_file(const fs::path& p) {
  const auto n = p.filename().string();
  return fs::exists(p.parent_path() / "hypotheses.json") &&
         (n == "hypotheses.json" || n == "hypotheses.md" || n == "manifest.json");
}

struct ReportInputs {
  std::vector<fs::path> compare_dirs;
  std::vector<fs::path> hypotheses;  // hypotheses.json of the sets the directories came from
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
    if (fs::is_directory(p) && fs::exists(p / "compare.json")) {
      add_unique(in.compare_dirs, p);
      if (fs::exists(p.parent_path() / "hypotheses.json")) add_unique(in.hypotheses, p.parent_path() / "hypotheses.json");
    } else if (fs::is_directory(p) && fs::exists(p / "hypotheses.json")) {
      add_unique(in.hypotheses, p / "hypotheses.json");
      const auto set = nlohmann::json::parse(io::read_file(p / "hypotheses.json"));  // outlives the loop
      for (const auto& r : set["runs"]) add_unique(in.compare_dirs, p / r["name"].get<std::string>());
    } else if (fs::is_regular_file(p) && set_file(p)) {
      add_unique(in.hypotheses, p.parent_path() / "hypotheses.json");
    } else {
      throw InputError(fmt::format("{}: neither a directory of `iwb compare` (compare.json) nor a set of "
                                   "`iwb compare --runs` (hypotheses.json)", p.string()));
    }
  }
  return in;
}

}  // namespace

std::vector<fs::path> write_report(const std::vector<fs::path>& paths, const fs::path& html) {
  const fs::path files = html.parent_path() / (html.stem().string() + "_files");
  fs::create_directories(files);
  std::vector<fs::path> figures;
  std::string body;
  const auto [compare_dirs, hypotheses] = resolve(paths);
  for (const auto& h : hypotheses) body += hypotheses_section(h);
  for (std::size_t k = 0; k < compare_dirs.size(); ++k) {
    const fs::path& dir = compare_dirs[k];
    if (!fs::exists(dir / "compare.json"))
      throw InputError(fmt::format("{}: no compare.json (not a directory of `iwb compare`)", dir.string()));
    const auto cmp = nlohmann::json::parse(io::read_file(dir / "compare.json"));
    const fs::path dem_dir = cmp["dem"]["dir"].get<std::string>();
    const auto curves = io::read_csv_table(dir / "compare.csv");
    const auto summary = nlohmann::json::parse(io::read_file(dem_dir / "summary.json"));
    const fs::path fig_dir = files / fmt::format("{}-{}", k, dir.filename().string());
    fs::create_directories(fig_dir);
    const auto& vs = cmp["variants"];
    std::vector<Figure> figs = {versus_u_x("tau_ux", "tau (kPa)", "tau_dem_kPa", "tau_model_kPa", curves, vs),
                                versus_u_x("un_ux", "u_n (mm), dilation positive", "u_n_dem_mm", "u_n_model_mm", curves, vs),
                                versus_u_x("sigman_ux", "sigma_n (kPa)", "sigma_n_dem_kPa", "sigma_n_model_kPa", curves, vs),
                                velocity_profile(dem_dir, summary)};
    body += fmt::format("<section><h2>{} against {} ({} engine, {})</h2>\n", escape_html(cmp["model"].get<std::string>()),
                        escape_html(dem_dir.string()), escape_html(cmp["dem"]["engine"].get<std::string>()),
                        escape_html(cmp["dem"]["boundary"].get<std::string>()));
    body += fmt::format("<p>Wall R_n = {:.3g}, d50 = {:g} mm, initial sigma_n = {:.1f} kPa, band void ratio e0 = {:.3f}. "
                        "The model is driven along the DEM's own path: {}.</p>\n",
                        cmp["dem"]["R_n"].get<double>(), cmp["dem"]["d50_mm"].get<double>(),
                        cmp["dem"]["sigma_n0_kPa"].get<double>(), cmp["dem"]["e0_band"].get<double>(),
                        escape_html(cmp["replay"]["normal_control"].get<std::string>()));
    body += "<h3>Metrics</h3>\n" + metrics_table(cmp);
    body += "<div class=\"figures\">\n";
    for (const auto& f : figs) {
      const auto svg = draw(f, fig_dir);
      figures.push_back(svg);
      body += fmt::format("<figure>{}<figcaption>{} (data: {})</figcaption></figure>\n", inline_svg(svg),
                          escape_html(f.title), escape_html(fs::relative(fig_dir / (f.name + ".csv"), html.parent_path()).string()));
    }
    body += "</div>\n<h3>DEM derived quantities</h3>\n" + summary_table(summary);
    body += fmt::format("<details><summary>Provenance: DEM manifest</summary><pre>{}</pre></details>\n",
                        escape_html(nlohmann::json::parse(io::read_file(dem_dir / "manifest.json")).dump(2)));
    body += fmt::format("<details><summary>Provenance: comparison manifest</summary><pre>{}</pre></details></section>\n",
                        escape_html(io::read_file(dir / "manifest.json")));
  }
  const std::string page = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>iwb validation report</title>\n"
      "<style>body{{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}}table{{border-collapse:collapse;margin:1em 0}}"
      "td,th{{border:1px solid #bbb;padding:3px 8px;text-align:left;font-size:0.9em}}figure{{margin:1em 0}}"
      "figure svg{{max-width:100%;height:auto}}pre{{font-size:0.8em;background:#f6f6f6;padding:1em;overflow:auto}}</style>\n"
      "</head><body><h1>iwb validation report</h1>\n<p>Generated {} by iwb {}. Compression positive, u_n &gt; 0 is "
      "dilation, kPa and mm. Figures are also in {} as SVG and PNG, each with its data (CSV) and gnuplot script.</p>\n{}"
      "</body></html>\n",
      io::utc_timestamp(), IWB_VERSION, escape_html(files.filename().string()), body);
  io::write_atomically(html, page);
  return figures;
}

}  // namespace iwb::comparison
