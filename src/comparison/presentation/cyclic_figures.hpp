#pragma once
// The figures of a cyclic comparison (issue 34, item 4): what a reader of a cyclic interface test
// looks at, the DEM drawn last, thick and black so that no model curve hides it:
//   tau against u_x, one loop per figure, for the cycles the verdicts judge (1, 2, 5, the last);
//   under CNS and CV, sigma_n at each cycle's end over sigma_n0 against N (the degradation behind
//   friction fatigue);
//   under CNL and CNS, the accumulated u_n at each cycle's end against N (ratcheting);
//   (against N with the seeds' mean and 95 % t-interval at the judged cycles, where there are
//   seeds, beside the compared run's own line);
//   under CV, the stress path tau against sigma_n over the cycles;
//   the post-cyclic monotonic shear, tau against u_x, where the program has one.
// A loop's rows run from the last row at or before the cycle's start to the first at or after its
// end (travel 4 A (c - 1) to 4 A c), so that each loop closes on the figure.
#include <nlohmann/json.hpp>
#include <vector>

#include "comparison/presentation/figure.hpp"
#include "cycles/cycle_quantities.hpp"
#include "io/csv_table.hpp"

namespace iwb::comparison {

// `cmp`: compare.json of a cyclic run; `curves`: its compare.csv; `travel_mm`: the DEM's travel
// at each of its rows (cyclic_travel); `shown`: the variants drawn (indices into cmp's variants).
std::vector<Figure> cyclic_figures(const nlohmann::json& cmp, const io::CsvTable& curves,
                                   const std::vector<double>& travel_mm,
                                   const cycles::Program& program,
                                   const std::vector<std::size_t>& shown);

}  // namespace iwb::comparison
