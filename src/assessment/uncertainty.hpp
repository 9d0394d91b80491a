#pragma once
// Parameter uncertainty (issue 17; seed 4.3.2, Table 4.8): the coefficient of variation CV_Y of
// each quantity of interest when the parameters follow their distributions, from a Latin hypercube
// sample (McKay et al. 1979: each parameter's range cut into N equally probable strata, one sample
// in each, the strata paired at random), which converges faster than plain Monte Carlo.
#include <functional>
#include <string>
#include <vector>

#include "assessment/sobol.hpp"

namespace iwb::assessment {

std::vector<std::vector<double>> latin_hypercube(const std::vector<Distribution>& parameters,
                                                 int samples, unsigned seed);

struct QuantityUncertainty {
  std::string name;
  double mean, sd, cv;  // cv = sd / |mean|
};

struct UncertaintyResult {
  std::vector<QuantityUncertainty> quantities;
  int samples = 0;
  long failed = 0;  // samples whose run failed (a quantity not finite): left out
};

// Mean, SD and CV of each quantity over the rows of `outputs` ([sample][quantity]) whose quantities
// are all finite; the others are counted as failed.
UncertaintyResult summarize(const std::vector<std::string>& quantities,
                            const std::vector<std::vector<double>>& outputs);

UncertaintyResult parameter_uncertainty(const std::vector<Distribution>& parameters,
                                        const std::vector<std::string>& quantities,
                                        const Quantities& f, int samples, unsigned seed,
                                        int threads = 0);

}  // namespace iwb::assessment
