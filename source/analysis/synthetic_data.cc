// Synthetic replicates of a measured R(delta) series from a known law (seed Eq. 2).
#include "fiberbridge/analysis/synthetic_data.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <random>
#include <sstream>

namespace fiberbridge::analysis {

RDeltaData make_synthetic_rdelta(const law::TractionLaw& law, double j_tip, int n_replicates,
                                 int n_points_per_replicate, double noise_J_m2, double delta_max,
                                 unsigned seed) {
  const std::string what = "synthetic R(delta) data";
  if (n_replicates < 1)
    throw InputError(what + ": need at least 1 replicate, got " + std::to_string(n_replicates));
  if (n_points_per_replicate < 8)
    throw InputError(what + ": need at least 8 points per replicate (the reader's minimum), got " +
                     std::to_string(n_points_per_replicate));
  if (!(noise_J_m2 >= 0) || !(j_tip >= 0))
    throw InputError(what + ": the noise and J_tip must be >= 0");
  const double dc = law.critical_opening();
  // The shortest replicate reaches 0.95 delta_max (see the header): it must pass delta_c.
  if (!(0.95 * delta_max > dc)) {
    std::ostringstream s;
    s << what << ": delta_max = " << delta_max / units::mm
      << " mm must exceed delta_c / 0.95 = " << dc / 0.95 / units::mm
      << " mm so that every replicate shows the steady-state plateau";
    throw InputError(s.str());
  }

  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  RDeltaData data;
  {
    std::ostringstream s;
    s << "synthetic (" << law.name() << " law, seed " << seed << ")";
    data.source = s.str();
  }
  std::size_t row = 0;
  const int m = n_points_per_replicate;
  for (int r = 0; r < n_replicates; ++r) {
    Replicate rep;
    rep.label = std::to_string(r + 1);
    const double j_r = j_tip * (1 + 0.02 * std::clamp(normal(rng), -3.0, 3.0));
    const double end = delta_max * (1 - 0.05 * uniform(rng));
    const double spacing = end / (m - 1);
    for (int j = 0; j < m; ++j) {
      // Jitter below half a spacing keeps the openings strictly increasing; the ends stay put.
      const double jitter = (j == 0 || j == m - 1) ? 0.0 : 0.8 * (uniform(rng) - 0.5);
      const double d = spacing * (j + jitter);
      const double R = law::r_curve_eq2(law, j_r, d) + noise_J_m2 * normal(rng);
      rep.time_s.push_back(j);
      rep.delta.push_back(d);
      rep.R.push_back(std::max(0.0, R));
      rep.line.push_back(++row);
    }
    data.replicates.push_back(std::move(rep));
  }
  return data;
}

std::vector<std::string> describe_synthetic_rdelta(const law::TractionLaw& law, double j_tip,
                                                   int n_replicates, int n_points_per_replicate,
                                                   double noise_J_m2, double delta_max,
                                                   unsigned seed) {
  std::ostringstream points;
  points.precision(6);
  for (double d : law.kinks())
    points << (points.tellp() > 0 ? ", " : "") << d / units::mm << ":"
           << law.envelope(d) / units::kPa;
  std::ostringstream a, b, c;
  a << "SYNTHETIC DATA (not measured): R(delta) from seed Eq. 2 of the " << law.name()
    << " law with points delta_mm:sigma_kPa = " << points.str() << " (delta_c "
    << law.critical_opening() / units::mm << " mm, area " << law.area() << " J/m^2)";
  b << n_replicates << " replicates x " << n_points_per_replicate << " points; J_tip = " << j_tip
    << " J/m^2 with 2 % normal scatter per replicate; delta from 0 to delta_max = "
    << delta_max / units::mm << " mm (each replicate stops 0-5 % earlier), sampled with +-0.4 "
    << "spacing jitter; time_s = sample index (1 Hz)";
  c << "Gaussian noise of " << noise_J_m2 << " J/m^2 on R; std::mt19937 seed " << seed
    << " (fiberbridge make_synthetic_rdelta)";
  return {a.str(), b.str(), c.str()};
}

void write_rdelta_csv(const std::string& path, const RDeltaData& data,
                      const std::vector<std::string>& comment_lines) {
  std::ostringstream out;
  out.precision(12);
  for (const auto& c : comment_lines)
    out << "# " << c << "\n";
  out << "replicate,time_s,delta_mm,R_J_m2\n";
  for (const auto& r : data.replicates) {
    if (r.label.find_first_of(",\r\n") != std::string::npos)
      throw InputError(path + ": replicate label '" + r.label +
                       "' contains a comma or line break and cannot be written as CSV");
    if (r.delta.size() != r.R.size() || (!r.time_s.empty() && r.time_s.size() != r.delta.size()))
      throw InputError(path + ": replicate '" + r.label + "' has columns of different lengths");
    for (std::size_t i = 0; i < r.delta.size(); ++i)
      out << r.label << "," << (r.time_s.empty() ? static_cast<double>(i) : r.time_s[i]) << ","
          << r.delta[i] / units::mm << "," << r.R[i] << "\n";
  }
  write_file_atomically(path, out.str());
}

} // namespace fiberbridge::analysis
