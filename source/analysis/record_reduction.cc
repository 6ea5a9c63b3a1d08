// R(a) from raw DCB records: direct energy and the ASTM D5528 / ISO 15024 beam-theory
// reductions (record_reduction.h; docs/design.md, "Test records").
#include "fiberbridge/analysis/record_reduction.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace fiberbridge::analysis {

namespace {

/// Automatic smoothing window: at least 10 reading spacings (11 readings leave 9 degrees of
/// freedom for the residual-based standard error of the slope) and at least 4 arm thicknesses.
/// The second bound is the one that acts on the shared records (0.2-0.3 mm between readings):
/// D = W - P opening/2 carries the load-cell and crosshead noise times the opening, and the local
/// slope over one arm thickness (2.7 mm) scatters by +-30 % against MBT there, over 4 (10.8 mm)
/// by +-10 % (docs/verification.md, "Test records"); 4 h is still short against the 40-70 mm
/// over which those R curves rise.
constexpr double readings_per_window = 10;
constexpr double arm_thicknesses_per_window = 4;
constexpr std::size_t min_readings = 5;
/// The band's scatter of neighbouring estimates is taken over this many windows (centred).
constexpr double scatter_windows = 4;

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double median(std::vector<double> v) {
  if (v.empty())
    return NAN;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

/// Local straight lines of y against x over windows [begin, end) in O(1) each: prefix sums of
/// the samples taken about their overall means, so that window sums far from the origin keep
/// their digits (the dissipated energy grows to a few joules while its noise is ~1e-4 J).
class WindowLines {
public:
  WindowLines(const std::vector<double>& x, const std::vector<double>& y) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      x0_ += x[i] / static_cast<double>(x.size());
      y0_ += y[i] / static_cast<double>(y.size());
    }
    sx_.assign(x.size() + 1, 0.0);
    sy_ = sxx_ = sxy_ = syy_ = sx_;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double u = x[i] - x0_, v = y[i] - y0_;
      sx_[i + 1] = sx_[i] + u;
      sy_[i + 1] = sy_[i] + v;
      sxx_[i + 1] = sxx_[i] + u * u;
      sxy_[i + 1] = sxy_[i] + u * v;
      syy_[i + 1] = syy_[i] + v * v;
    }
  }
  /// Slope over [b, e) and its standard error from the residuals; NaN below 3 points or with
  /// no spread in x.
  std::pair<double, double> slope(std::size_t b, std::size_t e) const {
    const double n = static_cast<double>(e - b);
    if (e - b < 3)
      return {NAN, NAN};
    const double mx = (sx_[e] - sx_[b]) / n, my = (sy_[e] - sy_[b]) / n;
    const double Sxx = sxx_[e] - sxx_[b] - n * mx * mx;
    const double Sxy = sxy_[e] - sxy_[b] - n * mx * my;
    const double Syy = syy_[e] - syy_[b] - n * my * my;
    if (!(Sxx > 0))
      return {NAN, NAN};
    const double k = Sxy / Sxx;
    const double ss = std::max(0.0, Syy - k * Sxy);
    return {k, std::sqrt(ss / (n - 2) / Sxx)};
  }

private:
  double x0_ = 0, y0_ = 0;
  std::vector<double> sx_, sy_, sxx_, sxy_, syy_;
};

/// Initiation (first value) and plateau (mean and std over da >= (1 - fraction) da_max).
MethodSummary summarize(const std::vector<double>& da, const std::vector<double>& R,
                        double fraction) {
  MethodSummary m;
  std::size_t first = 0;
  while (first < R.size() && !(da[first] > 0 && std::isfinite(R[first])))
    ++first;
  if (first == R.size())
    return m;
  m.initiation = R[first];
  const double from = (1 - fraction) * da.back();
  double sum = 0, sum2 = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < R.size(); ++i)
    if (da[i] >= from && std::isfinite(R[i])) {
      sum += R[i];
      sum2 += R[i] * R[i];
      ++n;
    }
  if (n) {
    m.plateau = sum / static_cast<double>(n);
    m.plateau_std =
        n > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * m.plateau) / static_cast<double>(n - 1)))
              : 0.0;
  }
  return m;
}

} // namespace

ReducedRecord reduce_record(const TestRecord& rec, const TestSpecimen& sp, const ReduceOptions& o) {
  const std::string src = rec.source + " (record '" + rec.name + "')";
  sp.check(src);
  const double B = sp.width, h = sp.arm_thickness;
  const double l1 = std::isnan(sp.pin_to_arm_midplane) ? h / 2 : sp.pin_to_arm_midplane;
  const bool blocks = !std::isnan(sp.pin_to_block_edge);
  const double l2 = blocks ? sp.pin_to_block_edge : 0.0;

  ReducedRecord out;
  out.name = rec.name;
  out.source = rec.source;
  out.cleaning = rec.cleaning;
  out.a0 = std::isnan(sp.initial_crack) ? rec.crack_length.front() : sp.initial_crack;
  if (out.a0 > rec.crack_length.front() + 1e-9)
    throw InputError(src + ": Specimen/Initial crack " + num(out.a0 / units::mm) +
                     " mm lies beyond the first crack reading " +
                     num(rec.crack_length.front() / units::mm) + " mm on line " +
                     std::to_string(rec.line.front()));

  // Dissipated energy D = W - U along the whole record (every row: the load and opening are
  // good on rows that repeat a stale crack reading).
  const std::size_t n = rec.opening.size();
  std::vector<double> D(n, 0.0);
  double W = 0;
  for (std::size_t i = 1; i < n; ++i) {
    W += 0.5 * (rec.load[i] + rec.load[i - 1]) * (rec.opening[i] - rec.opening[i - 1]);
    D[i] = W - 0.5 * rec.load[i] * rec.opening[i];
  }

  // The rows with a fresh crack reading; the first is the notch (a0).
  const auto readings = crack_reading_rows(rec);
  std::vector<double> ar, Dr;
  for (std::size_t k : readings) {
    ar.push_back(rec.crack_length[k]);
    Dr.push_back(D[k]);
  }
  for (std::size_t j = 1; j < ar.size(); ++j)
    if (ar[j] < ar[j - 1])
      throw InputError(src + ":" + std::to_string(rec.line[readings[j]]) +
                       ": the crack reading decreases; read records with read_test_records, "
                       "which holds readings within the tracking tolerance at their maximum");
  std::vector<std::size_t> beyond;
  for (std::size_t j = 0; j < readings.size(); ++j)
    if (ar[j] > out.a0 && rec.load[readings[j]] > 0)
      beyond.push_back(j);
  if (beyond.size() < min_readings)
    throw InputError(src + ": only " + std::to_string(beyond.size()) +
                     " crack readings beyond a0 = " + num(out.a0 / units::mm) +
                     " mm under load; at least " + std::to_string(min_readings) +
                     " are needed for the compliance fits");

  std::vector<double> spacing;
  for (std::size_t j = 1; j < ar.size(); ++j)
    spacing.push_back(ar[j] - ar[j - 1]);
  out.window = std::isnan(o.smoothing_window)
                   ? std::max(readings_per_window * median(spacing), arm_thicknesses_per_window * h)
                   : o.smoothing_window;
  if (!(out.window > 0))
    throw InputError(src + ": the smoothing window must be > 0 mm, got " +
                     num(out.window / units::mm));

  // Beam-theory corrections per reading.
  auto F_of = [&](double d, double a) {
    return o.large_displacement_correction ? 1 - 0.3 * (d / a) * (d / a) - 1.5 * (d * l1 / (a * a))
                                           : 1.0;
  };
  // N is not only the end-block correction: its last term, -9/35 (delta/a)^2, is the
  // arms' own geometric stiffening (the load-line opening of an elastica falls behind the linear
  // cantilever's), so it applies with hinges too (l2 = 0). F alone overcorrects: F/N, not F, is
  // the ratio of the exact G of the elastica to 3 P delta / (2 B a) (to 0.05 % at delta/a = 0.5,
  // RecordReduction.ElasticaDcbIsReducedExactlyWithFOverN).
  auto N_of = [&](double d, double a) {
    if (!o.large_displacement_correction)
      return 1.0;
    const double r = l2 / a;
    return 1 - r * r * r - 9.0 / 8.0 * (1 - r * r) * d * l1 / (a * a) -
           9.0 / 35.0 * (d / a) * (d / a);
  };

  // Compliance fits over the readings beyond a0.
  std::vector<double> a_fit, cbrt_C, log_a, log_C, a_over_H;
  for (std::size_t j : beyond) {
    const std::size_t k = readings[j];
    const double C = rec.opening[k] / rec.load[k] / N_of(rec.opening[k], ar[j]);
    a_fit.push_back(ar[j]);
    cbrt_C.push_back(std::cbrt(C));
    log_a.push_back(std::log(ar[j]));
    log_C.push_back(std::log(C));
    a_over_H.push_back(ar[j] / (2 * h));
  }
  const LineFit mbt = fit_line(a_fit, cbrt_C, 0, a_fit.size());
  const LineFit cc = fit_line(log_a, log_C, 0, log_a.size());
  const LineFit mcc = fit_line(cbrt_C, a_over_H, 0, cbrt_C.size());
  if (!mbt.valid || !cc.valid || !mcc.valid || !(mbt.slope > 0))
    throw InputError(src + ": the compliance does not rise with the crack length over the " +
                     "readings beyond a0; the beam-theory fits cannot be made");
  // (C/N)^(1/3) = m (a + Delta): Delta is minus the crack length where the line reaches zero.
  out.mbt_delta = std::abs(mbt.at(0.0) / mbt.slope);
  out.cc_n = cc.slope;
  out.mcc_A1 = mcc.slope;

  // Direct energy at every reading (the window is centred on each reading, so it always spans
  // whole reading steps: D is known only where a new reading was made). Two estimates: the
  // slope over the window w and over 2 w. Where R is locally linear over 2 w both are unbiased,
  // and their difference measures the scatter of the w estimate that the 2 w one averages out:
  // reading noise (then close to the standard error) and tracking errors correlated over a few
  // mm (crack readings that drift ahead of the crack and fall back), which the residual-based
  // standard error of one window cannot see because they bend D(a) smoothly inside it.
  const WindowLines lines(ar, Dr);
  auto window_of = [&](double a, double w) {
    const auto lo = std::lower_bound(ar.begin(), ar.end(), a - w / 2) - ar.begin();
    const auto hi = std::upper_bound(ar.begin(), ar.end(), a + w / 2) - ar.begin();
    return std::pair<std::size_t, std::size_t>(static_cast<std::size_t>(lo),
                                               static_cast<std::size_t>(hi));
  };
  std::vector<double> slope(ar.size(), NAN), slope_se(ar.size(), NAN);
  std::vector<double> diff2_sum(ar.size() + 1, 0.0), diff_count(ar.size() + 1, 0.0);
  for (std::size_t j = 0; j < ar.size(); ++j) {
    const auto [b, e] = window_of(ar[j], out.window);
    std::tie(slope[j], slope_se[j]) = lines.slope(b, e);
    const auto [b2, e2] = window_of(ar[j], 2 * out.window);
    const double wide = lines.slope(b2, e2).first;
    const bool ok = std::isfinite(slope[j]) && std::isfinite(wide);
    diff2_sum[j + 1] = diff2_sum[j] + (ok ? std::pow(slope[j] - wide, 2) : 0.0);
    diff_count[j + 1] = diff_count[j] + (ok ? 1.0 : 0.0);
  }
  out.max_opening_over_a = 0;
  for (std::size_t j : beyond) {
    const std::size_t k = readings[j];
    const double P = rec.load[k], d = rec.opening[k], a = ar[j];
    const double F = F_of(d, a), N = N_of(d, a), C = d / P / N;
    out.line.push_back(rec.line[k]);
    out.a.push_back(a);
    out.da.push_back(a - out.a0);
    out.load.push_back(P);
    out.opening.push_back(d);
    out.max_opening_over_a = std::max(out.max_opening_over_a, d / a);
    out.R_MBT.push_back(3 * P * d * F / (2 * B * (a + out.mbt_delta) * N));
    out.R_CC.push_back(out.cc_n * P * d * F / (2 * B * a * N));
    out.R_MCC.push_back(3 * P * P * std::pow(C, 2.0 / 3.0) * F / (2 * out.mcc_A1 * B * 2 * h));
    if (!rec.delta_root.empty())
      out.delta_root.push_back(rec.delta_root[k]);

    // Band: +-2 s, s the larger of the slope's standard error and the scatter of neighbouring
    // estimates: the RMS difference between the w and 2 w estimates over the readings within
    // two windows either side, scaled by sqrt(4/3). Why that factor: for reading errors
    // correlated over less than a window the 2 w slope carries a quarter of the w slope's error
    // variance (an end-to-end difference over twice the length), so the difference of the two
    // holds 3/4 of it; for independent reading noise (1/8 of it) the factor overstates s by 7 %.
    // Why two windows: the RMS over one window either side rests on few independent
    // differences when the errors are correlated and scatters with them (docs/verification.md,
    // "Test records": coverage measured both ways).
    const auto [nb, ne] = window_of(a, scatter_windows * out.window);
    const double n_diff = diff_count[ne] - diff_count[nb];
    const double scatter =
        n_diff > 0 ? std::sqrt((diff2_sum[ne] - diff2_sum[nb]) / n_diff * 4.0 / 3.0) : slope_se[j];
    const double half = 2 * std::max(slope_se[j], scatter);
    out.R_energy.push_back(slope[j] / B);
    out.R_energy_lo.push_back((slope[j] - half) / B);
    out.R_energy_hi.push_back((slope[j] + half) / B);
  }

  out.energy = summarize(out.da, out.R_energy, o.plateau_fraction);
  out.mbt = summarize(out.da, out.R_MBT, o.plateau_fraction);
  out.cc = summarize(out.da, out.R_CC, o.plateau_fraction);
  out.mcc = summarize(out.da, out.R_MCC, o.plateau_fraction);

  out.notes.push_back("direct energy: R = dD/(B da), D = W - P opening/2, slope of a local "
                      "least-squares line of D against a over a " +
                      num(out.window / units::mm) + " mm window" +
                      (std::isnan(o.smoothing_window)
                           ? " (automatic: the larger of 10 median reading spacings and 4 arm "
                             "thicknesses)"
                           : "") +
                      "; band +-2 x the larger of the slope's standard error and the scatter of "
                      "neighbouring estimates (RMS difference to the slope over twice the "
                      "window, x sqrt(4/3), over the readings within two windows either side)");
  out.notes.push_back(
      std::string("beam theory: ") + std::to_string(beyond.size()) + " readings beyond a0 = " +
      num(out.a0 / units::mm) + " mm; MBT |Delta| " + num(out.mbt_delta / units::mm) +
      " mm, CC n " + num(out.cc_n) + ", MCC A1 " + num(out.mcc_A1) + "; " +
      (o.large_displacement_correction
           ? "large-displacement corrections F and N applied (l1 " + num(l1 / units::mm) + " mm" +
                 (blocks ? ", N with end blocks l2 " + num(l2 / units::mm) + " mm"
                         : ", N without end blocks (l2 = 0)") +
                 ")"
           : std::string("no large-displacement correction")) +
      "; largest opening/a " + num(out.max_opening_over_a));
  return out;
}

ReducedMean average_reduced(const std::vector<ReducedRecord>& records, double plateau_fraction,
                            int n_grid) {
  if (records.empty())
    throw InputError("reduce: no records to average");
  ReducedMean m;
  m.n_records = static_cast<int>(records.size());
  m.plateau_fraction = plateau_fraction;
  double end = INFINITY;
  for (const auto& r : records)
    end = std::min(end, r.da.back());
  for (int i = 0; i < n_grid; ++i)
    m.da.push_back(end * i / (n_grid - 1));

  struct Column {
    std::vector<double> ReducedRecord::*in;
    std::vector<double> ReducedMean::*mean;
    std::vector<double> ReducedMean::*std;
  };
  const Column columns[] = {
      {&ReducedRecord::R_energy, &ReducedMean::R_energy, &ReducedMean::R_energy_std},
      {&ReducedRecord::R_MBT, &ReducedMean::R_MBT, &ReducedMean::R_MBT_std},
      {&ReducedRecord::R_CC, &ReducedMean::R_CC, &ReducedMean::R_CC_std},
      {&ReducedRecord::R_MCC, &ReducedMean::R_MCC, &ReducedMean::R_MCC_std}};
  for (const auto& c : columns) {
    std::vector<std::vector<double>> values;
    for (const auto& r : records) {
      // Equal extensions (none after the reader's cleaning) would break the polyline; the
      // readings are strictly increasing by construction of crack_reading_rows.
      values.push_back(resample_linear(r.da, r.*(c.in), m.da));
    }
    auto& mean = m.*(c.mean);
    auto& sd = m.*(c.std);
    for (int i = 0; i < n_grid; ++i) {
      double s = 0, ss = 0;
      for (const auto& v : values)
        s += v[i];
      const double mu = s / static_cast<double>(values.size());
      for (const auto& v : values)
        ss += (v[i] - mu) * (v[i] - mu);
      mean.push_back(mu);
      sd.push_back(values.size() > 1 ? std::sqrt(ss / static_cast<double>(values.size() - 1))
                                     : 0.0);
    }
  }
  m.energy = summarize(m.da, m.R_energy, plateau_fraction);
  m.mbt = summarize(m.da, m.R_MBT, plateau_fraction);
  m.cc = summarize(m.da, m.R_CC, plateau_fraction);
  m.mcc = summarize(m.da, m.R_MCC, plateau_fraction);
  return m;
}

RDeltaData to_rdelta(const std::vector<ReducedRecord>& records, const std::string& source) {
  RDeltaData data;
  data.source = source;
  for (const auto& r : records) {
    if (r.delta_root.empty())
      throw InputError(r.source + ": record '" + r.name +
                       "' has no delta_root_mm column; R(delta_root) needs the measured "
                       "notch-root opening");
    Replicate rep;
    rep.label = r.name;
    double running = 0;
    for (std::size_t i = 0; i < r.a.size(); ++i) {
      if (!std::isfinite(r.R_energy[i]))
        continue;
      running = std::max(running, r.delta_root[i]);
      rep.delta.push_back(running);
      rep.R.push_back(std::max(0.0, r.R_energy[i]));
      rep.a.push_back(r.a[i]);
      rep.line.push_back(r.line[i]);
    }
    data.replicates.push_back(rep);
  }
  return data;
}

} // namespace fiberbridge::analysis
