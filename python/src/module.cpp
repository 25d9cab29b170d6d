// The compiled part of the Python module `molchaos`: the kinetic-theory prediction and one
// simulation run, each returned as plain Python values (dicts, numpy arrays).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/dimension.hpp"
#include "molchaos/version.hpp"

namespace py = pybind11;

namespace molchaos::python {
namespace {

py::dict estimate(const theory::Estimate& e) {
  py::dict d;
  d["value"] = e.value;
  d["error"] = e.error;
  return d;
}

// The same combination the CLI prints (theory::predict_cooling), with every error estimate.
py::dict theory_prediction(int dim, double restitution, double density, double b,
                           double tolerance) {
  if (dim != 2 && dim != 3) throw py::value_error("dim: value must be 2 or 3");
  if (!(restitution > 0.0 && restitution <= 1.0))
    throw py::value_error("restitution: value is outside the allowed range (0, 1]");
  if (!(b >= -1.0 && b <= 1.0))
    throw py::value_error("b: value is outside the allowed range [-1, 1]");
  if (!(tolerance >= 1e-13 && tolerance <= 1e-2))
    throw py::value_error("tolerance: value is outside the allowed range [1e-13, 1e-2]");
  try {
    theory::require_density(dim, density);
  } catch (const std::invalid_argument&) {
    throw py::value_error("density: value " + std::to_string(density) +
                          " is outside the allowed range (0, close packing " +
                          std::to_string(theory::close_packing_density(dim)) + ")");
  }
  theory::CoolingInputs inputs;
  inputs.dimension = dim;
  inputs.density = density;
  inputs.restitution = restitution;
  inputs.correlation_b = b;
  inputs.quadrature.relative_tolerance = tolerance;
  theory::CoolingPrediction p;
  {
    py::gil_scoped_release release;
    p = theory::predict_cooling(inputs);
  }
  py::dict d;
  d["dim"] = dim;
  d["restitution"] = restitution;
  d["density"] = density;
  d["b"] = b;
  d["packing_fraction"] = p.packing_fraction;
  d["g2"] = estimate({p.g2, 0.0});  // closed forms: exact
  d["a2"] = estimate({p.a2, 0.0});
  d["mu2"] = estimate(p.mu2);
  d["mu2_ratio"] = estimate(p.mu2_ratio);
  d["omega0"] = p.omega0;
  d["tau0"] = estimate(p.tau0);
  d["A"] = estimate(p.A);
  d["A_uncorrelated"] = estimate(p.A_uncorrelated);
  d["enskog_collision_frequency"] = p.enskog_collision_frequency;
  d["version"] = std::string(k_version);
  return d;
}

template <class T>
T keyword_as(const std::string& name, py::handle value) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw py::value_error(name + ": cannot convert " + py::repr(value).cast<std::string>() +
                          " to the parameter's type");
  }
}

// Keyword arguments into sim::Parameters, one field at a time. A walk over the shared parameter
// table replaces this list once the table exists; validation stays sim::validate.
sim::Parameters parameters_from(const py::kwargs& kwargs) {
  sim::Parameters p;
  for (auto item : kwargs) {
    const auto name = item.first.cast<std::string>();
    const py::handle v = item.second;
    if (name == "dim" || name == "dimension")
      p.dimension = keyword_as<int>(name, v);
    else if (name == "particles")
      p.particles = keyword_as<std::int64_t>(name, v);
    else if (name == "density")
      p.density = keyword_as<double>(name, v);
    else if (name == "restitution")
      p.restitution = keyword_as<double>(name, v);
    else if (name == "randomize") {
      const auto mode = sim::parse_randomization(keyword_as<std::string>(name, v));
      if (!mode) throw py::value_error("randomize: must be one of none, paper, flux");
      p.randomize = *mode;
    } else if (name == "seed")
      p.seed = keyword_as<std::uint64_t>(name, v);
    else if (name == "t_end")
      p.t_end = keyword_as<double>(name, v);
    else if (name == "relax_collisions_per_particle")
      p.relax_collisions_per_particle = keyword_as<double>(name, v);
    else if (name == "tc")
      p.tc = keyword_as<double>(name, v);
    else if (name == "samples_per_decade")
      p.samples_per_decade = keyword_as<int>(name, v);
    else if (name == "t_first_sample")
      p.t_first_sample = keyword_as<double>(name, v);
    else if (name == "contact_statistics")
      p.contact_statistics = keyword_as<bool>(name, v);
    else if (name == "snapshot_times")
      p.snapshot_times = keyword_as<std::vector<double>>(name, v);
    else if (name == "max_collisions")
      p.max_collisions = keyword_as<std::uint64_t>(name, v);
    else if (name == "min_temperature")
      p.min_temperature = keyword_as<double>(name, v);
    else if (name == "method") {
      const sim::ParameterInfo& row = *sim::find_parameter("method");
      const auto index = sim::find_choice(row, keyword_as<std::string>(name, v));
      if (!index) throw py::value_error("method: must be one of " + sim::choice_list(row));
      sim::set_choice_index(p, row, *index);
    } else
      throw py::type_error("simulate() got an unexpected keyword argument '" + name + "'");
  }
  try {
    sim::validate(p);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());  // the message starts with the field's name
  }
  return p;
}

py::dict parameters_dict(const sim::Parameters& p) {
  py::dict d;
  d["dimension"] = p.dimension;
  d["particles"] = p.particles;
  d["density"] = p.density;
  d["restitution"] = p.restitution;
  d["randomize"] = std::string(sim::to_string(p.randomize));
  d["seed"] = p.seed;
  d["t_end"] = p.t_end;
  d["relax_collisions_per_particle"] = p.relax_collisions_per_particle;
  d["tc"] = p.tc;
  d["samples_per_decade"] = p.samples_per_decade;
  d["t_first_sample"] = p.t_first_sample;
  d["contact_statistics"] = p.contact_statistics;
  d["snapshot_times"] = p.snapshot_times;
  d["max_collisions"] = p.max_collisions;
  d["min_temperature"] = p.min_temperature;
  d["method"] = sim::format_value(p, *sim::find_parameter("method"));
  return d;
}

template <class T, class Get>
py::array_t<T> column(const std::vector<sim::Sample>& samples, Get get) {
  py::array_t<T> a(static_cast<py::ssize_t>(samples.size()));
  auto view = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < samples.size(); ++i)
    view(static_cast<py::ssize_t>(i)) = get(samples[i]);
  return a;
}

py::array_t<double> particle_matrix(const std::vector<double>& flat, int dimension) {
  const auto n = static_cast<py::ssize_t>(flat.size()) / dimension;
  py::array_t<double> a({n, static_cast<py::ssize_t>(dimension)});
  std::copy(flat.begin(), flat.end(), a.mutable_data());
  return a;
}

py::dict simulate(const py::kwargs& kwargs) {
  const sim::Parameters p = parameters_from(kwargs);
  sim::RunResult r;
  {
    py::gil_scoped_release release;  // the engine touches no Python object
    r = sim::run(p);
  }
  const auto& s = r.samples;
  py::dict d;
  d["t"] = column<double>(s, [](const sim::Sample& x) { return x.t; });
  d["T"] = column<double>(s, [](const sim::Sample& x) { return x.temperature; });
  d["a2"] = column<double>(s, [](const sim::Sample& x) { return x.a2; });
  d["collisions"] = column<std::uint64_t>(s, [](const sim::Sample& x) { return x.collisions; });
  d["events"] = column<std::uint64_t>(s, [](const sim::Sample& x) { return x.events; });
  d["velocity_mode"] = column<double>(s, [](const sim::Sample& x) { return x.velocity_mode; });
  d["density_mode"] = column<double>(s, [](const sim::Sample& x) { return x.density_mode; });
  py::list snapshots;
  for (const auto& snap : r.snapshots) {
    py::dict sd;
    sd["t"] = snap.t;
    sd["box"] = snap.box;
    sd["positions"] = particle_matrix(snap.positions, p.dimension);
    sd["velocities"] = particle_matrix(snap.velocities, p.dimension);
    snapshots.append(sd);
  }
  d["snapshots"] = snapshots;
  d["parameters"] = parameters_dict(r.parameters);
  d["version"] = r.version;
  d["stop_reason"] = sim::stop_message(r);
  d["total_collisions"] = r.collisions;
  d["total_events"] = r.events;
  d["wall_seconds"] = r.wall_seconds;
  return d;
}

}  // namespace
}  // namespace molchaos::python

PYBIND11_MODULE(_molchaos, m) {
  using namespace molchaos::python;
  m.doc() = "molchaos: kinetic theory and event-driven MD of granular gases (sigma = m = k_B = 1)";
  m.attr("__version__") = std::string(molchaos::k_version);
  m.def("theory", &theory_prediction, py::kw_only(), py::arg("dim") = 2,
        py::arg("restitution") = 0.9, py::arg("density") = 0.05, py::arg("b") = 0.0,
        py::arg("tolerance") = 1e-10,
        "Kinetic-theory prediction for one state point: g2, a2, mu2, tau0, A as "
        "{value, error} dicts.");
  m.def("simulate", &simulate,
        "One cooling run. Keyword arguments are the fields of sim::Parameters (dim, particles, "
        "density, restitution, randomize, seed, t_end, ...), validated like the CLI's flags; "
        "returns a dict with numpy arrays t, T, a2, collisions and the run's metadata.");
}
