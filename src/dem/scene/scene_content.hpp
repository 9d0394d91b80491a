#pragma once
// What a scene asks the engine to do, as data: two scene files are the same scene when their
// contents are equal, whatever their names, comments, layout or key order. `iwb validate` reuses
// a complete DEM run of the same content; `iwb plan` accepts a scene whose content is that of
// the scene its tradeoff ran, and names the keys that differ otherwise.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iwb::dem {

// The scene's TOML tree as JSON without the keys that do not change a DEM run: `description`
// (words) and `[requirements]` (what the results must meet). Values as written: 2 and 2.0 compare
// equal, a key left at its default differs from one set to the default. InputError on bad TOML.
nlohmann::json scene_content(const std::string& text, const std::string& source);

// Each dotted key in which `mine` and `theirs` differ, as "key 'particles.friction' = 0.6 here,
// = 0.5 there" (or "absent here", "absent there"), in key order; empty when they are equal.
std::vector<std::string> content_differences(const nlohmann::json& mine,
                                             const nlohmann::json& theirs);

// The differences for a message: the first few joined by "; ", then how many more.
std::string differences_text(const std::vector<std::string>& differences);

}  // namespace iwb::dem
