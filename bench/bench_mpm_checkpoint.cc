// Cost of an MPM checkpoint (mpm/checkpoint.h) on the seed DCB with the PVA control law: writing
// the whole state (atomically, into a temporary directory) and reading it back into a fresh
// model. Argument: the cell size in micrometres (2500 = the default 2.5 mm cells).
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/mpm/checkpoint.h"
#include "fiberbridge/mpm/dcb.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <unistd.h>

using namespace fiberbridge;

namespace {

struct Setup {
  specimen::Specimen specimen;
  specimen::Material material;
  law::PiecewiseLinearLaw law = law::make_trilinear({0.1e-3, 661e3, 1.0e-3, 187e3, 6e-3});
  mpm::MpmParameters params;
  std::string dir;
  explicit Setup(long cell_um) {
    params.cell_size = cell_um * 1e-6;
    params.vtu_every_advances = 0;
    dir = (std::filesystem::temp_directory_path() /
           ("fb_bench_checkpoint_" + std::to_string(getpid())))
              .string();
    std::filesystem::create_directories(dir);
  }
  ~Setup() { std::filesystem::remove_all(dir); }
};

void BM_WriteCheckpoint(benchmark::State& state) {
  Setup s(state.range(0));
  mpm::DcbModel model(s.specimen, s.material, s.law, 200, s.params, s.dir);
  for (int i = 0; i < 10; ++i)
    model.step(true);
  for (auto _ : state)
    model.write_checkpoint();
  state.counters["particles"] = static_cast<double>(model.solver().particles().size());
  state.counters["MB"] = std::filesystem::file_size(mpm::checkpoint_path(s.dir)) / 1e6;
}
BENCHMARK(BM_WriteCheckpoint)->Arg(2500)->Arg(1250)->Unit(benchmark::kMillisecond);

void BM_ResumeFromCheckpoint(benchmark::State& state) {
  Setup s(state.range(0));
  {
    mpm::DcbModel model(s.specimen, s.material, s.law, 200, s.params, s.dir);
    for (int i = 0; i < 10; ++i)
      model.step(true);
    model.write_checkpoint();
  }
  s.params.resume = true;
  mpm::DcbModel model(s.specimen, s.material, s.law, 200, s.params, s.dir);
  for (auto _ : state)
    benchmark::DoNotOptimize(model.resume_from_checkpoint());
}
BENCHMARK(BM_ResumeFromCheckpoint)->Arg(2500)->Arg(1250)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
