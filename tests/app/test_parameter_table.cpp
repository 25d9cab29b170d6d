// Walks the parameter table and checks that every consumer knows every row: a value changed in
// one field shows up in the CSV header (written and read back), the cache key, the MPI message and
// the `simulate` command line. A row some consumer forgets fails here.
#define BOOST_TEST_MODULE parameter_table
#include <sys/wait.h>

#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/validation/sweep.hpp"
#ifdef MOLCHAOS_HAVE_MPI
#include "molchaos/mpi/wire.hpp"
#endif

using namespace molchaos;

namespace {

// A fast run: the base every field is changed from.
sim::Parameters small_run() {
  sim::Parameters p;
  p.particles = 100;
  p.t_end = 0.5;
  p.relax_collisions_per_particle = 1.0;
  return p;
}

// `base` with the field of `info` set to another allowed value.
sim::Parameters changed(const sim::Parameters& base, const sim::ParameterInfo& info) {
  sim::Parameters p = base;
  std::visit(
      [&](auto member) {
        auto& v = p.*member;
        using T = std::remove_cvref_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>)
          v = !v;
        else if constexpr (std::is_same_v<T, sim::Randomization>)
          v = sim::Randomization::flux;
        else if constexpr (std::is_same_v<T, std::vector<double>>)
          v = {0.25};
        else if constexpr (std::is_same_v<T, std::uint64_t>)
          v += 7;
        else if constexpr (std::is_same_v<T, double>)
          v = v == 0.0 ? 0.5 : 0.75 * v;
        else
          v = static_cast<double>(v + 1) <= info.range.hi ? v + 1 : v - 1;
      },
      info.field);
  return p;
}

std::string header_text(const sim::Parameters& p) {
  sim::RunResult r;
  r.parameters = p;
  r.version = "test";
  r.stop_reason = sim::StopReason::t_end;
  std::ostringstream out;
  sim::write_csv(r, out);
  return out.str();
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_row_names_a_distinct_field_flag_and_range) {
  const auto& table = sim::parameter_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    BOOST_TEST_CONTEXT(table[i].name) {
      BOOST_TEST(table[i].flag.rfind("--", 0) == 0u);
      BOOST_TEST(!table[i].doc.empty());
      BOOST_TEST(sim::find_parameter(table[i].name) == &table[i]);
      for (std::size_t j = 0; j < i; ++j) {
        BOOST_TEST(table[j].flag != table[i].flag);
        BOOST_TEST((table[j].field != table[i].field));
      }
      // The default lies inside the row's range.
      BOOST_CHECK_NO_THROW(sim::check_range(sim::Parameters{}, table[i]));
    }
  }
}

BOOST_AUTO_TEST_CASE(every_row_reaches_the_csv_header_and_back) {
  for (const auto& info : sim::parameter_table()) {
    BOOST_TEST_CONTEXT(info.name) {
      const sim::Parameters p = changed(small_run(), info);
      BOOST_CHECK_NO_THROW(sim::validate(p));
      BOOST_TEST(sim::format_value(p, info) != sim::format_value(small_run(), info));
      const std::string text = header_text(p);
      BOOST_TEST(text.find("# " + std::string(info.name) + " = " + sim::format_value(p, info) +
                           "\n") != std::string::npos);
      std::istringstream in(text);
      const sim::RunResult back = sim::read_csv(in);
      BOOST_TEST(sim::format_value(back.parameters, info) == sim::format_value(p, info));
    }
  }
}

BOOST_AUTO_TEST_CASE(every_row_changes_the_cache_key) {
  const std::string base_key = validation::cache_key(small_run(), "v");
  for (const auto& info : sim::parameter_table()) {
    BOOST_TEST_CONTEXT(info.name) {
      BOOST_TEST(validation::cache_key(changed(small_run(), info), "v") != base_key);
    }
  }
}

#ifdef MOLCHAOS_HAVE_MPI
BOOST_AUTO_TEST_CASE(every_row_travels_in_the_mpi_message) {
  const std::string base = mpi::encode(mpi::JobMessage{3, small_run()});
  for (const auto& info : sim::parameter_table()) {
    BOOST_TEST_CONTEXT(info.name) {
      const sim::Parameters p = changed(small_run(), info);
      const std::string bytes = mpi::encode(mpi::JobMessage{3, p});
      BOOST_TEST(bytes != base);
      const auto back = mpi::decode_job(bytes);
      BOOST_TEST(validation::canonical_parameters(back.parameters, "") ==
                 validation::canonical_parameters(p, ""));
    }
  }
}
#endif

// The flag of each row given to `molchaos simulate` ends up in the run's CSV header.
BOOST_AUTO_TEST_CASE(every_row_is_a_flag_of_simulate) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("molchaos_table_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const sim::Parameters base = small_run();
  for (const auto& info : sim::parameter_table()) {
    BOOST_TEST_CONTEXT(info.name) {
      const sim::Parameters p = changed(base, info);
      std::string args;
      for (const auto& other : sim::parameter_table()) {
        const sim::Parameters& source = &other == &info ? p : base;
        if (std::holds_alternative<bool sim::Parameters::*>(other.field)) {
          if (sim::format_value(source, other) == "true") args += " " + std::string(other.flag);
        } else if (!sim::format_value(source, other).empty()) {
          args += " " + std::string(other.flag) + " " + sim::format_value(source, other);
        }
      }
      const fs::path out = dir / (std::string(info.name) + ".csv");
      const std::string command =
          std::string(MOLCHAOS_BIN) + " simulate --quiet" + args + " --out " + out.string();
      const int status = std::system((command + " 2>/dev/null").c_str());
      BOOST_TEST_MESSAGE(command);
      BOOST_TEST((WIFEXITED(status) && WEXITSTATUS(status) == 0));
      if (!fs::exists(out)) continue;
      const sim::RunResult back = sim::read_csv_file(out.string());
      BOOST_TEST(validation::canonical_parameters(back.parameters, "") ==
                 validation::canonical_parameters(p, ""));
    }
  }
  fs::remove_all(dir);
}
