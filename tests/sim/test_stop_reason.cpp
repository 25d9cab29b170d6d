// Unit tests of the stop reasons: names, the CSV texts of today's files, parsing them back.
#define BOOST_TEST_MODULE sim_stop_reason
#include <boost/test/unit_test.hpp>

#include "molchaos/sim/stop_reason.hpp"

using namespace molchaos::sim;

BOOST_AUTO_TEST_CASE(plain_reasons_are_their_names) {
  BOOST_TEST(describe(StopReason::t_end, 5.0) == "t_end");
  BOOST_TEST(describe(StopReason::max_collisions, 5.0) == "max_collisions");
  BOOST_TEST(describe(StopReason::min_temperature, 5.0) == "min_temperature");
}

BOOST_AUTO_TEST_CASE(collapse_and_stall_name_the_time_and_threshold) {
  BOOST_TEST(describe(StopReason::collapse, 12.5) ==
             "collapse: 100000 consecutive collisions less than 1e-10 mean free times apart at "
             "t = 12.500000 (inelastic collapse; the TC model, simulate --tc > 0, avoids it)");
  BOOST_TEST(describe(StopReason::stalled, 3.0) ==
             "stalled: 10000000 events without a collision at the same time t = 3.000000 (a "
             "numerical dead-lock in the engine; please report it with the parameters)");
}

BOOST_AUTO_TEST_CASE(a_collapse_with_the_tc_model_does_not_suggest_turning_it_on) {
  const std::string text = describe(StopReason::collapse, 12.5, 1e-6);
  BOOST_TEST(text.find("tc > 0") == std::string::npos, text);
  BOOST_TEST(text.find("tc = 1e-06") != std::string::npos, text);
  BOOST_TEST(text.find("a larger tc") != std::string::npos, text);
}

BOOST_AUTO_TEST_CASE(event_bound_and_temperature_floor_name_the_time) {
  BOOST_TEST(describe(StopReason::max_events, 1e23).find("max_events: ") == 0u);
  BOOST_TEST(describe(StopReason::max_events, 1e23).find("t = 1e+23") != std::string::npos);
  BOOST_TEST(describe(StopReason::temperature_floor, 2.5e151).find(
                 "temperature_floor: T/T0 fell below 1e-300") == 0u);
}

BOOST_AUTO_TEST_CASE(every_text_parses_back_to_its_reason) {
  for (const StopReason reason :
       {StopReason::t_end, StopReason::max_collisions, StopReason::min_temperature,
        StopReason::collapse, StopReason::stalled, StopReason::max_events,
        StopReason::temperature_floor}) {
    const auto parsed = parse_stop_reason(describe(reason, 1.25));
    BOOST_REQUIRE(parsed.has_value());
    BOOST_TEST((*parsed == reason), to_string(reason));
  }
  BOOST_TEST(!parse_stop_reason("collapse").has_value());  // a collapse text has its details
  BOOST_TEST(!parse_stop_reason("t_end ").has_value());
  BOOST_TEST(!parse_stop_reason("").has_value());
}
