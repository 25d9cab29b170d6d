// The compiled part of the Python module `molchaos`: the kinetic-theory prediction and one
// simulation run, each returned as plain Python values (dicts, numpy arrays).
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <map>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "molchaos/sim/atomic_file.hpp"
#include "molchaos/sim/checkpoint.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/relaxed_states.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/theory_report.hpp"
#include "molchaos/theory/theory_report_json.hpp"
#include "molchaos/version.hpp"
#include "sigint_watch.hpp"

namespace py = pybind11;

namespace molchaos::python {
namespace {

std::string repr_text(py::handle value) { return py::repr(value).cast<std::string>(); }

[[noreturn]] void wrong_type(const std::string& name, const char* expected, py::handle value) {
  throw py::type_error(name + ": expected " + expected + ", got " + repr_text(value) + " (" +
                       py::type::handle_of(value).attr("__name__").cast<std::string>() + ")");
}

// numpy's scalars and arrays: the kind of their dtype ('b' bool, 'i' and 'u' integers, 'f' reals,
// 'c' complex, ...) and their number of dimensions; kind 0 for any other object.
struct NumpyKind {
  char kind = 0;
  py::ssize_t ndim = 0;
};

NumpyKind numpy_kind(py::handle value) {
  PyObject* const o = value.ptr();
  if (PyBool_Check(o) || PyLong_CheckExact(o) || PyFloat_CheckExact(o) || PyUnicode_Check(o))
    return {};
  if (py::isinstance<py::array>(value)) {
    const auto array = py::reinterpret_borrow<py::array>(value);
    return {array.dtype().kind(), array.ndim()};
  }
  if (py::isinstance(value, py::module_::import("numpy").attr("generic")))
    return {value.attr("dtype").attr("kind").cast<std::string>().at(0), 0};
  return {};
}

// A keyword's value as the parameter's C++ type, or a TypeError naming the parameter and the type
// it takes. A bool is refused where a number is expected: Python's True is the integer 1, and
// restitution=True would otherwise run silently as eps = 1 (numpy's bool likewise). An int is
// taken where a real is expected (restitution=1), as is any real with __float__ (numpy.float32,
// Fraction); a float is never taken where an integer is (particles=2.5), nor a complex number
// (numpy's would drop its imaginary part) or an array (np.array([0.9])) where one number is.
// An integer beyond the C++ type is a ValueError naming `range`, the parameter's allowed range.
template <class T>
T keyword_as(const std::string& name, py::handle value, const std::string& range = "") {
  PyObject* const o = value.ptr();
  const NumpyKind numpy = numpy_kind(value);
  if constexpr (std::is_same_v<T, bool>) {
    if (!PyBool_Check(o) && !(numpy.kind == 'b' && numpy.ndim == 0))
      wrong_type(name, "True or False", value);
  } else if constexpr (std::is_integral_v<T>) {
    const bool numpy_integer = (numpy.kind == 'i' || numpy.kind == 'u') && numpy.ndim == 0;
    if (PyBool_Check(o) || !PyIndex_Check(o) || (numpy.kind != 0 && !numpy_integer))
      wrong_type(name, "an integer", value);
  } else if constexpr (std::is_floating_point_v<T>) {
    const bool numpy_real =
        (numpy.kind == 'i' || numpy.kind == 'u' || numpy.kind == 'f') && numpy.ndim == 0;
    if (PyBool_Check(o) || (numpy.kind != 0 && !numpy_real) ||
        !(PyFloat_Check(o) || PyIndex_Check(o) || py::hasattr(value, "__float__")))
      wrong_type(name, "a real number", value);
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    if (PyUnicode_Check(o) || PyBytes_Check(o) || PyByteArray_Check(o) || !PySequence_Check(o) ||
        (numpy.kind != 0 && numpy.ndim != 1))
      wrong_type(name, "a list of real numbers", value);
    // A tuple owns its items: numpy hands out each element as a new object, which a handle
    // into the sequence would not keep alive.
    const py::tuple items(py::reinterpret_borrow<py::object>(value));
    T out;
    for (py::handle item : items) out.push_back(keyword_as<double>(name, item));
    return out;
  } else {
    if (!PyUnicode_Check(o)) wrong_type(name, "a string", value);
  }
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {  // an integer beyond the parameter's type: a value error
    if (range.empty())
      throw py::value_error(name + ": value " + repr_text(value) +
                            " does not fit the parameter's type");
    throw py::value_error(name + ": value " + repr_text(value) +
                          " is outside the allowed range " + range);
  }
}

// A file name: a str or an os.PathLike (pathlib.Path), as Python's own file functions take.
std::string path_keyword(const std::string& name, py::handle value) {
  if (!PyUnicode_Check(value.ptr()) && !py::hasattr(value, "__fspath__"))
    wrong_type(name, "a file name (str or os.PathLike)", value);
  std::string path = keyword_as<std::string>(name, py::module_::import("os").attr("fspath")(value));
  // An empty name would read as "none given": restart="" would start a new run without a word.
  if (path.empty()) throw py::value_error(name + ": the file name is empty");
  return path;
}

// An output file is written to a temporary beside it and renamed over `path` only at the end (at
// a checkpoint, after part of the run): a directory there, or a file of another kind (a device,
// FIFO, socket or symlink, which the rename would replace), is refused now, as the CLI refuses it.
void require_writable_file(const std::string& name, const std::string& path) {
  try {
    sim::probe_writable(path);  // no directory or special file, and /proc, /sys and over-long
  } catch (const std::exception& e) {  // names fail now
    throw py::value_error(name + ": " + e.what());
  }
}

// The CLI's `molchaos theory --json` document for these inputs, key for key (one computation,
// theory::compute_report, and one document, theory::report_json), as Python values.
py::object theory_report(py::handle dim_arg, py::handle restitution_arg, py::handle density_arg,
                         py::handle b_arg, py::handle quadrature_arg, py::handle tolerance_arg,
                         py::handle particles_arg, py::handle growth_arg) {
  const std::string dims = "{2, 3}";
  theory::ReportInputs in;
  in.dimension = keyword_as<int>("dim", dim_arg, dims);
  in.restitution = keyword_as<double>("restitution", restitution_arg);
  in.density = keyword_as<double>("density", density_arg);
  in.correlation_b = keyword_as<double>("b", b_arg);
  const std::string quadrature = keyword_as<std::string>("quadrature", quadrature_arg);
  const std::string particles_range = "[" + std::to_string(theory::k_min_box_particles) + ", " +
                                      std::to_string(theory::k_max_box_particles) + "]";
  in.box.particles = keyword_as<std::int64_t>("particles", particles_arg, particles_range);
  in.box.growth = keyword_as<double>("growth", growth_arg);
  if (in.dimension != 2 && in.dimension != 3)
    throw py::value_error("dim: value " + std::to_string(in.dimension) +
                          " is outside the allowed range " + dims);
  if (quadrature != "gauss" && quadrature != "adaptive")
    throw py::value_error("quadrature: must be one of {gauss, adaptive}, got " +
                          repr_text(quadrature_arg));
  // The Gauss rules are exact for these integrands and take no tolerance: one given with them
  // would be ignored without a word.
  const double tolerance =
      tolerance_arg.is_none() ? theory::QuadratureOptions{}.relative_tolerance
                              : keyword_as<double>("tolerance", tolerance_arg);
  if (quadrature == "gauss" && !tolerance_arg.is_none())
    throw py::value_error(
        "tolerance: applies to quadrature='adaptive' only (the Gauss rules are "
        "exact for these integrands)");
  if (!(tolerance >= theory::k_min_relative_tolerance &&
        tolerance <= theory::k_max_relative_tolerance))
    throw py::value_error("tolerance: value " + repr_text(py::float_(tolerance)) +
                          " is outside the allowed range [" +
                          repr_text(py::float_(theory::k_min_relative_tolerance)) + ", " +
                          repr_text(py::float_(theory::k_max_relative_tolerance)) + "]");
  in.quadrature.method = quadrature == "adaptive" ? theory::QuadratureMethod::adaptive
                                                  : theory::QuadratureMethod::gauss;
  in.quadrature.relative_tolerance = tolerance;
  // Restitution, density (close packing, and where τ0 overflows), b (where f2 and μ2 stay
  // positive), particles and growth: compute_report checks them and names them, the checks the
  // CLI reports.
  std::string document;
  try {
    py::gil_scoped_release release;
    document = theory::report_json(in, theory::compute_report(in), k_version).dump();
  } catch (const std::invalid_argument& e) {
    // The message starts with the field's name, which is the keyword's but for correlation_b.
    const std::string field = "correlation_b:";
    std::string message = e.what();
    if (message.starts_with(field)) message.replace(0, field.size(), "b:");
    throw py::value_error(message);
  }
  return py::module_::import("json").attr("loads")(document);
}

template <class T>
constexpr bool is_plain_v =
    std::is_arithmetic_v<T> || std::is_same_v<T, std::vector<double>>;  // else: a named choice

// Keyword arguments into sim::Parameters by a walk over the parameter table (a keyword is a
// row's name; `dim` also names the dimension); named choices (randomize) are read as the CSV
// header reads them. Validation stays sim::validate. The checkpoint keywords go to `checkpoints`.
sim::Parameters parameters_from(const py::kwargs& kwargs, sim::CheckpointOptions& checkpoints) {
  // A restart's parameters are its checkpoint's unless keywords give them (a missing file is the
  // restart's to refuse: FileNotFoundError).
  sim::Parameters p;
  bool from_checkpoint = false;
  if (kwargs.contains("restart"))
    if (const std::string path = path_keyword("restart", kwargs["restart"]);
        std::filesystem::is_regular_file(path)) {
      try {
        p = sim::checkpoint_parameters(path);
      } catch (const sim::CheckpointError& e) {
        throw py::value_error(std::string("restart: ") + e.what());
      }
      from_checkpoint = true;
    }
  std::map<const sim::ParameterInfo*, std::string> given;  // row -> the keyword that set it
  for (auto item : kwargs) {
    const auto name = item.first.cast<std::string>();
    const py::handle v = item.second;
    if (name == "checkpoint") {
      checkpoints.path = path_keyword(name, v);
      continue;
    }
    if (name == "checkpoint_interval") {
      checkpoints.interval = keyword_as<double>(name, v);
      if (!(checkpoints.interval >= 0 && std::isfinite(checkpoints.interval)))
        throw py::value_error("checkpoint_interval: value " + repr_text(v) +
                              " is outside the allowed range [0, inf)");
      continue;
    }
    if (name == "checkpoint_wall") {  // the CLI's --checkpoint-wall
      checkpoints.wall_interval = keyword_as<double>(name, v);
      if (!(checkpoints.wall_interval >= 0 && std::isfinite(checkpoints.wall_interval)))
        throw py::value_error("checkpoint_wall: value " + repr_text(v) +
                              " is outside the allowed range [0, inf)");
      continue;
    }
    if (name == "restart") {
      checkpoints.restart = path_keyword(name, v);
      continue;
    }
    const sim::ParameterInfo* info = sim::find_parameter(name == "dim" ? "dimension" : name);
    if (info == nullptr) {
      // The allowed keywords, and the row a CLI flag's name given as a keyword means (relax for
      // relax_collisions_per_particle): the message says what to write instead.
      std::string allowed = "dim", meant;
      for (const sim::ParameterInfo& row : sim::parameter_table()) {
        allowed += ", " + std::string(row.name);
        std::string flag(row.flag.substr(2));
        std::replace(flag.begin(), flag.end(), '-', '_');
        if (flag == name)
          meant =
              "; the CLI's " + std::string(row.flag) + " is '" + std::string(row.name) + "' here";
      }
      throw py::type_error("simulate() got an unexpected keyword argument '" + name + "'" + meant +
                           "; allowed: " + allowed +
                           ", checkpoint, checkpoint_interval, checkpoint_wall, restart");
    }
    if (const auto [first, inserted] = given.emplace(info, name); !inserted)  // dim and dimension
      throw py::type_error("simulate() got '" + name + "' and '" + first->second +
                           "' for the same parameter; give one");
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(p.*member)>;
          if constexpr (is_plain_v<T>) {
            p.*member = keyword_as<T>(name, v, sim::range_text(*info));
          } else {
            try {
              sim::parse_value(p, *info, keyword_as<std::string>(name, v));
            } catch (const std::invalid_argument&) {
              throw py::value_error(name + ": must be one of " + sim::range_text(*info));
            }
          }
        },
        info->field);
  }
  if (!from_checkpoint && given.count(sim::find_parameter("relax_collisions_per_particle")) == 0)
    sim::default_relaxation_for_method(p);
  if (checkpoints.path.empty() && checkpoints.interval > 0)
    throw py::value_error("checkpoint_interval: needs checkpoint=FILE");
  if (checkpoints.path.empty() && checkpoints.wall_interval > 0)
    throw py::value_error("checkpoint_wall: needs checkpoint=FILE");
  if (!checkpoints.path.empty()) {
    require_writable_file("checkpoint", checkpoints.path);
    try {
      sim::require_replaceable_by_checkpoint(checkpoints.path, checkpoints.restart);
    } catch (const std::invalid_argument& e) {
      throw py::value_error(std::string("checkpoint: ") + e.what());
    }
  }
  try {
    sim::validate(p);
  } catch (const std::invalid_argument& e) {
    // The message starts with the field's name: the keyword's, but where it was given as `dim`.
    std::string message = e.what();
    for (const auto& [info, keyword] : given)
      if (const std::string field = std::string(info->name) + ":"; message.starts_with(field))
        message.replace(0, field.size() - 1, keyword);
    throw py::value_error(message);
  }
  // A missing checkpoint is FileNotFoundError, as Python's own open() says it; after the
  // parameters, whose refusal names the keyword as the command line names the flag.
  std::error_code ec;
  if (!checkpoints.restart.empty() && !std::filesystem::exists(checkpoints.restart, ec)) {
    PyErr_SetObject(
        PyExc_FileNotFoundError,
        py::make_tuple(ENOENT, "restart: no checkpoint file", checkpoints.restart).ptr());
    throw py::error_already_set();
  }
  return p;
}

// Every row of the parameter table: numbers and lists as such, named choices as their names.
py::dict parameters_dict(const sim::Parameters& p) {
  py::dict d;
  for (const sim::ParameterInfo& info : sim::parameter_table())
    std::visit(
        [&](auto member) {
          using T = std::remove_cvref_t<decltype(p.*member)>;
          const std::string key(info.name);
          if constexpr (is_plain_v<T>)
            d[key.c_str()] = p.*member;
          else
            d[key.c_str()] = sim::format_value(p, info);
        },
        info.field);
  return d;
}

// The names of the table's parameters of C++ type T: the flags (bool), True or False in
// parameters_dict, which an H5MD file stores as the integers 0 and 1 (HDF5 has no boolean type)
// and read_trajectory reads back as bools; the reals (double), floats in parameters_dict, which a
// result file's header writes as "5" where the value is whole and the readers read back as floats.
template <class T>
py::tuple parameters_of_type() {
  py::list names;
  for (const sim::ParameterInfo& info : sim::parameter_table())
    if (std::holds_alternative<T sim::Parameters::*>(info.field))
      names.append(std::string(info.name));
  return py::tuple(names);
}

template <class T, class Get>
py::array_t<T> column(const std::vector<sim::Sample>& samples, Get get) {
  py::array_t<T> a(static_cast<py::ssize_t>(samples.size()));
  auto view = a.template mutable_unchecked<1>();
  for (std::size_t i = 0; i < samples.size(); ++i)
    view(static_cast<py::ssize_t>(i)) = get(samples[i]);
  return a;
}

// The contact statistics of every sample (contact_statistics = True), under the names of the
// result CSV's columns: the sums of the collisions since the previous sample, and the
// impact-parameter histogram as one row of ContactMoments::k_impact_bins counts per sample.
void add_contact_columns(py::dict& d, const std::vector<sim::Sample>& s) {
  using C = sim::ContactMoments;
  d["contacts"] = column<std::uint64_t>(s, [](const sim::Sample& x) { return x.contacts.count; });
  const std::pair<const char*, double C::*> sums[] = {{"sum_c1e_c2e", &C::sum_c1e_c2e},
                                                      {"sum_c1_dot_c2", &C::sum_c1_dot_c2},
                                                      {"sum_gn2", &C::sum_gn2},
                                                      {"sum_abs_gn", &C::sum_abs_gn},
                                                      {"sum_g2", &C::sum_g2}};
  for (const auto& [name, field] : sums)
    d[name] = column<double>(s, [field](const sim::Sample& x) { return x.contacts.*field; });
  constexpr auto bins = static_cast<py::ssize_t>(C::k_impact_bins);
  py::array_t<std::uint64_t> impact({static_cast<py::ssize_t>(s.size()), bins});
  auto view = impact.mutable_unchecked<2>();
  for (std::size_t i = 0; i < s.size(); ++i)
    for (py::ssize_t b = 0; b < bins; ++b)
      view(static_cast<py::ssize_t>(i), b) = s[i].contacts.impact_histogram[b];
  d["impact"] = impact;
}

py::array_t<double> particle_matrix(const std::vector<double>& flat, int dimension) {
  const auto n = static_cast<py::ssize_t>(flat.size()) / dimension;
  py::array_t<double> a({n, static_cast<py::ssize_t>(dimension)});
  std::copy(flat.begin(), flat.end(), a.mutable_data());
  return a;
}

struct RunInterrupted {};  // thrown out of a DSMC run, which has no interrupt of its own

py::dict simulate(const py::kwargs& kwargs) {
  sim::CheckpointOptions checkpoints;
  const sim::Parameters p = parameters_from(kwargs, checkpoints);
  const bool main_thread = in_main_thread();
  std::optional<py::error_already_set> signal_error;  // raised by a Python signal handler
  std::optional<sim::RunResult> result;
  {
    const SigintWatch watch;
    checkpoints.interrupt = &interrupt_requested();
    const sim::ProgressReporter look_at_signals = [&](const sim::Progress&) {
      if (main_thread && !interrupt_requested().load()) {
        const py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) {
          signal_error.emplace();  // takes the exception the handler raised
          interrupt_requested().store(true);
        }
      }
      if (p.method == sim::Method::dsmc && interrupt_requested().load()) throw RunInterrupted{};
    };
    try {
      py::gil_scoped_release release;  // the engine touches no Python object
      result = sim::run_with_checkpoints(p, look_at_signals, checkpoints);
    } catch (const sim::CheckpointError& e) {  // the checkpoint continued: restart's file
      throw py::value_error(std::string("restart: ") + e.what());
    } catch (const RunInterrupted&) {
      result.reset();
    }
  }  // Python's own SIGINT handler is back
  // A handler's exception goes on, whether the run stopped for it or had just ended when it ran.
  if (signal_error) throw std::move(*signal_error);
  if (!result) {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    PyErr_SetNone(PyExc_KeyboardInterrupt);  // a handler that raised nothing: still no result
    throw py::error_already_set();
  }
  // checkpoint= alone writes only when the run is interrupted: a run that finished leaves no
  // file to go on from, which the caller may have counted on.
  if (checkpoints.only_on_interrupt()) {
    const std::string note = "no checkpoint written to " + checkpoints.path +
                             ": without checkpoint_interval or checkpoint_wall one is written "
                             "only when the run is interrupted";
    if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0) throw py::error_already_set();
  }
  const sim::RunResult& r = *result;
  const auto& s = r.samples;
  py::dict d;
  d["t"] = column<double>(s, [](const sim::Sample& x) { return x.t; });
  d["T"] = column<double>(s, [](const sim::Sample& x) { return x.temperature; });
  d["a2"] = column<double>(s, [](const sim::Sample& x) { return x.a2; });
  d["collisions"] = column<std::uint64_t>(s, [](const sim::Sample& x) { return x.collisions; });
  d["events"] = column<std::uint64_t>(s, [](const sim::Sample& x) { return x.events; });
  d["velocity_mode"] = column<double>(s, [](const sim::Sample& x) { return x.velocity_mode; });
  d["density_mode"] = column<double>(s, [](const sim::Sample& x) { return x.density_mode; });
  if (r.parameters.contact_statistics) add_contact_columns(d, s);
  py::list snapshots;
  for (const auto& snap : r.snapshots) {
    py::dict sd;
    sd["t"] = snap.t;
    sd["box"] = snap.box;
    sd["collisions"] = snap.collisions;
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

// help(molchaos.simulate): every keyword from the parameter table, with its default, range, unit
// and meaning, so that the text cannot fall behind the parameters the function takes.
std::string simulate_doc() {
  std::string doc =
      "One cooling run: relaxation at restitution 1, then the cooling gas to t_end, sampled on a\n"
      "log-spaced grid (the CLI's `molchaos simulate`; the same parameters give the same numbers,\n"
      "bit for bit). Keywords only; an unknown keyword, a value of the wrong type (TypeError) or\n"
      "out of its range (ValueError) is refused naming the parameter.\n\n"
      "Run parameters (default; allowed range; unit):\n";
  const sim::Parameters defaults;
  for (const sim::ParameterInfo& info : sim::parameter_table()) {
    const std::string name(info.name);
    std::string text = sim::format_value(defaults, info);
    if (name == "snapshot_times") text = "[]";
    if (text == "false") text = "False";
    if (!info.choices.empty()) text = "'" + text + "'";
    doc += "  " + name + (name == "dimension" ? " (or dim)" : "") + " = " + text + "; ";
    if (text == "False")
      doc += "True or False";
    else
      doc += info.choices.empty() ? sim::range_text(info) : sim::choice_list(info);
    if (!info.unit.empty()) doc += "; " + std::string(info.unit);
    doc += "\n      " + std::string(info.doc) + "\n";
  }
  doc +=
      "  (relax_collisions_per_particle defaults to 0 for method = 'dsmc', which relaxes nothing)\n"
      "\nCheckpoints (event-driven method only):\n"
      "  checkpoint = FILE (str or os.PathLike), checkpoint_interval = DT (simulated time between\n"
      "      checkpoints, >= 0), checkpoint_wall = S (wall-clock seconds between checkpoints,\n"
      "      >= 0): writes the run's whole state;\n"
      "  restart = FILE: continues a checkpoint (FileNotFoundError if there is none), its\n"
      "      parameters taken from the file where no keyword gives them (only t_end may\n"
      "      differ); the result equals the uninterrupted run's.\n"
      "\nCtrl-C stops a run called from the main thread at its next sample time or progress\n"
      "pause (at most 2^20 events, in the relaxation too; while the initial state is built,\n"
      "within 2^16 particles) and raises KeyboardInterrupt; with checkpoint = FILE the run's\n"
      "state at that point is written there first (none before t = 0). A signal\n"
      "handler of the caller's that raises stops it the same way: for a batch system's\n"
      "SIGTERM, which otherwise ends Python at once, install one (signal.signal(\n"
      "signal.SIGTERM, handler), handler raising KeyboardInterrupt). Python runs signal\n"
      "handlers in the main thread only, so a run called from another thread is not stopped\n"
      "by them. The engine runs without the GIL.\n" +
      fmt::format(
          "\nThe relaxed state of a run (N, density, seed, relaxation and the other parameters\n"
          "the relaxation reads) is kept in the process for the next run of the same key, which\n"
          "then starts from it bit for bit instead of relaxing again (an ensemble over\n"
          "restitutions): states of up to {} MB, {} MB in all, the oldest dropped first.\n"
          "clear_relaxed_states() frees them (a loop over many seeds).\n",
          sim::k_largest_kept_state >> 20, sim::k_kept_bytes >> 20) +
      "\nReturns a dict:\n"
      "  t, T, a2, velocity_mode, density_mode: float64 arrays, one entry per sample (time,\n"
      "      temperature T = m<v^2>/d, second Sonine coefficient, largest-scale momentum and\n"
      "      density fluctuations); collisions, events: uint64 arrays, counts up to each sample;\n"
      "  with contact_statistics = True also, per sample, of the collisions since the one\n"
      "      before (the result CSV's columns): contacts (uint64), sum_c1e_c2e, sum_c1_dot_c2,\n"
      "      sum_gn2, sum_abs_gn, sum_g2 (float64), and impact (uint64, samples x 10): the\n"
      "      impact-parameter histogram;\n"
      "  snapshots: list of dicts with t, box, collisions (since t = 0) and positions, velocities\n"
      "      (float64, N x d), one per snapshot time;\n"
      "  parameters: dict of every run parameter above (choices as their names);\n"
      "  version, stop_reason (str); total_collisions, total_events (int); wall_seconds (float).";
  return doc;
}

}  // namespace
}  // namespace molchaos::python

PYBIND11_MODULE(_molchaos, m) {
  using namespace molchaos::python;
  m.doc() = "molchaos: kinetic theory and event-driven MD of granular gases (sigma = m = k_B = 1)";
  // MemoryError with the CLI's words instead of pybind11's bare "std::bad_alloc".
  py::register_exception_translator([](std::exception_ptr raised) {
    try {
      if (raised) std::rethrow_exception(raised);
    } catch (const std::bad_alloc&) {
      PyErr_SetString(PyExc_MemoryError, molchaos::sim::k_out_of_memory_message);
    }
  });
  m.attr("__version__") = std::string(molchaos::k_version);
  // theory()'s keywords: its signature below, and the check of unknown keywords in the package
  // (__init__.py), whose message names the keyword (pybind11's prints the whole signature).
  static constexpr std::array<const char*, 8> keywords{
      "dim", "restitution", "density", "b", "quadrature", "tolerance", "particles", "growth"};
  m.attr("_theory_keywords") = py::cast(std::vector<std::string>(keywords.begin(), keywords.end()));
  const molchaos::theory::ReportInputs defaults;
  m.def(
      "_theory", &theory_report, py::kw_only(), py::arg(keywords[0]) = py::int_(defaults.dimension),
      py::arg(keywords[1]) = py::float_(defaults.restitution),
      py::arg(keywords[2]) = py::float_(defaults.density),
      py::arg(keywords[3]) = py::float_(defaults.correlation_b),
      py::arg(keywords[4]) = py::str("gauss"), py::arg(keywords[5]) = py::none(),
      py::arg(keywords[6]) = py::int_(defaults.box.particles),
      py::arg(keywords[7]) = py::float_(defaults.box.growth),
      "Kinetic-theory report for one state point: the document `molchaos theory --json` prints,\n"
      "key for key, as Python values.\n\n"
      "dim (or dimension): 2 or 3; restitution: in (0, 1]; density: reduced density n, above 0\n"
      "and below close packing; b: the velocity correlation at contact of the paper's ansatz, in\n"
      "the range where f2 and mu2 stay positive (the error names it); quadrature: 'gauss' (fixed\n"
      "rules, exact for these integrands) or 'adaptive' (GSL's QAGIU, the independent check);\n"
      "tolerance: its relative tolerance, in [1e-13, 1e-2], default 1e-10 (adaptive only);\n"
      "particles: N of the box whose largest shear mode is followed, in [2, 1e8]; growth: the\n"
      "level of that mode's S_perp whose time is given, in (1, 1e12].\n"
      "Keywords only; a value of the wrong type raises TypeError, one out of range ValueError,\n"
      "each naming the parameter.\n\n"
      "Returns a dict: version; inputs; packing_fraction, g2, g2_extrapolated, a2, mu2 and\n"
      "mu2_error, mu2_ratio, omega0, tau0 and tau0_error (None where the gas does not cool),\n"
      "A and A_error, A_uncorrelated (A at b = 0), enskog_collision_frequency; b_range; "
      "coefficients\n"
      "(mu2's expansion against the paper's printed values and the exact forms),\n"
      "coefficients_traceless_dyad, prefactors; sonine (a2, a3 and A at four levels of Sonine\n"
      "theory); contact_response; critical_box_size, critical_shear_wavenumber,\n"
      "critical_heat_wavenumber, transport, largest_shear_mode (linear hydrodynamics); seconds.\n"
      "Each error is the quadrature's estimate of the value beside it.");
  m.def("simulate", &simulate, simulate_doc().c_str());
  m.def("clear_relaxed_states", &molchaos::sim::clear_relaxed_states,
        "Frees the relaxed states that simulate() keeps for later runs of the same key (see\n"
        "simulate's help); the runs after it relax again, to the same bits.");
  m.attr("_flag_parameters") = parameters_of_type<bool>();
  m.attr("_real_parameters") = parameters_of_type<double>();
}
