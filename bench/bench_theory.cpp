// Work–precision of the kinetic-theory quadrature: CPU time for the full μ2 coefficient table
// (d = 2 and 3) against the requested tolerance, with the error actually reached (against the
// closed forms) and the error estimate, as Google Benchmark counters.
#include <benchmark/benchmark.h>

#include <cmath>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/reference_values.hpp"

namespace {

void coefficient_table(benchmark::State& state) {
  const int dimension = static_cast<int>(state.range(0));
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  molchaos::theory::QuadratureOptions q;
  q.relative_tolerance = tolerance;
  double max_error = 0.0, max_estimate = 0.0;
  std::size_t evaluations = 0;
  for (auto _ : state) {
    const auto table = molchaos::theory::expand_collision_moment(dimension, 2, 0.5, 3.0, q);
    benchmark::DoNotOptimize(table.base.value);
    evaluations = table.integrand_evaluations;
    const auto error = molchaos::theory::reference::table_error(table);
    max_error = error.reached;
    max_estimate = error.estimated;
  }
  state.counters["requested_tol"] = tolerance;
  state.counters["max_error_reached"] = max_error;
  state.counters["max_error_estimate"] = max_estimate;
  state.counters["integrand_evals"] = static_cast<double>(evaluations);
}

}  // namespace

BENCHMARK(coefficient_table)
    ->ArgsProduct({{2, 3}, {4, 6, 8, 10, 12}})
    ->ArgNames({"dim", "neg_log10_tol"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK_MAIN();
