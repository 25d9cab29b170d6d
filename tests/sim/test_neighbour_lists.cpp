// Unit tests of the neighbour-list storage: adding, removing and growing keep every list's
// members (as a set) and its spare slot.
#define BOOST_TEST_MODULE sim_neighbour_lists
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cstdint>
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

BOOST_AUTO_TEST_CASE(lists_fill_whole_cache_lines_and_reset_keeps_the_grown_capacity) {
  NeighbourLists lists;
  BOOST_TEST(lists.capacity() == 0);
  lists.reset(16, 2);
  BOOST_TEST(lists.capacity() == 15);  // one line: the count and 15 slots
  for (std::int32_t i = 0; i < 16; ++i) {
    // The count and the first 15 slots share a 64-byte line.
    BOOST_TEST(reinterpret_cast<std::uintptr_t>(lists.slots(i)) % 64 == sizeof(std::int32_t));
  }
  for (std::int32_t j = 1; j <= 14; ++j) lists.add(0, j);  // fits, one slot to spare
  lists.add(1, 2);
  BOOST_TEST(lists.capacity() == 15);
  lists.add(0, 15);  // would use the spare slot: grows to two lines first
  BOOST_TEST(lists.capacity() == 31);
  BOOST_TEST(reinterpret_cast<std::uintptr_t>(lists.slots(2)) % 64 == sizeof(std::int32_t));
  BOOST_TEST(lists.count(0) == 15);
  BOOST_TEST((members(lists, 1) == std::set<std::int32_t>{2}));
  BOOST_TEST(lists.well_formed(16));
  BOOST_TEST(!lists.well_formed(17));
  lists.reset(16, 0);
  BOOST_TEST(lists.capacity() == 31);
  BOOST_TEST(lists.count(0) == 0);
  lists.add(2, 0);
  lists.clear(2);
  BOOST_TEST(lists.neighbours(2).empty());
}

BOOST_AUTO_TEST_CASE(a_member_out_of_range_is_not_well_formed) {
  NeighbourLists lists;
  lists.reset(4, 15);
  lists.add(0, 3);
  BOOST_TEST(lists.well_formed(4));
  lists.slots(0)[0] = 4;  // as a tampered checkpoint could hold
  BOOST_TEST(!lists.well_formed(4));
}
