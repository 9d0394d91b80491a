#include "common/template.hpp"

#include <fmt/core.h>

#include <stdexcept>

namespace iwb {

std::string render_template(const std::string& text, const TemplateValues& values,
                            const std::string& name) {
  std::string out;
  std::size_t pos = 0;
  while (true) {
    const auto open = text.find("{{", pos);
    if (open == std::string::npos) break;
    const auto close = text.find("}}", open);
    if (close == std::string::npos)
      throw std::logic_error(
          fmt::format("template {}: unclosed placeholder at offset {}", name, open));
    const std::string key = text.substr(open + 2, close - open - 2);
    const auto it = values.find(key);
    if (it == values.end())
      throw std::logic_error(fmt::format("template {}: no value for placeholder '{}'", name, key));
    out += text.substr(pos, open - pos) + it->second;
    pos = close + 2;
  }
  out += text.substr(pos);
  return out;
}

}  // namespace iwb
