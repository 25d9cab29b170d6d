// `molchaos theory --json` for d = 2 and 3: one complete JSON document with the inputs, the
// predictions and the coefficient rows the issue names, with the verdicts the integral implies.
#define BOOST_TEST_MODULE cli_theory_json
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace {
nlohmann::json run(const std::string& args) {
  const std::string command = std::string(MOLCHAOS_BINARY) + " theory --json " + args;
  FILE* pipe = popen(command.c_str(), "r");
  BOOST_REQUIRE(pipe != nullptr);
  std::string text;
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) text.append(buffer, n);
  BOOST_REQUIRE_EQUAL(pclose(pipe), 0);
  return nlohmann::json::parse(text);
}

const nlohmann::json& row(const nlohmann::json& j, const std::string& term) {
  for (const auto& r : j.at("coefficients"))
    if (r.at("term") == term) return r;
  BOOST_FAIL("no coefficient row " + term);
  return j;
}
}  // namespace

BOOST_AUTO_TEST_CASE(two_and_three_dimensions) {
  for (int d : {2, 3}) {
    const auto j = run("--dim " + std::to_string(d) + " --restitution 0.9 --density 0.05");
    BOOST_TEST(j.at("inputs").at("dim") == d);
    BOOST_TEST(j.at("inputs").at("restitution") == 0.9);
    for (const char* key : {"g2", "a2", "mu2", "tau0", "A"}) BOOST_TEST(j.at(key).is_number());
    BOOST_TEST(j.at("coefficients").size() == 5u);
    const auto& a2 = row(j, "a2");
    BOOST_TEST(a2.at("paper") == 3.0 / 16.0);
    BOOST_TEST(a2.at("reproduced") == true);
    BOOST_TEST(std::abs(a2.at("computed").get<double>() - 3.0 / 16.0) <= 1e-9);
    const auto& b = row(j, "b");
    BOOST_TEST(b.at("paper") == -63.0 / 40.0);
    BOOST_TEST(b.at("reproduced") == false);
    BOOST_TEST(std::abs(b.at("computed").get<double>() + 1.5) <= 1e-9);
    BOOST_TEST(row(j, "a2^2").at("paper").is_null());
    BOOST_TEST(row(j, "a2^2").at("reproduced").is_null());
    const double A = j.at("A").get<double>(), tau0 = j.at("tau0").get<double>();
    BOOST_TEST(std::abs(A - tau0 * (1 - 0.9 * 0.9)) <= 1e-12 * A);
  }
}

BOOST_AUTO_TEST_CASE(elastic_input_gives_null_tau0) {
  const auto j = run("--dim 2 --restitution 1 --density 0.1");
  BOOST_TEST(j.at("tau0").is_null());
  BOOST_TEST(j.at("A").is_number());
}
