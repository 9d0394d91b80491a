#pragma once
// The tradeoff's files: tradeoff.json (everything), tradeoff.csv (one row per setting),
// tradeoff.md (the tables people read) and pareto.svg/.png (error against cost per QoI, drawn by
// comparison/presentation/figure.hpp).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace iwb::tradeoff {

std::string tradeoff_markdown(const nlohmann::json& tradeoff);
std::string tradeoff_csv(const nlohmann::json& tradeoff);

// Writes the four files (atomically) into `dir`; the figure only when a reference exists.
void write_tradeoff(const nlohmann::json& tradeoff, const std::filesystem::path& dir);

}  // namespace iwb::tradeoff
