// The correlation study's analysis: paired differences between the original and the
// molecular-chaos gas, generalised least squares for the ansatz, the verdict on the b routes.
#include "molchaos/validation/correlation_analysis.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "molchaos/validation/pair_correlations.hpp"
#include "molchaos/validation/verdict.hpp"

namespace molchaos::validation {
namespace {

using Vec4 = Eigen::Vector4d;

Vec4 as_vector(const ContactQuantities& q) { return {q.P, q.Q, q.W, q.Y}; }

// Runs of both gases with the same seed, both fitted.
std::vector<std::pair<const RunContacts*, const RunContacts*>> paired(const GasPair& p) {
  std::vector<std::pair<const RunContacts*, const RunContacts*>> out;
  for (const auto& o : p.original)
    for (const auto& c : p.chaos)
      if (o.ok && c.ok && o.seed == c.seed) out.emplace_back(&o, &c);
  return out;
}

// Original − chaos at contact, with the molecular-chaos values' a2 difference removed.
Vec4 shift(const RunContacts& o, const RunContacts& c) {
  return as_vector(o.measured) - as_vector(c.measured) -
         (as_vector(molecular_chaos_contact(o.a2)) - as_vector(molecular_chaos_contact(c.a2)));
}

double dyad_value(const Vec4& x, double k) { return k * x(0) - x(1); }

// The two routes to b per seed pair (printed dyad, linear order in b).
std::pair<double, double> b_routes(int d, const RunContacts& o, const RunContacts& c) {
  const ContactQuantities s = slopes_dyad(d, k_printed_dyad_factor);
  // ζ ∝ W·Y: A_chaos/A_orig = ζ_orig/ζ_chaos = (W Y)_MC(a2_o)(1 + b k_ζ)/(W Y)_MC(a2_c).
  const auto mc = [](double a2) {
    const auto q = molecular_chaos_contact(a2);
    return q.W * q.Y;
  };
  const double k_zeta = s.W + s.Y;
  const double b_cooling = ((c.A / o.A) * mc(c.a2) / mc(o.a2) - 1.0) / k_zeta;
  const double b_contact =
      dyad_value(shift(o, c), k_printed_dyad_factor) / (k_printed_dyad_factor * s.P - s.Q);
  return {b_cooling, b_contact};
}

Measurement mean_se(const std::vector<double>& v) { return mean_and_standard_error(v); }

RoutePair route_pair(const std::vector<double>& cooling, const std::vector<double>& contact) {
  RoutePair r;
  std::vector<double> diff;
  for (std::size_t i = 0; i < cooling.size(); ++i) diff.push_back(cooling[i] - contact[i]);
  r.cooling = mean_se(cooling);
  r.contact = mean_se(contact);
  r.difference = mean_se(diff);
  r.pairs = static_cast<int>(diff.size());
  // cov of the means from var(difference) = var_c + var_k − 2 cov.
  r.covariance = 0.5 * (r.cooling.error * r.cooling.error + r.contact.error * r.contact.error -
                        r.difference.error * r.difference.error);
  return r;
}

}  // namespace

ContactMomentRow summarize_contacts(int dimension, double density, double restitution,
                                    const std::string& mode, const std::vector<RunContacts>& runs) {
  ContactMomentRow row;
  row.dimension = dimension;
  row.density = density;
  row.restitution = restitution;
  row.mode = mode;
  std::vector<double> W, Y, P, Q, a2, A;
  std::vector<std::uint64_t> histogram(sim::ContactMoments::k_impact_bins, 0);
  for (const auto& r : runs) {
    if (!r.ok) continue;
    ++row.runs;
    W.push_back(r.measured.W);
    Y.push_back(r.measured.Y);
    P.push_back(r.measured.P);
    Q.push_back(r.measured.Q);
    a2.push_back(r.a2);
    A.push_back(r.A);
    for (std::size_t b = 0; b < histogram.size(); ++b) histogram[b] += r.impact_histogram[b];
  }
  row.omega_over_enskog = mean_se(W);
  row.gn2_over_4T = mean_se(Y);
  row.c1e_c2e = mean_se(P);
  row.c1_dot_c2 = mean_se(Q);
  row.a2 = mean_se(a2);
  row.A = mean_se(A);
  const FlatnessTest flat = impact_flatness(histogram);
  row.impact_chi2 = flat.chi2;
  row.impact_dof = flat.dof;
  return row;
}

CoolingDecompositionRow decompose_cooling(const GasPair& point) {
  CoolingDecompositionRow row;
  row.dimension = point.dimension;
  row.density = point.density;
  row.restitution = point.restitution;
  std::vector<double> a_ratio, product, difference, log_w, log_y;
  for (const auto& [o, c] : paired(point)) {
    a_ratio.push_back(o->A / c->A);
    product.push_back(c->measured.W * c->measured.Y / (o->measured.W * o->measured.Y));
    difference.push_back(a_ratio.back() - product.back());
    log_w.push_back(std::log(c->measured.W / o->measured.W));
    log_y.push_back(std::log(c->measured.Y / o->measured.Y));
  }
  row.pairs = static_cast<int>(a_ratio.size());
  row.A_ratio = mean_se(a_ratio);
  row.product_ratio = mean_se(product);
  row.difference = mean_se(difference);
  row.log_frequency = mean_se(log_w);
  row.log_dissipation = mean_se(log_y);
  return row;
}

namespace {

struct PointShifts {
  Vec4 mean = Vec4::Zero();
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();  ///< of the mean
  int pairs = 0;
};

PointShifts point_shifts(const GasPair& point) {
  PointShifts s;
  std::vector<Vec4> v;
  for (const auto& [o, c] : paired(point)) v.push_back(shift(*o, *c));
  s.pairs = static_cast<int>(v.size());
  if (v.size() < 2) return s;
  for (const auto& x : v) s.mean += x;
  s.mean /= static_cast<double>(v.size());
  for (const auto& x : v) s.covariance += (x - s.mean) * (x - s.mean).transpose();
  const double n = static_cast<double>(v.size());
  s.covariance /= (n - 1.0) * n;
  return s;
}

Eigen::Matrix4d correlation_of(const Eigen::Matrix4d& c) {
  const Vec4 sd = c.diagonal().cwiseSqrt();
  return c.cwiseQuotient(sd * sd.transpose());
}

// Generalised least squares Δ = X β with covariance Σ: β, its covariance, χ², residuals.
struct Gls {
  Eigen::VectorXd beta;
  Eigen::MatrixXd covariance;
  double chi2 = 0.0;
  Vec4 residual = Vec4::Zero();
};

Gls gls(const Eigen::MatrixXd& X, const Vec4& y, const Eigen::Matrix4d& sigma) {
  const Eigen::Matrix4d inv = sigma.inverse();
  Gls g;
  g.covariance = (X.transpose() * inv * X).inverse();
  g.beta = g.covariance * X.transpose() * inv * y;
  g.residual = y - X * g.beta;
  g.chi2 = g.residual.dot(inv * g.residual);
  return g;
}

Measurement component(const Vec4& mean, const Eigen::Matrix4d& cov, int i) {
  return {mean(i), std::sqrt(cov(i, i))};
}

AnsatzFitRow fit_point(const GasPair& point, const PointShifts& s, const Eigen::Matrix4d& corr) {
  AnsatzFitRow row;
  row.dimension = point.dimension;
  row.density = point.density;
  row.restitution = point.restitution;
  row.pairs = s.pairs;
  row.shift_P = component(s.mean, s.covariance, 0);
  row.shift_Q = component(s.mean, s.covariance, 1);
  row.shift_W = component(s.mean, s.covariance, 2);
  row.shift_Y = component(s.mean, s.covariance, 3);
  const Vec4 se = s.covariance.diagonal().cwiseSqrt();
  const Eigen::Matrix4d sigma = se.asDiagonal() * corr * se.asDiagonal();
  const int d = point.dimension;
  Eigen::MatrixXd one(4, 1), two(4, 2);
  one.col(0) = as_vector(slopes_dyad(d, k_printed_dyad_factor));
  two.col(0) = as_vector(slopes_longitudinal(d));
  two.col(1) = as_vector(slopes_transverse(d));
  const Gls g1 = gls(one, s.mean, sigma), g2 = gls(two, s.mean, sigma);
  row.b = {g1.beta(0), std::sqrt(g1.covariance(0, 0))};
  row.chi2_one = g1.chi2;
  row.residual_P = g1.residual(0) / se(0);
  row.residual_Q = g1.residual(1) / se(1);
  row.residual_W = g1.residual(2) / se(2);
  row.residual_Y = g1.residual(3) / se(3);
  row.beta_par = {g2.beta(0), std::sqrt(g2.covariance(0, 0))};
  row.beta_perp = {g2.beta(1), std::sqrt(g2.covariance(1, 1))};
  row.beta_covariance = g2.covariance(0, 1);
  row.chi2_two = g2.chi2;
  std::vector<double> cool, contact, par_cool, par_contact;
  const double k_par = k_printed_dyad_factor - 1.0;  // printed: β∥ = (κ − 1) b
  for (const auto& [o, c] : paired(point)) {
    const auto [bc, bk] = b_routes(d, *o, *c);
    cool.push_back(bc);
    contact.push_back(bk);
    par_cool.push_back(k_par * bc);
    par_contact.push_back(shift(*o, *c)(0) / slopes_longitudinal(d).P);
  }
  row.b_routes = route_pair(cool, contact);
  row.beta_par_routes = route_pair(par_cool, par_contact);
  return row;
}

}  // namespace

std::vector<AnsatzFitRow> fit_ansatz(const std::vector<GasPair>& points) {
  std::vector<PointShifts> shifts;
  std::map<std::pair<int, double>, std::pair<Eigen::Matrix4d, double>> pooled;
  for (const auto& p : points) {
    shifts.push_back(point_shifts(p));
    const auto& s = shifts.back();
    if (s.pairs < 3) continue;
    auto& [sum, weight] = pooled[{p.dimension, p.density}];
    if (weight == 0.0) sum.setZero();
    sum += (s.pairs - 1.0) * correlation_of(s.covariance);
    weight += s.pairs - 1.0;
  }
  std::vector<AnsatzFitRow> rows;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (shifts[i].pairs < 3) continue;
    const auto& [sum, weight] = pooled.at({points[i].dimension, points[i].density});
    // A 4×4 correlation matrix needs ≳ 3 × 4 degrees of freedom to be invertible and stable;
    // with fewer the shifts are treated as independent.
    const Eigen::Matrix4d corr =
        weight >= 12.0 ? Eigen::Matrix4d(sum / weight) : Eigen::Matrix4d::Identity();
    rows.push_back(fit_point(points[i], shifts[i], corr));
  }
  return rows;
}

BRoutesVerdict compare_routes(const std::vector<RoutePair>& routes, const std::string& amplitude) {
  BRoutesVerdict v;
  GlobalTest equal;
  for (const auto& f : routes)
    if (f.difference.error > 0.0) equal.add(f.difference.value / f.difference.error, f.pairs);
  v.points = equal.points;
  v.chi2_equal = equal.chi2;
  v.p_value = equal.p();
  const auto variance = [](const RoutePair& f, double r) {
    return f.cooling.error * f.cooling.error + r * r * f.contact.error * f.contact.error -
           2.0 * r * f.covariance;
  };
  // cooling = r · contact: weights 1/var(cooling − r contact), iterated to a fixed point.
  double r = 1.0, info = 0.0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    double num = 0.0;
    info = 0.0;
    for (const auto& f : routes) {
      const double var = variance(f, r);
      if (!(var > 0.0)) continue;
      num += f.cooling.value * f.contact.value / var;
      info += f.contact.value * f.contact.value / var;
    }
    if (info <= 0.0) break;
    const double next = num / info;
    if (std::abs(next - r) < 1e-12) break;
    r = next;
  }
  // Error from the information, inflated by √(χ²/dof) of the fit when above 1 (as fit_line).
  double chi2_ratio = 0.0;
  for (const auto& f : routes)
    if (variance(f, r) > 0.0)
      chi2_ratio += std::pow(f.cooling.value - r * f.contact.value, 2) / variance(f, r);
  const double inflate = v.points > 1 ? std::max(1.0, chi2_ratio / (v.points - 1)) : 1.0;
  v.ratio = {r, info > 0.0 ? std::sqrt(inflate / info) : 0.0};
  v.verdict = v.p_value >= k_global_p_threshold ? "consistent" : "inconsistent";
  v.statement = fmt::format(
      "Over {} state points {} from the cooling rate is {:.2f} ± {:.2f} times {} from the contact "
      "statistics, and equality gives chi2 = {:.1f} for {} dof (p = {:.2g}): the two routes are "
      "{}.",
      v.points, amplitude, v.ratio.value, v.ratio.error, amplitude, v.chi2_equal, v.points,
      v.p_value, v.verdict);
  return v;
}

}  // namespace molchaos::validation
