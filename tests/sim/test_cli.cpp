// The `simulate` command: bad arguments exit 2 with one line naming the argument; a good run
// writes a CSV that reads back; an inelastic collapse exits non-zero with the reason.
#define BOOST_TEST_MODULE sim_cli
#include <sys/wait.h>

#include <boost/test/unit_test.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "molchaos/sim/csv.hpp"

namespace {

struct Outcome {
  int status = -1;
  std::string err;
};

Outcome simulate(const std::string& args) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string err_path = (dir / "molchaos_test_sim_cli.err").string();
  const std::string command =
      std::string(MOLCHAOS_BIN) + " simulate " + args + " 2>" + err_path + " >/dev/null";
  const int raw = std::system(command.c_str());
  Outcome out;
  out.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  std::ifstream in(err_path);
  std::stringstream text;
  text << in.rdbuf();
  out.err = text.str();
  return out;
}

std::size_t lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

void expect_usage_error(const std::string& args, const std::string& argument) {
  const Outcome o = simulate(args);
  BOOST_TEST_MESSAGE(args << " -> " << o.status << ": " << o.err);
  BOOST_TEST(o.status == 2);
  BOOST_TEST(lines(o.err) == 1u);
  BOOST_TEST(o.err.find(argument) != std::string::npos);
}

}  // namespace

BOOST_AUTO_TEST_CASE(bad_arguments_exit_2_naming_the_argument) {
  expect_usage_error("--density 0", "--density");
  expect_usage_error("--density 1.2", "--density");  // above 2D close packing 1.1547
  expect_usage_error("--dim 3 --density 1.5", "--density");
  expect_usage_error("--restitution 1.5", "--restitution");
  expect_usage_error("--restitution 0", "--restitution");
  expect_usage_error("--dim 4", "--dim");
  expect_usage_error("--particles 1", "--particles");
  expect_usage_error("--randomize shuffle", "--randomize");
  expect_usage_error("--t-end -1", "--t-end");
  expect_usage_error("--t-end 10 --snapshot-times 20", "--snapshot-times");
  expect_usage_error("--particles 8 --density 1", "--particles");  // box below 4 sigma
  const Outcome o = simulate("--randomize shuffle");
  BOOST_TEST(o.err.find("none, paper, flux") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_run_writes_a_readable_csv) {
  const auto path = (std::filesystem::temp_directory_path() / "molchaos_test_sim_cli.csv").string();
  std::filesystem::remove(path);
  const Outcome o = simulate(
      "--particles 500 --density 0.1 --restitution 0.9 --randomize paper "
      "--t-end 20 --contacts --out " +
      path);
  BOOST_TEST(o.status == 0);
  const auto r = molchaos::sim::read_csv_file(path);
  BOOST_TEST(r.parameters.particles == 500);
  BOOST_TEST((r.stop_reason == molchaos::sim::StopReason::t_end));
  BOOST_TEST(r.samples.back().t == 20.0);
  BOOST_TEST(r.samples.back().temperature < 1.0);
  std::filesystem::remove(path);
}

BOOST_AUTO_TEST_CASE(collapse_exits_nonzero_with_the_reason) {
  const auto path =
      (std::filesystem::temp_directory_path() / "molchaos_test_sim_cli2.csv").string();
  const Outcome o =
      simulate("--particles 1000 --density 0.3 --restitution 0.2 --t-end 1e6 --out " + path);
  BOOST_TEST_MESSAGE(o.err);
  BOOST_TEST(o.status != 0);
  BOOST_TEST(o.status != 2);
  BOOST_TEST(o.err.find("collapse") != std::string::npos);
  const auto r = molchaos::sim::read_csv_file(path);  // partial results are still written
  BOOST_TEST((r.stop_reason == molchaos::sim::StopReason::collapse));
  std::filesystem::remove(path);
}
