// `molchaos theory --json` for d = 2 and 3: one complete JSON document with the inputs, the
// predictions, the coefficient rows, the Sonine levels and the contact response, with the verdicts
// the integral implies.
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

BOOST_AUTO_TEST_CASE(sonine_levels_contact_response_and_b_range) {
  for (int d : {2, 3}) {
    const auto j = run("--dim " + std::to_string(d) + " --restitution 0.6 --b 0.05");
    // Four Sonine levels side by side; the first is van Noije & Ernst's a2 (as "a2" above).
    const auto& levels = j.at("sonine");
    BOOST_TEST(levels.size() == 4u);
    BOOST_TEST(levels.at(0).at("level") == "first_sonine");
    const double a2_level = levels.at(0).at("a2").at("value").get<double>();
    BOOST_TEST(std::abs(a2_level - j.at("a2").get<double>()) <=
               3.0 * levels.at(0).at("a2").at("error").get<double>() + 1e-15);
    BOOST_TEST(levels.at(0).at("a3").at("value").get<double>() == 0.0);
    BOOST_TEST(levels.at(3).at("level") == "a2_a3");
    BOOST_TEST(levels.at(3).at("a3").at("value").get<double>() < 0.0);  // a3 < 0 at ε = 0.6
    // The first level's A is the prediction's A (same a2 up to its error, same b).
    BOOST_TEST(std::abs(levels.at(0).at("A").at("value").get<double>() - j.at("A").get<double>()) <=
               levels.at(0).at("A").at("error").get<double>() + j.at("A_error").get<double>());
    for (const auto& l : levels)
      for (const char* k : {"a2", "a3", "mu2_ratio", "A"}) BOOST_TEST(l.at(k).at("error") >= 0.0);
    // Contact response with its exact forms; molecular chaos ⟨D⟩ = −1/2 for the printed dyad.
    const auto& dyad = j.at("contact_response").at("printed_dyad").at("dyad");
    BOOST_TEST(std::abs(dyad.at("value").at("value").get<double>() + 0.5) <= 1e-12);
    BOOST_TEST(dyad.at("exact").at(0) == "-1/2");
    // The allowed range of b contains the input and excludes the zero of μ2.
    BOOST_TEST(j.at("b_range").at("lower").get<double>() == -2.0);
    BOOST_TEST(j.at("b_range").at("upper").get<double>() > 0.05);
    BOOST_TEST(j.at("A_error").get<double>() >= 0.0);
    BOOST_TEST(j.at("tau0_error").get<double>() >= 0.0);
  }
}

// Near the end of b's range, where the first level's μ2 is just positive, a level whose a2 and a3
// put μ2 at or below zero has no A (null, not a negative cooling time); every A given is positive.
BOOST_AUTO_TEST_CASE(a_level_that_does_not_cool_has_no_A) {
  for (int d : {2, 3}) {
    const std::string state = "--dim " + std::to_string(d) + " --restitution 0.9";
    const double upper = run(state).at("b_range").at("upper").get<double>();
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", upper - 1e-9);
    const auto j = run(state + " --b " + b);
    int without = 0;
    for (const auto& level : j.at("sonine")) {
      // The ratio behind A, at the given b, says why a level has none.
      const auto& ratio = level.at("mu2_ratio_at_b");
      const bool cools = ratio.at("value").get<double>() > ratio.at("error").get<double>();
      BOOST_TEST(level.at("A").is_null() == !cools);
      if (level.at("A").is_null()) {
        ++without;
        continue;
      }
      BOOST_TEST(level.at("A").at("value").get<double>() > 0.0);
    }
    BOOST_TEST(!j.at("sonine").at(0).at("A").is_null());  // the range's own level
    BOOST_TEST(without >= 1);
  }
}
