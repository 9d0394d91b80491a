#pragma once
// history.csv of an element test: geotechnical signs (compression positive, u_n > 0 dilation),
// units in the column names (CONVENTIONS.md).
#include <string>
#include <vector>

#include "driver/element_test.hpp"
#include "models/model.hpp"

namespace iwb::element {

// tau_over_sigma_n is the shear stress along the path's direction over sigma_n.
std::string history_csv(const models::Model& model, const driver::ShearZone& zone,
                        const std::vector<driver::HistoryRow>& rows,
                        driver::ShearDirection direction);

// cycles.csv: one row per cycle of a cyclic path (peak tau each way, sigma_n at the reversals,
// accumulated and per-cycle u_n, e at the cycle's end). Incomplete cycles are marked.
std::string cycles_csv(const driver::ShearZone& zone,
                       const std::vector<driver::CycleSummary>& cycles);

}  // namespace iwb::element
