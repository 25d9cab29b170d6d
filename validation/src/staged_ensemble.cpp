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

// The ensembles of the points of one list that need more seeds, one per point (a gas: one method
// and mode at one density, whose points differ in restitution, is sized as a whole).
std::vector<EnsembleSpec> ensembles_needing_seeds(const StagedList& list) {
  if (list.spec->target_relative_error <= 0.0) return {};
  SeedSizing sizing;
  sizing.target_relative_error = list.spec->target_relative_error;
  sizing.max_seeds = list.spec->max_seeds;
  std::map<std::tuple<double, int, std::string>, std::vector<const PointResult*>> gases;
  for (const auto& p : *list.points)
    gases[{p.summary.density, static_cast<int>(p.method), p.summary.mode}].push_back(&p);
  std::vector<EnsembleSpec> specs;
  for (const auto& [gas, members] : gases) {
    std::vector<PointScatter> scatter;
    for (const auto* p : members) {
      const auto& s = p->summary;
      const bool usable = s.runs >= 2 && s.A.value > 0.0;
      scatter.push_back({s.restitution, s.runs + s.failed, usable ? s.runs : 0,
                         usable ? s.A.error * std::sqrt(s.runs) / s.A.value : 0.0});
    }
    const std::vector<int> needed = seeds_needed(scatter, sizing);
    for (std::size_t k = 0; k < members.size(); ++k) {
      if (needed[k] <= scatter[k].seeds) continue;
      EnsembleSpec spec = *list.spec;
      spec.densities = {members[k]->summary.density};
      spec.restitutions = {members[k]->summary.restitution};
      spec.methods = {members[k]->method};
      spec.modes = {*sim::parse_randomization(members[k]->summary.mode)};
      spec.seeds = needed[k];
      specs.push_back(spec);
    }
  }
  return specs;
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
  return failures;
}

}  // namespace molchaos::validation
