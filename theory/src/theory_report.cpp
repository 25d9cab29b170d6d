// The whole theory report of one state point (see the header).
#include "molchaos/theory/theory_report.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/exact_values.hpp"

namespace molchaos::theory {

void require_box(const BoxInputs& box) {
  if (box.particles < k_min_box_particles || box.particles > k_max_box_particles)
    throw std::invalid_argument(
        "particles: value " + std::to_string(box.particles) + " is outside the allowed range [" +
        std::to_string(k_min_box_particles) + ", " + std::to_string(k_max_box_particles) + "]");
  if (!(box.growth > 1.0 && box.growth <= k_max_growth))
    throw std::invalid_argument("growth: value " + exact_text(box.growth) +
                                " is outside the allowed range (1, " + exact_text(k_max_growth) +
                                "]");
}

// τ collisions per particle after time t of Haff's law: τ = ω_E(T0) τ0 ln(1 + t/τ0), since
// ω_E ∝ √T = √T0/(1 + t/τ0); inverted for t. The τ0 is molecular chaos's (b = 0, whatever the
// report's correlation_b), as are the transport coefficients the mode's rate comes from.
LargestShearMode largest_shear_mode(const TransportCoefficients& c, const ReportInputs& in) {
  const int d = in.dimension;
  LargestShearMode m;
  // (N/n)^(1/d) as N^(1/d) / n^(1/d): the quotient N/n overflows for n below about 1e-300.
  m.box = std::pow(static_cast<double>(in.box.particles), 1.0 / d) / std::pow(in.density, 1.0 / d);
  m.wavenumber = 2.0 * std::numbers::pi / m.box;
  m.rate = shear_mode_rate(c, m.wavenumber);
  m.collisions = collisions_to_reach(c, m.wavenumber, in.box.growth);
  m.stationary_level = stationary_transverse_structure_factor(c, m.wavenumber);
  CoolingInputs cooling;
  cooling.dimension = d;
  cooling.density = in.density;
  cooling.restitution = in.restitution;
  const auto p = predict_cooling(cooling);
  const double scale = p.enskog_collision_frequency * p.tau0.value;
  const bool finite = std::isfinite(m.collisions) && std::isfinite(scale);
  m.time = finite ? p.tau0.value * std::expm1(m.collisions / scale)
                  : std::numeric_limits<double>::infinity();
  m.log_time =
      finite ? log_time_after_collisions(m.collisions, p.tau0.value, p.enskog_collision_frequency)
             : std::numeric_limits<double>::infinity();
  return m;
}

std::array<const SonineSolution*, 4> levels(const HcsSonine& h) {
  return {&h.first_sonine, &h.a2_nonlinear, &h.a2_a3_linear, &h.a2_a3};
}

std::string exact_form(int dimension, double dyad_factor, const std::string& term) {
  const auto* t = exact::find_moment_term(dimension, 2, dyad_factor, term);
  return t ? t->coefficient_text : "-";
}

std::array<std::pair<const char*, const ResponseSeries*>, 5> contact_rows(
    const ContactResponse& c) {
  return {{{"normal_product", &c.normal_product},
           {"velocity_product", &c.velocity_product},
           {"dyad", &c.dyad},
           {"collision_frequency_ratio", &c.collision_frequency_ratio},
           {"dissipation_ratio", &c.dissipation_ratio}}};
}

namespace {

// μ2/μ2(0,0) and A at each Sonine level's a2, a3 and the given b.
void fill_levels(const ReportInputs& in, TheoryReport& r) {
  const int d = in.dimension;
  // The second-order Sonine theory always uses the exact Gauss rules (the adaptive check of
  // these 2 × 12 terms would take minutes; the tests run it).
  const QuadratureOptions gauss;
  r.sonine = hcs_sonine_coefficients(d, in.restitution, gauss);
  const auto with_a3 =
      expand_collision_moment(d, 2, 0.5, k_paper_dyad_factor, gauss, SonineTerms::a2_a3);
  const auto lv = levels(r.sonine);
  for (std::size_t i = 0; i < lv.size(); ++i) {
    const PairShape shape{lv[i]->a2.value, lv[i]->a3.value, in.correlation_b};
    const Estimate ratio = with_a3.ratio_estimate(shape);
    // The Sonine coefficients' own errors carried through ∂ratio/∂a (central differences of an
    // exactly quadratic polynomial).
    const double h = 1e-3;
    auto slope = [&](double da2, double da3) {
      const PairShape up{shape.a2 + da2, shape.a3 + da3, shape.b};
      const PairShape down{shape.a2 - da2, shape.a3 - da3, shape.b};
      return std::abs(with_a3.ratio(up) - with_a3.ratio(down)) / (2.0 * h);
    };
    const double ratio_error =
        ratio.error + slope(h, 0.0) * lv[i]->a2.error + slope(0.0, h) * lv[i]->a3.error;
    r.mu2_ratio_at_b[i] = {ratio.value, ratio_error};
    if (ratio.value > ratio_error)
      r.A_by_level[i] = cooling_prefactor_A(d, in.density, 1.0, {ratio.value, ratio_error});
  }
  // The first level is the header's prediction (first-Sonine a2, a3 = 0, the given b): one
  // quantity, so one value and one error, the prediction's (which carries the quadrature's
  // uncertainty of that a2 too). Not under adaptive quadrature, whose prediction is by another
  // rule than this table. The rule of the other levels holds: no A where μ2 is not positive
  // beyond its error.
  if (in.quadrature.method == QuadratureMethod::gauss) {
    r.mu2_ratio_at_b[0] = r.prediction.mu2_ratio;
    r.A_by_level[0] = std::nullopt;
    if (r.prediction.mu2_ratio.value > r.prediction.mu2_ratio.error)
      r.A_by_level[0] = r.prediction.A;
  }
}

}  // namespace

TheoryReport compute_report(const ReportInputs& in) {
  const auto start = std::chrono::steady_clock::now();
  require_box(in.box);
  const int d = in.dimension;
  TheoryReport r;
  CoolingInputs inputs;
  inputs.dimension = d;
  inputs.density = in.density;
  inputs.restitution = in.restitution;
  inputs.correlation_b = in.correlation_b;
  inputs.quadrature = in.quadrature;
  r.prediction = predict_cooling(inputs);  // refuses a density where τ0 overflows, and a b
  // Coefficients are ε-independent for μ2; evaluated at ε = 1/2 so that ε = 1 input works too.
  r.table = expand_collision_moment(d, 2, 0.5, k_paper_dyad_factor, in.quadrature);
  // The printed dyad 3·ee − U is traceless only in d = 3; in d = 2 the traceless one is 2·ee − U.
  r.traceless = d == 3 ? r.table : expand_collision_moment(d, 2, 0.5, d, in.quadrature);
  r.coefficient_rows = coefficient_checks(r.table);
  r.prefactor_rows = prefactor_checks(d, in.quadrature);
  r.b_range = correlation_b_range(d, r.prediction.a2, k_paper_dyad_factor, in.quadrature,
                                  r.prediction.a2_error);
  fill_levels(in, r);
  // The contact response by the exact Gauss rules, as the Sonine levels (12 terms).
  const QuadratureOptions gauss;
  r.contact = contact_response(d, k_paper_dyad_factor, gauss);
  r.contact_traceless = contact_response(d, d, gauss);
  r.transport = transport_coefficients({d, in.density, in.restitution, std::nullopt});
  r.shear_mode = largest_shear_mode(r.transport, in);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace molchaos::theory
