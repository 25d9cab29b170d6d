// Unit tests of the protocol messages: every parameter survives bit for bit, damaged messages
// are refused.
#define BOOST_TEST_MODULE mpi_wire
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>

#include "molchaos/mpi/wire.hpp"
#include "molchaos/validation/sweep.hpp"

using namespace molchaos;

namespace {

sim::Parameters unusual_parameters() {
  sim::Parameters p;
  p.dimension = 3;
  p.particles = 123457;
  p.density = std::nextafter(0.05, 1.0);  // one ulp off a round number
  p.restitution = 0.1 + 0.2;
  p.randomize = sim::Randomization::flux;
  p.seed = std::numeric_limits<std::uint64_t>::max() - 7;
  p.t_end = 1.0 / 3.0;
  p.relax_collisions_per_particle = 17.25;
  p.tc = 1e-300;
  p.samples_per_decade = 37;
  p.t_first_sample = 5e-324;  // smallest subnormal
  p.contact_statistics = true;
  p.snapshot_times = {0.5, 2.0 / 3.0};
  p.max_collisions = 987654321012345ULL;
  p.min_temperature = 1e-7;
  return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(job_round_trips_every_parameter_bit_for_bit) {
  const mpi::JobMessage job{42, unusual_parameters()};
  const auto back = mpi::decode_job(mpi::encode(job));
  BOOST_TEST(back.index == 42u);
  // canonical_parameters prints every field at round-trip precision.
  BOOST_TEST(validation::canonical_parameters(back.parameters, "") ==
             validation::canonical_parameters(job.parameters, ""));
  BOOST_TEST(validation::cache_key(back.parameters, "v") ==
             validation::cache_key(job.parameters, "v"));
}

BOOST_AUTO_TEST_CASE(default_parameters_round_trip) {
  const auto back = mpi::decode_job(mpi::encode(mpi::JobMessage{0, sim::Parameters{}}));
  BOOST_TEST(validation::canonical_parameters(back.parameters, "") ==
             validation::canonical_parameters(sim::Parameters{}, ""));
}

BOOST_AUTO_TEST_CASE(result_round_trips_text_with_any_bytes) {
  std::string text = "# header\n1,2,3\n";
  text.push_back('\0');
  text += "tail";
  for (bool ok : {true, false}) {
    const auto back = mpi::decode_result(mpi::encode(mpi::ResultMessage{7, ok, text}));
    BOOST_TEST(back.index == 7u);
    BOOST_TEST(back.ok == ok);
    BOOST_TEST(back.text == text);
  }
}

BOOST_AUTO_TEST_CASE(damaged_messages_are_refused) {
  const std::string job = mpi::encode(mpi::JobMessage{3, unusual_parameters()});
  BOOST_CHECK_THROW(mpi::decode_job(job.substr(0, job.size() - 1)), std::runtime_error);
  BOOST_CHECK_THROW(mpi::decode_job(job + "x"), std::runtime_error);
  BOOST_CHECK_THROW(mpi::decode_job(""), std::runtime_error);
  const std::string result = mpi::encode(mpi::ResultMessage{1, true, "abc"});
  BOOST_CHECK_THROW(mpi::decode_result(result.substr(0, result.size() - 1)), std::runtime_error);
  BOOST_CHECK_THROW(mpi::decode_result(result + "x"), std::runtime_error);
}
