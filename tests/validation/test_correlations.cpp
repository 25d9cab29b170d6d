// The correlation study's measurements on data with known answers: pair correlation functions of
// independent Maxwell velocities vanish at every r, the cell list finds the same pairs as all
// pairs, the contact accumulator reproduces the molecular-chaos collision averages and a flat
// impact-parameter histogram, and the ansatz's closed-form slopes agree with the theory library's
// quadrature.
#define BOOST_TEST_MODULE validation_correlations
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "molchaos/sim/contact_statistics.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/validation/analysis.hpp"
#include "molchaos/validation/contact_ansatz.hpp"
#include "molchaos/validation/contact_measurement.hpp"
#include "molchaos/validation/correlation_analysis.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/impact_parameter.hpp"
#include "molchaos/validation/pair_correlations.hpp"

using namespace molchaos;
using namespace molchaos::validation;

namespace {

// N particles at uniform random positions (overlaps allowed: an ideal gas, g = 1) with
// independent Maxwell velocities at temperature T.
sim::Snapshot ideal_gas(int d, int n, double box, double T, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, box);
  std::normal_distribution<double> gauss(0.0, std::sqrt(T));
  sim::Snapshot s;
  s.box = box;
  for (int i = 0; i < n * d; ++i) {
    s.positions.push_back(u(rng));
    s.velocities.push_back(gauss(rng));
  }
  return s;
}

// Upper bound of the acceptable χ²: p = 1e-3 (a false alarm once in a thousand runs).
bool chi_square_acceptable(const ChiSquare& c) { return c.p_value > 1e-3; }

}  // namespace

BOOST_AUTO_TEST_CASE(independent_velocities_have_no_pair_correlations) {
  for (int d : {2, 3}) {
    std::mt19937_64 rng(11 + d);
    const double box = d == 2 ? 100.0 : 24.0;
    std::vector<SnapshotPairSums> sums;
    for (int k = 0; k < 6; ++k) {
      const auto snap = ideal_gas(d, 2000, box, 0.37, rng);
      sums.push_back(pair_sums(snap, d, pair_grid(0.5 * box, 10, 0.05, 12)));
    }
    const auto bins = combine_pair_sums(sums, d);
    const ChiSquare c = chi_square_zero_velocity_correlations(bins);
    BOOST_TEST_MESSAGE("d = " << d << ": chi2 = " << c.chi2 << ", dof = " << c.dof
                              << ", p = " << c.p_value);
    BOOST_TEST(c.dof == 2 * 22);
    BOOST_TEST(chi_square_acceptable(c));
    // g = 1 for an ideal gas: the same global test on the Poisson errors.
    double chi2_g = 0.0;
    int dof_g = 0;
    for (const auto& b : bins)
      if (b.side == PairSide::all && b.g.error > 0) {
        chi2_g += std::pow((b.g.value - 1.0) / b.g.error, 2);
        ++dof_g;
      }
    BOOST_TEST(chi_square_p_value(chi2_g, dof_g) > 1e-3);
    // Approaching and receding pairs add up to all of them.
    for (std::size_t k = 0; k + 2 < bins.size(); k += 3)
      BOOST_TEST(bins[k].pairs == bins[k + 1].pairs + bins[k + 2].pairs);
  }
}

// The error of g is the scatter of g itself: over many ideal-gas snapshots, the variance of each
// bin's g over its error squared, summed over the bins as (K − 1) s²/σ², is χ² with Σ (K − 1)
// degrees of freedom. Both tails are tested: √pairs, which ignores that a count is drawn from a
// finite number of pairs, gives errors a third too large in the outermost bin here (its shell
// holds 0.44 of the box) and fails the lower tail.
BOOST_AUTO_TEST_CASE(error_of_g_matches_its_scatter_over_snapshots) {
  const int d = 2, snapshots = 1000;
  const double box = 40.0;
  const std::vector<double> edges = pair_grid(0.5 * box, 2, 0.5, 6);
  std::mt19937_64 rng(17);
  const std::size_t bins = edges.size() - 1;
  std::vector<double> sum(bins, 0.0), sum2(bins, 0.0), variance(bins, 0.0);
  for (int k = 0; k < snapshots; ++k) {
    const auto one = combine_pair_sums({pair_sums(ideal_gas(d, 400, box, 1.0, rng), d, edges)}, d);
    for (std::size_t b = 0; b < bins; ++b) {
      const auto& all = one[3 * b];  // sides in k_pair_sides order: all first
      sum[b] += all.g.value;
      sum2[b] += all.g.value * all.g.value;
      variance[b] += all.g.error * all.g.error / snapshots;
    }
  }
  double chi2 = 0.0;
  int dof = 0;
  for (std::size_t b = 0; b < bins; ++b) {
    const double mean = sum[b] / snapshots;
    const double s2 = (sum2[b] - snapshots * mean * mean) / (snapshots - 1);
    BOOST_TEST_MESSAGE("bin [" << edges[b] << ", " << edges[b + 1]
                               << "): scatter / error = " << std::sqrt(s2 / variance[b]));
    chi2 += (snapshots - 1) * s2 / variance[b];
    dof += snapshots - 1;
  }
  const double p = chi_square_p_value(chi2, dof);
  BOOST_TEST_MESSAGE("chi2 = " << chi2 << ", dof = " << dof << ", p = " << p);
  BOOST_TEST(p > 1e-3);
  BOOST_TEST(p < 1.0 - 1e-3);
}

BOOST_AUTO_TEST_CASE(real_snapshot_with_shuffled_velocities_has_no_pair_correlations) {
  // Positions of an elastic hard-disk gas (g ≠ 1 near contact), velocities permuted at random.
  sim::Parameters p;
  p.particles = 2000;
  p.density = 0.1;
  p.t_end = 5.0;
  p.snapshot_times = {1.0, 3.0, 5.0};
  const auto run = sim::run(p);
  std::mt19937_64 rng(5);
  std::vector<SnapshotPairSums> sums;
  for (auto snap : run.snapshots) {
    std::vector<std::size_t> order(static_cast<std::size_t>(p.particles));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    const auto v = snap.velocities;
    for (std::size_t i = 0; i < order.size(); ++i)
      for (int a = 0; a < 2; ++a) snap.velocities[2 * i + a] = v[2 * order[i] + a];
    sums.push_back(pair_sums(snap, 2, pair_grid(0.5 * snap.box, 10, 0.05, 12)));
  }
  const ChiSquare c = chi_square_zero_velocity_correlations(combine_pair_sums(sums, 2));
  BOOST_TEST_MESSAGE("shuffled hard-disk snapshots: chi2 = " << c.chi2 << ", dof = " << c.dof);
  BOOST_TEST(chi_square_acceptable(c));
  // No overlaps: nothing below contact is binned, and g near contact exceeds 1 (Enskog's g2).
  const auto bins = combine_pair_sums(sums, 2);
  BOOST_TEST(bins.front().g.value > 1.0);
}

// The default grid ends at half the box exactly, for every box a run can have: its last edge
// computed as a power rounded above it for a quarter of them (2D, n = 0.05, N = 39, 41, 47, 3000),
// and pair_sums() refused the grid after the whole run.
BOOST_AUTO_TEST_CASE(default_grid_ends_at_half_the_box) {
  int beyond = 0;
  for (int d : {2, 3})
    for (std::int64_t n = 20; n <= 20000; n += 7) {
      sim::Parameters p;
      p.dimension = d;
      p.particles = n;
      const double box = sim::box_side(p);
      const std::vector<double> edges = default_pair_grid(box);
      beyond += edges.back() != 0.5 * box || !std::is_sorted(edges.begin(), edges.end());
    }
  BOOST_TEST(beyond == 0);
}

BOOST_AUTO_TEST_CASE(cell_list_finds_the_same_pairs_as_all_pairs) {
  std::mt19937_64 rng(3);
  for (int d : {2, 3}) {
    const double box = d == 2 ? 60.0 : 20.0;
    const auto snap = ideal_gas(d, 1500, box, 1.0, rng);
    const std::vector<double> near{1.0, 1.5, 2.0, 3.0};  // box/3 ≥ 3: cell list
    std::vector<double> all = near;
    all.push_back(0.5 * box);  // cells of half the box: all pairs
    const auto a = pair_sums(snap, d, near), b = pair_sums(snap, d, all);
    for (std::size_t k = 0; k + 1 < near.size(); ++k)
      for (int s = 0; s < 3; ++s) {
        BOOST_TEST(a.bins[k].pairs[s] == b.bins[k].pairs[s]);
        BOOST_TEST(a.bins[k].sum_par[s] == b.bins[k].sum_par[s],
                   boost::test_tools::tolerance(1e-12));
      }
  }
}

BOOST_AUTO_TEST_CASE(contact_accumulator_reproduces_molecular_chaos) {
  // Maxwell pairs with a uniformly random contact normal, accepted with probability ∝ the
  // collision flux |g·e| (bounded by 10√(2T): the tail beyond is e^{−50}): colliding pairs
  // under molecular chaos, where P = Q = −1/4, Y = 1 and the impact parameter is uniform.
  for (int d : {2, 3}) {
    std::mt19937_64 rng(17 + d);
    const double T = 2.5;
    std::normal_distribution<double> gauss(0.0, std::sqrt(T));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    sim::ContactMoments m;
    std::vector<double> P, Q, Y;
    const double bound = 10.0 * std::sqrt(2.0 * T);
    while (m.count < 200000) {
      double vi[3], vj[3], e[3], norm = 0.0, gn = 0.0;
      for (int a = 0; a < d; ++a) {
        vi[a] = gauss(rng);
        vj[a] = gauss(rng);
        e[a] = gauss(rng);
        norm += e[a] * e[a];
      }
      for (int a = 0; a < d; ++a) {
        e[a] /= std::sqrt(norm);
        gn += (vi[a] - vj[a]) * e[a];
      }
      if (!(gn < 0) || unit(rng) * bound > -gn) continue;
      const sim::ContactMoments before = m;
      if (d == 2)
        sim::accumulate<2>(m, vi, vj, e, T);
      else
        sim::accumulate<3>(m, vi, vj, e, T);
      P.push_back(m.sum_c1e_c2e - before.sum_c1e_c2e);
      Q.push_back(m.sum_c1_dot_c2 - before.sum_c1_dot_c2);
      Y.push_back(0.5 * (m.sum_gn2 - before.sum_gn2));
    }
    const ContactQuantities mc = molecular_chaos_contact(0.0);
    double chi2 = 0.0;
    for (const auto& [values, expected] :
         {std::pair{P, mc.P}, std::pair{Q, mc.Q}, std::pair{Y, mc.Y}}) {
      const Measurement x = mean_and_standard_error(values);
      BOOST_TEST_MESSAGE("d = " << d << ": " << x.value << " +- " << x.error << " (expected "
                                << expected << ")");
      chi2 += std::pow((x.value - expected) / x.error, 2);
    }
    BOOST_TEST(chi_square_p_value(chi2, 3) > 1e-3);
    const std::vector<std::uint64_t> h(m.impact_histogram.begin(), m.impact_histogram.end());
    const FlatnessTest flat = impact_flatness(h);
    BOOST_TEST_MESSAGE("impact parameter: chi2 = " << flat.chi2 << ", dof = " << flat.dof);
    BOOST_TEST(flat.count == m.count);
    BOOST_TEST(flat.p_value > 1e-3);
  }
}

BOOST_AUTO_TEST_CASE(impact_histogram_detects_head_on_collisions) {
  // All collisions head-on: every count in the first bin, flatness rejected.
  sim::ContactMoments m;
  const double vi[2] = {-1.0, 0.0}, vj[2] = {1.0, 0.0}, e[2] = {1.0, 0.0};
  for (int k = 0; k < 100; ++k) sim::accumulate<2>(m, vi, vj, e, 1.0);
  BOOST_TEST(m.impact_histogram[0] == 100u);
  const std::vector<std::uint64_t> h(m.impact_histogram.begin(), m.impact_histogram.end());
  BOOST_TEST(impact_flatness(h).p_value < 1e-10);
}

BOOST_AUTO_TEST_CASE(closed_form_slopes_agree_with_quadrature) {
  // ⟨D⟩_coll(b) = (J_D + b J_DD)/(J_1 + b J_D) (theory library, quadrature): at b = 0 it is
  // κ P − Q, its b-derivative κ ∂P/∂b − ∂Q/∂b, and W's b-derivative is ⟨D⟩ itself.
  theory::QuadratureOptions q;
  q.relative_tolerance = 1e-10;
  for (int d : {2, 3})
    for (double kappa : {3.0, static_cast<double>(d)}) {
      const auto J = theory::contact_integrals(d, 0.0, kappa, q);
      const double mean = J.dyad.value / J.one.value;
      const double slope = J.dyad_squared.value / J.one.value - mean * mean;
      const ContactQuantities mc = molecular_chaos_contact(0.0), s = slopes_dyad(d, kappa);
      BOOST_TEST(mean == kappa * mc.P - mc.Q, boost::test_tools::tolerance(1e-8));
      BOOST_TEST(slope == kappa * s.P - s.Q, boost::test_tools::tolerance(1e-8));
      BOOST_TEST(s.W == mean, boost::test_tools::tolerance(1e-8));
      // d ln(W·Y)/db is the b coefficient of μ2 (−3/2 printed, −3/4 traceless in 2D).
      const auto mu = theory::expand_collision_moment(d, 2, 0.5, kappa, q);
      BOOST_TEST(s.W + s.Y == mu.term("b").coefficient.value, boost::test_tools::tolerance(1e-8));
      // First order in a2: ⟨D⟩ at small a2 against the closed form, O(a2²) apart.
      const double a2 = 1e-3;
      const auto Ja = theory::contact_integrals(d, a2, kappa, q);
      const ContactQuantities mca = molecular_chaos_contact(a2);
      BOOST_TEST(std::abs(Ja.dyad.value / Ja.one.value - (kappa * mca.P - mca.Q)) < 10 * a2 * a2);
    }
}

BOOST_AUTO_TEST_CASE(molecular_chaos_with_sonine_terms_agrees_with_quadrature) {
  // The closed forms in full (no linearisation in a2, a3) against the theory library's
  // quadrature of the same integrals: ⟨D⟩ = (κ − 1)P (P = Q under molecular chaos) and the
  // normalisation W at a2 ≠ 0; W·Y = μ2(a2, a3)/μ2(0, 0) (energy loss ∝ (g·e)², rate ∝ |g·e|).
  theory::QuadratureOptions q;
  q.relative_tolerance = 1e-10;
  const double a2 = 0.2, a3 = 0.1;  // large, so that the second-order terms matter at 1e-3
  for (int d : {2, 3}) {
    const auto J = theory::contact_integrals(d, a2, 3.0, q);
    const auto J0 = theory::contact_integrals(d, 0.0, 3.0, q);
    const ContactQuantities exact = molecular_chaos_contact_sonine(a2, 0.0);
    BOOST_TEST(J.dyad.value / J.one.value == 2.0 * exact.P, boost::test_tools::tolerance(1e-8));
    BOOST_TEST(J.one.value / J0.one.value == exact.W, boost::test_tools::tolerance(1e-8));
    const double mu2 =
        theory::collision_moment(d, 2, 0.5, theory::PairShape{a2, a3, 0.0}, 3.0, q).value /
        theory::collision_moment(d, 2, 0.5, theory::PairShape{}, 3.0, q).value;
    const ContactQuantities full = molecular_chaos_contact_sonine(a2, a3);
    BOOST_TEST(full.W * full.Y == mu2, boost::test_tools::tolerance(1e-8));
    // The first-order forms are the linearisation: O(a2²) apart, and visibly so here.
    const ContactQuantities linear = molecular_chaos_contact(a2);
    BOOST_TEST(std::abs(exact.P - linear.P) > 1e-4);
    BOOST_TEST(std::abs(exact.P - linear.P) < a2 * a2);
  }
}

BOOST_AUTO_TEST_CASE(impact_parameter_rows_and_claims) {
  // Multinomial histograms (independent draws) of a flat and of a grazing-poor distribution: the
  // fractions' mean ± SE over runs, the pooled flatness test and the grazing claim see the
  // difference; the run scatter matches the multinomial variance.
  std::mt19937_64 rng(5);
  const int bins = sim::ContactMoments::k_impact_bins, per_run = 20000, runs = 12;
  auto make_runs = [&](double grazing_weight) {
    std::vector<double> w(bins, 1.0);
    w.back() = grazing_weight;
    std::discrete_distribution<int> draw(w.begin(), w.end());
    std::vector<RunContacts> out(runs);
    for (int r = 0; r < runs; ++r) {
      out[r].ok = true;
      out[r].impact_histogram.assign(bins, 0);
      for (int k = 0; k < per_run; ++k) ++out[r].impact_histogram[draw(rng)];
    }
    return out;
  };
  auto rows = summarize_impact_parameter(2, 0.1, 0.8, "flux", make_runs(1.0));
  const auto poor = summarize_impact_parameter(2, 0.1, 0.8, "none", make_runs(0.8));
  BOOST_TEST(rows.size() == std::size_t(bins));
  double total = 0.0, scatter = 0.0;
  for (const auto& r : rows) {
    total += r.fraction.value;
    scatter += r.scatter_over_multinomial / bins;
    BOOST_TEST(r.runs == runs);
  }
  BOOST_TEST(total == 1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(rows.back().s_hi == 1.0);
  BOOST_TEST(scatter > 0.5);  // a mean of 10 variance ratios with 11 dof each: 1 ± 0.15
  BOOST_TEST(scatter < 1.6);
  rows.insert(rows.end(), poor.begin(), poor.end());
  const auto claims = impact_parameter_claims(rows);
  BOOST_TEST_REQUIRE(claims.size() == 4u);   // per gas: flatness, grazing
  BOOST_TEST(claims[0].verdict == "fails");  // the grazing-poor gas ("none" first)
  BOOST_TEST(claims[1].verdict == "resolved");
  BOOST_TEST(claims[1].deciding.value < 0.0);
  // Weight 0.8 of 9.8: fraction 0.8/9.8 in the last bin, departure 10·0.8/9.8 − 1 = −1.8/9.8.
  BOOST_TEST(std::abs(claims[1].deciding.value + 1.8 / 9.8) < 4 * claims[1].deciding.error);
  BOOST_TEST(claims[2].verdict == "holds");
  BOOST_TEST(claims[3].verdict == "not resolved");
}

BOOST_AUTO_TEST_CASE(dsmc_gas_has_the_molecular_chaos_contact_moments) {
  // DSMC draws every collision pair from the one-particle distribution: molecular chaos by
  // construction, with the a2 < 0 of the cooling state at ε = 0.8. Its four contact quantities
  // must equal the Sonine form with its own measured a2 (the study's exact reference), and its
  // impact parameter must be flat.
  EnsembleSpec spec;
  spec.particles = 5000;
  spec.densities = {0.1};
  spec.restitutions = {0.8};
  spec.methods = {sim::Method::dsmc};
  spec.modes = {sim::Randomization::none};
  spec.seeds = 64;
  spec.contact_statistics = true;
  std::vector<RunContacts> runs;
  std::vector<std::uint64_t> histogram(sim::ContactMoments::k_impact_bins, 0);
  for (const auto& p : expand(spec)) {
    runs.push_back(measure_contacts(sim::run(p), WindowRule{}));
    BOOST_REQUIRE(runs.back().ok);
    for (std::size_t b = 0; b < histogram.size(); ++b)
      histogram[b] += runs.back().impact_histogram[b];
  }
  const ContactMomentRow row = summarize_contacts(2, 0.1, 0.8, "dsmc", runs);
  const ContactQuantities mc = molecular_chaos_contact_sonine(row.a2.value, 0.0);
  double chi2 = 0.0;
  for (const auto& [m, expected] :
       {std::pair{row.c1e_c2e, mc.P}, std::pair{row.c1_dot_c2, mc.Q},
        std::pair{row.omega_over_enskog, mc.W}, std::pair{row.gn2_over_4T, mc.Y}}) {
    BOOST_TEST_MESSAGE(m.value << " +- " << m.error << " (molecular chaos " << expected << ")");
    chi2 += std::pow(normal_score((m.value - expected) / m.error, row.runs - 1), 2);
  }
  BOOST_TEST_MESSAGE("a2 = " << row.a2.value << " +- " << row.a2.error << ", chi2 = " << chi2);
  BOOST_TEST(chi_square_p_value(chi2, 4) > 1e-3);
  BOOST_TEST(row.a2.value < -3.0 * row.a2.error);  // the cooling state, not a Maxwell gas
  BOOST_TEST(impact_flatness(histogram).p_value > 1e-3);
}
