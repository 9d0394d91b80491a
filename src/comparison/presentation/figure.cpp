#include "comparison/presentation/figure.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/subprocess.hpp"
#include "io/run_directory.hpp"

namespace iwb::comparison {

namespace fs = std::filesystem;

std::string gnuplot_string(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return "'" + out + "'";
}

namespace {
std::string series_lines(const Figure& f) {
  std::string plot = "plot ";
  for (std::size_t i = 0; i < f.titles.size(); ++i)
    plot += fmt::format("{}{} using 1:{} skip 1 with lines lw {} title {}", i ? ", " : "",
                        gnuplot_string(f.name + ".csv"), i + 2, i == 0 ? 3 : 1.5,
                        gnuplot_string(f.titles[i]));
  return plot;
}
}  // namespace

Figure curves_figure(const std::string& name, const std::string& title, const std::string& xlabel,
                     const std::string& ylabel, const std::vector<PlotCurve>& curves) {
  Figure f{name, title, xlabel, ylabel, {}, {}, "set datafile missing 'nan'\n", ""};
  std::size_t rows = 0;
  for (std::size_t i = 0; i < curves.size(); ++i) {
    f.data.columns.push_back(fmt::format("x{}", i));
    f.data.columns.push_back(fmt::format("y{}", i));
    f.titles.push_back(curves[i].title);
    rows = std::max(rows, std::min(curves[i].x.size(), curves[i].y.size()));
  }
  f.data.rows.assign(rows, std::vector<double>(2 * curves.size(), NAN));
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (std::size_t k = 0; k < std::min(curves[i].x.size(), curves[i].y.size()); ++k) {
      f.data.rows[k][2 * i] = curves[i].x[k];
      f.data.rows[k][2 * i + 1] = curves[i].y[k];
    }
  f.plot = "plot ";
  for (std::size_t i = 0; i < curves.size(); ++i)
    f.plot += fmt::format("{}{} using {}:{} skip 1 {} title {}", i ? ", " : "",
                          gnuplot_string(name + ".csv"), 2 * i + 1, 2 * i + 2, curves[i].style,
                          gnuplot_string(curves[i].title));
  return f;
}

fs::path draw(const Figure& f, const fs::path& dir) {
  io::write_atomically(dir / (f.name + ".csv"), f.data.to_csv(8));
  std::string gp = "set datafile separator ','\nset key below\nset grid\n";
  gp += fmt::format("set title {}\nset xlabel {}\nset ylabel {}\n{}\n", gnuplot_string(f.title),
                    gnuplot_string(f.xlabel), gnuplot_string(f.ylabel), f.extra);
  const std::string plot = f.plot.empty() ? series_lines(f) : f.plot;
  // noenhanced on each terminal: labels hold underscores (kappa_r, d_s) that are not subscripts
  gp += fmt::format(
      "set terminal svg size 900,560 font 'sans,12' noenhanced background '#ffffff'\nset output "
      "'{}.svg'\n{}\n"
      "set terminal pngcairo size 900,560 font 'sans,10' noenhanced\nset output "
      "'{}.png'\nreplot\nunset output\n",
      f.name, plot, f.name);
  io::write_atomically(dir / (f.name + ".gp"), gp);
  std::string log;
  const auto r = run_process({"gnuplot", f.name + ".gp"}, dir, [&log](const std::string& l) {
    log += l + "\n";
    return true;
  });
  if (r.exit_code != 0 || !fs::exists(dir / (f.name + ".svg")))
    throw std::runtime_error(fmt::format("gnuplot failed on {} (exit {}): {}",
                                         (dir / (f.name + ".gp")).string(), r.exit_code, log));
  return dir / (f.name + ".svg");
}

}  // namespace iwb::comparison
