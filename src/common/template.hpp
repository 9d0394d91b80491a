#pragma once
// Fills double-brace placeholders in an engine template. Every placeholder must have a value (a
// renamed key fails here, not as an engine error ten minutes into a run); one value map serves
// all stage templates, so values a template does not use are allowed.
#include <map>
#include <string>

namespace iwb {

using TemplateValues = std::map<std::string, std::string>;

std::string render_template(const std::string& text, const TemplateValues& values,
                            const std::string& template_name);

}  // namespace iwb
