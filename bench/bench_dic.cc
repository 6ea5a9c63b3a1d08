// The dic step's speed (issue 32: 300 frames of 10^4 points in under 10 s on 2 cores, reading
// included): frames of the synthetic DCB (tests/dic/dic_synthetic.h) in VIC's layout (pixels, y
// down, 1 % failed points) written once to a temporary folder, then analysed as the scene item
// does (read in parallel, tip rule, extensometer, tracking). Run from a Release build:
//   build/bench/bench_dic --benchmark_min_time=0.01
#include "../tests/dic/dic_synthetic.h"
#include "fiberbridge/dic/dic_analysis.h"

#include <benchmark/benchmark.h>

#include <filesystem>

namespace {

using namespace fiberbridge;
namespace fs = std::filesystem;

/// 300 frames of 100 x 100 = 10^4 points (0.5 mm grid: 50 mm along the plane, +-25 mm across).
const std::vector<std::string>& frames() {
  static std::vector<std::string> paths;
  if (!paths.empty())
    return paths;
  const fs::path dir = fs::temp_directory_path() / "fb_bench_dic";
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::SyntheticDcb dcb;
  dcb.s_min = -5e-3;
  dcb.s_max = 44.5e-3;
  dcb.n_half = 25e-3;
  dcb.noise_v = 1e-6;
  dcb.fail_fraction = 0.01;
  dic::FrameGeometry g;
  g.pixels = true;
  g.pixel_size = 0.05e-3;
  g.y_down = true;
  g.crack_plane_y = 600;
  g.notch_root_x = 200;
  for (int k = 0; k < 300; ++k) {
    const std::string p = (dir / ("dcb_" + std::to_string(1000 + k) + "_0.csv")).string();
    test::write_frame(p,
                      dcb.frame(k < 20 ? 0.0 : 0.1e-3 * (k - 19), std::min(1.0, (k + 1) / 20.0),
                                static_cast<unsigned>(k)),
                      g, test::Out::vic);
    paths.push_back(p);
  }
  return paths;
}

void BM_DicThreeHundredFrames(benchmark::State& state) {
  const auto& paths = frames();
  dic::DicOptions o;
  o.read.pixel_coordinates = true;
  o.geometry.pixels = true;
  o.geometry.pixel_size = 0.05e-3;
  o.geometry.y_down = true;
  o.geometry.crack_plane_y = 600;
  o.geometry.notch_root_x = 200;
  o.threads = static_cast<unsigned>(state.range(0));
  std::size_t points = 0;
  for (auto _ : state) {
    const auto a = dic::analyse_frames(dic::order_frames(paths, "bench"), o);
    points = a.points_used + a.points_failed;
    benchmark::DoNotOptimize(a.frames.back().s_tip);
  }
  state.counters["frames"] = static_cast<double>(paths.size());
  state.counters["points_per_frame"] = static_cast<double>(points) / paths.size();
}
BENCHMARK(BM_DicThreeHundredFrames)->Arg(1)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
