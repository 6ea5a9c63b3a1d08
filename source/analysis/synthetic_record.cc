// Synthetic raw DCB test records from a simulation (synthetic_record.h).
#include "fiberbridge/analysis/synthetic_record.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

namespace fiberbridge::analysis {

namespace {

double clipped_normal(std::mt19937& rng, double sigma) {
  std::normal_distribution<double> n(0.0, 1.0);
  return sigma * std::clamp(n(rng), -3.0, 3.0);
}

} // namespace

TestRecord make_synthetic_record(const result::SimulationResult& result,
                                 const SyntheticRecordOptions& o, const std::string& name) {
  const auto& rows = result.rcurve;
  if (rows.size() < 2)
    throw InputError("synthetic record '" + name + "': the " + result.model + " result has " +
                     std::to_string(rows.size()) + " R-curve rows; at least 2 are needed");
  if (!(o.sampling_rate_hz > 0) || !(o.opening_rate > 0) || !(o.crack_reading_interval > 0) ||
      o.load_noise < 0 || o.opening_noise < 0 || o.crack_reading_noise < 0 ||
      o.delta_root_noise < 0 || o.crack_tracking_drift < 0 || !(o.crack_tracking_correlation > 0))
    throw InputError("synthetic record '" + name +
                     "': sampling rate, opening rate, reading interval and tracking correlation "
                     "must be > 0 and the noise levels >= 0");
  // The curve in opening: the origin, then the rows (the first row's crack length and compliance
  // on the elastic rise before it).
  std::vector<double> x = {0.0}, P = {0.0}, a = {rows[0].a}, root = {0.0};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    if (!(r.load_point_opening > x.back()))
      throw InputError("synthetic record '" + name + "': the load-point opening of the " +
                       result.model + " result does not increase at R-curve row " +
                       std::to_string(i + 1) +
                       " (snap-back); a constant crosshead rate cannot sample it");
    x.push_back(r.load_point_opening);
    P.push_back(r.load);
    a.push_back(r.a);
    root.push_back(std::isnan(r.delta_root) ? 0.0 : r.delta_root);
  }
  if (o.with_delta_root && std::isnan(rows.back().delta_root))
    throw InputError("synthetic record '" + name + "': the " + result.model +
                     " result has no delta_root column to write");

  const double dt = 1.0 / o.sampling_rate_hz;
  const std::size_t n = static_cast<std::size_t>(std::floor(x.back() / (o.opening_rate * dt)));
  std::vector<double> xs(n + 1);
  for (std::size_t k = 0; k <= n; ++k)
    xs[k] = o.opening_rate * dt * static_cast<double>(k);
  const auto Ps = resample_linear(x, P, xs);
  const auto as = resample_linear(x, a, xs);
  const auto roots = resample_linear(x, root, xs);

  std::mt19937 rng(o.seed);
  TestRecord rec;
  rec.name = name;
  rec.source = "synthetic (" + result.model + ")";
  double reading = as[0], next_reading = 0, drift = 0, drift_a = as[0];
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = dt * static_cast<double>(k);
    if (t >= next_reading) {
      if (o.crack_tracking_drift > 0) {
        const double rho = std::exp(-(as[k] - drift_a) / o.crack_tracking_correlation);
        drift =
            rho * drift + std::sqrt(1 - rho * rho) * clipped_normal(rng, o.crack_tracking_drift);
        drift_a = as[k];
      }
      reading = as[k] + drift + clipped_normal(rng, o.crack_reading_noise);
      next_reading += o.crack_reading_interval;
    }
    rec.time.push_back(t);
    // The machine starts at zero: no noise on the first row's opening.
    rec.opening.push_back(k == 0 ? 0.0
                                 : std::max(0.0, xs[k] + clipped_normal(rng, o.opening_noise)));
    rec.load.push_back(Ps[k] + clipped_normal(rng, o.load_noise));
    rec.crack_length.push_back(reading);
    if (o.with_delta_root)
      rec.delta_root.push_back(
          std::max(0.0, roots[k] + (k == 0 ? 0.0 : clipped_normal(rng, o.delta_root_noise))));
    rec.line.push_back(k + 2);
  }
  return rec;
}

void write_test_record_csv(const std::string& path, const TestRecord& r,
                           const std::vector<std::string>& comment_lines) {
  std::vector<std::string> header = {"time_s", "opening_mm", "load_N", "a_mm"};
  const bool root = !r.delta_root.empty();
  if (root)
    header.push_back("delta_root_mm");
  CsvWriter w(path, header, comment_lines);
  for (std::size_t i = 0; i < r.opening.size(); ++i) {
    std::vector<double> v = {r.time.empty() ? static_cast<double>(i) : r.time[i],
                             r.opening[i] / units::mm, r.load[i],
                             // NaN (an empty cell): no reading on this row, or no crack column
                             (r.crack_length.empty() ? NAN : r.crack_length[i]) / units::mm};
    if (root)
      v.push_back(r.delta_root[i] / units::mm);
    w.row(v);
  }
  w.close();
}

std::vector<std::string> describe_synthetic_record(const result::SimulationResult& result,
                                                   const SyntheticRecordOptions& o) {
  std::ostringstream s;
  s << "Synthetic DCB record sampled from a " << result.model << " simulation ("
    << result.rcurve.size() << " R-curve rows, G_ss " << result.G_ss << " J/m^2) at "
    << o.sampling_rate_hz << " Hz and " << o.opening_rate / units::mm * 60
    << " mm/min; noise (1 sigma, clipped at 3): load " << o.load_noise << " N, opening "
    << o.opening_noise / units::mm << " mm, crack reading " << o.crack_reading_noise / units::mm
    << " mm every " << o.crack_reading_interval << " s";
  if (o.crack_tracking_drift > 0)
    s << ", crack tracking drift " << o.crack_tracking_drift / units::mm << " mm correlated over "
      << o.crack_tracking_correlation / units::mm << " mm of growth";
  if (o.with_delta_root)
    s << ", delta_root " << o.delta_root_noise / units::mm << " mm";
  s << "; seed " << o.seed << ".";
  return {s.str()};
}

} // namespace fiberbridge::analysis
