// Cost of a durability campaign without simulations (issue 33): 120 specimens (the seed's five
// materials x four cycle counts x 6 specimens, synthetic R(delta) files from the Table 1 laws)
// read, grouped, and each group bootstrapped 1000 times (Eq. 6 and the trilinear fit on every
// resample), then degradation and ranking over the samples. Target: under 60 s on 2 cores; this
// runs on one process (the scene spreads the groups over MPI ranks).
//   cmake --build BUILD --target bench_campaign && BUILD/bench/bench_campaign
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/analysis/campaign_synthetic.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

using namespace fiberbridge::analysis;

namespace {

std::string campaign_of_120() {
  static const std::string manifest = [] {
    const auto truth = table1_truth(
        read_property_table(std::string(FIBERBRIDGE_BENCH_DATA) + "/reference/seed_table1.csv"));
    SyntheticCampaignOptions so;
    so.replicates = 6; // 20 groups x 6 = 120 specimens
    const auto dir = std::filesystem::temp_directory_path() / "fiberbridge_bench_campaign";
    return write_synthetic_campaign(dir.string(), truth, so);
  }();
  return manifest;
}

void BM_Campaign120Specimens1000Samples(benchmark::State& state) {
  const auto manifest = read_campaign_manifest(campaign_of_120());
  CampaignOptions o;
  o.bootstrap_samples = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const auto r = analyse_campaign(manifest, {}, o, {"DF"});
    benchmark::DoNotOptimize(r.ranking.samples);
  }
  state.counters["specimens"] = static_cast<double>(manifest.rows.size());
}
BENCHMARK(BM_Campaign120Specimens1000Samples)->Arg(1000)->Unit(benchmark::kSecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
