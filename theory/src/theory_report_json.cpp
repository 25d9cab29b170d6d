// The theory report as one JSON document (see the header).
#include "molchaos/theory/theory_report_json.hpp"

#include <cmath>
#include <string>

#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/exact_values.hpp"

namespace molchaos::theory {
namespace {

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

nlohmann::json to_json(const Estimate& e) { return {{"value", e.value}, {"error", e.error}}; }

nlohmann::json to_json(const PaperCheck& c, const std::string& term) {
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

nlohmann::json to_json(const ContactResponse& c) {
  nlohmann::json j;
  j["dyad_factor"] = c.dyad_factor;
  for (const auto& [name, s] : contact_rows(c)) {
    const auto* x = exact::find_contact_term(c.dimension, c.dyad_factor, name);
    j[name] = {{"value", to_json(s->value)},
               {"d_a2", to_json(s->d_a2)},
               {"d_b", to_json(s->d_b)},
               {"d_a2b", to_json(s->d_a2b)}};
    if (x) j[name]["exact"] = {x->texts[0], x->texts[1], x->texts[2], x->texts[3]};
  }
  return j;
}

// Critical sizes, transport coefficients and the largest shear mode of the box.
void add_hydrodynamics(nlohmann::json& j, const ReportInputs& in, const TheoryReport& r) {
  const auto& c = r.transport;
  const auto& m = r.shear_mode;
  j["critical_box_size"] = number_or_null(critical_box_size(c));
  j["critical_shear_wavenumber"] = critical_shear_wavenumber(c);
  // Where the longitudinal modes grow at every k no k∥ exists: null, and the flag says why (a
  // 0 read as 2π/k∥ = ∞ would say the opposite, never unstable).
  const bool every_wavelength = heat_mode_unstable_at_every_wavelength(c);
  j["critical_heat_wavenumber"] =
      every_wavelength ? nlohmann::json(nullptr) : nlohmann::json(critical_heat_wavenumber(c));
  j["heat_mode_unstable_at_every_wavelength"] = every_wavelength;
  j["transport"] = {
      {"cooling_rate", c.cooling_rate},           {"pressure", c.pressure},
      {"compressibility", c.compressibility},     {"shear_viscosity", c.shear_viscosity},
      {"bulk_viscosity", c.bulk_viscosity},       {"thermal_conductivity", c.thermal_conductivity},
      {"heat_flux_density", c.heat_flux_density}, {"length_unit", c.length_unit},
      {"collision_ratio", c.collision_ratio}};
  j["largest_shear_mode"] = {{"particles", in.box.particles},
                             {"box", m.box},
                             {"wavenumber", m.wavenumber},
                             {"reduced_wavenumber", reduced_wavenumber(c, m.wavenumber)},
                             {"beyond_hydrodynamics", beyond_hydrodynamics(c, m.wavenumber)},
                             {"rate_per_collision", m.rate},
                             {"growth", in.box.growth},
                             {"collisions_per_particle", number_or_null(m.collisions)},
                             {"time", number_or_null(m.time)},
                             {"log_time", number_or_null(m.log_time)},
                             {"stationary_level", number_or_null(m.stationary_level)}};
}

}  // namespace

nlohmann::json report_json(const ReportInputs& in, const TheoryReport& r, const char* version) {
  const auto& p = r.prediction;
  const bool adaptive = in.quadrature.method == QuadratureMethod::adaptive;
  nlohmann::json j;
  j["version"] = version;
  j["inputs"] = {{"dim", in.dimension},
                 {"restitution", in.restitution},
                 {"density", in.density},
                 {"b", in.correlation_b},
                 {"initial_temperature", 1.0},
                 {"quadrature", adaptive ? "adaptive" : "gauss"},
                 {"tolerance", in.quadrature.relative_tolerance},
                 {"units", "sigma = m = k_B = 1; T = m<v^2>/d"}};
  j["packing_fraction"] = p.packing_fraction;
  j["g2"] = p.g2;
  j["g2_extrapolated"] = g2_extrapolated(in.dimension, p.packing_fraction);
  j["a2"] = p.a2;
  j["mu2"] = p.mu2.value;
  j["mu2_error"] = p.mu2.error;
  j["mu2_ratio"] = p.mu2_ratio.value;
  j["omega0"] = p.omega0;
  j["tau0"] = number_or_null(p.tau0.value);
  j["tau0_error"] = std::isfinite(p.tau0.value) ? nlohmann::json(p.tau0.error) : nullptr;
  j["A"] = p.A.value;
  j["A_error"] = p.A.error;
  j["A_uncorrelated"] = p.A_uncorrelated.value;
  j["enskog_collision_frequency"] = p.enskog_collision_frequency;
  j["b_range"] = {{"lower", r.b_range.lower},
                  {"upper", number_or_null(r.b_range.upper)},
                  {"upper_error", r.b_range.upper_error}};
  j["coefficients"] = nlohmann::json::array();
  for (std::size_t i = 0; i < r.coefficient_rows.size(); ++i) {
    const std::string& term = r.table.terms[i].name;
    j["coefficients"].push_back(to_json(r.coefficient_rows[i], term));
    j["coefficients"].back()["exact"] = exact_form(in.dimension, k_paper_dyad_factor, term);
  }
  j["coefficients_traceless_dyad"] = nlohmann::json::array();
  for (const auto& t : r.traceless.terms)
    j["coefficients_traceless_dyad"].push_back(
        {{"term", t.name},
         {"computed", t.coefficient.value},
         {"error", t.coefficient.error},
         {"exact", exact_form(in.dimension, in.dimension, t.name)}});
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
  add_hydrodynamics(j, in, r);
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace molchaos::theory
