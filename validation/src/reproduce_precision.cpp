// The precision of the Fig. 4 ensembles: which τ0 estimator the suite uses and why (the scatter
// of each on the same runs, its shift from the least-squares fit in each gas), and the precision
// every Fig. 4 point reached.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>

#include "molchaos/validation/estimator_study.hpp"
#include "molchaos/validation/report.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation::steps {
namespace {

struct Gas {
  std::string label;
  std::vector<const PointSummary*> points;
};

// The Fig. 4 points by gas: the three MD modes and DSMC.
std::vector<Gas> gases(const ReproduceResults& R) {
  std::vector<Gas> out;
  for (const auto mode : k_modes) {
    Gas g{std::string(sim::to_string(mode)), {}};
    for (const auto& p : R.fig4_points)
      if (p.summary.mode == g.label) g.points.push_back(&p.summary);
    out.push_back(std::move(g));
  }
  Gas dsmc{"dsmc", {}};
  for (const auto& p : R.dsmc_points) dsmc.points.push_back(&p.summary);
  out.push_back(std::move(dsmc));
  return out;
}

// The Fig. 4 slopes' variance by the jackknife over seeds (the ε points of a gas share their
// seeds' relaxed states) over the fit's own, which treats the points as independent: the mean
// of the ratio over the fits, and its standard error; 1 if sharing the seeds does not matter.
// None without a jackknife (one seed per point).
std::optional<Measurement> shared_seed_variance_ratio(const ReproduceResults& R) {
  std::vector<double> ratios;
  for (const auto& panel : R.fig4.panels)
    for (const auto& s : panel.series)
      if (s.fit && s.slope_error_over_seeds > 0.0 && s.fit->slope_error > 0.0)
        ratios.push_back(std::pow(s.slope_error_over_seeds / s.fit->slope_error, 2));
  if (ratios.empty()) return std::nullopt;
  return mean_and_standard_error(ratios);
}

// "value ± error" with the given format of each, or what was missing to measure it: a quantity
// over seeds that too few seeds did not give (error 0) is not printed as 0 ± 0.
std::string measured_or(const std::optional<Measurement>& m, const char* format,
                        const char* missing) {
  if (!m || !(m->error > 0.0)) return fmt::format("not measured ({})", missing);
  return fmt::format(fmt::runtime(format), m->value, m->error);
}

}  // namespace

double largest_relative_error_of_A(const ReproduceResults& R) {
  double largest = 0.0;
  for (const auto* list : {&R.fig4_points, &R.dsmc_points})
    for (const auto& p : *list)
      if (p.summary.runs >= 2) largest = std::max(largest, p.summary.A.error / p.summary.A.value);
  return largest;
}

Claim finding_estimator_precision(const ReproduceResults& R) {
  Claim c{ClaimSource::suite,
          fmt::format("the integrated form of Haff's law estimates A with less scatter than the "
                      "least-squares fit of T(t), without a shift in a gas that obeys Haff's law "
                      "(the estimator of every A here)"),
          "beyond the paper", "", {}};
  std::string deciding;
  constexpr const char* k_one_run = "fewer than two runs per point";
  for (const auto& gas : gases(R)) {
    for (const auto& s : compare_estimator_scatter(gas.points)) {
      if (s.degrees_of_freedom == 0) {  // no scatter within a point to compare
        if (s.estimator == k_haff_estimator)
          deciding += fmt::format("{}{}: not measured ({})", deciding.empty() ? "" : "; ",
                                  gas.label, k_one_run);
        continue;
      }
      ComparisonRow row{fmt::format("{} gas, {}: relative sd of A per run, %", gas.label,
                                    to_string(s.estimator)),
                        std::nullopt,
                        Measurement{100.0 * s.relative_sd_per_run, 0.0},
                        std::nullopt,
                        std::nullopt,
                        "information",
                        k_information_rule,
                        fmt::format("runs for a given precision ×{:.3f} of the fit's; shift from "
                                    "the fit {:+.4f} ± {:.4f} % ({} dof)",
                                    s.cost_ratio, 100.0 * s.shift_from_least_squares.value,
                                    100.0 * s.shift_from_least_squares.error,
                                    s.degrees_of_freedom)};
      c.rows.push_back(std::move(row));
      if (s.estimator == k_haff_estimator)
        deciding += fmt::format("{}{}: cost ×{:.2f}, shift {:+.3f} ± {:.3f} %",
                                deciding.empty() ? "" : "; ", gas.label, s.cost_ratio,
                                100.0 * s.shift_from_least_squares.value,
                                100.0 * s.shift_from_least_squares.error);
    }
  }
  const auto all = gases(R);
  constexpr const char* k_few_seeds = "fewer than three seeds shared per point";
  const std::string none_flux = measured_or(seed_correlation(all[0].points, all[2].points),
                                            "r = {:+.3f} ± {:.3f}", k_few_seeds);
  const std::string paper_flux = measured_or(seed_correlation(all[1].points, all[2].points),
                                             "r = {:+.3f} ± {:.3f}", k_few_seeds);
  const std::string seed_ratio =
      measured_or(shared_seed_variance_ratio(R), "{:.2f} ± {:.2f} times", "one seed per point");
  const double largest = largest_relative_error_of_A(R);
  c.deciding = fmt::format(
      "{} against the least-squares fit on the same runs; largest SE(A)/A "
      "of a Fig. 4 point {}; the correlation over seeds of A in two gases "
      "from the same relaxed states, (none, flux): {}, (paper, flux): {} "
      "(pairing the gases' runs would shrink the variance of a difference by the fraction r "
      "at most, so differences between gases are taken as of independent runs); the Fig. 4 "
      "slopes' variance by the jackknife over seeds (which the ε points of a gas share) is {} "
      "the fits' own (which treat the points as independent), mean over the fits",
      deciding,
      largest > 0.0 ? fmt::format("{:.3f} %", 100.0 * largest)
                    : fmt::format("not measured ({})", k_one_run),
      none_flux, paper_flux, seed_ratio);
  return c;
}

}  // namespace molchaos::validation::steps

namespace molchaos::validation {

void write_estimator_table(const ReproduceResults& R, const std::string& directory) {
  using steps::gases;
  std::string csv = fmt::format(
      "# molchaos reproduce: tau0 estimators on the same Fig. 4 runs\n"
      "# version = {}\n"
      "# relative_sd_per_run pooled over the gas's points; cost_ratio = (sd/sd_least_squares)^2;\n"
      "# shift = A/A_least_squares - 1 run by run, mean and standard error; nan where no point "
      "had two runs (degrees_of_freedom = 0)\n"
      "gas,estimator,relative_sd_per_run,degrees_of_freedom,cost_ratio,shift,shift_err,"
      "used\n",
      R.version);
  for (const auto& gas : gases(R))
    for (const auto& s : compare_estimator_scatter(gas.points)) {
      const auto measured = [&s](double v) {
        return s.degrees_of_freedom > 0 ? v : std::numeric_limits<double>::quiet_NaN();
      };
      csv +=
          fmt::format("{},{},{:.6e},{},{:.4f},{:.6e},{:.6e},{}\n", gas.label,
                      to_string(s.estimator), measured(s.relative_sd_per_run), s.degrees_of_freedom,
                      measured(s.cost_ratio), measured(s.shift_from_least_squares.value),
                      measured(s.shift_from_least_squares.error), s.estimator == k_haff_estimator);
    }
  write_file_atomically((std::filesystem::path(directory) / "haff_estimators.csv").string(),
                        after_title(csv, rerun_lines(R.config)));
}

}  // namespace molchaos::validation
