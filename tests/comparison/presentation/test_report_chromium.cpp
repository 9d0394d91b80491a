// The report as a reader meets it (issue 6 "what it must show"): Debian's headless Chromium opens
// a report made from a synthetic comparison (no DEM engine), and we check what it rendered (a
// screenshot with coloured curves), what its DOM holds (inline SVG figures with plotted paths),
// and that it asked the network for nothing. A negative control, the same page with one remote
// <img>, must be caught by the same network check, or the check proves nothing.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>

#include "comparison/compare/compare.hpp"
#include "comparison/presentation/report.hpp"
#include "io/run_directory.hpp"
#include "support/synthetic_dem.hpp"

using namespace iwb;
namespace fs = std::filesystem;

namespace {

const fs::path kChromiumWork = fs::path(IWB_TEST_RUNS_DIR) / "chromium";
constexpr const char* kChromiumFlags =
    "--headless --no-sandbox --disable-gpu --disable-background-networking "
    "--disable-component-update "
    "--disable-default-apps --disable-sync --no-first-run "
    // nothing may leave the machine even if a request is made: a dead proxy (port 9, discard)
    "--proxy-server=127.0.0.1:9 --window-size=1200,2600";

// Runs Chromium on `html` with `args`; its stdout goes to `stdout_file`. A fresh profile each time.
void chromium(const fs::path& html, const std::string& args, const fs::path& stdout_file) {
  REQUIRE(std::system("command -v chromium > /dev/null") == 0);  // setup.sh installs it
  const fs::path profile = kChromiumWork / ("profile-" + stdout_file.stem().string());
  fs::remove_all(profile);
  const std::string cmd =
      fmt::format("timeout 120 chromium {} --user-data-dir={} {} file://{} > {} 2> {}.stderr",
                  kChromiumFlags, profile.string(), args, fs::absolute(html).string(),
                  stdout_file.string(), stdout_file.string());
  INFO(cmd);
  REQUIRE(std::system(cmd.c_str()) == 0);
}

// URLs the page asked for, from Chromium's net log: requests started on behalf of web content
// carry an initiator origin; the browser's own background requests (update, time, accounts)
// carry "not an origin" and are not the page's doing.
std::vector<std::string> page_requests(const fs::path& net_log) {
  const auto log = nlohmann::json::parse(io::read_file(net_log));
  const int start_job = log["constants"]["logEventTypes"]["URL_REQUEST_START_JOB"].get<int>();
  std::vector<std::string> urls;
  for (const auto& e : log["events"]) {
    // the job's begin event holds the URL and the initiator; its end event holds neither
    if (e["type"].get<int>() != start_job || !e.contains("params") || !e["params"].contains("url"))
      continue;
    const auto& p = e["params"];
    if (p.value("initiator", "") != "not an origin") urls.push_back(p["url"].get<std::string>());
  }
  return urls;
}

// Pixel statistics of a PNG with Debian's Python and PIL: "width height non_white coloured"
// (coloured: channels differ by more than 60, which grey text and table rules never do).
std::vector<double> png_stats(const fs::path& png) {
  const fs::path out = png.string() + ".stats";
  const std::string script =
      "import sys; from PIL import Image; im = Image.open(sys.argv[1]).convert('RGB'); px = "
      "list(im.getdata()); "
      "print(im.width, im.height, sum(1 for p in px if min(p) < 245), "
      "sum(1 for p in px if max(p) - min(p) > 60))";
  const std::string cmd =
      fmt::format("/usr/bin/python3 -c \"{}\" {} > {}", script, png.string(), out.string());
  REQUIRE(std::system(cmd.c_str()) == 0);
  std::istringstream in(io::read_file(out));
  std::vector<double> v(4, -1.0);
  for (auto& x : v) in >> x;
  return v;
}

fs::path synthetic_report() {
  const auto dem =
      test::write_synthetic_dem({.name = "chromium_dem", .kappa_r = 0.8, .d_s_mm = 1.4});
  comparison::CompareOptions opt;
  opt.dem_dir = dem;
  opt.params = "data/params/table_5_1_evaluation.toml";
  opt.out = kChromiumWork / "compare";
  opt.force = true;
  comparison::run_comparison(opt);
  const fs::path html = kChromiumWork / "report.html";
  REQUIRE(comparison::write_report({opt.out}, html).size() == 4);
  return html;
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("headless Chromium renders the report offline: figures drawn, no network request",
          "[comparison][chromium]") {
  fs::remove_all(kChromiumWork);
  fs::create_directories(kChromiumWork);
  const fs::path html = synthetic_report();

  // (a) screenshot, with the net log of the same load
  chromium(html,
           fmt::format("--screenshot={} --log-net-log={}", (kChromiumWork / "shot.png").string(),
                       (kChromiumWork / "net.json").string()),
           kChromiumWork / "shot.out");
  const auto px = png_stats(kChromiumWork / "shot.png");
  INFO("screenshot " << px[0] << " x " << px[1] << ": " << px[2] << " non-white, " << px[3]
                     << " coloured pixels");
  REQUIRE(px[0] * px[1] > 0);
  CHECK(px[2] > 0.02 * px[0] * px[1]);  // text, tables and figures, not a blank page
  CHECK(px[3] > 2000);                  // the coloured curves of the figures were drawn
  // (c) nothing fetched by the page
  const auto requests = page_requests(kChromiumWork / "net.json");
  CHECK(requests == std::vector<std::string>{});

  // (b) the DOM Chromium built: four inline SVG figures, each with plotted paths
  chromium(html, "--dump-dom", kChromiumWork / "dom.html");
  const std::string dom = io::read_file(kChromiumWork / "dom.html");
  CHECK(count(dom, "<svg") == 4);
  const std::regex plotted(
      R"(<path[^>]*\sd=['"]M[^'"]{200,})");  // a curve: a long path, not a tick
  for (auto p = dom.find("<svg"); p != std::string::npos; p = dom.find("<svg", p + 1)) {
    const std::string svg = dom.substr(p, dom.find("</svg>", p) - p);
    INFO("figure at DOM offset " << p);
    CHECK(std::regex_search(svg, plotted));
  }

  // negative control: one remote image must show up in the same check
  std::string page = io::read_file(html);
  page.insert(page.find("</body>"), "<img src=\"http://example.com/x.png\">");
  const fs::path leaky = kChromiumWork / "leaky.html";
  io::write_atomically(leaky, page);
  chromium(leaky, "--log-net-log=" + (kChromiumWork / "leaky_net.json").string() + " --dump-dom",
           kChromiumWork / "leaky.out");
  const auto leaked = page_requests(kChromiumWork / "leaky_net.json");
  REQUIRE_FALSE(leaked.empty());
  for (const auto& url : leaked) CHECK(url == "http://example.com/x.png");
}
