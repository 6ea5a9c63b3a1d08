#pragma once
// Synthetic raw DCB test records written from a simulation with a known law: what a testing
// machine would have written had it tested the simulated specimen. They exercise `reduce` and
// `identify` against a known answer (docs/verification.md, "Test records").
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/result/rcurve.h"

#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct SyntheticRecordOptions {
  double sampling_rate_hz = 10;        ///< rows per second, as a machine logs
  double opening_rate = 5e-3 / 60;     ///< crosshead rate [m/s] (5 mm/min, a usual DCB rate)
  double load_noise = 0.05;            ///< standard deviation of the load cell [N]
  double opening_noise = 1e-6;         ///< standard deviation of the crosshead reading [m]
  double crack_reading_interval = 5;   ///< a new crack reading every this many seconds [s]
  double crack_reading_noise = 0.1e-3; ///< standard deviation of each crack reading [m]
  /// Standard deviation of a slowly varying tracking error on every crack reading [m] (0: none):
  /// an optical tracker that runs ahead of the crack and falls back over millimetres of growth,
  /// as the shared records' readings do (data/dcb_records). An AR(1) process in crack growth,
  /// correlation exp(-growth / crack_tracking_correlation) between successive readings.
  double crack_tracking_drift = 0;
  double crack_tracking_correlation = 5e-3; ///< [m]
  double delta_root_noise = 1e-6;           ///< clip-gauge noise [m] (only with_delta_root)
  bool with_delta_root = false;             ///< also write the notch-root opening
  unsigned seed = 1;
};

/// A record sampled from `result`'s R-curve rows (load, load_point_opening, a, delta_root) at
/// constant crosshead rate: rows at t_k = k / sampling_rate_hz with opening rate * t_k up to the
/// last row's opening, load and crack length interpolated linearly in opening between the rows.
/// Before the first row the specimen rises linearly from the origin at the first row's
/// compliance with the crack at the first row's a (the simulation's rows start at the first
/// advance). Crack readings: a new reading (true length plus Gaussian noise, clipped at 3 sigma)
/// every crack_reading_interval seconds, repeated on the rows in between, as an optical tracker
/// read by hand does; with crack_tracking_drift > 0 each reading also carries the drift (drawn
/// only then, so records without it are unchanged for a given seed). One std::mt19937 seeded with
/// `seed`: reproducible. Throws InputError when the rows' load-point opening does not increase
/// (snap-back cannot be sampled at constant crosshead rate), there are fewer than 2 rows, or an
/// option is not positive where it must be.
TestRecord make_synthetic_record(const result::SimulationResult& result,
                                 const SyntheticRecordOptions& options, const std::string& name);

/// Writes `r` as CSV with columns time_s, opening_mm, load_N, a_mm (and delta_root_mm when
/// measured), preceded by `comment_lines` as '#' lines (say there how the data were made).
void write_test_record_csv(const std::string& path, const TestRecord& r,
                           const std::vector<std::string>& comment_lines);

/// Comment lines describing `options` and the simulation for write_test_record_csv().
std::vector<std::string> describe_synthetic_record(const result::SimulationResult& result,
                                                   const SyntheticRecordOptions& options);

} // namespace fiberbridge::analysis
