// `molchaos theory`: the kinetic-theory prediction for one state point, and the paper's printed
// coefficients and prefactors checked against quadrature.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/contact_response.hpp"
#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/correlation_range.hpp"
#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/exact_values.hpp"
#include "molchaos/theory/paper_checks.hpp"
#include "molchaos/theory/sonine.hpp"
#include "molchaos/theory/sonine_hcs.hpp"
#include "molchaos/version.hpp"
#include "parameter_options.hpp"
#include "theory_hydrodynamics_output.hpp"

namespace molchaos::app {
namespace {

struct TheoryOptions {
  int dimension = 2;
  double restitution = 0.9;
  double density = 0.05;
  double correlation_b = 0.0;
  double tolerance = theory::QuadratureOptions{}.relative_tolerance;
  std::string quadrature = "gauss";
  bool json = false;
  /// --b's text when it is not a finite number, refused in validate_theory_inputs: b's range
  /// depends on --dim and --restitution, known only once every flag is read.
  std::string b_refused_text;
};

theory::QuadratureOptions quadrature_of(const TheoryOptions& o) {
  theory::QuadratureOptions q;
  q.method = o.quadrature == "adaptive" ? theory::QuadratureMethod::adaptive
                                        : theory::QuadratureMethod::gauss;
  q.relative_tolerance = o.tolerance;
  return q;
}

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

// A number in text without a sign on zero: "-0" or "-0.0000" (−0, or a tiny negative value
// rounded away) reads as a negative quantity that is not there.
std::string unsigned_zero(std::string text) {
  if (!text.empty() && text[0] == '-' && text.find_first_of("123456789") == std::string::npos)
    text.erase(0, 1);
  return text;
}

// The digits a value's error supports: the last printed digit at the error's second significant
// digit (the errors are printed with two), i.e. at 10^(⌊log10 error⌋ − 1). `most` caps them: the
// default Gauss rules' errors, near rounding, support more digits than the columns show, and
// those columns stay as they are.
int last_digit_exponent(double error) {
  return static_cast<int>(std::floor(std::log10(error))) - 1;
}

// value in fixed notation to the decimals its error supports (at most `most`).
std::string fixed(double value, double error, int most) {
  int decimals = most;
  if (error > 0.0 && std::isfinite(error))
    decimals = std::clamp(-last_digit_exponent(error), 0, most);
  return unsigned_zero(fmt::format("{:.{}f}", value, decimals));
}

// value in general notation to the significant digits its error supports (at most `most`).
std::string general(double value, double error, int most) {
  int digits = most;
  if (error > 0.0 && std::isfinite(error) && value != 0.0 && std::isfinite(value)) {
    const int magnitude = static_cast<int>(std::floor(std::log10(std::abs(value))));
    digits = std::clamp(magnitude - last_digit_exponent(error) + 1, 1, most);
  }
  return unsigned_zero(fmt::format("{:.{}g}", value, digits));
}

nlohmann::json to_json(const theory::PaperCheck& c, const std::string& term) {
  nlohmann::json row;
  if (!term.empty())
    row["term"] = term;
  else
    row["quantity"] = c.quantity;
  row["paper"] = c.paper ? nlohmann::json(*c.paper) : nlohmann::json(nullptr);
  row["computed"] = c.computed;
  row["error"] = c.error;
  row["reproduced"] = c.reproduced ? nlohmann::json(*c.reproduced) : nlohmann::json(nullptr);
  if (c.paper) row["difference"] = c.computed - *c.paper;
  if (!c.note.empty()) row["note"] = c.note;
  return row;
}

// The exact form the symbolic derivation gives for a μ2 coefficient ("-" where it has none).
std::string exact_text(int dimension, double dyad_factor, const std::string& term) {
  const auto* t = theory::exact::find_moment_term(dimension, 2, dyad_factor, term);
  return t ? t->coefficient_text : "-";
}

std::string verdict_text(const theory::PaperCheck& c) {
  if (!c.reproduced) return c.paper && !c.note.empty() ? c.note : "-";
  return *c.reproduced ? "reproduced" : "NOT reproduced";
}

// Flag values that are each in range but together describe no gas: density beyond close
// packing, b outside the range where the ansatz's f2 and μ2 stay positive.
void validate_theory_inputs(const TheoryOptions& o) {
  try {
    theory::require_density(o.dimension, o.density);
  } catch (const std::invalid_argument&) {
    throw UsageError("--density", fmt::format("value {} is outside the allowed range (0, {}) "
                                              "for --dim {} (close packing)",
                                              o.density, theory::close_packing_density(o.dimension),
                                              o.dimension));
  }
  const double a2 = theory::a2_first_sonine(o.dimension, o.restitution);
  // By the exact Gauss rules whatever --quadrature says: the range is the integrands' (the two
  // quadratures agree to 1e-12), and the adaptive one would take seconds before refusing. With
  // a2's uncertainty, as predict_cooling takes it, so that both name one range.
  const double a2_error = theory::a2_from_moments(o.dimension, o.restitution).error;
  const auto range = theory::correlation_b_range(o.dimension, a2, theory::k_paper_dyad_factor,
                                                 theory::QuadratureOptions{}, a2_error);
  const std::string allowed = fmt::format(
      "allowed range {} for --dim {}, --restitution {} (where the ansatz's f2 at grazing impact "
      "and the collision rate stay positive, and μ2 is positive beyond its error: a cooling time "
      "exists)",
      theory::range_text(range), o.dimension, o.restitution);
  if (!o.b_refused_text.empty()) {
    double x = 0.0;
    const std::size_t used = parse_real(o.b_refused_text, x);
    const bool infinite = used == o.b_refused_text.size() && std::isinf(x);
    throw UsageError("--b",
                     infinite ? fmt::format("value {} is not finite; {}", o.b_refused_text, allowed)
                              : fmt::format("'{}' is not a number; {}", o.b_refused_text, allowed));
  }
  if (!(o.correlation_b >= range.lower && o.correlation_b < range.upper))
    throw UsageError("--b", fmt::format("value {} is outside the {}", o.correlation_b, allowed));
}

// Everything `molchaos theory` prints, computed once.
struct TheoryResults {
  theory::CoolingPrediction prediction;
  theory::ExpansionTable table, traceless;
  std::vector<theory::PaperCheck> coefficient_rows, prefactor_rows;
  theory::CorrelationRange b_range;
  theory::HcsSonine sonine;
  /// A with each level's a2, a3 and the given b; none where that μ2 is not positive beyond its
  /// error (the b range makes sure of it for the first level only): the gas would not cool.
  std::array<std::optional<theory::Estimate>, 4> A_by_level;
  std::array<theory::Estimate, 4> mu2_ratio_at_b;  ///< μ2/μ2(0,0) behind each A, at the given b
  theory::ContactResponse contact, contact_traceless;
  double seconds = 0.0;
};

std::array<const theory::SonineSolution*, 4> levels(const theory::HcsSonine& h) {
  return {&h.first_sonine, &h.a2_nonlinear, &h.a2_a3_linear, &h.a2_a3};
}

TheoryResults compute_theory(const TheoryOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const theory::QuadratureOptions quad = quadrature_of(o);
  TheoryResults r;
  theory::CoolingInputs inputs;
  inputs.dimension = o.dimension;
  inputs.density = o.density;
  inputs.restitution = o.restitution;
  inputs.correlation_b = o.correlation_b;
  inputs.quadrature = quad;
  try {
    r.prediction = theory::predict_cooling(inputs);  // refuses a density where τ0 overflows
  } catch (const std::invalid_argument& e) {
    throw_as_usage_error("theory", e.what());
  }
  // Coefficients are ε-independent for μ2; evaluated at ε = 1/2 so that ε = 1 input works too.
  r.table = theory::expand_collision_moment(o.dimension, 2, 0.5, theory::k_paper_dyad_factor, quad);
  // The printed dyad 3·ee − U is traceless only in d = 3; in d = 2 the traceless one is 2·ee − U.
  r.traceless = o.dimension == 3
                    ? r.table
                    : theory::expand_collision_moment(o.dimension, 2, 0.5, o.dimension, quad);
  r.coefficient_rows = theory::coefficient_checks(r.table);
  r.prefactor_rows = theory::prefactor_checks(o.dimension, quad);
  r.b_range = theory::correlation_b_range(o.dimension, r.prediction.a2, theory::k_paper_dyad_factor,
                                          quad, r.prediction.a2_error);
  // The second-order Sonine theory and the contact response always use the exact Gauss rules
  // (the adaptive check of these 2 × 12 + 12 terms would take minutes; the tests run it).
  const theory::QuadratureOptions gauss;
  r.sonine = theory::hcs_sonine_coefficients(o.dimension, o.restitution, gauss);
  const auto with_a3 = theory::expand_collision_moment(
      o.dimension, 2, 0.5, theory::k_paper_dyad_factor, gauss, theory::SonineTerms::a2_a3);
  const auto lv = levels(r.sonine);
  for (std::size_t i = 0; i < lv.size(); ++i) {
    const theory::PairShape shape{lv[i]->a2.value, lv[i]->a3.value, o.correlation_b};
    const theory::Estimate ratio = with_a3.ratio_estimate(shape);
    // The Sonine coefficients' own errors carried through ∂ratio/∂a (central differences of an
    // exactly quadratic polynomial).
    const double h = 1e-3;
    auto slope = [&](double da2, double da3) {
      const theory::PairShape up{shape.a2 + da2, shape.a3 + da3, shape.b};
      const theory::PairShape down{shape.a2 - da2, shape.a3 - da3, shape.b};
      return std::abs(with_a3.ratio(up) - with_a3.ratio(down)) / (2.0 * h);
    };
    const double ratio_error =
        ratio.error + slope(h, 0.0) * lv[i]->a2.error + slope(0.0, h) * lv[i]->a3.error;
    r.mu2_ratio_at_b[i] = {ratio.value, ratio_error};
    if (ratio.value > ratio_error)
      r.A_by_level[i] =
          theory::cooling_prefactor_A(o.dimension, o.density, 1.0, {ratio.value, ratio_error});
  }
  // The first level is the header's prediction (first-Sonine a2, a3 = 0, the given b): one
  // quantity, so one value and one error, the prediction's (which carries the quadrature's
  // uncertainty of that a2 too). Not under --quadrature adaptive, whose prediction is by another
  // rule than this table. The rule of the other levels holds: no A where μ2 is not positive
  // beyond its error.
  if (quad.method == theory::QuadratureMethod::gauss) {
    r.mu2_ratio_at_b[0] = r.prediction.mu2_ratio;
    r.A_by_level[0] = std::nullopt;
    if (r.prediction.mu2_ratio.value > r.prediction.mu2_ratio.error)
      r.A_by_level[0] = r.prediction.A;
  }
  r.contact = theory::contact_response(o.dimension, theory::k_paper_dyad_factor, gauss);
  r.contact_traceless = theory::contact_response(o.dimension, o.dimension, gauss);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

nlohmann::json to_json(const theory::Estimate& e) {
  return {{"value", e.value}, {"error", e.error}};
}

// The contact response's five quantities by the names the symbolic derivation gives them.
std::array<std::pair<const char*, const theory::ResponseSeries*>, 5> contact_rows(
    const theory::ContactResponse& c) {
  return {{{"normal_product", &c.normal_product},
           {"velocity_product", &c.velocity_product},
           {"dyad", &c.dyad},
           {"collision_frequency_ratio", &c.collision_frequency_ratio},
           {"dissipation_ratio", &c.dissipation_ratio}}};
}

nlohmann::json to_json(const theory::ContactResponse& c) {
  nlohmann::json j;
  j["dyad_factor"] = c.dyad_factor;
  for (const auto& [name, s] : contact_rows(c)) {
    const auto* x = theory::exact::find_contact_term(c.dimension, c.dyad_factor, name);
    j[name] = {{"value", to_json(s->value)},
               {"d_a2", to_json(s->d_a2)},
               {"d_b", to_json(s->d_b)},
               {"d_a2b", to_json(s->d_a2b)}};
    if (x) j[name]["exact"] = {x->texts[0], x->texts[1], x->texts[2], x->texts[3]};
  }
  return j;
}

void print_theory_json(const TheoryOptions& o, const TheoryResults& r,
                       const HydrodynamicsOptions& h) {
  const auto& p = r.prediction;
  nlohmann::json j;
  j["version"] = k_version;
  j["inputs"] = {{"dim", o.dimension},         {"restitution", o.restitution},
                 {"density", o.density},       {"b", o.correlation_b},
                 {"initial_temperature", 1.0}, {"quadrature", o.quadrature},
                 {"tolerance", o.tolerance},   {"units", "sigma = m = k_B = 1; T = m<v^2>/d"}};
  j["packing_fraction"] = p.packing_fraction;
  j["g2"] = p.g2;
  j["g2_extrapolated"] = theory::g2_extrapolated(o.dimension, p.packing_fraction);
  j["a2"] = p.a2;
  j["mu2"] = p.mu2.value;
  j["mu2_error"] = p.mu2.error;
  j["mu2_ratio"] = p.mu2_ratio.value;
  j["omega0"] = p.omega0;
  j["tau0"] = number_or_null(p.tau0.value);
  j["tau0_error"] = number_or_null(p.tau0.value).is_null() ? nlohmann::json(nullptr)
                                                           : nlohmann::json(p.tau0.error);
  j["A"] = p.A.value;
  j["A_error"] = p.A.error;
  j["A_uncorrelated"] = p.A_uncorrelated.value;
  j["enskog_collision_frequency"] = p.enskog_collision_frequency;
  j["b_range"] = {{"lower", r.b_range.lower},
                  {"upper", number_or_null(r.b_range.upper)},
                  {"upper_error", r.b_range.upper_error}};
  j["coefficients"] = nlohmann::json::array();
  for (std::size_t i = 0; i < r.coefficient_rows.size(); ++i) {
    j["coefficients"].push_back(to_json(r.coefficient_rows[i], r.table.terms[i].name));
    j["coefficients"].back()["exact"] =
        exact_text(o.dimension, theory::k_paper_dyad_factor, r.table.terms[i].name);
  }
  j["coefficients_traceless_dyad"] = nlohmann::json::array();
  for (const auto& t : r.traceless.terms)
    j["coefficients_traceless_dyad"].push_back(
        {{"term", t.name},
         {"computed", t.coefficient.value},
         {"error", t.coefficient.error},
         {"exact", exact_text(o.dimension, o.dimension, t.name)}});
  j["prefactors"] = nlohmann::json::array();
  for (const auto& row : r.prefactor_rows) j["prefactors"].push_back(to_json(row, ""));
  j["sonine"] = nlohmann::json::array();
  const auto lv = levels(r.sonine);
  for (std::size_t i = 0; i < lv.size(); ++i)
    j["sonine"].push_back({{"level", lv[i]->level},
                           {"a2", to_json(lv[i]->a2)},
                           {"a3", to_json(lv[i]->a3)},
                           {"mu2_ratio", to_json(lv[i]->mu2_ratio)},
                           {"mu2_ratio_at_b", to_json(r.mu2_ratio_at_b[i])},
                           {"A", r.A_by_level[i] ? to_json(*r.A_by_level[i]) : nullptr}});
  j["contact_response"] = {{"printed_dyad", to_json(r.contact)},
                           {"traceless_dyad", to_json(r.contact_traceless)}};
  add_hydrodynamics_json(j, o.dimension, o.restitution, o.density, h);
  j["seconds"] = r.seconds;
  std::cout << j.dump(2) << '\n';
}

void print_prediction_text(const TheoryOptions& o, const TheoryResults& r) {
  const auto& p = r.prediction;
  std::cout << fmt::format("molchaos {} — kinetic theory, d = {}, ε = {}, n = {}, b = {}\n",
                           k_version, o.dimension, o.restitution, o.density, o.correlation_b);
  std::cout << "units: σ = m = k_B = 1, T0 = 1, T = m<v²>/d\n\n";
  std::cout << fmt::format("  packing fraction η   {:.10g}\n", p.packing_fraction);
  std::cout << fmt::format("  g2(σ)                {:.10g}\n", p.g2);
  if (theory::g2_extrapolated(o.dimension, p.packing_fraction))
    std::cout << fmt::format(
        "  note: η lies beyond the equilibrium fluid (η ≤ {} for {}): g2(σ), from the fluid's "
        "equation of state, and every number below built on it are extrapolations\n",
        theory::fluid_limit_packing(o.dimension), o.dimension == 2 ? "disks" : "spheres");
  std::cout << fmt::format("  a2(ε)                {}\n",
                           unsigned_zero(fmt::format("{:.10g}", p.a2)));
  std::cout << fmt::format("  μ2                   {} ± {:.2g}\n",
                           general(p.mu2.value, p.mu2.error, 12), p.mu2.error);
  std::cout << fmt::format("  μ2/μ2(0,0)           {} ± {:.2g}\n",
                           general(p.mu2_ratio.value, p.mu2_ratio.error, 12), p.mu2_ratio.error);
  std::cout << fmt::format("  ω0                   {:.10g}\n", p.omega0);
  std::cout << fmt::format("  τ0                   {} ± {:.2g}\n",
                           general(p.tau0.value, p.tau0.error, 10), p.tau0.error);
  std::cout << fmt::format("  A = τ0(1-ε²)         {} ± {:.2g}\n",
                           general(p.A.value, p.A.error, 10), p.A.error);
  std::cout << fmt::format("  A (b = 0)            {} ± {:.2g}\n",
                           general(p.A_uncorrelated.value, p.A_uncorrelated.error, 10),
                           p.A_uncorrelated.error);
  std::cout << fmt::format("  Enskog ω_coll        {:.10g}\n", p.enskog_collision_frequency);
  // The end to six digits, cut rather than rounded (rounded, 0.666666666666631 read 0.666667, a
  // b the range refuses); the full end is in --json and in the message refusing a b.
  std::cout << fmt::format("  allowed b            {}\n\n", theory::range_text(r.b_range, 6));
}

void print_coefficients_text(const TheoryOptions& o, const TheoryResults& r) {
  std::cout << fmt::format("{:<34} {:>14} {:>20} {:>9} {:>10}  {}\n", "μ2/μ2(0,0) coefficient",
                           "paper", "computed", "error", "exact", "verdict");
  for (std::size_t i = 0; i < r.coefficient_rows.size(); ++i) {
    const auto& c = r.coefficient_rows[i];
    std::cout << fmt::format(
        "{:<34} {:>14} {:>20} {:>9.1e} {:>10}  {}\n", c.quantity,
        c.paper ? fmt::format("{:.6f}", *c.paper) : "-", fixed(c.computed, c.error, 15), c.error,
        exact_text(o.dimension, theory::k_paper_dyad_factor, r.table.terms[i].name),
        verdict_text(c));
  }
  std::cout << (o.dimension == 3
                    ? std::string("\nthe printed dyad 3·ee − U is already traceless in d = 3:\n")
                    : std::string(
                          "\ntraceless dyad (2·ee − U) instead of the printed 3·ee − U:\n"));
  for (const auto& t : r.traceless.terms)
    std::cout << fmt::format("{:<34} {:>14} {:>20} {:>9.1e} {:>10}\n",
                             "μ2 coefficient of " + t.name, "-",
                             fixed(t.coefficient.value, t.coefficient.error, 15),
                             t.coefficient.error, exact_text(o.dimension, o.dimension, t.name));
  std::cout << fmt::format("\n{:<52} {:>10} {:>14} {:>9}  {}\n", "prefactor", "paper", "computed",
                           "error", "verdict");
  for (const auto& c : r.prefactor_rows)
    std::cout << fmt::format("{:<52} {:>10.6f} {:>14} {:>9.1e}  {}\n", c.quantity,
                             c.paper.value_or(std::nan("")), fixed(c.computed, c.error, 10),
                             c.error, verdict_text(c));
}

void print_sonine_text(const TheoryOptions& o, const TheoryResults& r) {
  std::cout << fmt::format(
      "\nhomogeneous cooling state beyond the first Sonine term (b = {}):\n{:<14} {:>22} "
      "{:>22} {:>22}\n",
      o.correlation_b, "level", "a2", "a3", "A");
  const auto lv = levels(r.sonine);
  for (std::size_t i = 0; i < lv.size(); ++i) {
    const auto& A = r.A_by_level[i];
    std::cout << fmt::format(
        "{:<14} {:>13} ± {:<6.1e} {:>13} ± {:<6.1e} {:>22}\n", lv[i]->level,
        fixed(lv[i]->a2.value, lv[i]->a2.error, 10), lv[i]->a2.error,
        fixed(lv[i]->a3.value, lv[i]->a3.error, 10), lv[i]->a3.error,
        A ? fmt::format("{:>13} ± {:<6.1e}", fixed(A->value, A->error, 9), A->error)
          : std::string("none: μ2 ≤ 0, no cooling"));
  }
}

void print_contact_text(const theory::ContactResponse& c) {
  std::cout << fmt::format(
      "\ncolliding pairs under f2 = f f g2 [1 + b D], D = {}·ee − U, to first order:\n"
      "{:<26} {:>26} {:>26} {:>26} {:>26}\n",
      c.dyad_factor, "quantity", "value (exact)", "∂/∂a2", "∂/∂b", "∂²/∂a2∂b");
  for (const auto& [name, s] : contact_rows(c)) {
    const auto* x = theory::exact::find_contact_term(c.dimension, c.dyad_factor, name);
    auto cell = [&](const theory::Estimate& e, int k) {
      return fmt::format("{} ({:>5})", unsigned_zero(fmt::format("{:.12f}", e.value)),
                         x ? x->texts[k] : "-");
    };
    std::cout << fmt::format("{:<26} {:>26} {:>26} {:>26} {:>26}\n", name, cell(s->value, 0),
                             cell(s->d_a2, 1), cell(s->d_b, 2), cell(s->d_a2b, 3));
  }
}

void print_theory_text(const TheoryOptions& o, const TheoryResults& r,
                       const HydrodynamicsOptions& h) {
  print_prediction_text(o, r);
  print_coefficients_text(o, r);
  print_sonine_text(o, r);
  print_contact_text(r.contact);
  if (o.dimension == 2) print_contact_text(r.contact_traceless);
  std::cout << hydrodynamics_text(o.dimension, o.restitution, o.density, h);
  if (o.quadrature == "adaptive")
    std::cout << fmt::format(
        "\ncomputed in {:.3f} s (adaptive quadrature, tolerance {:g}: the prediction, allowed b, "
        "the μ2 coefficients and the prefactors; exact Gauss rules: the Sonine levels and the "
        "colliding pairs)\n",
        r.seconds, o.tolerance);
  else
    std::cout << fmt::format("\ncomputed in {:.3f} s (gauss quadrature)\n", r.seconds);
}

void run_theory(const TheoryOptions& o, const HydrodynamicsOptions& h) {
  validate_theory_inputs(o);
  const TheoryResults r = compute_theory(o);
  if (o.json)
    print_theory_json(o, r, h);
  else
    print_theory_text(o, r, h);
}

}  // namespace

void add_theory_command(CLI::App& app) {
  auto options = std::make_shared<TheoryOptions>();
  CLI::App* cmd = app.add_subcommand(
      "theory", "Kinetic-theory prediction (g2, a2, μ2, τ0, A) and the paper's coefficients");
  add_parameter_option(cmd, "dimension", options->dimension);
  add_parameter_option(cmd, "restitution", options->restitution);
  add_parameter_option(cmd, "density", options->density);
  // b's range depends on --dim and --restitution: a text that is no finite number is kept and
  // refused once they are known (validate_theory_inputs), with the real range; a shared
  // real_in(-inf, inf) would name an infinite range that is not b's.
  cmd->add_option("--b", options->correlation_b,
                  "velocity-correlation coefficient b (range: where f2 and μ2 stay positive)")
      ->transform(CLI::Validator(
          [options](std::string& text) -> std::string {
            double x = 0.0;
            const std::size_t used = parse_real(text, x);
            if (used == 0 || used != text.size() || !std::isfinite(x)) {
              options->b_refused_text = text;
              text = "0";
            } else if (x == 0) {
              text = "0";  // -0 is 0, as real_in makes it
            }
            return {};
          },
          "in [-2, b_max(--dim, --restitution))"))
      ->capture_default_str();
  cmd->add_option("--quadrature", options->quadrature,
                  "gauss (exact fixed rules) or adaptive (GSL QAGIU, the independent check)")
      ->check(CLI::IsMember({"gauss", "adaptive"}))
      ->capture_default_str();
  CLI::Option* tolerance =
      cmd->add_option("--tolerance", options->tolerance,
                      "relative tolerance of the adaptive quadrature (with --quadrature adaptive)")
          ->transform(real_in(theory::k_min_relative_tolerance, true,
                              theory::k_max_relative_tolerance, true))
          ->capture_default_str();
  cmd->add_flag("--json", options->json, "print one JSON document");
  auto hydrodynamics = add_hydrodynamics_options(*cmd);
  set_callback_with_config(cmd, [options, hydrodynamics, tolerance] {
    // The Gauss rules are exact for these integrands: a tolerance would be taken and do nothing.
    if (tolerance->count() > 0 && options->quadrature != "adaptive")
      throw UsageError("--tolerance",
                       "applies to --quadrature adaptive only (the default Gauss "
                       "rules are exact and take no tolerance)");
    run_theory(*options, *hydrodynamics);
  });
}

}  // namespace molchaos::app
