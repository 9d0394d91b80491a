#pragma once
// What `iwb assess --reference` writes (issue 17): per model a JSON record (models/<model>.json,
// written as soon as the model is assessed, so that a stopped league resumes), and from the records
// the league table first (league.md, league.csv), then per model its calibration, objective points,
// parameter uncertainty and Sobol indices, and the figures of the samples (figures/).
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "assessment/league.hpp"

namespace iwb::assessment {

nlohmann::json entry_json(const LeagueEntry& entry);

// The records sorted by global uncertainty (shear and normal), failed ones last.
std::vector<nlohmann::json> ranked(std::vector<nlohmann::json> entries);

// `header`: what the league ran on (runs, scene, samples), as league.json's "league".
std::string league_markdown(const nlohmann::json& header,
                            const std::vector<nlohmann::json>& ranked_entries);
std::string league_csv(const std::vector<nlohmann::json>& ranked_entries);

// figures/<model>_tau.svg and figures/<model>_normal.svg (DEM seed mean and SD, the calibrated
// model, the 5-95 % band of its parameter samples) and figures/league.svg (the uncertainties).
void draw_league_figures(const std::vector<nlohmann::json>& ranked_entries,
                         const std::filesystem::path& dir);

}  // namespace iwb::assessment
