// `iwb report COMPARE_DIR... -o report.html` (comparison/presentation/report.hpp).
#include "comparison/presentation/report.hpp"

#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "app/command_list.hpp"
#include "app/commands/commands.hpp"
#include "app/option_checks.hpp"

namespace iwb::app {

namespace {
struct ReportOptions {
  std::vector<std::string> compare_dirs;
  std::string out = "report.html";
};

int write_report(const ReportOptions& o) {
  const std::vector<std::filesystem::path> dirs(o.compare_dirs.begin(), o.compare_dirs.end());
  const auto figures = comparison::write_report(dirs, o.out);
  fmt::print("report: {} ({} figures)\n", std::filesystem::absolute(o.out).string(),
             figures.size());
  return 0;
}
}  // namespace

void add_report_command(CLI::App& app, CommandList& commands) {
  auto o = std::make_shared<ReportOptions>();
  auto* report = app.add_subcommand(
      "report",
      "Write one self-contained HTML report (inline SVG figures, opens offline) from comparison "
      "directories of `iwb compare` and run directories of `iwb column` (their profiles beside "
      "the DEM runs given to the column with --dem); figures also as SVG and PNG with their data "
      "and gnuplot scripts.");
  report
      ->add_option("compare_dirs", o->compare_dirs,
                   "directories of `iwb compare`, or the OUT of `iwb compare --runs` "
                   "(its verdicts come first), or runs of `iwb column`")
      ->required()
      ->check(input_path());
  report->add_option("-o,--out", o->out, "HTML file")->check(output_file())->capture_default_str();
  commands.add(report, [o](const CommandContext&) { return write_report(*o); });
}

}  // namespace iwb::app
