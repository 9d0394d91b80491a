#pragma once
// The workbench's HTML pages (the validation report, the clay study): one style, figures inlined as
// SVG so that a page opens offline.
#include <filesystem>
#include <string>

namespace iwb::comparison {

std::string escape_html(const std::string& s);
// An SVG file's <svg> element, to inline in a page.
std::string inline_svg(const std::filesystem::path& svg);
// A whole page: the shared style, `<h1>title</h1>`, then `body` (already HTML).
std::string html_page(const std::string& title, const std::string& body);

}  // namespace iwb::comparison
