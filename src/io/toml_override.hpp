#pragma once
// Setting one dotted key of a TOML document: how a campaign derives each job's scene from a base
// scene. The text is parsed and re-serialised by toml++, so the key lands in its own table
// whatever the base file's layout (a regex on lines cannot tell [wall] height_d50 from
// [plate] height_d50). Comments of the base are not kept; callers add a header saying what changed.
#include <toml++/toml.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace iwb::io {

// A TOML value as a campaign may set it: a number, a boolean, a string, or a list of numbers (a
// grading's `particles.d_over_d50`); no tables or dates.
using TomlValue = std::variant<std::int64_t, double, bool, std::string, std::vector<double>>;

// InputError naming `where` when the node is none of those.
TomlValue toml_value_of(const toml::node& node, const std::string& where);

// The value as TOML writes it: 0.5, 2, true, "CNL", [0.8, 1, 1.2].
std::string to_toml(const TomlValue& value);

// `root` with `dotted_key` ("wall.height_d50", "seed") set to `value`; missing tables are created.
// InputError naming `source` and the key when a part of the path is a value, not a table.
void set_dotted(toml::table& root, const std::string& dotted_key, const TomlValue& value,
                const std::string& source);

std::string serialise(const toml::table& root);

}  // namespace iwb::io
