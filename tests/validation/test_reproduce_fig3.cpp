// The Fig. 3 step of the reproduction (validation/src/reproduce_figures.cpp) when its runs fail:
// a gas whose runs all failed stops the step with the runs' own errors, not an empty curve that
// the renderer rejects later as "Fig3Data.curves[0].t is empty".
// build/tests/validation/validation_reproduce_fig3 --log_level=message prints the messages.
#define BOOST_TEST_MODULE validation_reproduce_fig3
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "molchaos/sim/run.hpp"
#include "molchaos/validation/reproduce.hpp"
#include "reproduce_steps.hpp"

using namespace molchaos;
using namespace molchaos::validation;

namespace {

// Fig. 3's ensemble made small (200 disks to t = 20), its runs computed except those of the
// modes in `failing`, which fail with `reason` as the sweep reports a failed run.
ReproduceResults fig3_with_failures(const std::vector<sim::Randomization>& failing,
                                    const std::string& reason) {
  ReproduceResults R;
  R.config = ReproduceConfig::quick_look();
  R.fig3_spec.particles = 200;
  R.fig3_spec.densities = {R.config.fig3_density};
  R.fig3_spec.restitutions = {R.config.fig3_restitution};
  R.fig3_spec.modes = steps::k_modes;
  R.fig3_spec.seeds = 2;
  R.fig3_spec.t_end_fixed = 20.0;
  R.fig3_spec.relax_collisions_per_particle = 2.0;
  const auto runs = expand(R.fig3_spec);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    RunOutcome o;
    if (std::find(failing.begin(), failing.end(), runs[i].randomize) != failing.end()) {
      o.error = "run " + std::to_string(i) +
                " (randomize=" + std::string(sim::to_string(runs[i].randomize)) +
                ") failed: " + reason;
    } else {
      o.result = sim::run(runs[i]);
      o.ok = true;
    }
    R.fig3_runs.push_back(o);
  }
  R.fig3_points = summarize(R.fig3_spec, R.fig3_runs, R.config.window);
  R.fig3_original = R.fig3_points.at(0);
  return R;
}

std::string fig3_error(ReproduceResults& R) {
  try {
    steps::figure_fig3(R);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(every_gas_with_a_run_gives_every_curve) {
  ReproduceResults R = fig3_with_failures({}, "");
  steps::figure_fig3(R);
  BOOST_TEST_REQUIRE(R.fig3.curves.size() >= 3u);
  for (std::size_t k = 0; k < 3; ++k) BOOST_TEST(!R.fig3.curves[k].t.empty());
}

BOOST_AUTO_TEST_CASE(every_run_failed_names_the_runs_and_their_cause) {
  const std::string reason = "run stopped: collapse: injected for the test";
  ReproduceResults R = fig3_with_failures(steps::k_modes, reason);
  const std::string what = fig3_error(R);
  BOOST_TEST_MESSAGE(what);
  BOOST_TEST(what.find("Fig. 3 cannot be drawn: no run of randomize = none, paper, flux succeeded "
                       "(6 failed): run 0 (randomize=none) failed: " +
                       reason) == 0u);
  BOOST_TEST(what.find("; and 3 more") != std::string::npos);
  BOOST_TEST(what.find("is empty") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(one_gas_without_runs_is_named_alone) {
  const std::string reason =
      "cannot write /full/disk/x.csv: write failed (No space left on device)";
  ReproduceResults R = fig3_with_failures({sim::Randomization::flux}, reason);
  const std::string what = fig3_error(R);
  BOOST_TEST_MESSAGE(what);
  BOOST_TEST(what ==
             "Fig. 3 cannot be drawn: no run of randomize = flux succeeded (2 failed): run 4 "
             "(randomize=flux) failed: " +
                 reason + "; run 5 (randomize=flux) failed: " + reason);
}

// The whole reproduction through a sweep runner that fails every run: the Fig. 3 step is the
// first to need a run, and its message is what `molchaos reproduce` prints (exit 1).
BOOST_AUTO_TEST_CASE(a_reproduction_whose_runs_all_fail_names_them) {
  SweepOptions sweep;
  sweep.progress = false;
  sweep.runner = [](const std::vector<sim::Parameters>& runs, const SweepOptions&) {
    std::vector<RunOutcome> out(runs.size());
    for (std::size_t i = 0; i < runs.size(); ++i)
      out[i].error = "run " + std::to_string(i) + " failed: injected";
    return out;
  };
  std::string what;
  try {
    reproduce(ReproduceConfig::quick_look(), sweep);
  } catch (const std::exception& e) {
    what = e.what();
  }
  BOOST_TEST_MESSAGE(what);
  // The quick look's Fig. 4 ensemble holds runs 0..53 of the one sweep; Fig. 3's follow.
  BOOST_TEST(what.find("Fig. 3 cannot be drawn: no run of randomize = none, paper, flux succeeded "
                       "(9 failed): run 54 failed: injected; run 55 failed: injected; run 56 "
                       "failed: injected; and 6 more") == 0u);
}
