// `molchaos theory`: the kinetic-theory prediction for one state point, and the paper's printed
// coefficients and prefactors checked against quadrature.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "cli_support.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/correlation_range.hpp"
#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/exact_values.hpp"
#include "molchaos/theory/sonine.hpp"
#include "molchaos/theory/theory_report.hpp"
#include "molchaos/theory/theory_report_json.hpp"
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

theory::ReportInputs report_inputs(const TheoryOptions& o, const theory::BoxInputs& box) {
  theory::ReportInputs in;
  in.dimension = o.dimension;
  in.restitution = o.restitution;
  in.density = o.density;
  in.correlation_b = o.correlation_b;
  in.quadrature = quadrature_of(o);
  in.box = box;
  return in;
}

void print_prediction_text(const TheoryOptions& o, const theory::TheoryReport& r) {
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
  // The end to its last certain digit, cut rather than rounded (rounded to six digits,
  // 0.666666666666631 read 0.666667, a b the range refuses; cut to six, it hid b it takes), as
  // the message refusing a b prints it; --json has the full end and its error.
  std::cout << fmt::format("  allowed b            {}\n\n", theory::range_text(r.b_range));
}

void print_coefficients_text(const TheoryOptions& o, const theory::TheoryReport& r) {
  std::cout << fmt::format("{:<34} {:>14} {:>20} {:>9} {:>10}  {}\n", "μ2/μ2(0,0) coefficient",
                           "paper", "computed", "error", "exact", "verdict");
  for (std::size_t i = 0; i < r.coefficient_rows.size(); ++i) {
    const auto& c = r.coefficient_rows[i];
    std::cout << fmt::format(
        "{:<34} {:>14} {:>20} {:>9.1e} {:>10}  {}\n", c.quantity,
        c.paper ? fmt::format("{:.6f}", *c.paper) : "-", fixed(c.computed, c.error, 15), c.error,
        theory::exact_form(o.dimension, theory::k_paper_dyad_factor, r.table.terms[i].name),
        verdict_text(c));
  }
  std::cout << (o.dimension == 3
                    ? std::string("\nthe printed dyad 3·ee − U is already traceless in d = 3:\n")
                    : std::string(
                          "\ntraceless dyad (2·ee − U) instead of the printed 3·ee − U:\n"));
  for (const auto& t : r.traceless.terms)
    std::cout << fmt::format(
        "{:<34} {:>14} {:>20} {:>9.1e} {:>10}\n", "μ2 coefficient of " + t.name, "-",
        fixed(t.coefficient.value, t.coefficient.error, 15), t.coefficient.error,
        theory::exact_form(o.dimension, o.dimension, t.name));
  std::cout << fmt::format("\n{:<52} {:>10} {:>14} {:>9}  {}\n", "prefactor", "paper", "computed",
                           "error", "verdict");
  for (const auto& c : r.prefactor_rows)
    std::cout << fmt::format("{:<52} {:>10.6f} {:>14} {:>9.1e}  {}\n", c.quantity,
                             c.paper.value_or(std::nan("")), fixed(c.computed, c.error, 10),
                             c.error, verdict_text(c));
}

void print_sonine_text(const TheoryOptions& o, const theory::TheoryReport& r) {
  std::cout << fmt::format(
      "\nhomogeneous cooling state beyond the first Sonine term (b = {}):\n{:<14} {:>22} "
      "{:>22} {:>22}\n",
      o.correlation_b, "level", "a2", "a3", "A");
  const auto lv = theory::levels(r.sonine);
  for (std::size_t i = 0; i < lv.size(); ++i) {
    const auto& A = r.A_by_level[i];
    std::cout << fmt::format(
        "{:<14} {:>13} ± {:<6.1e} {:>13} ± {:<6.1e} {:>22}\n", lv[i]->level,
        fixed(lv[i]->a2.value, lv[i]->a2.error, 10), lv[i]->a2.error,
        fixed(lv[i]->a3.value, lv[i]->a3.error, 10), lv[i]->a3.error,
        A ? fmt::format("{:>13} ± {:<6.1e}", general(A->value, A->error, 12), A->error)
          : std::string("none: μ2 ≤ 0, no cooling"));
  }
  // The quadrature errors above are those of each level's integrals; how far the levels
  // themselves disagree is the error of truncating the Sonine expansion, and at strong
  // dissipation it is the larger one by many orders of magnitude.
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const auto& A : r.A_by_level)
    if (A) lowest = std::min(lowest, A->value), highest = std::max(highest, A->value);
  if (highest > lowest)
    std::cout << fmt::format(
        "the levels differ by {:.2g} % in A: the truncation error of the Sonine expansion is of "
        "this order (DSMC, `simulate --method dsmc`, solves the Enskog–Boltzmann equation "
        "without it)\n",
        100.0 * (highest - lowest) / lowest);
}

void print_contact_text(const theory::ContactResponse& c) {
  std::cout << fmt::format(
      "\ncolliding pairs under f2 = f f g2 [1 + b D], D = {}·ee − U, to first order:\n"
      "{:<26} {:>26} {:>26} {:>26} {:>26}\n",
      c.dyad_factor, "quantity", "value (exact)", "∂/∂a2", "∂/∂b", "∂²/∂a2∂b");
  for (const auto& [name, s] : theory::contact_rows(c)) {
    const auto* x = theory::exact::find_contact_term(c.dimension, c.dyad_factor, name);
    auto cell = [&](const theory::Estimate& e, int k) {
      return fmt::format("{} ({:>5})", unsigned_zero(fmt::format("{:.12f}", e.value)),
                         x ? x->texts[k] : "-");
    };
    std::cout << fmt::format("{:<26} {:>26} {:>26} {:>26} {:>26}\n", name, cell(s->value, 0),
                             cell(s->d_a2, 1), cell(s->d_b, 2), cell(s->d_a2b, 3));
  }
}

void print_theory_text(const TheoryOptions& o, const theory::ReportInputs& in,
                       const theory::TheoryReport& r) {
  print_prediction_text(o, r);
  print_coefficients_text(o, r);
  print_sonine_text(o, r);
  print_contact_text(r.contact);
  if (o.dimension == 2) print_contact_text(r.contact_traceless);
  std::cout << hydrodynamics_text(in, r);
  if (o.quadrature == "adaptive")
    std::cout << fmt::format(
        "\ncomputed in {:.3f} s (adaptive quadrature, tolerance {:g}: the prediction, allowed b, "
        "the μ2 coefficients and the prefactors; exact Gauss rules: the Sonine levels and the "
        "colliding pairs)\n",
        r.seconds, o.tolerance);
  else
    std::cout << fmt::format("\ncomputed in {:.3f} s (gauss quadrature)\n", r.seconds);
}

void run_theory(const TheoryOptions& o, const theory::BoxInputs& box) {
  validate_theory_inputs(o);
  const theory::ReportInputs in = report_inputs(o, box);
  theory::TheoryReport r;
  try {
    r = theory::compute_report(in);  // refuses a density where τ0 overflows
  } catch (const std::invalid_argument& e) {
    throw_as_usage_error("theory", e.what());
  }
  if (o.json)
    std::cout << theory::report_json(in, r, k_version).dump(2) << '\n';
  else
    print_theory_text(o, in, r);
}

}  // namespace

void add_theory_command(CLI::App& app) {
  auto options = std::make_shared<TheoryOptions>();
  CLI::App* cmd = app.add_subcommand(
      "theory", "Kinetic-theory prediction (g2, a2, μ2, τ0, A) and the paper's coefficients");
  add_parameter_option(cmd, "dimension", options->dimension);
  add_parameter_option(cmd, "restitution", options->restitution);
  // The table's text names the densest start of N particles as well, which a run builds and
  // theory does not (its gas is that of N → ∞; --particles sizes only the box of its modes): what
  // theory checks is close packing (validate_theory_inputs) and, for a tiny n, that τ0 and A stay
  // finite (compute_report).
  add_parameter_option(cmd, "density", options->density)
      ->description(fmt::format(
          "Reduced density n = N sigma^d / V, below close packing ({:.6g} for d = 2, {:.6g} for "
          "d = 3) and above the n where τ0 or A overflows a double (a refusal names the range); "
          "theory places no particles, so the densest start a run of N allows is not checked "
          "[{}]",
          theory::close_packing_density(2), theory::close_packing_density(3),
          parameter_row("density").unit));
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
