#pragma once
// history.csv of an element test: geotechnical signs (compression positive, u_n > 0 dilation),
// units in the column names (CONVENTIONS.md).
#include <string>
#include <vector>

#include "driver/element_test.hpp"
#include "models/model.hpp"

namespace iwb::io {

std::string history_csv(const models::Model& model, const driver::ShearZone& zone,
                        const std::vector<driver::HistoryRow>& rows);

}  // namespace iwb::io
