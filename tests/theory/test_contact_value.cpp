// g2(σ): limits, closed forms at chosen packing fractions, and argument checks.
#define BOOST_TEST_MODULE theory_contact_value
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <numbers>

#include "molchaos/theory/contact_value.hpp"
#include "molchaos/theory/dimension.hpp"

using namespace molchaos::theory;

BOOST_AUTO_TEST_CASE(ideal_gas_limit_is_one) {
  BOOST_TEST(contact_value_g2(2, 0.0) == 1.0);
  BOOST_TEST(contact_value_g2(3, 0.0) == 1.0);
}

BOOST_AUTO_TEST_CASE(henderson_and_carnahan_starling_at_half_packing) {
  // η = 1/2: disks (1 − 7/32)/(1/4) = 25/8; spheres (3/4)/(1/8) = 6.
  BOOST_TEST(std::abs(contact_value_g2(2, 0.5) - 25.0 / 8.0) <= 1e-15);
  BOOST_TEST(std::abs(contact_value_g2(3, 0.5) - 6.0) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(second_virial_slope) {
  // Low-density expansion g2 = 1 + c η + O(η²): c = 25/16 (disks: 2 − 7/16), 5/2 (spheres).
  const double eta = 1e-7;
  BOOST_TEST(std::abs((contact_value_g2(2, eta) - 1.0) / eta - 25.0 / 16.0) <= 1e-5);
  BOOST_TEST(std::abs((contact_value_g2(3, eta) - 1.0) / eta - 2.5) <= 1e-5);
}

BOOST_AUTO_TEST_CASE(paper_densities) {
  // n = 0.05 and 0.1 disks: η = π n / 4.
  for (double n : {0.05, 0.1}) {
    const double eta = std::numbers::pi * n / 4.0;
    BOOST_TEST(std::abs(packing_fraction(2, n) - eta) <= 1e-16);
    const double expected = (1.0 - 7.0 * eta / 16.0) / ((1.0 - eta) * (1.0 - eta));
    BOOST_TEST(std::abs(contact_value_g2_at_density(2, n) - expected) <= 1e-15);
  }
}

BOOST_AUTO_TEST_CASE(bad_arguments_name_the_parameter) {
  auto message_of = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  BOOST_TEST(message_of([] { contact_value_g2(4, 0.1); }).find("dimension") == 0u);
  BOOST_TEST(message_of([] { contact_value_g2(2, 1.0); }).find("packing_fraction") == 0u);
  BOOST_TEST(message_of([] { contact_value_g2_at_density(2, 0.0); }).find("density") == 0u);
  BOOST_TEST(message_of([] { contact_value_g2_at_density(2, 1.2); }).find("(0, 1.1547") !=
             std::string::npos);
  BOOST_TEST(message_of([] { contact_value_g2_at_density(3, 1.5); }).find("density") == 0u);
}
