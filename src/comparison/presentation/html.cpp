#include "comparison/presentation/html.hpp"

#include <fmt/core.h>

#include "io/run_directory.hpp"

namespace iwb::comparison {

std::string escape_html(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string inline_svg(const std::filesystem::path& svg) {
  std::string s = io::read_file(svg);
  const auto start = s.find("<svg");
  return start == std::string::npos ? s : s.substr(start);
}

std::string html_page(const std::string& title, const std::string& body) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{0}</title>\n"
      "<style>body{{font-family:sans-serif;max-width:1100px;margin:2em "
      "auto;color:#222}}table{{border-collapse:collapse;margin:1em 0}}"
      "td,th{{border:1px solid #bbb;padding:3px "
      "8px;text-align:left;font-size:0.9em}}figure{{margin:1em 0}}"
      ".holds{{color:#1a7f37;font-weight:bold}}.breaks{{color:#c62828;font-weight:bold}}.scatter{{"
      "color:#b26a00;font-weight:bold}}"
      "figure "
      "svg{{max-width:100%;height:auto}}pre{{font-size:0.8em;background:#f6f6f6;padding:1em;"
      "overflow:auto}}</style>\n"
      "</head><body><h1>{0}</h1>\n{1}</body></html>\n",
      escape_html(title), body);
}

}  // namespace iwb::comparison
