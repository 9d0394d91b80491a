#include "studies/study_figures.hpp"

#include <fmt/core.h>

#include "comparison/presentation/figure.hpp"
#include "comparison/presentation/html.hpp"
#include "io/output_path.hpp"
#include "io/run_directory.hpp"

namespace iwb::studies {

namespace fs = std::filesystem;

namespace {

const std::vector<double>& values(const ClayCurve& c, Axis a) {
  switch (a) {
    case Axis::kGamma:
      return c.gamma;
    case Axis::kEpsN:
      return c.eps_n;
    case Axis::kTau:
      return c.tau;
    case Axis::kSigmaN:
      return c.sigma_n;
  }
  return c.tau;
}

const char* label(Axis a) {
  switch (a) {
    case Axis::kGamma:
      return "shear strain gamma_x";
    case Axis::kEpsN:
      return "normal strain eps_n (opening positive)";
    case Axis::kTau:
      return "shear stress tau_x (kPa)";
    case Axis::kSigmaN:
      return "normal stress sigma_n (kPa)";
  }
  return "";
}

comparison::Figure figure_of(const FigureSpec& spec,
                             const std::map<std::string, ClayCurve>& curves) {
  std::vector<comparison::PlotCurve> plotted;
  for (const auto& [name, title] : spec.curves) {
    const auto& c = curves.at(name);
    comparison::PlotCurve p{title, {}, {}};
    for (std::size_t k = 0; k < c.gamma.size() && c.gamma[k] <= spec.gamma_limit; ++k) {
      p.x.push_back(values(c, spec.x)[k]);
      p.y.push_back(values(c, spec.y)[k]);
    }
    plotted.push_back(p);
  }
  return comparison::curves_figure(spec.name, spec.title, label(spec.x), label(spec.y), plotted);
}

}  // namespace

std::vector<StudyFigure> draw_figures(const std::vector<FigureSpec>& specs,
                                      const std::map<std::string, ClayCurve>& curves,
                                      const fs::path& out) {
  io::StagedDirectory staged(out / "figures", "figures");
  std::vector<StudyFigure> figures;
  for (const auto& spec : specs) {
    comparison::draw(figure_of(spec, curves), staged.path());
    figures.push_back({out / "figures" / (spec.name + ".svg"), spec.title});
  }
  staged.commit();
  return figures;
}

std::string study_page(const std::string& title, const std::string& command,
                       const std::string& setting, const std::vector<ClayClaim>& claims,
                       const std::vector<StudyFigure>& figures, const fs::path& out) {
  using comparison::escape_html;
  std::string body = fmt::format(
      "<p>Generated {} by iwb {} (<code>{}</code>). {} Compression positive, kPa. Each case is an "
      "element run "
      "directory beside this page; each figure is also an SVG and PNG with its CSV and gnuplot "
      "script in figures/.</p>\n"
      "<section><h2>The seed's "
      "claims</h2>\n<table><tr><th>seed</th><th>claim</th><th>measured</th><th>verdict</th></tr>\n",
      io::utc_timestamp(), IWB_VERSION, escape_html(command), escape_html(setting));
  for (const auto& c : claims)
    body += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"{}\">{}</td></tr>\n",
                        escape_html(c.section), escape_html(c.claim), escape_html(c.measured),
                        c.holds ? "holds" : "breaks", c.holds ? "holds" : "does not hold");
  body += "</table></section>\n<section><h2>Figures</h2>\n";
  for (const auto& f : figures)
    body += fmt::format(
        "<figure>{}<figcaption>{} (data: {})</figcaption></figure>\n",
        comparison::inline_svg(f.svg), escape_html(f.caption),
        escape_html(
            fs::relative(f.svg.parent_path() / (f.svg.stem().string() + ".csv"), out).string()));
  return comparison::html_page(title, body + "</section>\n");
}

}  // namespace iwb::studies
