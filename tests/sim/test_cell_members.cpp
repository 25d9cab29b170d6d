// Unit tests of the cells' member lists: filing and taking out particles keeps every cell's
// members (as a set), and a stencil's gather returns exactly the members of its cells, in list
// order, whether copied by the loop or by the unrolled copies; with the links in an array of
// their own and in records among other fields.
#define BOOST_TEST_MODULE sim_cell_members
#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>
#include <set>
#include <vector>

#include "molchaos/sim/cell_members.hpp"
#include "molchaos/sim/rng.hpp"

using namespace molchaos::sim;

namespace {
struct Record {  // a particle record: the link among other fields
  double x = 0;
  std::int32_t next = -3;
  std::int32_t other = -4;
};

// The links of n particles and the end, in one of the two kinds of storage.
struct ArrayStorage {
  std::vector<std::int32_t> links;
  explicit ArrayStorage(std::int32_t n) : links(static_cast<std::size_t>(n) + 1, -3) {}
  std::vector<std::int32_t>& view() { return links; }
};
struct RecordStorage {
  std::vector<Record> records;
  explicit RecordStorage(std::int32_t n) : records(static_cast<std::size_t>(n) + 1) {}
  RecordLinks<Record> view() { return {records.data()}; }
};

template <class Links>
std::vector<std::int32_t> walk(const CellMembers& cells, const Links& links, int c) {
  std::vector<std::int32_t> out;
  for (std::int32_t j = cells.first(c); j != cells.end(); j = links[j]) out.push_back(j);
  return out;
}

// The three cells {a, b, c} gathered with Unrolled copies, against the walks of the cells.
template <int Unrolled, class Links>
void check_gather(const CellMembers& cells, const Links& links, std::int32_t n, int a, int b,
                  int c) {
  const int stencil[3] = {a, b, c};
  std::vector<std::int32_t> out(static_cast<std::size_t>(n) + 1, -7);
  const std::int32_t count = cells.gather<3, Unrolled>(links, stencil, out.data());
  std::vector<std::int32_t> expected;
  for (const int s : stencil)
    for (const std::int32_t j : walk(cells, links, s)) expected.push_back(j);
  BOOST_TEST_REQUIRE(count == static_cast<std::int32_t>(expected.size()));
  BOOST_TEST(std::vector<std::int32_t>(out.begin(), out.begin() + count) == expected,
             boost::test_tools::per_element());
}

using Storages = boost::mpl::list<ArrayStorage, RecordStorage>;
}  // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(random_moves_match_a_set_model_and_gathers_match_the_walks, Storage,
                              Storages) {
  // 200 particles moving at random among 40 cells (crowded and empty ones), checked against
  // std::set after every move; gathers of random stencils, repeated cells included.
  const std::int32_t n = 200;
  const int n_cells = 40;
  CellMembers cells;
  Storage storage(n);
  auto links = storage.view();
  cells.reset(n_cells, n, links);
  BOOST_TEST(links[n] == n);  // the end links to itself
  BOOST_TEST(cells.shaped_for(n_cells, n));
  BOOST_TEST(!cells.shaped_for(n_cells + 1, n));
  BOOST_TEST(!cells.shaped_for(n_cells, n + 1));
  std::vector<std::set<std::int32_t>> model(n_cells);
  std::vector<int> where(n);
  Rng rng(5);
  for (std::int32_t i = 0; i < n; ++i) {
    where[i] = static_cast<int>(rng.below(n_cells / 4));  // crowded cells first: 20 a cell
    cells.add(links, i, where[i]);
    model[where[i]].insert(i);
  }
  for (int step = 0; step < 20000; ++step) {
    const auto i = static_cast<std::int32_t>(rng.below(n));
    const auto to = static_cast<int>(rng.below(n_cells));
    cells.remove(links, i, where[i]);
    model[where[i]].erase(i);
    cells.add(links, i, to);
    model[to].insert(i);
    where[i] = to;
    for (const int c : {where[i], static_cast<int>(rng.below(n_cells))}) {
      const std::vector<std::int32_t> listed = walk(cells, links, c);
      BOOST_TEST_REQUIRE(std::set<std::int32_t>(listed.begin(), listed.end()) == model[c]);
      BOOST_TEST_REQUIRE(listed.size() == model[c].size());  // none listed twice
    }
    if (step % 97 == 0) {
      const int a = static_cast<int>(rng.below(n_cells)), b = static_cast<int>(rng.below(n_cells));
      check_gather<1>(cells, links, n, a, b, where[i]);
      check_gather<4>(cells, links, n, a, b, where[i]);
    }
  }
  if constexpr (std::is_same_v<Storage, RecordStorage>)  // the records' other fields untouched
    for (const Record& r : storage.records) BOOST_TEST_REQUIRE((r.x == 0 && r.other == -4));
}

BOOST_AUTO_TEST_CASE(a_cell_lists_its_members_last_filed_first_and_empty_cells_gather_nothing) {
  CellMembers cells;
  std::vector<std::int32_t> links(6, -3);
  cells.reset(3, 5, links);
  for (const std::int32_t i : {4, 1, 3}) cells.add(links, i, 1);
  BOOST_TEST(walk(cells, links, 1) == (std::vector<std::int32_t>{3, 1, 4}),
             boost::test_tools::per_element());
  cells.remove(links, 1, 1);
  BOOST_TEST(walk(cells, links, 1) == (std::vector<std::int32_t>{3, 4}),
             boost::test_tools::per_element());
  cells.remove(links, 3, 1);
  cells.remove(links, 4, 1);
  BOOST_TEST(walk(cells, links, 1).empty());
  const int empty[3] = {0, 1, 2};
  std::vector<std::int32_t> out(6, -7);
  const std::int32_t loop = cells.gather<3>(links, empty, out.data());
  const std::int32_t unrolled = cells.gather<3, 4>(links, empty, out.data());
  BOOST_TEST(loop == 0);
  BOOST_TEST(unrolled == 0);
}
