// Notes on runs, one line per distinct reason.
#include "molchaos/validation/run_notes.hpp"

#include <fmt/format.h>

#include <cstddef>

namespace molchaos::validation {
namespace {

// Seeds named in a line before "and K more": enough to re-run a few by hand, few enough that a
// sweep over thousands of seeds still prints one short line.
constexpr std::size_t k_seeds_named = 3;

struct Group {
  const std::string* reason = nullptr;
  std::size_t runs = 0;
  std::vector<std::uint64_t> seeds;
};

std::string line_of(const Group& g) {
  if (g.runs == 1)
    return g.seeds.empty() ? *g.reason : fmt::format("seed {}: {}", g.seeds.front(), *g.reason);
  std::string seeds;
  for (std::size_t k = 0; k < g.seeds.size() && k < k_seeds_named; ++k)
    seeds += fmt::format("{}{}", k == 0 ? "" : ", ", g.seeds[k]);
  if (g.seeds.size() > k_seeds_named)
    seeds += fmt::format(" and {} more", g.seeds.size() - k_seeds_named);
  return seeds.empty() ? fmt::format("{} runs: {}", g.runs, *g.reason)
                       : fmt::format("{} runs (seeds {}): {}", g.runs, seeds, *g.reason);
}

}  // namespace

std::vector<std::string> note_lines(const std::vector<RunNote>& notes) {
  std::vector<Group> groups;
  for (const RunNote& note : notes) {
    Group* group = nullptr;
    for (Group& g : groups)
      if (*g.reason == note.reason) group = &g;
    if (group == nullptr) group = &groups.emplace_back(Group{&note.reason, 0, {}});
    ++group->runs;
    if (note.seed) group->seeds.push_back(*note.seed);
  }
  std::vector<std::string> lines;
  for (const Group& g : groups) lines.push_back(line_of(g));
  return lines;
}

}  // namespace molchaos::validation
