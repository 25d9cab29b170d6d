// `molchaos theory`: the kinetic-theory prediction for one state point, and the paper's printed
// coefficients and prefactors checked against quadrature.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_support.hpp"
#include "commands.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/dimension.hpp"
#include "molchaos/theory/paper_checks.hpp"
#include "molchaos/version.hpp"
#include "parameter_options.hpp"

namespace molchaos::app {
namespace {

struct TheoryOptions {
  int dimension = 2;
  double restitution = 0.9;
  double density = 0.05;
  double correlation_b = 0.0;
  double tolerance = 1e-10;
  bool json = false;
};

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
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

std::string verdict_text(const theory::PaperCheck& c) {
  if (!c.reproduced) return "-";
  return *c.reproduced ? "reproduced" : "NOT reproduced";
}

void run_theory(const TheoryOptions& o) {
  try {
    theory::require_density(o.dimension, o.density);
  } catch (const std::invalid_argument&) {
    throw UsageError("--density", fmt::format("value {} is outside the allowed range (0, {:.6f}) "
                                              "for --dim {} (close packing)",
                                              o.density, theory::close_packing_density(o.dimension),
                                              o.dimension));
  }
  const auto start = std::chrono::steady_clock::now();
  theory::QuadratureOptions quad;
  quad.relative_tolerance = o.tolerance;
  theory::CoolingInputs inputs;
  inputs.dimension = o.dimension;
  inputs.density = o.density;
  inputs.restitution = o.restitution;
  inputs.correlation_b = o.correlation_b;
  inputs.quadrature = quad;
  const theory::CoolingPrediction p = theory::predict_cooling(inputs);
  // Coefficients are ε-independent for μ2; evaluated at ε = 1/2 so that ε = 1 input works too.
  const auto table =
      theory::expand_collision_moment(o.dimension, 2, 0.5, theory::k_paper_dyad_factor, quad);
  // The printed dyad 3·ee − U is traceless only in d = 3; in d = 2 the traceless one is 2·ee − U.
  const auto traceless =
      o.dimension == 3 ? table
                       : theory::expand_collision_moment(o.dimension, 2, 0.5, o.dimension, quad);
  const auto coefficient_rows = theory::coefficient_checks(table);
  const auto prefactor_rows = theory::prefactor_checks(o.dimension, quad);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (o.json) {
    nlohmann::json j;
    j["version"] = k_version;
    j["inputs"] = {{"dim", o.dimension},
                   {"restitution", o.restitution},
                   {"density", o.density},
                   {"b", o.correlation_b},
                   {"initial_temperature", 1.0},
                   {"tolerance", o.tolerance},
                   {"units", "sigma = m = k_B = 1; T = m<v^2>/d"}};
    j["packing_fraction"] = p.packing_fraction;
    j["g2"] = p.g2;
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
    j["coefficients"] = nlohmann::json::array();
    for (std::size_t i = 0; i < coefficient_rows.size(); ++i)
      j["coefficients"].push_back(to_json(coefficient_rows[i], table.terms[i].name));
    j["coefficients_traceless_dyad"] = nlohmann::json::array();
    for (const auto& t : traceless.terms)
      j["coefficients_traceless_dyad"].push_back(
          {{"term", t.name}, {"computed", t.coefficient.value}, {"error", t.coefficient.error}});
    j["prefactors"] = nlohmann::json::array();
    for (const auto& row : prefactor_rows) j["prefactors"].push_back(to_json(row, ""));
    j["seconds"] = seconds;
    std::cout << j.dump(2) << '\n';
    return;
  }
  std::cout << fmt::format("molchaos {} — kinetic theory, d = {}, ε = {}, n = {}, b = {}\n",
                           k_version, o.dimension, o.restitution, o.density, o.correlation_b);
  std::cout << "units: σ = m = k_B = 1, T0 = 1, T = m<v²>/d\n\n";
  std::cout << fmt::format("  packing fraction η   {:.10g}\n", p.packing_fraction);
  std::cout << fmt::format("  g2(σ)                {:.10g}\n", p.g2);
  std::cout << fmt::format("  a2(ε)                {:.10g}\n", p.a2);
  std::cout << fmt::format("  μ2                   {:.12g} ± {:.2g}\n", p.mu2.value, p.mu2.error);
  std::cout << fmt::format("  μ2/μ2(0,0)           {:.12g} ± {:.2g}\n", p.mu2_ratio.value,
                           p.mu2_ratio.error);
  std::cout << fmt::format("  ω0                   {:.10g}\n", p.omega0);
  std::cout << fmt::format("  τ0                   {:.10g} ± {:.2g}\n", p.tau0.value, p.tau0.error);
  std::cout << fmt::format("  A = τ0(1-ε²)         {:.10g} ± {:.2g}\n", p.A.value, p.A.error);
  std::cout << fmt::format("  A (b = 0)            {:.10g} ± {:.2g}\n", p.A_uncorrelated.value,
                           p.A_uncorrelated.error);
  std::cout << fmt::format("  Enskog ω_coll        {:.10g}\n\n", p.enskog_collision_frequency);
  std::cout << fmt::format("{:<34} {:>14} {:>20} {:>9}  {}\n", "μ2/μ2(0,0) coefficient", "paper",
                           "computed", "error", "verdict");
  for (const auto& r : coefficient_rows)
    std::cout << fmt::format("{:<34} {:>14} {:>20.15f} {:>9.1e}  {}\n", r.quantity,
                             r.paper ? fmt::format("{:.6f}", *r.paper) : "-", r.computed, r.error,
                             verdict_text(r));
  std::cout << (o.dimension == 3
                    ? std::string("\nthe printed dyad 3·ee − U is already traceless in d = 3:\n")
                    : std::string(
                          "\ntraceless dyad (2·ee − U) instead of the printed 3·ee − U:\n"));
  for (const auto& t : traceless.terms)
    std::cout << fmt::format("{:<34} {:>14} {:>20.15f} {:>9.1e}\n", "μ2 coefficient of " + t.name,
                             "-", t.coefficient.value, t.coefficient.error);
  std::cout << fmt::format("\n{:<52} {:>10} {:>14} {:>9}  {}\n", "prefactor", "paper", "computed",
                           "error", "verdict");
  for (const auto& r : prefactor_rows)
    std::cout << fmt::format("{:<52} {:>10.6f} {:>14.10f} {:>9.1e}  {}\n", r.quantity,
                             r.paper.value_or(std::nan("")), r.computed, r.error, verdict_text(r));
  std::cout << fmt::format("\ncomputed in {:.3f} s (quadrature tolerance {:g})\n", seconds,
                           o.tolerance);
}

}  // namespace

void add_theory_command(CLI::App& app) {
  auto options = std::make_shared<TheoryOptions>();
  CLI::App* cmd = app.add_subcommand(
      "theory", "Kinetic-theory prediction (g2, a2, μ2, τ0, A) and the paper's coefficients");
  add_parameter_option(cmd, "dimension", options->dimension);
  add_parameter_option(cmd, "restitution", options->restitution);
  add_parameter_option(cmd, "density", options->density);
  cmd->add_option("--b", options->correlation_b, "velocity-correlation coefficient b")
      ->check(real_in(-1.0, true, 1.0, true))
      ->capture_default_str();
  cmd->add_option("--tolerance", options->tolerance, "relative quadrature tolerance")
      ->check(real_in(1e-13, true, 1e-2, true))
      ->capture_default_str();
  cmd->add_flag("--json", options->json, "print one JSON document");
  cmd->callback([options] { run_theory(*options); });
}

}  // namespace molchaos::app
