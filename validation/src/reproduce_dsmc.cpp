// The claims that set the MD gases beside DSMC, whose gas obeys molecular chaos by construction:
// the flux-shuffled gas should cool as the DSMC gas does (same A at every Fig. 4 point), the
// paper's shuffle (biased) and the original gas (velocity correlations) need not. Each claim is
// one global χ² over all points; the per-point rows are information.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/verdict.hpp"
#include "reproduce_steps.hpp"

namespace molchaos::validation::steps {
namespace {

struct DsmcComparison {
  std::vector<ComparisonRow> rows;
  double chi2 = 0.0;
  int points = 0;
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
      if (a.difference_in_se) {
        // The MD's error comes from a few runs (Student's t); mapped to a normal score first.
        const double z = normal_score(*a.difference_in_se, md.summary.runs - 1);
        c.chi2 += z * z;
        ++c.points;
      }
      c.largest_percent = std::max(
          c.largest_percent, 100.0 * std::abs(md.summary.A.value / dsmc.summary.A.value - 1.0));
    }
  return c;
}

Claim dsmc_claim(const ReproduceResults& R, const std::string& mode, std::string statement) {
  DsmcComparison d = compare_with_dsmc(R, mode);
  Claim c{ClaimSource::suite, std::move(statement), "beyond the paper", "", std::move(d.rows)};
  if (d.points == 0) {
    c.deciding = "no points with both MD and DSMC runs";
    return c;
  }
  const double p = chi_square_p_value(d.chi2, d.points);
  c.deciding = fmt::format(
      "{}: χ² of A_MD = A_DSMC = {:.1f} for {} points (p = {:.2g}); largest difference {:.2f} %",
      p >= k_global_p_threshold ? "equal within errors" : "different", d.chi2, d.points, p,
      d.largest_percent);
  return c;
}

}  // namespace

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
