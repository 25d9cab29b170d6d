// Walks the parameter table and checks that every consumer knows every row: a value changed in
// one field shows up in the CSV header (written and read back), the cache key, the MPI message and
// the `simulate` command line. A row some consumer forgets fails here.
#define BOOST_TEST_MODULE parameter_table
#include <sys/wait.h>

#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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
        else if constexpr (std::is_enum_v<T>)  // a choice: its last value
          v = static_cast<T>(info.choices.size() - 1);
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
  // The one field that follows another: a method that does not relax has relax 0.
  sim::default_relaxation_for_method(p);
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
        const sim::Parameters& source = p;  // base but for the row changed
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

// Every name of a choice row reads back to its value and prints as itself; a value outside the
// list is refused with the list in the message.
BOOST_AUTO_TEST_CASE(every_choice_row_walks_its_names) {
  std::size_t choice_rows = 0;
  for (const auto& info : sim::parameter_table()) {
    if (info.choices.empty()) continue;
    ++choice_rows;
    BOOST_TEST_CONTEXT(info.name) {
      BOOST_TEST(sim::range_text(info) == "{" + sim::choice_list(info) + "}");
      for (std::size_t i = 0; i < info.choices.size(); ++i) {
        sim::Parameters p;
        sim::parse_value(p, info, info.choices[i]);
        BOOST_TEST(sim::choice_index(p, info) == i);
        BOOST_TEST(sim::format_value(p, info) == info.choices[i]);
      }
      sim::Parameters p;
      BOOST_CHECK_THROW(sim::parse_value(p, info, "no-such-choice"), std::invalid_argument);
      BOOST_CHECK_THROW(sim::set_choice_index(p, info, info.choices.size()), std::invalid_argument);
    }
  }
  BOOST_TEST(choice_rows == 2u);  // randomize, method
  BOOST_TEST(sim::choice_list(*sim::find_parameter("method")) == "edmd, dsmc");
}

// The method row came after cache entries existed: at its default (edmd) it is absent from the
// CSV header and the cache key, so an EDMD run's header and key are those of the code before it.
BOOST_AUTO_TEST_CASE(the_default_method_keeps_old_headers_and_keys) {
  // The parameters of one cache entry of `molchaos sweep --particles 100 --density 0.1
  // --restitution 0.9 --seeds 1 --t-end-tau0 0.5 --relax 1` (default base seed).
  sim::Parameters p;
  p.particles = 100;
  p.density = 0.1;
  p.restitution = 0.9;
  p.seed = 10451216379200822465ULL;
  p.t_end = 26.242185231712927;
  p.relax_collisions_per_particle = 1;
  p.samples_per_decade = 40;
  p.contact_statistics = true;
  // Computed by the code before the method row existed: FNV-1a of the canonical text with
  // version "v" (the same code named that sweep's cache file by the key of its version string).
  BOOST_TEST(validation::cache_key(p, "v") == "909b3df1ffb4811f");
  BOOST_TEST(header_text(p).find("method") == std::string::npos);
  sim::Parameters dsmc = p;
  dsmc.method = sim::Method::dsmc;
  BOOST_TEST(validation::cache_key(dsmc, "v") != "909b3df1ffb4811f");
  BOOST_TEST(header_text(dsmc).find("# method = dsmc\n") != std::string::npos);
  // A header without the row reads as the default.
  std::istringstream in(header_text(p));
  BOOST_TEST((sim::read_csv(in).parameters.method == sim::Method::edmd));
}

namespace {

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The column line: the first line that is not a comment.
std::string column_line(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  while (std::getline(in, line))
    if (line.empty() || line[0] != '#') return line;
  return {};
}

int run_command(const std::string& command) {
  BOOST_TEST_MESSAGE(command);
  const int status = std::system((command + " 2>/dev/null").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

// `simulate --method dsmc` writes the columns of an MD run, and the flags its header lists re-run
// it to the same bytes.
BOOST_AUTO_TEST_CASE(a_dsmc_run_has_the_md_columns_and_its_header_reruns_it) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("molchaos_dsmc_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string bin = std::string(MOLCHAOS_BIN) + " simulate --quiet";
  const std::string common = " --particles 400 --restitution 0.8 --t-end 2 --contacts";
  BOOST_TEST_REQUIRE(run_command(bin + common + " --out " + (dir / "md.csv").string()) == 0);
  BOOST_TEST_REQUIRE(
      run_command(bin + common + " --method dsmc --out " + (dir / "dsmc.csv").string()) == 0);
  const std::string md = file_text(dir / "md.csv"), dsmc = file_text(dir / "dsmc.csv");
  BOOST_TEST(!column_line(dsmc).empty());
  BOOST_TEST(column_line(dsmc) == column_line(md));
  const sim::RunResult first = sim::read_csv_file((dir / "dsmc.csv").string());
  BOOST_TEST((first.parameters.method == sim::Method::dsmc));
  BOOST_TEST(first.collisions > 0u);

  std::string args;
  for (const auto& info : sim::parameter_table()) {
    const std::string value = sim::format_value(first.parameters, info);
    if (std::holds_alternative<bool sim::Parameters::*>(info.field)) {
      if (value == "true") args += " " + std::string(info.flag);
    } else if (!value.empty()) {
      args += " " + std::string(info.flag) + " " + value;
    }
  }
  BOOST_TEST_REQUIRE(run_command(bin + args + " --out " + (dir / "again.csv").string()) == 0);
  BOOST_TEST(file_text(dir / "again.csv") == dsmc);
  fs::remove_all(dir);
}
