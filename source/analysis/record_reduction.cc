// R(a) from raw DCB records: direct energy and the ASTM D5528 / ISO 15024 beam-theory
// reductions (record_reduction.h; docs/design.md, "Test records").
#include "fiberbridge/analysis/record_reduction.h"

#include "fiberbridge/analysis/energy_rate.h"
#include "fiberbridge/analysis/initial_rise.h"
#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/median.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/specimen/large_displacement.h"

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
/// The automatic window above is the widest the data-chosen windows may take
/// (energy_slopes_adaptive); the narrowest spans this many reading spacings (6 readings: 4
/// degrees of freedom for the residuals that estimate the noise).
constexpr double readings_per_narrowest_window = 5;
constexpr std::size_t min_readings = 5;

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

namespace {

/// Ingredients every part of one record's reduction shares.
struct Setup {
  std::string src;
  double B = 0, h = 0, l1 = 0, l2 = 0;
  bool blocks = false;
  const ReduceOptions* o = nullptr;
  /// ISO 15024's F and N (specimen/large_displacement.h), 1 when the correction is off.
  double F(double d, double a) const {
    return o->large_displacement_correction ? specimen::large_displacement_F(d, a, l1) : 1.0;
  }
  double N(double d, double a) const {
    return o->large_displacement_correction ? specimen::end_block_N(d, a, l1, l2) : 1.0;
  }
};

/// Median spacing of a sorted abscissa (0 for fewer than 2 values).
double median_step(const std::vector<double>& a) {
  std::vector<double> d;
  for (std::size_t j = 1; j < a.size(); ++j)
    d.push_back(a[j] - a[j - 1]);
  return d.empty() ? 0.0 : median_upper(d);
}

/// Automatic window of the energy slopes for reading spacing `spacing`: the widest the
/// data-chosen windows may take.
double auto_window(double spacing, double h) {
  return std::max(readings_per_window * spacing, arm_thicknesses_per_window * h);
}

/// Energy slopes with the user's window, or (automatic) a window chosen at each reading from the
/// data between 5 reading spacings and auto_window (energy_rate.h), or the windows of an earlier
/// reduction (ReduceOptions::window_da, at the extensions a - a0). `reported` takes the median
/// window used.
EnergySlopes slopes_of(const std::vector<double>& a, const std::vector<double>& D,
                       const ReduceOptions& o, double a0, double spacing, double h,
                       double& reported) {
  if (!o.window_da.empty()) {
    std::vector<double> w;
    for (const double x : a)
      w.push_back(interpolate_linear(o.window_da, o.window_width, x - a0));
    reported = median_upper(w);
    return energy_slopes_per_point(a, D, w);
  }
  if (!std::isnan(o.smoothing_window)) {
    reported = o.smoothing_window;
    return energy_slopes(a, D, o.smoothing_window);
  }
  const double w_max = auto_window(spacing, h);
  EnergySlopes e =
      energy_slopes_adaptive(a, D, std::min(w_max, readings_per_narrowest_window * spacing), w_max);
  reported = median_upper(e.window);
  return e;
}

/// Times between fresh readings over which monotone_crack fits its local lines: the readings
/// either side of a stall and of the jump that ends it (energy_rate.h; docs/design.md section 6).
constexpr double monotone_reading_intervals = 4;

/// R_energy at initiation from the dissipated energy itself (initial_rise.h), where the notch-root
/// opening is measured: the readings from the first growth reading to the end of the fit take
/// the fitted R(delta_root), their band keeps its half-widths. `first_growth`: the record's row
/// of the first growth reading (the rows before it give D's noise).
void refit_initiation(const std::vector<double>& D, std::size_t first_growth,
                      const std::vector<double>& windows, const Setup& s, ReducedRecord& out) {
  if (out.rows.empty() || first_growth == 0)
    return;
  // D's noise before growth: successive differences (its slow elastic-nonlinear trend cancels).
  double ss = 0;
  std::size_t m = 0;
  for (std::size_t k = 1; k < first_growth; ++k, ++m)
    ss += std::pow(D[k] - D[k - 1], 2);
  const double noise = m ? std::sqrt(ss / static_cast<double>(m) / 2) : 0.0;
  std::vector<double> Dr;
  for (std::size_t k : out.rows)
    Dr.push_back(D[k]);
  const InitialRise fit =
      fit_initial_rise(out.a, out.delta_root, Dr, D[first_growth - 1], noise, s.B);
  if (!fit.fitted) {
    out.notes.push_back("R at initiation: left to the windowed slopes (" + fit.why + ")");
    return;
  }
  // The fit and the windowed slopes must agree where the fit ends (the windows there are no
  // longer one-sided): a fit that bent to the noise of a few sparse readings does not.
  const std::size_t last = fit.end - 1;
  double delta_last = 0;
  for (std::size_t i = 0; i <= last; ++i)
    delta_last = std::max(delta_last, out.delta_root[i]);
  if (!(fit.R(delta_last) >= out.R_energy_lo[last] && fit.R(delta_last) <= out.R_energy_hi[last])) {
    out.notes.push_back("R at initiation: left to the windowed slopes (the fit to D, J " +
                        num(fit.j_tip) + " J/m^2, gives R " + num(fit.R(delta_last)) +
                        " J/m^2 at its last reading, outside the windowed band " +
                        num(out.R_energy_lo[last]) + " to " + num(out.R_energy_hi[last]) + ")");
    return;
  }
  auto set_R = [&](std::size_t i, double R) {
    out.R_energy_lo[i] = R - (out.R_energy[i] - out.R_energy_lo[i]);
    out.R_energy_hi[i] = R + (out.R_energy_hi[i] - out.R_energy[i]);
    out.R_energy[i] = R;
  };
  double running = 0;
  for (std::size_t i = 0; i < fit.end; ++i) {
    running = std::max(running, out.delta_root[i]);
    set_R(i, fit.R(running));
  }
  // Past the fit, the readings whose window still reaches back before the onset would be
  // one-sided too (and step up from the fitted R: a kink that Eq. 6 and dR/ddelta read as
  // stress). Their slope is taken over the window centred on them that reaches back to the
  // onset, at least the fit's readings either side, until their own window fits.
  const double a_onset = out.a[fit.onset];
  std::size_t transition = 0;
  for (std::size_t i = fit.end; i < out.a.size() && out.a[i] - windows[i] / 2 < a_onset; ++i) {
    const double half = out.a[i] - a_onset;
    const auto b = static_cast<std::size_t>(
        std::lower_bound(out.a.begin(), out.a.end(), out.a[i] - half * (1 + 1e-6)) - out.a.begin());
    const auto e = static_cast<std::size_t>(
        std::upper_bound(out.a.begin(), out.a.end(), out.a[i] + half * (1 + 1e-6)) - out.a.begin());
    const LineFit f = fit_line(out.a, Dr, b, e);
    if (f.valid && e - b >= 3) {
      set_R(i, f.slope / s.B);
      ++transition;
    }
  }
  out.notes.push_back(
      "R at initiation: R_energy over the first " + std::to_string(fit.end) +
      " readings (delta_root up to " + num(fit.delta_end / units::mm) +
      " mm) is R = J + s max(0, delta_root - delta_h) fitted to D itself (seed Eq. 2 near "
      "initiation; a window's slope there is one-sided and reads high): J " +
      num(fit.j_tip) + " J/m^2, s " + num(fit.slope * units::mm) + " J/m^2 per mm, delta_h " +
      num(fit.hinge / units::mm) + " mm; dissipation starts at reading " +
      std::to_string(fit.onset + 1) + " (a " + num(out.a[fit.onset] / units::mm) +
      " mm); the next " + std::to_string(transition) +
      " readings take windows centred on them that reach back to the onset; "
      "R_energy_readings keeps the windowed slopes");
  if (fit.slope > 0 && !(fit.hinge > out.delta_root[fit.onset]))
    out.notes.push_back(
        "R at initiation: the fit finds no flat part; R rises from the first dissipating reading "
        "(delta_root " +
        num(out.delta_root[fit.onset] / units::mm) +
        " mm) on. The law's elastic part (where R = J_tip, seed Eq. 2) ends before that reading, "
        "or "
        "spans too few readings to be fitted: J_tip may lie below the first R, " +
        num(fit.j_tip) + " J/m^2, by an amount the record does not hold");
}

/// The beam-theory reductions and direct energy against the measured crack readings.
void reduce_measured(const TestRecord& rec, const std::vector<double>& D, const Setup& s,
                     ReducedRecord& out) {
  const ReduceOptions& o = *s.o;
  const std::string& src = s.src;
  // The rows with a fresh crack reading; the first is the notch (a0).
  auto readings = crack_reading_rows(rec);
  // Rows without a reading are NaN (test_record.h): never a reading, whichever reader made them.
  readings.erase(std::remove_if(readings.begin(), readings.end(),
                                [&](std::size_t k) { return !std::isfinite(rec.crack_length[k]); }),
                 readings.end());
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
  const double reading_spacing = median_upper(spacing);
  if (!(o.smoothing_window > 0) && !std::isnan(o.smoothing_window))
    throw InputError(src + ": the smoothing window must be > 0 mm, got " +
                     num(o.smoothing_window / units::mm));
  if (std::isnan(o.smoothing_window) && !(auto_window(reading_spacing, s.h) > 0))
    throw InputError(src + ": the automatic smoothing window is 0 mm (no spacing between the "
                           "crack readings and no arm thickness)");

  // Compliance fits over the readings beyond a0.
  std::vector<double> a_fit, cbrt_C, log_a, log_C, a_over_H;
  for (std::size_t j : beyond) {
    const std::size_t k = readings[j];
    const double C = rec.opening[k] / rec.load[k] / s.N(rec.opening[k], ar[j]);
    a_fit.push_back(ar[j]);
    cbrt_C.push_back(std::cbrt(C));
    log_a.push_back(std::log(ar[j]));
    log_C.push_back(std::log(C));
    a_over_H.push_back(ar[j] / (2 * s.h));
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

  // Direct energy: D and a at the fresh readings (as read), and with a from the monotone smooth
  // crack (energy_rate.h) at the same rows. The window is centred on each reading, so it always
  // spans whole reading steps.
  const EnergySlopes as_read = slopes_of(ar, Dr, o, out.a0, reading_spacing, s.h, out.window);
  std::vector<double> gaps;
  for (std::size_t j = 1; j < readings.size(); ++j)
    gaps.push_back(rec.time.empty() ? double(readings[j] - readings[j - 1])
                                    : rec.time[readings[j]] - rec.time[readings[j - 1]]);
  const double time_window = monotone_reading_intervals * median_upper(gaps);
  const auto smooth = monotone_crack(rec, readings, time_window);
  std::vector<double> am;
  for (std::size_t k : readings)
    am.push_back(smooth[k]);
  double monotone_window = NAN;
  const EnergySlopes monotone = slopes_of(am, Dr, o, out.a0, reading_spacing, s.h, monotone_window);
  const bool use_monotone = o.energy_crack == "monotone";
  if (use_monotone)
    out.window = monotone_window;
  const EnergySlopes& used = use_monotone ? monotone : as_read;

  out.max_opening_over_a = 0;
  for (std::size_t j : beyond) {
    const std::size_t k = readings[j];
    const double P = rec.load[k], d = rec.opening[k], a = ar[j];
    const double F = s.F(d, a), N = s.N(d, a), C = d / P / N;
    out.line.push_back(rec.line[k]);
    out.a.push_back(a);
    out.da.push_back(a - out.a0);
    out.load.push_back(P);
    out.opening.push_back(d);
    out.max_opening_over_a = std::max(out.max_opening_over_a, d / a);
    out.R_MBT.push_back(3 * P * d * F / (2 * s.B * (a + out.mbt_delta) * N));
    out.R_CC.push_back(out.cc_n * P * d * F / (2 * s.B * a * N));
    out.R_MCC.push_back(3 * P * P * std::pow(C, 2.0 / 3.0) * F / (2 * out.mcc_A1 * s.B * 2 * s.h));
    if (!rec.delta_root.empty())
      out.delta_root.push_back(rec.delta_root[k]);
    out.R_energy.push_back(used.slope[j] / s.B);
    out.R_energy_lo.push_back(used.lo[j] / s.B);
    out.R_energy_hi.push_back(used.hi[j] / s.B);
    out.R_energy_readings.push_back(as_read.slope[j] / s.B);
    out.windows.push_back(used.window[j]);
    out.rows.push_back(k);
  }
  std::vector<double> windows_used;
  for (std::size_t j : beyond)
    windows_used.push_back(used.window[j]);
  if (!rec.delta_root.empty())
    refit_initiation(D, beyond.empty() ? 0 : readings[beyond.front()], windows_used, s, out);
  out.notes.push_back(
      "direct energy: R = dD/(B da), D = W - P opening/2, slope of a local least-squares line of "
      "D against a over a " +
      (!o.window_da.empty()
           ? "window at each reading taken from an earlier reduction (another record's, at the "
             "same crack extension; median " +
                 num(out.window / units::mm) + " mm)"
       : std::isnan(o.smoothing_window)
           ? "window chosen at each reading from the data (intersection of confidence intervals "
             "over windows from 5 median reading spacings up to the larger of 10 spacings and 4 "
             "arm thicknesses, " +
                 num(auto_window(reading_spacing, s.h) / units::mm) + " mm; median " +
                 num(out.window / units::mm) + " mm)"
           : num(out.window / units::mm) + " mm window") +
      "; a " +
      (use_monotone ? "from isotonic regression of the readings against time, smoothed by local "
                      "lines over " +
                          num(time_window) +
                          " s (4 median reading intervals); R_energy_readings is the estimate "
                          "against the readings as read"
                    : std::string("as read at the fresh readings")) +
      "; band +-2 x the larger of the slope's standard error and the scatter of neighbouring "
      "estimates (RMS difference to the slope over twice the window, x sqrt(4/3), over the "
      "readings within two windows either side)");
  out.notes.push_back(
      std::string("beam theory: ") + std::to_string(beyond.size()) + " readings beyond a0 = " +
      num(out.a0 / units::mm) + " mm; MBT |Delta| " + num(out.mbt_delta / units::mm) +
      " mm, CC n " + num(out.cc_n) + ", MCC A1 " + num(out.mcc_A1) + "; " +
      (o.large_displacement_correction
           ? "large-displacement corrections F and N applied (l1 " + num(s.l1 / units::mm) + " mm" +
                 (s.blocks ? ", N with end blocks l2 " + num(s.l2 / units::mm) + " mm"
                           : ", N without end blocks (l2 = 0)") +
                 ")"
           : std::string("no large-displacement correction")) +
      "; largest opening/a " + num(out.max_opening_over_a));
}

/// CBBM's beam: E_f from the initial compliance at a0 + |Delta| (|Delta| as ReduceOptions says).
CbbmBeam calibrate_cbbm(const Setup& s, const ReducedRecord& out, bool measured,
                        std::vector<std::string>& notes) {
  const ReduceOptions& o = *s.o;
  CbbmBeam beam;
  beam.width = s.B;
  beam.arm_thickness = s.h;
  beam.shear_modulus = o.shear_modulus;
  std::string how;
  if (std::isfinite(o.root_rotation)) {
    beam.delta = o.root_rotation;
    how = "as given";
  } else if (measured && std::isfinite(out.mbt_delta)) {
    beam.delta = out.mbt_delta;
    how = "MBT's, from the crack readings";
  } else if (std::isfinite(o.shear_modulus) && std::isfinite(o.transverse_modulus)) {
    // chi depends on E11 = E_f, which depends on |Delta|: a fixed point, reached in a few steps
    // (chi grows like the square root of E_f, and E_f changes by a few per cent with |Delta|).
    beam.delta = 0;
    for (int it = 0; it < 20; ++it) {
      beam.flexural_modulus = cbbm_flexural_modulus(s.B, s.h, o.shear_modulus, beam.delta, out.a0,
                                                    out.initial_compliance, s.src);
      beam.delta =
          corrected_beam_delta(beam.flexural_modulus, o.transverse_modulus, o.shear_modulus, s.h);
    }
    how = "chi h of corrected beam theory with E11 = E_f, E22 and G13";
  } else {
    beam.delta = 0;
    how = "0: no crack readings and no G13 and E22 to estimate it (E_f then absorbs the root "
          "rotation; G by CBBM is high by about |Delta|/a0, chi h/a0 ~ 5-10 %)";
  }
  beam.flexural_modulus = cbbm_flexural_modulus(s.B, s.h, o.shear_modulus, beam.delta, out.a0,
                                                out.initial_compliance, s.src);
  notes.push_back(
      "CBBM (de Moura et al. 2008): initial compliance " + num(out.initial_compliance * 1e3) +
      " mm/N (opening at zero load " + num(out.opening_offset / units::mm) + " mm), E_f " +
      num(beam.flexural_modulus / 1e9) + " GPa at a0 + |Delta|, |Delta| " +
      num(beam.delta / units::mm) + " mm (" + how + "), " +
      (std::isfinite(o.shear_modulus) && o.shear_modulus > 0
           ? "G13 " + num(o.shear_modulus / 1e9) + " GPa"
           : std::string("no shear term (no G13 given)")) +
      "; the equivalent crack includes most of the bridging zone (on FEM records it sits a "
      "tenth of the zone behind the tip, far ahead of the traction-free crack; docs/design.md "
      "section 6)");
  return beam;
}

/// The equivalent crack from the load line (a_e - |Delta|) at row i, with N at that crack.
double equivalent_at(const TestRecord& rec, std::size_t i, const CbbmBeam& beam,
                     const ReducedRecord& out, const Setup& s) {
  const double d = rec.opening[i] - out.opening_offset, P = rec.load[i];
  if (!(P > 0) || !(d > 0))
    return NAN;
  double a = out.a0;
  for (int it = 0; it < 3; ++it) // N depends weakly on a: three fixed-point steps
    a = beam.effective_crack(d / P / s.N(d, a)) - beam.delta;
  return a;
}

} // namespace

ReducedRecord reduce_record(const TestRecord& rec, const specimen::Specimen& sp,
                            const ReduceOptions& o) {
  Setup s;
  s.src = rec.source + " (record '" + rec.name + "')";
  sp.check_test_geometry(s.src);
  s.o = &o;
  s.B = sp.width;
  s.h = sp.arm_thickness();
  s.l1 = std::isnan(sp.pin_to_arm_midplane) ? s.h / 2 : sp.pin_to_arm_midplane;
  s.blocks = !std::isnan(sp.pin_to_block_edge);
  s.l2 = s.blocks ? sp.pin_to_block_edge : 0.0;
  const std::string& src = s.src;
  if (o.energy_crack != "readings" && o.energy_crack != "monotone")
    throw InputError(src + ": energy crack must be 'readings' or 'monotone', got '" +
                     o.energy_crack + "'");

  ReducedRecord out;
  out.name = rec.name;
  out.source = rec.source;
  out.cleaning = rec.cleaning;
  // Rows without a reading are NaN; a record with none is reduced as one without the column.
  const bool has_readings = std::any_of(rec.crack_length.begin(), rec.crack_length.end(),
                                        [](double a) { return std::isfinite(a); });
  const bool measured = has_readings && !o.use_equivalent_crack;
  out.crack = measured ? "measured" : "equivalent";
  if (has_readings) {
    // The first row with a reading (rows without one are NaN, test_record.h).
    std::size_t first = 0;
    while (first < rec.crack_length.size() && !std::isfinite(rec.crack_length[first]))
      ++first;
    const double a_first = rec.crack_length[first];
    out.a0 = std::isnan(sp.initial_crack) ? a_first : sp.initial_crack;
    if (out.a0 > a_first + 1e-9)
      throw InputError(src + ": Specimen/Initial crack " + num(out.a0 / units::mm) +
                       " mm lies beyond the first crack reading " + num(a_first / units::mm) +
                       " mm on line " + std::to_string(rec.line[first]));
  } else {
    out.a0 = std::isnan(sp.initial_crack) ? o.initial_crack_without_readings : sp.initial_crack;
    if (!(out.a0 > 0))
      throw InputError(src + ": the record has no crack readings; the equivalent crack needs "
                             "the initial crack a0 (Specimen/Initial crack, --initial-crack)");
  }

  // Dissipated energy D = W - U along the whole record (every row: the load and opening are
  // good on rows that repeat a stale crack reading).
  const std::vector<double> D = dissipated_energy(rec);
  if (measured)
    reduce_measured(rec, D, s, out);

  // CBBM beside the measured crack, or instead of it.
  CbbmBeam beam;
  InitialCompliance initial;
  try {
    initial = initial_linear_part(rec);
    out.initial_compliance = initial.compliance;
    out.opening_offset = initial.offset;
    beam = calibrate_cbbm(s, out, measured, out.notes);
    out.flexural_modulus = beam.flexural_modulus;
    out.cbbm_delta = beam.delta;
  } catch (const InputError& e) {
    if (!measured)
      throw;
    out.notes.push_back(std::string("CBBM not computed: ") + e.what());
  }

  if (!measured) {
    // Rows: where the running maximum of a_eq passes a0 + k step (from the end of the initial
    // linear part: before it a_eq is a0 and its noise).
    const double step = std::isnan(o.equivalent_step) ? s.h / 10 : o.equivalent_step;
    if (!(step > 0))
      throw InputError(src + ": the equivalent crack step must be > 0 mm");
    const double peak = *std::max_element(rec.load.begin(), rec.load.end());
    double running = out.a0, next = out.a0 + step;
    for (std::size_t i = initial.end; i < rec.load.size(); ++i) {
      // Below 5 % of the peak the compliance is the load cell's noise over a small load.
      if (!(rec.load[i] > 0.05 * peak))
        continue;
      const double a = equivalent_at(rec, i, beam, out, s);
      if (!std::isfinite(a))
        continue;
      running = std::max(running, a);
      if (running < next)
        continue;
      next = out.a0 + step * (std::floor((running - out.a0) / step) + 1);
      out.rows.push_back(i);
      out.line.push_back(rec.line[i]);
      out.a.push_back(running);
      out.da.push_back(running - out.a0);
      out.load.push_back(rec.load[i]);
      out.opening.push_back(rec.opening[i]);
      if (!rec.delta_root.empty())
        out.delta_root.push_back(rec.delta_root[i]);
    }
    if (out.rows.size() < min_readings)
      throw InputError(src + ": the equivalent crack grows by only " +
                       std::to_string(out.rows.size()) + " steps of " + num(step / units::mm) +
                       " mm beyond a0 = " + num(out.a0 / units::mm) + " mm; at least " +
                       std::to_string(min_readings) + " are needed");
    if (!(o.smoothing_window > 0) && !std::isnan(o.smoothing_window))
      throw InputError(src + ": the smoothing window must be > 0 mm, got " +
                       num(o.smoothing_window / units::mm));
    out.window = std::isnan(o.smoothing_window) ? auto_window(step, s.h) : o.smoothing_window;
    out.max_opening_over_a = 0;
    for (std::size_t j = 0; j < out.rows.size(); ++j)
      out.max_opening_over_a = std::max(out.max_opening_over_a, out.opening[j] / out.a[j]);
    const std::size_t n = out.rows.size();
    out.R_MBT.assign(n, NAN);
    out.R_CC.assign(n, NAN);
    out.R_MCC.assign(n, NAN);
    out.notes.push_back("no crack readings" +
                        std::string(has_readings ? " used (equivalent crack asked for)" : "") +
                        ": R against the CBBM equivalent crack at " + std::to_string(n) +
                        " steps of " + num(step / units::mm) +
                        " mm; MBT, CC and MCC need measured cracks and are not given");
  }

  // a_eq, G by CBBM and direct energy against a_eq at the rows.
  if (std::isfinite(beam.flexural_modulus)) {
    std::vector<double> Dr;
    double running = out.a0;
    for (std::size_t j = 0; j < out.rows.size(); ++j) {
      const std::size_t i = out.rows[j];
      double a = measured ? equivalent_at(rec, i, beam, out, s) : out.a[j];
      // Held non-decreasing: the energy slopes need a sorted abscissa.
      running = std::max(running, std::isfinite(a) ? a : running);
      const double ae = running + beam.delta;
      const double d = rec.opening[i] - out.opening_offset;
      out.a_eq.push_back(running);
      out.R_CBBM.push_back(beam.energy_release_rate(rec.load[i], ae) * s.F(d, running) /
                           s.N(d, running));
      Dr.push_back(D[i]);
    }
    // Against the equivalent crack the automatic window is chosen from the data as with
    // readings, at the steps' spacing.
    double eq_window = out.window;
    const EnergySlopes eq =
        measured ? energy_slopes(out.a_eq, Dr, out.window)
                 : slopes_of(out.a_eq, Dr, o, out.a0, median_step(out.a_eq), s.h, eq_window);
    if (!measured)
      out.window = eq_window;
    for (std::size_t j = 0; j < out.rows.size(); ++j) {
      out.R_energy_eq.push_back(eq.slope[j] / s.B);
      out.R_energy_eq_lo.push_back(eq.lo[j] / s.B);
      out.R_energy_eq_hi.push_back(eq.hi[j] / s.B);
    }
    if (!measured) {
      out.windows = eq.window;
      out.R_energy = out.R_energy_eq;
      out.R_energy_lo = out.R_energy_eq_lo;
      out.R_energy_hi = out.R_energy_eq_hi;
      out.notes.push_back("direct energy: R = dD/(B da_eq), D = W - P opening/2 against the "
                          "equivalent crack, local lines over a " +
                          num(out.window / units::mm) + " mm window" +
                          (!o.window_da.empty()
                               ? " (median of the windows taken from an earlier reduction, at "
                                 "the same extension)"
                           : std::isnan(o.smoothing_window)
                               ? " (median of the windows chosen from the data at each step, as "
                                 "with readings)"
                               : "") +
                          "; band as with readings");
    }
  }

  // ASTM D5528 initiation values.
  if (std::isfinite(out.initial_compliance)) {
    InitiationReductions red;
    red.a0 = out.a0;
    red.mbt_delta = out.mbt_delta;
    red.width = s.B;
    red.cbbm = beam;
    red.initial = initial;
    red.large_displacement = o.large_displacement_correction;
    red.l1 = s.l1;
    red.l2 = s.l2;
    out.initiation = initiation_values(rec, red);
    if (!out.initiation.vis.note.empty())
      out.notes.push_back(out.initiation.vis.note);
  }

  out.energy = summarize(out.da, out.R_energy, o.plateau_fraction);
  out.mbt = summarize(out.da, out.R_MBT, o.plateau_fraction);
  out.cc = summarize(out.da, out.R_CC, o.plateau_fraction);
  out.mcc = summarize(out.da, out.R_MCC, o.plateau_fraction);
  if (!out.R_CBBM.empty()) {
    out.cbbm = summarize(out.da, out.R_CBBM, o.plateau_fraction);
    out.energy_eq = summarize(out.da, out.R_energy_eq, o.plateau_fraction);
  }
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
      {&ReducedRecord::R_MCC, &ReducedMean::R_MCC, &ReducedMean::R_MCC_std},
      {&ReducedRecord::R_CBBM, &ReducedMean::R_CBBM, &ReducedMean::R_CBBM_std}};
  for (const auto& c : columns) {
    std::vector<std::vector<double>> values;
    for (const auto& r : records) {
      if ((r.*(c.in)).empty()) { // CBBM not calibrated on this record
        values.push_back(std::vector<double>(m.da.size(), NAN));
        continue;
      }
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
  m.cbbm = summarize(m.da, m.R_CBBM, plateau_fraction);
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

void reduce_with_windows_of(const ReducedRecord& measured, ReduceOptions& options) {
  options.window_da.clear();
  options.window_width.clear();
  for (std::size_t j = 0; j < measured.da.size() && j < measured.windows.size(); ++j)
    if (options.window_da.empty() || measured.da[j] > options.window_da.back()) {
      options.window_da.push_back(measured.da[j]);
      options.window_width.push_back(measured.windows[j]);
    }
}

} // namespace fiberbridge::analysis
