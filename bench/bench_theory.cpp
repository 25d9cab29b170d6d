// Work–precision of the kinetic-theory quadrature: CPU time for the full μ2 coefficient table
// (d = 2 and 3) with the fixed Gauss rules (the default) and with the adaptive QAGIU reference at
// requested tolerances, the error reached (against the closed forms) and the error estimate as
// Google Benchmark counters; and the cost of a theory curve over a fine ε grid.
#include <benchmark/benchmark.h>

#include <cmath>

#include "molchaos/theory/collision_moments.hpp"
#include "molchaos/theory/cooling.hpp"
#include "molchaos/theory/reference_values.hpp"

namespace {

using molchaos::theory::QuadratureOptions;

void report_table(benchmark::State& state, const QuadratureOptions& q) {
  const int dimension = static_cast<int>(state.range(0));
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
  state.counters["max_error_reached"] = max_error;
  state.counters["max_error_estimate"] = max_estimate;
  state.counters["integrand_evals"] = static_cast<double>(evaluations);
}

void coefficient_table_gauss(benchmark::State& state) { report_table(state, QuadratureOptions{}); }

void coefficient_table_adaptive(benchmark::State& state) {
  QuadratureOptions q;
  q.method = molchaos::theory::QuadratureMethod::adaptive;
  q.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  state.counters["requested_tol"] = q.relative_tolerance;
  report_table(state, q);
}

// Every term a2^i a3^j b^k of μ_p, p = 2, 4, 6 (the moments of the second-order theory).
void moment_table_with_a3(benchmark::State& state) {
  const int dimension = static_cast<int>(state.range(0));
  const int p = static_cast<int>(state.range(1));
  for (auto _ : state) {
    const auto table = molchaos::theory::expand_collision_moment(
        dimension, p, 0.5, 3.0, {}, molchaos::theory::SonineTerms::a2_a3);
    benchmark::DoNotOptimize(table.base.value);
  }
}

// A(ε) with b = 0.05 on 200 restitutions: what a report's theory curve costs.
void theory_curve(benchmark::State& state) {
  const int dimension = static_cast<int>(state.range(0));
  for (auto _ : state) {
    for (int i = 1; i <= 200; ++i) {
      molchaos::theory::CoolingInputs in;
      in.dimension = dimension;
      in.restitution = i / 200.0;
      in.correlation_b = 0.05;
      benchmark::DoNotOptimize(molchaos::theory::predict_cooling(in).A.value);
    }
  }
}

}  // namespace

BENCHMARK(coefficient_table_gauss)->Arg(2)->Arg(3)->ArgName("dim")->Unit(benchmark::kMillisecond);
BENCHMARK(coefficient_table_adaptive)
    ->ArgsProduct({{2, 3}, {4, 6, 8, 10, 12}})
    ->ArgNames({"dim", "neg_log10_tol"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(moment_table_with_a3)
    ->ArgsProduct({{2, 3}, {2, 4, 6}})
    ->ArgNames({"dim", "p"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(theory_curve)->Arg(2)->Arg(3)->ArgName("dim")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
