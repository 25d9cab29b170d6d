// Seeds per state point and gas in stages (see staged_ensemble.hpp).
#include "molchaos/validation/staged_ensemble.hpp"

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "molchaos/sim/parameters.hpp"
#include "molchaos/validation/stopping_correction.hpp"

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

// Each gas's staging (stopping_correction.hpp) as it goes: the seeds its points had before the
// first further stage, and the factors its last sizing applied.
std::vector<Staging> stagings_of(const StagedList& list) {
  SeedSizing sizing;
  sizing.target_relative_error = list.spec->target_relative_error;
  sizing.max_seeds = list.spec->max_seeds;
  std::vector<Staging> out;
  for (const auto& gas : gases_of(list)) {
    Staging& staging = out.emplace_back(Staging{{}, sizing, k_target_stages, {}});
    for (const auto& p : gas.scatter) staging.first_seeds.push_back(p.seeds);
  }
  return out;
}

// The ensembles of the points of one list that need more seeds, one per point: sized for the SE
// they will report, whose factors each gas's staging keeps for the next stage.
std::vector<EnsembleSpec> ensembles_needing_seeds(const StagedList& list,
                                                  std::vector<Staging>& stagings) {
  if (list.spec->target_relative_error <= 0.0) return {};
  std::vector<EnsembleSpec> specs;
  const std::vector<Gas> gases = gases_of(list);
  for (std::size_t g = 0; g < gases.size(); ++g) {
    const Gas& gas = gases[g];
    Staging& staging = stagings[g];
    const std::vector<double> reported = reported_relative_scatter(gas.scatter);
    staging.sizing_factors = stopping_correction(gas.scatter, reported, staging);
    const std::vector<int> needed =
        seeds_needed_for_factors(gas.scatter, staging.sizing_factors, staging.sizing);
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

// SE(A) of every point of a list grown to a target: the scatter from reported_relative_scatter (the
// point's own scatter decided when it stopped, and alone would leave its error bar short), times
// the factor that undoes what stopping leaves of that bias (stopping_correction.hpp).
void report_errors_of_grown_points(const StagedList& list, const std::vector<Staging>& stagings) {
  if (list.spec->target_relative_error <= 0.0) return;
  const std::vector<Gas> gases = gases_of(list);
  for (std::size_t g = 0; g < gases.size(); ++g) {
    const Gas& gas = gases[g];
    const std::vector<double> reported = reported_relative_scatter(gas.scatter);
    const std::vector<double> factor = stopping_correction(gas.scatter, reported, stagings[g]);
    for (std::size_t k = 0; k < gas.members.size(); ++k) {
      auto& s = gas.members[k]->summary;
      if (gas.scatter[k].runs < 2) continue;
      s.A.error = factor[k] * reported[k] * s.A.value / std::sqrt(static_cast<double>(s.runs));
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
  std::vector<std::vector<Staging>> stagings;  // per list and gas
  for (const auto& list : lists) stagings.push_back(stagings_of(list));
  for (int stage = 0; stage < k_target_stages; ++stage) {
    struct Extension {
      EnsembleSpec spec;
      std::vector<PointResult>* points;
      std::size_t runs = 0;  // its share of the stage's runs
    };
    std::vector<Extension> extensions;
    for (std::size_t l = 0; l < lists.size(); ++l)
      for (auto& spec : ensembles_needing_seeds(lists[l], stagings[l]))
        extensions.push_back({std::move(spec), lists[l].points});
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
  for (std::size_t l = 0; l < lists.size(); ++l)
    report_errors_of_grown_points(lists[l], stagings[l]);
  return failures;
}

}  // namespace molchaos::validation
