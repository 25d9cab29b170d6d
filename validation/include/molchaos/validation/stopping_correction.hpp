// The bias that stopping once the SE meets a target leaves in a staged point's error bar, measured
// by running the same staging on simulated runs of known scatter, and the factor that undoes it.
#pragma once

#include <cstdint>
#include <vector>

#include "molchaos/validation/seed_sizing.hpp"

namespace molchaos::validation {

/// How the points of one gas were grown: the seeds each had before the first further stage, the
/// sizing of every stage, and how many further stages there were at most. Each stage sizes with
/// seeds_needed_for_factors(gas, sizing_factors, sizing): for error bars that will carry the
/// correction, with the factors found at the stage before (empty: none, plain seeds_needed).
struct Staging {
  std::vector<int> first_seeds;
  SeedSizing sizing;
  int stages = 0;
  std::vector<double> sizing_factors;
};

struct StoppingCorrectionOptions {
  int replicas = 2000;  ///< simulated gases; the factors' own scatter is below 1 % at 2000
  std::uint64_t seed = 0x5eed5ca7;
};

/// Per point of `gas` (its final seeds and runs), the factor c by which the scatter that
/// reported_relative_scatter gives (`reported`) is to be multiplied for an unbiased error bar.
///
/// Whether a point grows depends on the scatter of its own runs (and, through the gas's model, on
/// its neighbours'), so its final run count n and its reported scatter r are correlated: where
/// runs that scattered little stopped early, r/√n falls short of the true spread of its mean,
/// σ √E[1/n]. The staging is re-run `replicas` times on normal runs whose scatter per point is
/// the reported one and whose seeds fail at the point's own rate (a point with fewer than 2 runs
/// fails every seed, and keeps c = 1), and c = σ √E[1/n] / √E[r²/n] over the replicas. A point
/// that never grows, but reports the model's larger scatter, gets c < 1. The plug-in σ carries the
/// bias it corrects, which moves c only at second order; so do the sizing factors, held fixed in
/// the simulated stages where the real ones find them anew at each.
std::vector<double> stopping_correction(const std::vector<PointScatter>& gas,
                                        const std::vector<double>& reported, const Staging& staging,
                                        const StoppingCorrectionOptions& options = {});

/// seeds_needed on the gas with each point's scatter multiplied by its factor (empty: by 1), so
/// that a point grows until the SE it will report with that factor meets the target.
std::vector<int> seeds_needed_for_factors(const std::vector<PointScatter>& gas,
                                          const std::vector<double>& factors,
                                          const SeedSizing& sizing);

}  // namespace molchaos::validation
