// validation/verdict.hpp: the one agreement rule at its edges (exactly 3 combined standard
// errors, zero errors, exact closed forms) and the bound rule.
#define BOOST_TEST_MODULE validation_verdict
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "molchaos/validation/verdict.hpp"

using namespace molchaos::validation;

BOOST_AUTO_TEST_CASE(agreement_uses_the_combined_standard_error) {
  // σ = √(0.3² + 0.4²) = 0.5, so the limit is 1.5.
  const Agreement inside = agreement({11.49, 0.3}, {10.0, 0.4});
  BOOST_TEST(inside.agrees);
  BOOST_TEST(*inside.difference_in_se == 2.98, boost::test_tools::tolerance(1e-12));
  const Agreement outside = agreement({11.51, 0.3}, {10.0, 0.4});
  BOOST_TEST(!outside.agrees);
  BOOST_TEST(*outside.difference_in_se == 3.02, boost::test_tools::tolerance(1e-12));
  // Symmetric in sign.
  BOOST_TEST(!agreement({8.49, 0.3}, {10.0, 0.4}).agrees);
}

BOOST_AUTO_TEST_CASE(exact_values_agree_only_to_rounding) {
  // Closed forms without error: 3/16 computed as 0.1875 agrees, -1.5 against -63/40 does not.
  const Agreement same = agreement({3.0 / 16.0 * (1.0 + 1e-15), 0.0}, {0.1875, 0.0});
  BOOST_TEST(same.agrees);
  BOOST_TEST(!same.difference_in_se.has_value());
  BOOST_TEST(!agreement({-1.5, 0.0}, {-63.0 / 40.0, 0.0}).agrees);
}

BOOST_AUTO_TEST_CASE(bound_rule_needs_three_standard_errors_of_room) {
  BOOST_TEST(significantly_below({0.5, 0.03}, 0.6));   // 0.59 < 0.6
  BOOST_TEST(!significantly_below({0.5, 0.04}, 0.6));  // 0.62 > 0.6
  BOOST_TEST(!significantly_below({0.7, 0.0}, 0.6));
}
