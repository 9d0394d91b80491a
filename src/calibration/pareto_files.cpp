// Writing a Pareto front: its table, its JSON, its figure and each point's parameter file.
#include <fmt/core.h>

#include <cmath>

#include "calibration/pareto.hpp"
#include "comparison/presentation/figure.hpp"
#include "io/run_directory.hpp"

namespace iwb::calibration {

namespace {

namespace fs = std::filesystem;

io::CsvTable front_table(const ParetoFront& f) {
  io::CsvTable t;
  t.columns = {"share", fmt::format("weight_{}", to_string(f.a)),
               fmt::format("weight_{}", to_string(f.b))};
  // the groups the tests have (the same at every point: the same tests)
  for (const auto& g : f.points.front().result.objectives)
    t.columns.push_back(fmt::format("rms_{}", to_string(g.group)));
  t.columns.insert(t.columns.end(), {"s2", "given", "converged"});
  for (const auto& p : f.points.front().result.parameters) t.columns.push_back(p.key);
  for (const auto& p : f.points) {
    std::vector<double> row = {p.share, p.weights[f.a], p.weights[f.b]};
    for (const auto& g : p.result.objectives) row.push_back(g.rms);
    row.insert(row.end(), {p.result.s2, p.given ? 1.0 : 0.0, p.result.converged ? 1.0 : 0.0});
    for (const auto& e : p.result.parameters) row.push_back(e.value);
    t.rows.push_back(row);
  }
  return t;
}

nlohmann::json front_json(const ParetoFront& f) {
  nlohmann::json j = {{"kind", "pareto_front"},
                      {"groups", {to_string(f.a), to_string(f.b)}},
                      {"share",
                       "of the pair's weight on the first group: w_a = s T / N_a, w_b = "
                       "(1 - s) T / N_b (src/calibration/pareto.hpp)"},
                      {"wall_seconds", f.seconds},
                      {"evaluations", f.evaluations},
                      {"notes", f.notes},
                      {"points", nlohmann::json::array()}};
  for (std::size_t k = 0; k < f.points.size(); ++k) {
    const auto& p = f.points[k];
    nlohmann::json pj = {{"file", fmt::format("pareto/point-{}.toml", k + 1)},
                         {"share", p.share},
                         {"given", p.given},
                         {"converged", p.result.converged},
                         {"s2", p.result.s2}};
    for (const auto& g : p.result.objectives)
      pj["objectives"][to_string(g.group)] = {{"weight", p.weights[g.group]},
                                              {"rms_scatter_units", g.rms}};
    for (const auto& e : p.result.parameters)
      pj["parameters"][e.key] = {
          {"value", e.value},
          {"sigma", std::isfinite(e.sigma) ? nlohmann::json(e.sigma) : nlohmann::json()},
          {"identified", e.identified},
          {"at_bound", e.at_bound.empty() ? nlohmann::json() : nlohmann::json(e.at_bound)}};
    j["points"].push_back(pj);
  }
  return j;
}

// RMS of b against RMS of a, the path in order of share, the given point ringed.
void draw_front(const ParetoFront& f, const io::CsvTable& table, const fs::path& dir) {
  comparison::Figure fig{
      "pareto",
      fmt::format("calibration front: {} against {}", to_string(f.b), to_string(f.a)),
      fmt::format("{} RMS (scatter units)", to_string(f.a)),
      fmt::format("{} RMS (scatter units)", to_string(f.b)),
      table,
      {},
      "",
      ""};
  const int col_a = table.column(fmt::format("rms_{}", to_string(f.a))) + 1;
  const int col_b = table.column(fmt::format("rms_{}", to_string(f.b))) + 1;
  const int col_given = table.column("given") + 1;
  // each point labelled with the pair's weight ratio s / (1 - s): near s = 1 the share's digits
  // say nothing, the ratio's decades do
  for (const auto& p : f.points)
    fig.extra += fmt::format("set label '{:.2g}' at {},{} offset 0.8,0.5 font ',9'\n",
                             p.share / (1.0 - p.share), p.rms_a, p.rms_b);
  const std::string csv = comparison::gnuplot_string("pareto.csv");
  fig.plot = fmt::format(
      "plot {0} using {1}:{2} skip 1 with linespoints pt 7 lw 2 title 'optimum at the weight ratio "
      "{4}:{5} (labels)', {0} using {1}:(${3} > 0 ? ${2} : 1/0) skip 1 with points pt 6 ps 2.5 lw "
      "2 "
      "title 'the given weights'",
      csv, col_a, col_b, col_given, to_string(f.a), to_string(f.b));
  comparison::draw(fig, dir);
}

}  // namespace

void write_front_files(const ParetoFront& front, const fs::path& dir,
                       const std::vector<soil_test::SoilTest>& tests,
                       const std::string& command_line) {
  const auto table = front_table(front);
  draw_front(front, table, dir);  // pareto.csv is the figure's data
  io::write_atomically(dir / "pareto.json", front_json(front).dump(2) + "\n");
  fs::create_directories(dir / "pareto");
  for (std::size_t k = 0; k < front.points.size(); ++k)
    io::write_atomically(dir / "pareto" / fmt::format("point-{}.toml", k + 1),
                         parameter_file_text(front.points[k].result, tests, command_line));
}

}  // namespace iwb::calibration
