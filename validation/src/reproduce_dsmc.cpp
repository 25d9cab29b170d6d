// The claims that set the MD gases beside DSMC, whose gas obeys molecular chaos by construction:
// the flux-shuffled gas should cool as the DSMC gas does (same A at every Fig. 4 point), the
// paper's shuffle (biased) and the original gas (velocity correlations) need not; and DSMC's a2
// against the Sonine theory's. Each claim is one global χ² over all points; the per-point rows are
// information.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "molchaos/theory/sonine_hcs.hpp"
#include "molchaos/validation/verdict.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation::steps {
namespace {

struct DsmcComparison {
  std::vector<ComparisonRow> rows;
  GlobalTest test;
  double largest_percent = 0.0;  ///< largest |A_MD/A_DSMC − 1| in per cent
};

// A of the MD gas `mode` against DSMC at every Fig. 4 point where both have runs.
DsmcComparison compare_with_dsmc(const ReproduceResults& R, const std::string& mode) {
  DsmcComparison c;
  for (double n : R.config.densities)
    for (double e : R.config.restitutions) {
      const PointResult& md = find_point(R, n, e, mode);
      const PointResult& dsmc = find_dsmc_point(R, n, e);
      if (md.summary.runs == 0 || dsmc.summary.runs == 0) continue;
      const Agreement a = agreement(md.summary.A, dsmc.summary.A);
      ComparisonRow row{fmt::format("A, n = {}, eps = {:.2f}: MD ({}) vs DSMC", n, e, mode),
                        dsmc.summary.A,
                        md.summary.A,
                        std::nullopt,
                        a.difference_in_se,
                        "see the global test",
                        k_information_rule,
                        "'theory' column: DSMC; 'simulation': MD"};
      c.rows.push_back(std::move(row));
      // The MD's error comes from a few runs (Student's t).
      if (a.difference_in_se) c.test.add(*a.difference_in_se, md.summary.runs);
      c.largest_percent = std::max(
          c.largest_percent, 100.0 * std::abs(md.summary.A.value / dsmc.summary.A.value - 1.0));
    }
  return c;
}

Claim dsmc_claim(const ReproduceResults& R, const std::string& mode, std::string statement) {
  DsmcComparison d = compare_with_dsmc(R, mode);
  Claim c{ClaimSource::suite, std::move(statement), "beyond the paper", "", std::move(d.rows)};
  if (d.test.points == 0) {
    c.deciding = "no points with both MD and DSMC runs";
    return c;
  }
  c.deciding = fmt::format(
      "{}: χ² of A_MD = A_DSMC = {:.1f} for {} points (p = {:.2g}); largest difference {:.2f} %",
      d.test.holds() ? "equal within errors" : "different", d.test.chi2, d.test.points, d.test.p(),
      d.largest_percent);
  return c;
}

// One point of the χ² of the DSMC gas's a2 against one level of the Sonine theory over all
// Fig. 4 points; the rows go to `rows`.
void add_a2_row(const PointResult& dsmc, const theory::SonineSolution& level,
                const std::string& name, GlobalTest& test, std::vector<ComparisonRow>& rows) {
  const Agreement a = agreement(dsmc.summary.a2, level.a2);
  rows.push_back({fmt::format("a2, n = {}, eps = {:.2f}: DSMC vs {}", dsmc.summary.density,
                              dsmc.summary.restitution, name),
                  level.a2, dsmc.summary.a2, std::nullopt, a.difference_in_se,
                  "see the global test", k_information_rule, "'theory' column: " + name});
  if (a.difference_in_se) test.add(*a.difference_in_se, dsmc.summary.runs);
}

std::string a2_verdict(const char* name, const GlobalTest& t) {
  return fmt::format("{}: χ² = {:.1f} for {} points (p = {:.2g}, {})", name, t.chi2, t.points,
                     t.p(), t.holds() ? "agrees" : "differs");
}

}  // namespace

// The paper quotes van Noije and Ernst's first-Sonine a2(ε) (Eq. (25)); DSMC solves the same
// kinetic equation without the Sonine truncation, so it tests that a2 and the improved one
// (a2 with its square and a3, theory/sonine_hcs.hpp) at every Fig. 4 point.
Claim finding_dsmc_a2_against_sonine(const ReproduceResults& R) {
  Claim c{ClaimSource::suite,
          "the first-Sonine a2(ε) the paper quotes (Eq. (25)) and the improved a2 (with a2² "
          "and a3) against DSMC",
          "beyond the paper",
          "",
          {}};
  GlobalTest first, improved;
  const int d = R.dsmc_spec.dimension;
  for (const PointResult& p : R.dsmc_points) {
    if (p.summary.runs < 2) continue;
    const theory::HcsSonine levels = theory::hcs_sonine_coefficients(d, p.summary.restitution);
    add_a2_row(p, levels.first_sonine, "first Sonine", first, c.rows);
    add_a2_row(p, levels.a2_a3, "a2 and a3", improved, c.rows);
  }
  if (first.points == 0) {
    c.deciding = "no DSMC points";
    return c;
  }
  c.deciding = a2_verdict("first Sonine", first) + "; " + a2_verdict("with a2² and a3", improved);
  return c;
}

Claim finding_flux_equals_dsmc(const ReproduceResults& R) {
  return dsmc_claim(R, "flux",
                    "the flux-shuffled MD gas cools as the DSMC gas (molecular chaos by "
                    "construction) at every Fig. 4 point");
}

Claim finding_paper_shuffle_against_dsmc(const ReproduceResults& R) {
  return dsmc_claim(R, "paper",
                    "the paper's shuffle against DSMC: does the paper's randomized gas cool as a "
                    "molecular-chaos gas?");
}

}  // namespace molchaos::validation::steps
