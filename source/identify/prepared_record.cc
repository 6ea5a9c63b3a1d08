// The records as the misfit sees them: a0, the initial compliance, the calibrated modulus and the
// crack readings that count (docs/design.md section 6, "identify").
#include "prepared_record.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::identify {

using units::mm;

namespace detail {

double first_reading(const analysis::TestRecord& rec) {
  for (double a : rec.crack_length)
    if (std::isfinite(a))
      return a;
  return NAN;
}

namespace {

/// PreparedRecord::crack_estimate.
std::vector<double> crack_estimate(const analysis::TestRecord& rec, const PreparedRecord& pr) {
  if (std::isfinite(first_reading(rec))) {
    // Rows without a reading (NaN, as the reader leaves them) hold the last reading.
    std::vector<double> a = rec.crack_length;
    double last = pr.specimen.initial_crack;
    for (double& v : a)
      v = std::isfinite(v) ? (last = v) : last;
    return a;
  }
  const double a0 = pr.specimen.initial_crack;
  const double chi_h = specimen::cbt_chi(pr.material) * pr.specimen.arm_thickness();
  std::vector<double> a(rec.load.size(), a0);
  double running = a0;
  for (std::size_t i = 0; i < rec.load.size(); ++i) {
    if (rec.load[i] > 0.05 * pr.peak_load && rec.opening[i] > 0)
      running = std::max(
          running, (a0 + chi_h) * std::cbrt(rec.opening[i] / rec.load[i] / pr.compliance) - chi_h);
    a[i] = running;
  }
  return a;
}

} // namespace

std::vector<PreparedRecord>
prepare_records(const std::vector<analysis::TestRecord>& records,
                const specimen::Specimen& specimen, const specimen::Material& quoted,
                const IdentifySettings& settings, const ForwardModel& forward,
                const std::function<void(const std::string&)>& progress) {
  std::vector<PreparedRecord> prepared;
  for (const auto& rec : records) {
    PreparedRecord pr;
    pr.record = &rec;
    pr.specimen = specimen;
    // Without crack readings (load and opening alone) a0 is the specimen's.
    if (!rec.crack_length.empty())
      if (std::isfinite(first_reading(rec)))
        pr.specimen.initial_crack = first_reading(rec);
    pr.specimen.validate("Specimen (record " + rec.name + ")");
    pr.material = quoted;
    pr.peak_load = *std::max_element(rec.load.begin(), rec.load.end());
    pr.compliance = initial_compliance(rec, settings);
    if (settings.calibrate_modulus) {
      pr.material.E_L = modulus_for_compliance(pr.specimen, quoted, pr.compliance);
      // A forward model with its own compliance: from CBT's modulus, fixed-point passes on
      // E_L C_model(E_L) = E_L' C (bending dominates: C ~ 1/E_L, so each pass takes most of the
      // remaining ratio; three leave it well under the load scatter).
      if (forward.initial_compliance)
        for (int pass = 0; pass < 3; ++pass)
          pr.material.E_L *= forward.initial_compliance(pr.specimen, pr.material) / pr.compliance;
    }
    auto rows = analysis::crack_reading_rows(rec);
    // Rows without a reading are NaN (test_record.h): never a reading.
    rows.erase(std::remove_if(rows.begin(), rows.end(),
                              [&](std::size_t k) { return !std::isfinite(rec.crack_length[k]); }),
               rows.end());
    if (!rows.empty())
      pr.crack_rows.assign(rows.begin() + 1, rows.end());
    pr.crack_estimate = crack_estimate(rec, pr);
    if (progress)
      progress("identify: record " + rec.name + ": a0 " + fmt(pr.specimen.initial_crack / mm) +
               " mm, initial compliance " + fmt(pr.compliance / mm) + " mm/N, E_L " +
               fmt(pr.material.E_L * 1e-9) + " GPa");
    prepared.push_back(pr);
  }
  return prepared;
}

} // namespace detail

double initial_compliance(const analysis::TestRecord& rec, const IdentifySettings& s) {
  using detail::first_reading;
  const double peak = *std::max_element(rec.load.begin(), rec.load.end());
  // Before initiation: up to the first reading beyond a0 by more than three times the reading
  // scatter (a noisy tracker changes its reading before the crack grows).
  std::size_t end = 0;
  if (!std::isfinite(
          first_reading(rec))) // no readings: the rows before the load first passes the window
    while (end < rec.load.size() && rec.load[end] <= s.compliance_high * peak)
      ++end;
  else
    // A row without a reading (NaN) counts as before the growth.
    while (end < rec.load.size() &&
           !(rec.crack_length[end] - first_reading(rec) > 3 * s.crack_scatter))
      ++end;
  double n = 0, sp = 0, sd = 0, spp = 0, spd = 0;
  for (std::size_t i = 0; i < end; ++i)
    if (rec.load[i] >= s.compliance_low * peak && rec.load[i] <= s.compliance_high * peak) {
      n += 1;
      sp += rec.load[i];
      sd += rec.opening[i];
      spp += rec.load[i] * rec.load[i];
      spd += rec.load[i] * rec.opening[i];
    }
  const double var = spp - sp * sp / n;
  if (n < 3 || !(var > 0))
    throw InputError(rec.source + ": record '" + rec.name + "' has " + std::to_string(int(n)) +
                     " rows before the crack grows with a load between " +
                     fmt(100 * s.compliance_low) + " and " + fmt(100 * s.compliance_high) +
                     " % of the peak; Identify/Compliance window needs at least 3");
  return (spd - sp * sd / n) / var;
}

double modulus_for_compliance(const specimen::Specimen& specimen,
                              const specimen::Material& material, double compliance) {
  // CBT compliance falls monotonically with E_L (chi grows only like its square root):
  // bisection on log E_L.
  double lo = std::log(material.E_L / 50), hi = std::log(material.E_L * 50);
  specimen::Material m = material;
  for (int it = 0; it < 100; ++it) {
    m.E_L = std::exp(0.5 * (lo + hi));
    if (specimen::cbt_opening(specimen, m, 1.0, specimen.initial_crack) > compliance)
      lo = std::log(m.E_L);
    else
      hi = std::log(m.E_L);
  }
  return std::exp(0.5 * (lo + hi));
}

} // namespace fiberbridge::identify
