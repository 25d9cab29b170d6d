// Unit tests of the neighbour-list storage: adding, removing and growing keep every list's
// members (as a set) and its spare slot.
#define BOOST_TEST_MODULE sim_neighbour_lists
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <set>
#include <vector>

#include "molchaos/sim/neighbour_lists.hpp"
#include "molchaos/sim/rng.hpp"

using namespace molchaos::sim;

namespace {
std::set<std::int32_t> members(const NeighbourLists& lists, std::int32_t i) {
  const auto list = lists.neighbours(i);
  return {list.begin(), list.end()};
}
}  // namespace

BOOST_AUTO_TEST_CASE(random_adds_and_removes_match_a_set_model) {
  // 50 lists starting with 4 slots: random symmetric adds and removes, through several growths,
  // checked against std::set after every operation.
  const std::int32_t n = 50;
  NeighbourLists lists;
  lists.reset(n, 4);
  std::vector<std::set<std::int32_t>> model(n);
  Rng rng(3);
  for (int step = 0; step < 20000; ++step) {
    const auto i = static_cast<std::int32_t>(rng.below(n));
    const auto j = static_cast<std::int32_t>(rng.below(n));
    if (i == j) continue;
    if (model[i].count(j) == 0) {
      lists.add(i, j);
      lists.add(j, i);
      model[i].insert(j);
      model[j].insert(i);
    } else {
      lists.remove(i, j);
      lists.remove(j, i);
      model[i].erase(j);
      model[j].erase(i);
    }
    BOOST_REQUIRE((members(lists, i) == model[i]));
    BOOST_REQUIRE((members(lists, j) == model[j]));
    BOOST_REQUIRE(lists.count(i) < lists.capacity());  // the spare slot
  }
  for (std::int32_t i = 0; i < n; ++i) BOOST_TEST((members(lists, i) == model[i]));
  BOOST_TEST(lists.capacity() >= 8);
  BOOST_TEST_MESSAGE("capacity after growth: " << lists.capacity());
}

BOOST_AUTO_TEST_CASE(reset_keeps_the_grown_capacity_and_empties_the_lists) {
  NeighbourLists lists;
  lists.reset(3, 2);
  lists.add(0, 1);  // fits, one slot to spare
  BOOST_TEST(lists.capacity() == 2);
  lists.add(0, 2);  // would use the spare slot: grows to 8 first
  BOOST_TEST(lists.capacity() == 8);
  BOOST_TEST((members(lists, 0) == std::set<std::int32_t>{1, 2}));
  lists.reset(3, 0);
  BOOST_TEST(lists.capacity() == 8);
  BOOST_TEST(lists.count(0) == 0);
  lists.add(2, 0);
  lists.clear(2);
  BOOST_TEST(lists.neighbours(2).empty());
}
