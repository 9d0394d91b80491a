#pragma once
// The verdict table of one comparison (issue 14), as cells with units, for the terminal and the
// report alike: rows are the quantities of interest; columns the DEM (value +- seed SD), the
// predicted model (value, error), the jointly fitted model (value, error), the tolerance and the
// two verdicts.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace iwb::comparison {

struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};

// From compare.json.
Table verdict_table(const nlohmann::json& compare);

// The cyclic verdicts of a cyclic run (issue 34), predicted and fitted side by side: rows are the
// quantity at a cycle; empty rows for a monotonic run.
Table cyclic_verdict_table(const nlohmann::json& compare);

// Models judged along one cyclic run side by side (issue 34: does intergranular strain improve
// on its plain model, and where?): the rows of cyclic_verdict_table, the DEM once, then for each
// comparison its predicted and its fitted model (value, error, verdict). Empty when the first is
// not cyclic; a quantity a comparison did not judge is "-".
Table cyclic_models_table(const std::vector<nlohmann::json>& comparisons);

// The sentences under the table: what the predicted and fitted models hold, and the scan.
std::vector<std::string> verdict_findings(const nlohmann::json& compare);

// Fixed-width text, for the terminal.
std::string to_text(const Table& table);

}  // namespace iwb::comparison
