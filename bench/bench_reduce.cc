// Cost of `reduce` on a long record: reading + cleaning a 10^5-row CSV (our plain file and the same
// record as a machine exports it: preamble, units row, quoted cells, kN), the layout detection on
// its own, and the reduction (direct energy with O(1) window fits, MBT/CC/MCC). Target (issues
// 12 and 31): well under a second; detection adds no measurable time (it reads a bounded prefix).
//   cmake --build BUILD --target bench_reduce && BUILD/bench/bench_reduce
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/synthetic_record.h"
#include "fiberbridge/core/exported_table.h"
#include "fiberbridge/core/units.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace fiberbridge;
using units::mm;

namespace {

constexpr double B = 25 * mm, h = 2.7 * mm, E = 30e9;

/// A linear-elastic DCB (C = 8 a^3 / (E B h^3)) whose crack grows from 35 to 100 mm against an
/// R curve rising from 300 to 900 J/m^2: rows at every 0.05 mm of growth.
result::SimulationResult elastic_dcb() {
  result::SimulationResult r;
  r.model = "closed-form beam";
  for (double a = 35 * mm; a <= 100 * mm; a += 0.05 * mm) {
    const double G = 300 + 600 * (1 - std::exp(-(a - 35 * mm) / (15 * mm)));
    const double C = 8 * a * a * a / (E * B * h * h * h), dC = 24 * a * a / (E * B * h * h * h);
    result::RCurvePoint q;
    q.a = a;
    q.load = std::sqrt(2 * B * G / dC);
    q.load_point_opening = C * q.load;
    r.rcurve.push_back(q);
  }
  return r;
}

/// A 10^5-row record with a new crack reading on every row (the worst case for the fits).
std::string write_long_record() {
  const auto sim = elastic_dcb();
  analysis::SyntheticRecordOptions o;
  o.opening_rate = 1e-3;
  o.sampling_rate_hz = 1e5 * o.opening_rate / sim.rcurve.back().load_point_opening;
  o.crack_reading_interval = 1 / o.sampling_rate_hz;
  o.crack_reading_noise = 0;
  const auto rec = analysis::make_synthetic_record(sim, o, "long");
  const std::string path = "/tmp/fb_bench_reduce_" + std::to_string(::getpid()) + ".csv";
  analysis::write_test_record_csv(path, rec, analysis::describe_synthetic_record(sim, o));
  return path;
}

/// The same record as an Instron Bluehill export: a preamble, a quoted header and units row,
/// every cell quoted, the load in kN.
std::string write_long_export() {
  const std::string plain = write_long_record();
  const auto t = ExportedTable::read(plain);
  std::remove(plain.c_str());
  const auto T = t.numeric(0), x = t.numeric(1), P = t.numeric(2), a = t.numeric(3);
  std::string s =
      "Text Inputs : Specimen label,\"long\"\r\nGeneral : Start Date,13/11/2018\r\n\r\n"
      "\"Time\",\"Extension\",\"Load\",\"Crack\"\r\n\"(s)\",\"(mm)\",\"(kN)\",\"(mm)\"\r\n";
  char b[160];
  for (std::size_t i = 0; i < T.size(); ++i) {
    std::snprintf(b, sizeof b, "\"%.10g\",\"%.10g\",\"%.10g\",\"%.10g\"\r\n", T[i], x[i],
                  P[i] / 1e3, a[i]);
    s += b;
  }
  const std::string path = "/tmp/fb_bench_export_" + std::to_string(::getpid()) + ".csv";
  std::ofstream(path, std::ios::binary) << s;
  return path;
}

analysis::RecordReadOptions export_map() {
  analysis::RecordReadOptions o;
  o.columns = analysis::RecordColumnMap::parse(
      "time_s: Time, opening_mm: Extension, load_N: Load, a_mm: Crack", "bench");
  return o;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream b;
  b << in.rdbuf();
  return b.str();
}

specimen::Specimen test_specimen() {
  auto s = specimen::Specimen::unknown();
  s.width = B;
  s.height = 2 * h; // both arms
  return s;
}

void BM_ReadRecord(benchmark::State& state) {
  const std::string path = write_long_record();
  for (auto _ : state) {
    const auto r = analysis::read_test_records(path);
    benchmark::DoNotOptimize(r.data());
  }
  state.counters["rows"] =
      static_cast<double>(analysis::read_test_records(path).at(0).opening.size());
  std::remove(path.c_str());
}

void BM_ReadExportedRecord(benchmark::State& state) {
  const std::string path = write_long_export();
  const auto o = export_map();
  for (auto _ : state) {
    const auto r = analysis::read_test_records(path, o);
    benchmark::DoNotOptimize(r.data());
  }
  state.counters["rows"] =
      static_cast<double>(analysis::read_test_records(path, o).at(0).opening.size());
  std::remove(path.c_str());
}

/// Layout detection alone, on the text already in memory: it looks at a bounded prefix, so its
/// cost does not grow with the record (compare with the reads above).
void BM_DetectLayout(benchmark::State& state) {
  const std::string path = write_long_export();
  const std::string text = slurp(path);
  std::remove(path.c_str());
  for (auto _ : state) {
    const auto layout = detect_table_layout(text, "bench");
    benchmark::DoNotOptimize(layout.header_line);
  }
}

void BM_ReduceRecord(benchmark::State& state) {
  const std::string path = write_long_record();
  const auto rec = analysis::read_test_records(path).at(0);
  std::remove(path.c_str());
  for (auto _ : state) {
    const auto r = analysis::reduce_record(rec, test_specimen());
    benchmark::DoNotOptimize(r.R_energy.data());
  }
  // The answer beside the time: the closed-form R curve runs from 866 to 892 J/m^2 over the
  // last third of the growth (mean about 880 J/m^2).
  const auto r = analysis::reduce_record(rec, test_specimen());
  state.counters["rows"] = static_cast<double>(rec.opening.size());
  state.counters["readings"] = static_cast<double>(r.a.size());
  state.counters["plateau_energy_J_m2"] = r.energy.plateau;
  state.counters["plateau_MBT_J_m2"] = r.mbt.plateau;
}

} // namespace

BENCHMARK(BM_ReadRecord)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadExportedRecord)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DetectLayout)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReduceRecord)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
