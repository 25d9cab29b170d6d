// The reproduction's studies beyond the paper's figures, each with runs of its own: the
// two-particle distribution at contact and in r (correlation_study.hpp) and the break-down of the
// homogeneous cooling state against linear hydrodynamics (breakdown.hpp). Their verdicts come
// from the studies' own global tests; here they become claims of the report.
#include <fmt/format.h>

#include <cmath>

#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/verdict.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation::steps {

void run_studies(ReproduceResults& R, const SweepOptions& sweep) {
  CorrelationStudyConfig correlations =
      R.config.quick ? CorrelationStudyConfig::quick_look() : CorrelationStudyConfig::paper_scale();
  correlations.base_seed = R.config.study_seed(correlations.base_seed);
  R.correlations = run_correlation_study(correlations, sweep);
  R.failed_runs += R.correlations.failed_runs;
  run_breakdown_studies(R);
}

Claim finding_two_particle_distribution(const ReproduceResults& R) {
  Claim c{ClaimSource::suite,
          "the two-particle distribution at contact, measured directly, against the paper's ansatz",
          "beyond the paper",
          "",
          {}};
  for (const auto& s : R.correlations.claims)
    c.rows.push_back({s.claim, std::nullopt, s.deciding, std::nullopt, std::nullopt, s.verdict,
                      "the study's global test (χ² over all state points)", s.note});
  const auto& routes = R.correlations.b_routes;
  c.deciding = routes.statement;
  return c;
}

namespace {

// One claim from a break-down study's rows: each row prediction against measurement (the suite's
// rule), and the linear-regime rows (growth rates, stationary levels) tested together by one χ².
Claim linear_hydrodynamics_claim(const std::vector<BreakdownRow>& rows, std::string statement) {
  Claim c{ClaimSource::suite,
          std::move(statement),
          rows.empty() ? "not run" : "beyond the paper",
          rows.empty() ? "the study runs at paper scale only" : "",
          {}};
  double chi2 = 0;
  int linear = 0;
  for (const auto& b : rows) {
    ComparisonRow row;
    row.quantity = b.quantity;
    if (std::isfinite(b.predicted)) row.theory.emplace(b.predicted, 0.0);
    if (std::isfinite(b.measured)) row.simulation.emplace(b.measured, b.measured_error);
    if (row.theory && row.simulation && b.measured_error > 0) {
      const Agreement a = agreement(*row.simulation, *row.theory);
      row.difference_in_se = a.difference_in_se;
      row.verdict = a.agrees ? "agrees" : "differs";
      row.rule = agreement_rule_text();
      if (b.linear_regime && a.difference_in_se) {
        chi2 += *a.difference_in_se * *a.difference_in_se;
        ++linear;
      }
    }
    row.note = b.note;
    c.rows.push_back(row);
    if (c.deciding.empty() && row.theory && row.simulation)
      c.deciding = fmt::format("{}: predicted {:.4g}, measured {:.4g} ± {:.2g}", b.quantity,
                               b.predicted, b.measured, b.measured_error);
  }
  if (linear > 0) {
    const double p = chi_square_p_value(chi2, linear);
    c.deciding +=
        fmt::format("; linear regime as a whole: χ² = {:.2f} over {} rows, p = {:.3g} ({})", chi2,
                    linear, p, p >= k_global_p_threshold ? "agrees" : "differs");
  }
  return c;
}

}  // namespace

Claim finding_breakdown_prediction(const ReproduceResults& R) {
  return linear_hydrodynamics_claim(
      R.breakdown,
      "linear hydrodynamics predicts the break-down of the homogeneous cooling state "
      "(ε = 0.93, n = 0.05) with no free parameter");
}

Claim finding_breakdown_prediction_3d(const ReproduceResults& R) {
  const auto spec = BreakdownSpec::three_dimensional();
  return linear_hydrodynamics_claim(
      R.breakdown_3d,
      fmt::format("in d = 3 too, linear hydrodynamics predicts the growth of the largest shear "
                  "mode above L_c and its level below, with no free parameter (ε = {}, n = {}, "
                  "N = {} and {})",
                  spec.restitution, spec.density, spec.unstable_particles, spec.stable_particles));
}

}  // namespace molchaos::validation::steps
