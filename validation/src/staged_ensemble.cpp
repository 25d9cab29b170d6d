// Seeds per state point and gas in stages (see staged_ensemble.hpp).
#include "molchaos/validation/staged_ensemble.hpp"

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::validation {
namespace {

// The points of one list by gas (one method and mode at one density, whose points differ in
// restitution and are sized as a whole), each with its scatter as seed_sizing.hpp reads it.
struct Gas {
  std::vector<PointResult*> members;
  std::vector<PointScatter> scatter;
};
std::vector<Gas> gases_of(const StagedList& list) {
  std::map<std::tuple<double, int, std::string>, Gas> gases;
  for (auto& p : *list.points) {
    const auto& s = p.summary;
    const bool usable = s.runs >= 2 && s.A.value > 0.0;
    Gas& gas = gases[{s.density, static_cast<int>(p.method), s.mode}];
    gas.members.push_back(&p);
    gas.scatter.push_back({s.restitution, s.runs + s.failed, usable ? s.runs : 0,
                           usable ? s.A.error * std::sqrt(s.runs) / s.A.value : 0.0});
  }
  std::vector<Gas> out;
  for (auto& [key, gas] : gases) out.push_back(std::move(gas));
  return out;
}

// The ensembles of the points of one list that need more seeds, one per point.
std::vector<EnsembleSpec> ensembles_needing_seeds(const StagedList& list) {
  if (list.spec->target_relative_error <= 0.0) return {};
  SeedSizing sizing;
  sizing.target_relative_error = list.spec->target_relative_error;
  sizing.max_seeds = list.spec->max_seeds;
  std::vector<EnsembleSpec> specs;
  for (const auto& gas : gases_of(list)) {
    const std::vector<int> needed = seeds_needed(gas.scatter, sizing);
    for (std::size_t k = 0; k < gas.members.size(); ++k) {
      if (needed[k] <= gas.scatter[k].seeds) continue;
      const auto& member = *gas.members[k];
      EnsembleSpec spec = *list.spec;
      spec.densities = {member.summary.density};
      spec.restitutions = {member.summary.restitution};
      spec.methods = {member.method};
      spec.modes = {*sim::parse_randomization(member.summary.mode)};
      spec.seeds = needed[k];
      specs.push_back(spec);
    }
  }
  return specs;
}

// SE(A) of every point of a list grown to a target from reported_relative_scatter: the point's own
// scatter decided when it stopped, and alone would leave its error bar short.
void report_errors_of_grown_points(const StagedList& list) {
  if (list.spec->target_relative_error <= 0.0) return;
  for (const auto& gas : gases_of(list)) {
    const std::vector<double> scatter = reported_relative_scatter(gas.scatter);
    for (std::size_t k = 0; k < gas.members.size(); ++k) {
      auto& s = gas.members[k]->summary;
      if (gas.scatter[k].runs < 2) continue;
      s.A.error = scatter[k] * s.A.value / std::sqrt(static_cast<double>(s.runs));
    }
  }
}

bool same_point(const PointResult& a, const PointResult& b) {
  return a.summary.density == b.summary.density && a.summary.restitution == b.summary.restitution &&
         a.method == b.method && a.summary.mode == b.summary.mode;
}

}  // namespace

std::vector<RunOutcome> grow_to_target(const std::vector<StagedList>& lists,
                                       const SweepOptions& sweep, const WindowRule& window) {
  std::vector<RunOutcome> failures;
  for (int stage = 0; stage < k_target_stages; ++stage) {
    struct Extension {
      EnsembleSpec spec;
      std::vector<PointResult>* points;
      std::size_t runs = 0;  // its share of the stage's runs
    };
    std::vector<Extension> extensions;
    for (const auto& list : lists)
      for (auto& spec : ensembles_needing_seeds(list))
        extensions.push_back({std::move(spec), list.points});
    if (extensions.empty()) break;
    std::vector<sim::Parameters> runs;
    for (auto& x : extensions) {
      const auto r = expand(x.spec);
      x.runs = r.size();
      runs.insert(runs.end(), r.begin(), r.end());
    }
    SweepOptions staged = sweep;
    staged.label = sweep.label + ", further seeds for the target SE(A)/A";
    const auto outcomes = run_sweep(runs, staged);
    std::size_t offset = 0;
    for (const auto& x : extensions) {
      const std::vector<RunOutcome> part(
          outcomes.begin() + static_cast<std::ptrdiff_t>(offset),
          outcomes.begin() + static_cast<std::ptrdiff_t>(offset + x.runs));
      offset += x.runs;
      for (const auto& o : part)
        if (!o.ok) failures.push_back(o);
      for (auto& fresh : summarize(x.spec, part, window))
        for (auto& p : *x.points)
          if (same_point(p, fresh)) p = std::move(fresh);
    }
  }
  for (const auto& list : lists) report_errors_of_grown_points(list);
  return failures;
}

}  // namespace molchaos::validation
