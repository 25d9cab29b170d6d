// The reproduction's studies beyond the paper's figures, each with runs of its own: the
// two-particle distribution at contact and in r (correlation_study.hpp) and the break-down of the
// homogeneous cooling state against linear hydrodynamics (breakdown.hpp). Their verdicts come
// from the studies' own global tests; here they become claims of the report.
#include <fmt/format.h>

#include <cmath>

#include "molchaos/validation/verdict.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation::steps {

void run_studies(ReproduceResults& R, const SweepOptions& sweep) {
  R.correlations = run_correlation_study(
      R.config.quick ? CorrelationStudyConfig::quick_look() : CorrelationStudyConfig::paper_scale(),
      sweep);
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

Claim finding_breakdown_prediction(const ReproduceResults& R) {
  Claim c{ClaimSource::suite,
          "linear hydrodynamics predicts the break-down of the homogeneous cooling state "
          "(ε = 0.93, n = 0.05) with no free parameter",
          R.breakdown.empty() ? "not run" : "beyond the paper",
          R.breakdown.empty() ? "the study runs at paper scale only" : "",
          {}};
  for (const auto& b : R.breakdown) {
    ComparisonRow row;
    row.quantity = b.quantity;
    if (std::isfinite(b.predicted)) row.theory = Measurement{b.predicted, 0.0};
    if (std::isfinite(b.measured)) row.simulation = Measurement{b.measured, b.measured_error};
    if (row.theory && row.simulation && b.measured_error > 0) {
      const Agreement a = agreement(*row.simulation, *row.theory);
      row.difference_in_se = a.difference_in_se;
      row.verdict = a.agrees ? "agrees" : "differs";
      row.rule = agreement_rule_text();
    }
    row.note = b.note;
    c.rows.push_back(row);
    if (c.deciding.empty() && row.theory && row.simulation)
      c.deciding = fmt::format("{}: predicted {:.4g}, measured {:.4g} ± {:.2g}", b.quantity,
                               b.predicted, b.measured, b.measured_error);
  }
  return c;
}

}  // namespace molchaos::validation::steps
