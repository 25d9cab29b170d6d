// Shared relaxed states (relaxed_states.hpp): a run that restores the state an earlier run of the
// same key kept gives the same bytes as the run that relaxed itself, in 2D and 3D, with cells and
// with neighbour lists, with and without contact statistics; the key separates what relaxation
// depends on and ignores what it does not; a run without relaxation keeps nothing.
#define BOOST_TEST_MODULE test_relaxed_states
#include <boost/test/unit_test.hpp>
#include <sstream>
#include <string>

#include "molchaos/sim/csv.hpp"
#include "molchaos/sim/relaxed_states.hpp"
#include "molchaos/sim/run.hpp"

using namespace molchaos::sim;

namespace {

std::string csv_of(const Parameters& p) {
  std::ostringstream out;
  write_csv(run(p), out);
  return out.str();
}

Parameters small_run(int d, double density, double eps, Randomization mode) {
  Parameters p;
  p.dimension = d;
  p.particles = d == 2 ? 600 : 800;
  p.density = density;
  p.restitution = eps;
  p.randomize = mode;
  p.seed = 11;
  p.t_end = 20;
  return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(restored_runs_give_the_bytes_of_runs_that_relaxed_themselves) {
  struct Case {
    int d;
    double density;  // 3D: 0.7 is packing 0.37, with neighbour lists
    bool contacts;
  };
  for (const Case c : {Case{2, 0.1, false}, Case{2, 0.05, true}, Case{3, 0.1, false},
                       Case{3, 0.7, true}}) {
    Parameters first = small_run(c.d, c.density, 0.8, Randomization::none);
    Parameters second = small_run(c.d, c.density, 0.9, Randomization::flux);
    first.contact_statistics = second.contact_statistics = c.contacts;
    share_relaxed_states(false);
    const std::string alone = csv_of(second);
    share_relaxed_states(true);
    clear_relaxed_states();
    const std::string kept_by_first = csv_of(first);
    BOOST_TEST(kept_relaxed_states() == 1u);
    BOOST_TEST_CONTEXT("d = " << c.d << ", n = " << c.density << ", contacts " << c.contacts) {
      BOOST_TEST(csv_of(second) == alone);  // restored from the first run's relaxation
      BOOST_TEST(csv_of(first) == kept_by_first);  // and the first run restores its own
      BOOST_TEST(kept_relaxed_states() == 1u);     // one key for both runs
    }
  }
  clear_relaxed_states();
}

BOOST_AUTO_TEST_CASE(the_key_holds_what_relaxation_depends_on) {
  const Parameters base = small_run(2, 0.1, 0.8, Randomization::none);
  const std::string key = relaxed_state_key(base, "layout");
  Parameters p = base;
  p.restitution = 0.5;
  p.randomize = Randomization::paper;
  p.tc = 1e-3;
  p.t_end = 7;
  p.samples_per_decade = 5;
  p.contact_statistics = true;  // the observer is in the layout, not in the parameters' part
  BOOST_TEST(relaxed_state_key(p, "layout") == key);
  BOOST_TEST(relaxed_state_key(base, "other layout") != key);
  for (int k = 0; k < 6; ++k) {
    Parameters q = base;
    if (k == 0) q.dimension = 3;
    if (k == 1) q.particles = 601;
    if (k == 2) q.density = 0.11;
    if (k == 3) q.seed = 12;
    if (k == 4) q.relax_collisions_per_particle = 5;
    if (k == 5) q.max_collisions = 1000;
    BOOST_TEST(relaxed_state_key(q, "layout") != key, "field " << k);
  }
}

BOOST_AUTO_TEST_CASE(a_key_keeps_its_first_state_and_clearing_drops_all) {
  clear_relaxed_states();
  share_relaxed_states(true);
  keep_relaxed_state("k", "first");
  keep_relaxed_state("k", "second");
  BOOST_REQUIRE(find_relaxed_state("k"));
  BOOST_TEST(*find_relaxed_state("k") == "first");
  BOOST_TEST(!find_relaxed_state("other"));
  share_relaxed_states(false);
  BOOST_TEST(!find_relaxed_state("k"));  // sharing off: every run relaxes itself
  share_relaxed_states(true);
  clear_relaxed_states();
  BOOST_TEST(!find_relaxed_state("k"));
  keep_relaxed_state("big", std::string(k_largest_kept_state + 1, 'x'));
  BOOST_TEST(!find_relaxed_state("big"));
}

BOOST_AUTO_TEST_CASE(a_run_without_relaxation_keeps_no_state) {
  share_relaxed_states(true);
  clear_relaxed_states();
  Parameters p = small_run(2, 0.1, 0.8, Randomization::none);
  p.relax_collisions_per_particle = 0;
  const std::string first = csv_of(p);
  BOOST_TEST(kept_relaxed_states() == 0u);  // was one state per seed, up to k_kept_bytes
  BOOST_TEST(csv_of(p) == first);
  p.relax_collisions_per_particle = 1;
  csv_of(p);
  BOOST_TEST(kept_relaxed_states() == 1u);
  clear_relaxed_states();
}
