// Cost of the analysis chain against the number of points: Eq. 6 extraction (smoothed slopes +
// the O(n) suffix-sum form of Eq. 6) and the fixed trilinear fit. Both must scale like O(n);
// target: 10^6 points well under 0.1 s.
//   cmake --build BUILD --target bench_inverse && BUILD/bench/bench_inverse
#include "fiberbridge/analysis/inverse.h"
#include "fiberbridge/analysis/trilinear_fit.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <benchmark/benchmark.h>

using namespace fiberbridge;
using units::kPa;
using units::mm;

namespace {

law::TrilinearParameters pva_control() {
  return {0.1 * mm, 661 * kPa, 1.0 * mm, 187 * kPa, 6.0 * mm};
}

/// Eq. 2 of the PVA control law sampled at the n + 1 grid nodes up to delta_c plus a plateau.
analysis::RDeltaCurve pva_curve(int n) {
  const auto law = law::make_trilinear(pva_control());
  analysis::RDeltaCurve c;
  const double dc = law.critical_opening();
  for (int i = 0; i <= n + n / 4; ++i) {
    c.delta.push_back(dc * i / n);
    c.R.push_back(law::r_curve_eq2(law, 200, c.delta.back()));
  }
  c.R_std.assign(c.delta.size(), 0.0);
  return c;
}

void BM_SmoothedSlopesAndEq6(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto curve = pva_curve(n);
  for (auto _ : state) {
    const auto S = analysis::smoothed_slopes(curve, 6 * mm, n, 2);
    auto sigma = analysis::cohesive_law_eq6(S);
    benchmark::DoNotOptimize(sigma.data());
  }
  state.SetComplexityN(n);
}

void BM_SmoothedSlopesDenseRaw(benchmark::State& state) {
  // Dense mode: N raw points up to delta_c and a grid of n = N/4 intervals, so every window
  // fits the raw points (about 4 (2k + 1) of them). N counts the raw points.
  const int N = static_cast<int>(state.range(0));
  const auto curve = pva_curve(N);
  for (auto _ : state) {
    const auto S = analysis::smoothed_slopes(curve, 6 * mm, N / 4, 2);
    auto sigma = analysis::cohesive_law_eq6(S);
    benchmark::DoNotOptimize(sigma.data());
  }
  state.SetComplexityN(N);
}

void BM_Eq6Only(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto curve = pva_curve(n);
  const auto S = analysis::smoothed_slopes(curve, 6 * mm, n, 2);
  for (auto _ : state) {
    auto sigma = analysis::cohesive_law_eq6(S);
    benchmark::DoNotOptimize(sigma.data());
  }
  state.SetComplexityN(n);
}

void BM_TrilinearFixedFit(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto law = law::make_trilinear(pva_control());
  std::vector<double> delta(n + 1), sigma(n + 1);
  for (int i = 0; i <= n; ++i) {
    delta[i] = 6 * mm * i / n;
    sigma[i] = law.envelope(delta[i]);
  }
  const double G_B = law.area();
  for (auto _ : state) {
    auto fit = analysis::fit_trilinear_fixed(delta, sigma, 0.1 * mm, 1.0 * mm, 6 * mm, G_B);
    benchmark::DoNotOptimize(fit.law.s1);
  }
  state.SetComplexityN(n);
}

} // namespace

BENCHMARK(BM_SmoothedSlopesAndEq6)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);
BENCHMARK(BM_SmoothedSlopesDenseRaw)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);
BENCHMARK(BM_Eq6Only)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);
BENCHMARK(BM_TrilinearFixedFit)
    ->RangeMultiplier(10)
    ->Range(1000, 1000000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oN);

BENCHMARK_MAIN();
