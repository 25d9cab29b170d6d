// The correlation study's driver: one sweep (contact runs shared with reproduce() through the
// cache, new runs with snapshots for the pair correlations), then the tables and the claims.
#include "molchaos/validation/correlation_study.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>

#include "molchaos/validation/correlation_analysis.hpp"
#include "molchaos/validation/ensemble.hpp"
#include "molchaos/validation/impact_parameter.hpp"
#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/report.hpp"
#include "molchaos/validation/run_pair_correlations.hpp"
#include "molchaos/validation/verdict.hpp"

namespace molchaos::validation {

CorrelationStudyConfig CorrelationStudyConfig::quick_look() {
  CorrelationStudyConfig c;
  c.particles = 1000;
  c.restitutions = {0.8, 0.9};
  c.contact_seeds = 4;
  c.snapshot_restitutions = {0.8};
  c.snapshot_seeds = 2;
  c.restitutions_3d = {0.8};
  c.seeds_3d = 4;
  c.dsmc_seeds = 16;
  return c;
}

namespace {

using sim::Randomization;

EnsembleSpec study_spec(const CorrelationStudyConfig& cfg, int d, std::vector<double> densities,
                        std::vector<double> restitutions, int seeds) {
  EnsembleSpec s;  // the defaults of reproduce()'s Fig. 4 ensemble: same runs, same cache keys
  s.dimension = d;
  s.particles = cfg.particles;
  s.densities = std::move(densities);
  s.restitutions = std::move(restitutions);
  s.modes = {Randomization::none, Randomization::flux};
  s.seeds = seeds;
  s.base_seed = cfg.base_seed;
  s.contact_statistics = true;
  return s;
}

std::vector<sim::Parameters> with_snapshots(const CorrelationStudyConfig& cfg,
                                            const EnsembleSpec& spec) {
  auto runs = expand(spec);
  for (auto& p : runs) {
    const double tau0 = theory_tau0(p.dimension, p.density, p.restitution);
    p.contact_statistics = false;
    p.snapshot_times.clear();
    for (double f : cfg.snapshot_times_in_tau0) p.snapshot_times.push_back(f * tau0);
  }
  return runs;
}

// The outcomes of one (density, restitution) in expand() order: modes × seeds.
template <class F>
void for_each_point(const EnsembleSpec& spec, const std::vector<RunOutcome>& outcomes,
                    std::size_t offset, F f) {
  std::size_t k = offset;
  for (double n : spec.densities)
    for (double e : spec.restitutions) {
      std::vector<std::vector<const RunOutcome*>> by_mode(spec.modes.size());
      for (auto& group : by_mode)
        for (int i = 0; i < spec.seeds; ++i) group.push_back(&outcomes.at(k++));
      f(n, e, by_mode);
    }
}

void add_contact_point(CorrelationStudy& S, const CorrelationStudyConfig& cfg, int d, double n,
                       double e, const std::vector<std::vector<const RunOutcome*>>& by_mode,
                       std::vector<GasPair>& pairs) {
  GasPair gp{d, n, e, {}, {}};
  for (std::size_t m = 0; m < by_mode.size(); ++m)
    for (const auto* o : by_mode[m]) {
      if (!o->ok) continue;
      (m == 0 ? gp.original : gp.chaos).push_back(measure_contacts(o->result, cfg.window));
    }
  S.contact_moments.push_back(summarize_contacts(d, n, e, "none", gp.original));
  S.contact_moments.push_back(summarize_contacts(d, n, e, "flux", gp.chaos));
  for (const auto& [mode, runs] : {std::pair{"none", &gp.original}, std::pair{"flux", &gp.chaos}})
    for (auto& row : summarize_impact_parameter(d, n, e, mode, *runs))
      S.impact_parameter.push_back(std::move(row));
  S.decomposition.push_back(decompose_cooling(gp));
  pairs.push_back(std::move(gp));
}

void add_dsmc_point(CorrelationStudy& S, const CorrelationStudyConfig& cfg, int d, double n,
                    double e, const std::vector<std::vector<const RunOutcome*>>& by_mode) {
  std::vector<RunContacts> runs;
  for (const auto* o : by_mode.at(0))
    if (o->ok) runs.push_back(measure_contacts(o->result, cfg.window));
  S.contact_moments.push_back(summarize_contacts(d, n, e, "dsmc", runs));
  for (auto& row : summarize_impact_parameter(d, n, e, "dsmc", runs))
    S.impact_parameter.push_back(std::move(row));
}

void add_pair_point(CorrelationStudy& S, const CorrelationStudyConfig& cfg, int d, double n,
                    double e, const std::vector<std::vector<const RunOutcome*>>& by_mode) {
  for (std::size_t m = 0; m < by_mode.size(); ++m)
    for (std::size_t k = 0; k < cfg.snapshot_times_in_tau0.size(); ++k) {
      std::vector<SnapshotPairSums> sums;
      double tau = 0.0;
      for (const auto* o : by_mode[m]) {
        if (!o->ok || o->result.snapshots.size() <= k) continue;
        const auto& snap = o->result.snapshots[k];
        const FitWindow w =
            choose_window(o->result.samples, o->result.parameters.particles, cfg.window);
        if (!w.valid || snap.t < w.t_start || snap.t > w.t_stop) continue;  // not in the HCS
        sums.push_back(pair_sums(snap, d, default_pair_grid(snap.box)));
        tau += collisions_per_particle_at(o->result, snap.t);
      }
      if (sums.empty()) continue;
      tau /= static_cast<double>(sums.size());
      for (const auto& b : combine_pair_sums(sums, d))
        S.pair_correlations.push_back({d, n, e, m == 0 ? "none" : "flux", tau,
                                       static_cast<int>(sums.size()), to_string(b.side), b.r_lo,
                                       b.r_hi, b.g, b.G_par, b.G_perp, b.g_snapshot_error,
                                       b.G_par_snapshot_error, b.G_perp_snapshot_error, b.pairs});
    }
}

}  // namespace

namespace {

std::string verdict_p(double p) { return p >= k_global_p_threshold ? "holds" : "fails"; }

// Inverse-variance weighted mean of values with errors (points without an error skipped).
Measurement weighted_mean(const std::vector<Measurement>& v) {
  double sw = 0.0, swx = 0.0;
  for (const auto& m : v)
    if (m.error > 0.0) {
      sw += 1.0 / (m.error * m.error);
      swx += m.value / (m.error * m.error);
    }
  return sw > 0.0 ? Measurement{swx / sw, 1.0 / std::sqrt(sw)} : Measurement{};
}

void cooling_claims(CorrelationStudy& S) {
  GlobalTest equal;
  std::vector<Measurement> diffs;
  for (const auto& r : S.decomposition)
    if (r.difference.error > 0.0) {
      equal.add(r.difference.value / r.difference.error, r.pairs);
      diffs.push_back(r.difference);
    }
  S.claims.push_back(
      {"cooling rate = collision frequency x energy loss per collision: "
       "A_orig/A_chaos equals (omega Y)_chaos/(omega Y)_orig at every point",
       verdict_p(equal.p()), weighted_mean(diffs),
       fmt::format("weighted mean of A ratio − product; chi2 = {:.1f}, dof = {}, "
                   "p = {:.2g}",
                   equal.chi2, equal.points, equal.p())});
  std::vector<std::pair<int, double>> groups;
  for (const auto& r : S.decomposition)
    if (std::find(groups.begin(), groups.end(), std::pair{r.dimension, r.density}) == groups.end())
      groups.emplace_back(r.dimension, r.density);
  for (const auto& [d, n] : groups) {
    std::vector<Measurement> w, y;
    for (const auto& r : S.decomposition)
      if (r.dimension == d && r.density == n) {
        w.push_back(r.log_frequency);
        y.push_back(r.log_dissipation);
      }
    const Measurement mw = weighted_mean(w), my = weighted_mean(y);
    for (const auto& [what, m] : {std::pair{"collision-frequency deficit ln(omega_chaos/"
                                            "omega_orig)",
                                            mw},
                                  std::pair{"energy-loss deficit ln(Y_chaos/Y_orig)", my}})
      S.claims.push_back(
          {fmt::format("{} (d = {}, n = {}), weighted over eps", what, d, n),
           agreement(m, {0.0, 0.0}).agrees ? "not resolved" : "resolved", m,
           fmt::format("share of ln(A_orig/A_chaos): {:.2f}", m.value / (mw.value + my.value))});
  }
}

void ansatz_claims(CorrelationStudy& S) {
  double chi1 = 0.0, chi2 = 0.0;
  int points = 0;
  std::vector<Measurement> deviation;  // β⊥ + β∥/2: zero for the printed dyad
  for (const auto& f : S.ansatz) {
    chi1 += f.chi2_one;
    chi2 += f.chi2_two;
    ++points;
    const double var = f.beta_perp.error * f.beta_perp.error +
                       0.25 * f.beta_par.error * f.beta_par.error + f.beta_covariance;
    deviation.push_back(
        {f.beta_perp.value + 0.5 * f.beta_par.value, std::sqrt(std::max(var, 0.0))});
  }
  const double p1 = chi_square_p_value(chi1, 3 * points), p2 = chi_square_p_value(chi2, 2 * points);
  S.two_amplitude_chi2 = chi2;
  S.two_amplitude_dof = 2 * points;
  S.claims.push_back(
      {"one b (printed dyad 3 rr - U) fixes all four shifts at contact (P, Q, "
       "omega, energy loss)",
       verdict_p(p1), Measurement{chi1 / std::max(1, 3 * points), 0.0},
       fmt::format("chi2/dof, chi2 = {:.1f}, dof = {}, p = {:.2g}", chi1, 3 * points, p1)});
  S.claims.push_back(
      {"two amplitudes (longitudinal, transverse) fix all four shifts", verdict_p(p2),
       Measurement{chi2 / std::max(1, 2 * points), 0.0},
       fmt::format("chi2/dof, chi2 = {:.1f}, dof = {}, p = {:.2g}", chi2, 2 * points, p2)});
  const Measurement dev = weighted_mean(deviation);
  S.claims.push_back({"angular structure as printed: beta_perp = -beta_par/2",
                      agreement(dev, {0.0, 0.0}).agrees ? "holds" : "fails", dev,
                      "weighted mean of beta_perp + beta_par/2 over the points"});
  std::vector<RoutePair> b, beta;
  for (const auto& f : S.ansatz) {
    b.push_back(f.b_routes);
    beta.push_back(f.beta_par_routes);
  }
  S.b_routes = compare_routes(b, "b");
  S.claims.push_back({"b from the cooling rate equals b from the contact statistics",
                      S.b_routes.verdict, S.b_routes.ratio, S.b_routes.statement});
  S.beta_par_routes = compare_routes(beta, "beta_par");
  S.claims.push_back(
      {"two amplitudes close the gap: beta_par from the cooling rate equals "
       "beta_par from <(c1.e)(c2.e)>",
       S.beta_par_routes.verdict, S.beta_par_routes.ratio, S.beta_par_routes.statement});
}

// P, Q, ω/ω_E and Y of a row, in that order.
std::array<Measurement, 4> contact_quantities(const ContactMomentRow& r) {
  return {r.c1e_c2e, r.c1_dot_c2, r.omega_over_enskog, r.gn2_over_4T};
}

// A molecular-chaos reference's contact quantities against the Sonine form in full with its
// measured a2 (a3 = 0 as it is not measured; the theory's a3 ≈ −0.01 would move P by ≈ −2.5e-4,
// doc/validation.md): χ² of normal scores over all points.
StudyClaim chaos_values_claim(const CorrelationStudy& S, const std::string& mode) {
  GlobalTest test;
  for (const auto& r : S.contact_moments) {
    if (r.mode != mode) continue;
    const ContactQuantities mc = molecular_chaos_contact_sonine(r.a2.value, 0.0);
    const std::array<double, 4> expected{mc.P, mc.Q, mc.W, mc.Y};
    const auto measured = contact_quantities(r);
    for (std::size_t q = 0; q < 4; ++q)
      if (measured[q].error > 0.0)
        test.add((measured[q].value - expected[q]) / measured[q].error, r.runs);
  }
  return {gas_name(mode) + ": contact moments equal their molecular-chaos values",
          verdict_p(test.p()), Measurement{test.chi2_per_dof(), 0.0},
          fmt::format("chi2/dof of normal scores over P, Q, omega/omega_E, Y (treated as "
                      "independent), chi2 = {:.1f}, dof = {}, p = {:.2g}",
                      test.chi2, test.points, test.p())};
}

// The two references against each other, point by point, with no theory in between: a
// departure of the flux gas from the Sonine values that DSMC shares is the theory's, not the MD's.
StudyClaim flux_equals_dsmc_claim(const CorrelationStudy& S) {
  GlobalTest test;
  for (const auto& f : S.contact_moments) {
    if (f.mode != "flux") continue;
    for (const auto& g : S.contact_moments) {
      if (g.mode != "dsmc" || g.dimension != f.dimension || g.density != f.density ||
          g.restitution != f.restitution)
        continue;
      const auto a = contact_quantities(f), b = contact_quantities(g);
      for (std::size_t q = 0; q < 4; ++q) {
        const double se = std::hypot(a[q].error, b[q].error);
        if (se > 0.0) test.add((a[q].value - b[q].value) / se, std::min(f.runs, g.runs));
      }
    }
  }
  return {"flux-shuffled gas: contact moments equal the DSMC gas's at the same points",
          verdict_p(test.p()), Measurement{test.chi2_per_dof(), 0.0},
          fmt::format("chi2/dof of normal scores of the differences over P, Q, omega/omega_E, Y, "
                      "chi2 = {:.1f}, dof = {}, p = {:.2g}",
                      test.chi2, test.points, test.p())};
}

void control_claims(CorrelationStudy& S) {
  for (const std::string mode : {"flux", "dsmc"})
    if (std::any_of(S.contact_moments.begin(), S.contact_moments.end(),
                    [&](const auto& r) { return r.mode == mode; }))
      S.claims.push_back(chaos_values_claim(S, mode));
  S.claims.push_back(flux_equals_dsmc_claim(S));
  for (const char* mode : {"flux", "none"}) {
    double c = 0.0;
    int k = 0;
    for (const auto& r : S.pair_correlations) {
      if (r.mode != mode || r.side != "all") continue;
      for (const auto& m : {r.G_par, r.G_perp})
        if (m.error > 0.0) {
          c += std::pow(m.value / m.error, 2);
          ++k;
        }
    }
    const double pv = chi_square_p_value(c, k);
    S.claims.push_back(
        {fmt::format("{}: no velocity correlations at any r (G_par = G_perp = 0)", gas_name(mode)),
         verdict_p(pv), Measurement{k > 0 ? c / k : 0.0, 0.0},
         fmt::format("chi2/dof over all bins and times, chi2 = {:.1f}, dof = {}, "
                     "p = {:.2g}",
                     c, k, pv)});
  }
}

}  // namespace

CorrelationStudy run_correlation_study(const CorrelationStudyConfig& cfg,
                                       const SweepOptions& sweep) {
  const auto start = std::chrono::steady_clock::now();
  CorrelationStudy S;
  const EnsembleSpec c2 = study_spec(cfg, 2, cfg.densities, cfg.restitutions, cfg.contact_seeds);
  const EnsembleSpec c3 = study_spec(cfg, 3, {cfg.density_3d}, cfg.restitutions_3d, cfg.seeds_3d);
  const EnsembleSpec p2 =
      study_spec(cfg, 2, cfg.densities, cfg.snapshot_restitutions, cfg.snapshot_seeds);
  const EnsembleSpec p3 =
      study_spec(cfg, 3, {cfg.density_3d}, cfg.restitutions_3d, cfg.snapshot_seeds);
  const EnsembleSpec d2 = dsmc_twin(c2, cfg.dsmc_seeds), d3 = dsmc_twin(c3, cfg.dsmc_seeds);
  std::vector<sim::Parameters> all;
  std::vector<std::size_t> offsets;
  for (const auto& [spec, snapshots] :
       {std::pair{&c2, false}, std::pair{&c3, false}, std::pair{&p2, true}, std::pair{&p3, true},
        std::pair{&d2, false}, std::pair{&d3, false}}) {
    offsets.push_back(all.size());
    const auto runs = snapshots ? with_snapshots(cfg, *spec) : expand(*spec);
    all.insert(all.end(), runs.begin(), runs.end());
  }
  SweepOptions options = sweep;
  options.label = sweep.label + ", correlation study";
  const auto outcomes = run_sweep(all, options);
  for (const auto& o : outcomes) S.failed_runs += o.ok ? 0 : 1;

  std::vector<GasPair> pairs;
  for (int k = 0; k < 2; ++k) {
    const EnsembleSpec& spec = k == 0 ? c2 : c3;
    for_each_point(spec, outcomes, offsets[k], [&](double n, double e, const auto& by_mode) {
      add_contact_point(S, cfg, spec.dimension, n, e, by_mode, pairs);
    });
  }
  for (int k = 2; k < 4; ++k) {
    const EnsembleSpec& spec = k == 2 ? p2 : p3;
    for_each_point(spec, outcomes, offsets[k], [&](double n, double e, const auto& by_mode) {
      add_pair_point(S, cfg, spec.dimension, n, e, by_mode);
    });
  }
  for (int k = 4; k < 6; ++k) {
    const EnsembleSpec& spec = k == 4 ? d2 : d3;
    for_each_point(spec, outcomes, offsets[k], [&](double n, double e, const auto& by_mode) {
      add_dsmc_point(S, cfg, spec.dimension, n, e, by_mode);
    });
  }
  S.ansatz = fit_ansatz(pairs);
  cooling_claims(S);
  ansatz_claims(S);
  control_claims(S);
  for (auto& c : impact_parameter_claims(S.impact_parameter)) S.claims.push_back(std::move(c));
  S.config = cfg;
  S.version = sweep.version;
  S.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return S;
}

namespace {

// The '#' lines that open each table of the study: what ran and the code version, as every result
// file of the suite carries them, so that a table can be traced to its build.
std::string table_header(const CorrelationStudy& S) {
  const auto& c = S.config;
  return fmt::format(
      "# molchaos reproduce, correlation study: particles = {}, seeds = {} (d = 2), {} (d = 3), "
      "base_seed = {}; window: the Haff fit's\n# version = {}\n",
      c.particles, c.contact_seeds, c.seeds_3d, c.base_seed, S.version);
}

}  // namespace

std::string contact_moments_csv(const CorrelationStudy& S) {
  std::string out =
      table_header(S) +
      "dimension,density,restitution,randomize,runs,omega_over_enskog,omega_over_enskog_err,"
      "gn2_over_4T,gn2_over_4T_err,c1e_c2e,c1e_c2e_err,c1_dot_c2,c1_dot_c2_err,a2,a2_err,A,A_err,"
      "impact_chi2,impact_dof\n";
  for (const auto& r : S.contact_moments)
    out += fmt::format(
        "{},{},{},{},{},{:.8g},{:.3g},{:.8g},{:.3g},{:.8g},{:.3g},{:.8g},{:.3g},"
        "{:.6g},{:.3g},{:.8g},{:.3g},{:.4g},{}\n",
        r.dimension, r.density, r.restitution, r.mode, r.runs, r.omega_over_enskog.value,
        r.omega_over_enskog.error, r.gn2_over_4T.value, r.gn2_over_4T.error, r.c1e_c2e.value,
        r.c1e_c2e.error, r.c1_dot_c2.value, r.c1_dot_c2.error, r.a2.value, r.a2.error, r.A.value,
        r.A.error, r.impact_chi2, r.impact_dof);
  return out;
}

std::string cooling_decomposition_csv(const CorrelationStudy& S) {
  std::string out =
      table_header(S) +
      "# paired by seed, original gas against flux-shuffled gas: A_ratio = A_orig/A_chaos, "
      "product_ratio = (W Y)_chaos/(W Y)_orig with W = omega/omega_E and Y the energy lost per "
      "collision, difference = A_ratio - product_ratio (the report's chi2 sums the normal scores "
      "of difference/difference_err, Student's t with pairs - 1 dof), log_frequency = "
      "ln(W_chaos/W_orig), log_dissipation = ln(Y_chaos/Y_orig)\n"
      "dimension,density,restitution,pairs,A_ratio,A_ratio_err,product_ratio,product_ratio_err,"
      "difference,difference_err,log_frequency,log_frequency_err,log_dissipation,"
      "log_dissipation_err\n";
  for (const auto& r : S.decomposition)
    out += fmt::format(
        "{},{},{},{},{:.10g},{:.3g},{:.10g},{:.3g},{:.4g},{:.3g},{:.6g},{:.3g},{:.6g},{:.3g}\n",
        r.dimension, r.density, r.restitution, r.pairs, r.A_ratio.value, r.A_ratio.error,
        r.product_ratio.value, r.product_ratio.error, r.difference.value, r.difference.error,
        r.log_frequency.value, r.log_frequency.error, r.log_dissipation.value,
        r.log_dissipation.error);
  return out;
}

std::string ansatz_fits_csv(const CorrelationStudy& S) {
  std::string out =
      table_header(S) +
      "# shifts: original gas - flux-shuffled gas at contact (a2 difference removed), paired by "
      "seed; the fits weight them with their standard errors and the correlation matrix of the "
      "four pooled over the points of one dimension and density\n"
      "# routes: b (printed dyad) and beta_par (two amplitudes) from the cooling rate and from the "
      "contact statistics; diff = cooling - contact over the paired runs, cov = covariance of "
      "the two means. The report's chi2 of equality sums the normal scores of diff/diff_err "
      "(Student's t with pairs - 1 dof); its ratio fits cooling = r contact with weights "
      "1/(cooling_err^2 + r^2 contact_err^2 - 2 r cov), iterated, its error inflated by "
      "sqrt(chi2/(points - 1)) of that fit where above 1\n"
      "dimension,density,restitution,pairs,shift_P,shift_P_err,shift_Q,shift_Q_err,shift_W,"
      "shift_W_err,shift_Y,shift_Y_err,b,b_err,chi2_one,beta_par,beta_par_err,beta_perp,"
      "beta_perp_err,beta_cov,chi2_two,b_cooling,b_cooling_err,b_contact,b_contact_err,b_diff,"
      "b_diff_err,b_cov,beta_par_cooling,beta_par_cooling_err,beta_par_contact,"
      "beta_par_contact_err,beta_par_diff,beta_par_diff_err,beta_par_cov\n";
  const auto route = [](const RoutePair& r) {
    return fmt::format("{:.6g},{:.3g},{:.6g},{:.3g},{:.6g},{:.3g},{:.4g}", r.cooling.value,
                       r.cooling.error, r.contact.value, r.contact.error, r.difference.value,
                       r.difference.error, r.covariance);
  };
  for (const auto& r : S.ansatz)
    out += fmt::format(
        "{},{},{},{},{:.6g},{:.3g},{:.6g},{:.3g},{:.6g},{:.3g},{:.6g},{:.3g},{:.6g},{:.3g},{:.5g},"
        "{:.6g},{:.3g},{:.6g},{:.3g},{:.4g},{:.5g},{},{}\n",
        r.dimension, r.density, r.restitution, r.pairs, r.shift_P.value, r.shift_P.error,
        r.shift_Q.value, r.shift_Q.error, r.shift_W.value, r.shift_W.error, r.shift_Y.value,
        r.shift_Y.error, r.b.value, r.b.error, r.chi2_one, r.beta_par.value, r.beta_par.error,
        r.beta_perp.value, r.beta_perp.error, r.beta_covariance, r.chi2_two, route(r.b_routes),
        route(r.beta_par_routes));
  return out;
}

std::string pair_correlations_csv(const CorrelationStudy& S) {
  std::string out =
      table_header(S) +
      "dimension,density,restitution,randomize,tau,snapshots,side,r_lo,r_hi,g,g_err,G_par,"
      "G_par_err,G_perp,G_perp_err,g_err_snapshots,G_par_err_snapshots,G_perp_err_snapshots,"
      "pairs\n";
  for (const auto& r : S.pair_correlations)
    out += fmt::format(
        "{},{},{},{},{:.4g},{},{},{:.6g},{:.6g},{:.6g},{:.3g},{:.5g},{:.3g},{:.5g},"
        "{:.3g},{:.3g},{:.3g},{:.3g},{}\n",
        r.dimension, r.density, r.restitution, r.mode, r.tau, r.snapshots, r.side, r.r_lo, r.r_hi,
        r.g.value, r.g.error, r.G_par.value, r.G_par.error, r.G_perp.value, r.G_perp.error,
        r.g_snapshot_error, r.G_par_snapshot_error, r.G_perp_snapshot_error, r.pairs);
  return out;
}

void write_correlation_tables(const CorrelationStudy& S, const std::string& directory,
                              const std::string& rerun_lines) {
  const auto write = [&](const std::string& name, const std::string& csv) {
    write_file_atomically(directory + "/" + name, after_title(csv, rerun_lines));
  };
  write("contact_moments.csv", contact_moments_csv(S));
  write("ansatz_fits.csv", ansatz_fits_csv(S));
  write("cooling_decomposition.csv", cooling_decomposition_csv(S));
  write("pair_correlations.csv", pair_correlations_csv(S));
  write("impact_parameter.csv",
        impact_parameter_csv(S.impact_parameter,
                             table_header(S) +
                                 "# impact parameter s = (1 - (g.e/|g|)^2)^((d-1)/2) of the "
                                 "colliding pairs, uniform under molecular chaos\n"));
}

}  // namespace molchaos::validation
