#include "fiberbridge/identify/identify.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/identify/covariance.h"
#include "fiberbridge/specimen/large_displacement.h"

#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fiberbridge::identify {

using units::kPa;
using units::mm;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// A job's result as bytes (IdentifyJobRunner): doubles and integers copied bit for bit, so a
/// result computed in another process is the one this process would have computed.
class ByteWriter {
public:
  void number(double v) { put(v); }
  void integer(std::int64_t v) { put(v); }
  void text(const std::string& v) {
    integer(static_cast<std::int64_t>(v.size()));
    bytes += v;
  }
  void numbers(const std::vector<double>& v) {
    integer(static_cast<std::int64_t>(v.size()));
    bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
  std::string bytes;

private:
  template <class T>
  void put(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
};

class ByteReader {
public:
  explicit ByteReader(const std::string& b) : p_(b.data()), end_(b.data() + b.size()) {}
  double number() { return take<double>(); }
  std::int64_t integer() { return take<std::int64_t>(); }
  std::string text() {
    const auto n = static_cast<std::size_t>(integer());
    need(n);
    std::string v(p_, n);
    p_ += n;
    return v;
  }
  std::vector<double> numbers() {
    const auto n = static_cast<std::size_t>(integer());
    need(n * sizeof(double));
    std::vector<double> v(n);
    if (n)
      std::memcpy(v.data(), p_, n * sizeof(double));
    p_ += n * sizeof(double);
    return v;
  }

private:
  void need(std::size_t n) const {
    if (static_cast<std::size_t>(end_ - p_) < n)
      throw std::logic_error("identify: a job's result is shorter than its format");
  }
  template <class T>
  T take() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, p_, sizeof(T));
    p_ += sizeof(T);
    return v;
  }
  const char* p_;
  const char* end_;
};

void write_fit(ByteWriter& w, const RecordFit& f) {
  w.text(f.name);
  for (double v : {f.initial_crack, f.initial_compliance, f.E_L, f.peak_load, f.load_rms_rel,
                   f.crack_rms, f.max_opening_over_a, f.min_F})
    w.number(v);
  for (const auto* v : {&f.opening, &f.load, &f.crack_length, &f.model_load, &f.model_crack_length})
    w.numbers(*v);
}

RecordFit read_fit(ByteReader& r) {
  RecordFit f;
  f.name = r.text();
  for (double* v : {&f.initial_crack, &f.initial_compliance, &f.E_L, &f.peak_load, &f.load_rms_rel,
                    &f.crack_rms, &f.max_opening_over_a, &f.min_F})
    *v = r.number();
  for (auto* v : {&f.opening, &f.load, &f.crack_length, &f.model_load, &f.model_crack_length})
    *v = r.numbers();
  return f;
}

/// Physical parameters in the order of the report: d1, s1, d2, s2, dc [m, Pa], J_tip [J/m^2].
constexpr int n_parameters = 6;
using Parameters = std::array<double, n_parameters>;
const char* const parameter_names[n_parameters] = {"d1_mm",      "sigma1_kPa", "d2_mm",
                                                   "sigma2_kPa", "delta_c_mm", "J_tip_J_m2"};
const double parameter_units[n_parameters] = {mm, kPa, mm, kPa, mm, 1.0};

law::TrilinearParameters trilinear_of(const Parameters& p) {
  return {p[0], p[1], p[2], p[3], p[4]};
}

/// The optimizer works on u in [0,1]^6: delta_c, s1 and J_tip on log scales between their
/// bounds; d1/dc, (d2 - d1)/(dc - d1) and s2/s1 on linear ranges. Any u gives an ordered,
/// positive trilinear law (0 < d1 < d2 < dc, s2 <= s1), so the bounds are the only constraints.
struct Mapping {
  double log_dc_lo, log_dc_hi, log_s_lo, log_s_hi, log_j_lo, log_j_hi;
  static constexpr double t1_lo = 0.002, t1_hi = 0.4, t2_lo = 0.02, t2_hi = 0.95;
  static constexpr double r_lo = 0.01, r_hi = 1.0;

  explicit Mapping(const IdentifySettings& s)
      : log_dc_lo(std::log(s.delta_c_min)), log_dc_hi(std::log(s.delta_c_max)),
        log_s_lo(std::log(s.stress_max * 1e-3)), log_s_hi(std::log(s.stress_max)),
        log_j_lo(std::log(s.j_tip_min)), log_j_hi(std::log(s.j_tip_max)) {}

  static double lerp(double lo, double hi, double u) { return lo + (hi - lo) * u; }
  static double unlerp(double lo, double hi, double v) {
    return std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
  }
  Parameters physical(const std::vector<double>& u) const {
    const double dc = std::exp(lerp(log_dc_lo, log_dc_hi, u[0]));
    const double d1 = lerp(t1_lo, t1_hi, u[1]) * dc;
    const double d2 = d1 + lerp(t2_lo, t2_hi, u[2]) * (dc - d1);
    const double s1 = std::exp(lerp(log_s_lo, log_s_hi, u[3]));
    const double s2 = lerp(r_lo, r_hi, u[4]) * s1;
    return {d1, s1, d2, s2, dc, std::exp(lerp(log_j_lo, log_j_hi, u[5]))};
  }
  std::vector<double> normalized(const Parameters& p) const {
    return {unlerp(log_dc_lo, log_dc_hi, std::log(p[4])),
            unlerp(t1_lo, t1_hi, p[0] / p[4]),
            unlerp(t2_lo, t2_hi, (p[2] - p[0]) / (p[4] - p[0])),
            unlerp(log_s_lo, log_s_hi, std::log(p[1])),
            unlerp(r_lo, r_hi, p[3] / p[1]),
            unlerp(log_j_lo, log_j_hi, std::log(p[5]))};
  }
};

/// One record prepared for the misfit: its specimen, modulus and weights.
struct PreparedRecord {
  const analysis::TestRecord* record;
  specimen::Specimen specimen;
  specimen::Material material;
  double peak_load = 0;
  double compliance = 0;
  std::vector<std::size_t> crack_rows; ///< fresh crack readings (the first excluded)
  /// A crack length at each row for start values and diagnostics: the reading, or without
  /// readings (load and opening alone) the corrected-beam-theory crack from the row's compliance,
  /// a + chi h = (a0 + chi h) (C/C0)^(1/3) (held at a0 or more; rows under 5 % of the peak a0).
  std::vector<double> crack_estimate;
};

/// The first crack reading of a record (rows without one are NaN; NaN when it has none).
double first_reading(const analysis::TestRecord& rec) {
  for (double a : rec.crack_length)
    if (std::isfinite(a))
      return a;
  return NAN;
}

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

class Misfit {
public:
  Misfit(const std::vector<PreparedRecord>& records, const IdentifySettings& settings)
      : records_(records), settings_(settings) {}

  /// Weighted residuals (load rows, then fresh crack readings, record after record); the model
  /// curves go to `fits` if given.
  std::vector<double> residuals(const Parameters& p, std::vector<RecordFit>* fits = nullptr) {
    std::vector<double> r;
    for (const auto& pr : records_) {
      const auto& rec = *pr.record;
      std::vector<double> model_load, model_a;
      double min_F = 1;
      simulate(pr, p, model_load, model_a, min_F);
      for (std::size_t i = 0; i < rec.opening.size(); ++i)
        r.push_back((model_load[i] - rec.load[i]) / (settings_.load_scatter * pr.peak_load));
      for (std::size_t i : pr.crack_rows)
        r.push_back((model_a[i] - rec.crack_length[i]) / settings_.crack_scatter);
      if (fits) {
        RecordFit f;
        f.name = rec.name;
        f.initial_crack = pr.specimen.initial_crack;
        f.initial_compliance = pr.compliance;
        f.E_L = pr.material.E_L;
        f.peak_load = pr.peak_load;
        f.opening = rec.opening;
        f.load = rec.load;
        // NaN on every row without readings, so that writers can index it as the other columns.
        f.crack_length = rec.crack_length.empty() ? std::vector<double>(rec.opening.size(), NAN)
                                                  : rec.crack_length;
        f.model_load = model_load;
        f.model_crack_length = model_a;
        f.min_F = min_F;
        double sp = 0, sa = 0;
        for (std::size_t i = 0; i < rec.opening.size(); ++i) {
          sp += std::pow(model_load[i] - rec.load[i], 2);
          f.max_opening_over_a =
              std::max(f.max_opening_over_a, rec.opening[i] / pr.crack_estimate[i]);
        }
        for (std::size_t i : pr.crack_rows)
          sa += std::pow(model_a[i] - rec.crack_length[i], 2);
        f.load_rms_rel = std::sqrt(sp / rec.opening.size()) / pr.peak_load;
        f.crack_rms = pr.crack_rows.empty() ? 0 : std::sqrt(sa / pr.crack_rows.size());
        fits->push_back(std::move(f));
      }
    }
    return r;
  }

  double chi2(const Parameters& p) {
    double s = 0;
    for (double v : residuals(p))
      s += v * v;
    return s;
  }

  int forward_runs = 0;
  double forward_time_s = 0;
  std::string last_failure;

private:
  /// The beam's P(opening) and a(opening) at the record's openings, mapped onto large
  /// displacements when asked (`min_F`: the smallest F over the run).
  void simulate(const PreparedRecord& pr, const Parameters& p, std::vector<double>& load,
                std::vector<double>& a, double& min_F) {
    const auto& rec = *pr.record;
    beam::BeamParameters bp = settings_.beam;
    const double a_last = pr.crack_estimate.back();
    const double min_lig = bp.minimum_ligament > 0 ? bp.minimum_ligament : pr.specimen.height;
    // Run a few advances past the last reading (the model may lag it), within the ligament.
    bp.final_crack_length =
        std::min(a_last + 5 * bp.tip_advance, pr.specimen.length - min_lig - 2 * bp.tip_advance);
    const auto t = std::chrono::steady_clock::now();
    ++forward_runs;
    try {
      const auto law = law::make_trilinear(trilinear_of(p));
      auto run = beam::simulate_dcb(pr.specimen, pr.material, law, p[5], bp);
      if (settings_.large_displacement)
        min_F = with_large_displacements(run, pr.specimen.arm_thickness());
      model_at_openings(run, rec.opening, load, a);
    } catch (const std::exception& e) {
      // A law the beam cannot follow from initiation: the model carries no load, a large but
      // finite misfit that keeps the optimizer's quadratic model usable.
      last_failure = e.what();
      load.assign(rec.opening.size(), 0.0);
      a.assign(rec.opening.size(), pr.specimen.initial_crack);
    }
    forward_time_s += seconds_since(t);
  }

  const std::vector<PreparedRecord>& records_;
  const IdentifySettings& settings_;
};

/// CBT energy release rate of a record row (P/P(J = 1 J/m^2))^2: a start value only.
double cbt_g(const specimen::Specimen& s, const specimen::Material& m, double load, double a) {
  const double unit = specimen::cbt_load_at_crack_length(s, m, 1.0, a);
  return std::pow(load / unit, 2);
}

Parameters start_value(const std::vector<PreparedRecord>& records, const IdentifySettings& settings,
                       double dc_factor) {
  // J_tip from the load at the first crack jump, G_ss from the last third of the rows, delta_c
  // from the opening at the original notch root at the end (rigid arms about the tip).
  double j_tip = 0, g_end = 0, root_opening = 0;
  for (const auto& pr : records) {
    const auto& rec = *pr.record;
    const std::size_t first = pr.crack_rows.empty() ? rec.load.size() / 4 : pr.crack_rows.front();
    const auto& a = pr.crack_estimate;
    // Without readings: the row a quarter into the record, at a0 (an estimate to start from).
    j_tip += cbt_g(pr.specimen, pr.material, rec.load[first],
                   pr.crack_rows.empty() ? pr.specimen.initial_crack : a[first - 1]);
    double g = 0;
    const std::size_t from = 2 * rec.load.size() / 3;
    for (std::size_t i = from; i < rec.load.size(); ++i)
      g += cbt_g(pr.specimen, pr.material, rec.load[i], a[i]);
    g_end += g / static_cast<double>(rec.load.size() - from);
    const double a_end = a.back();
    root_opening += rec.opening.back() * (a_end - pr.specimen.initial_crack) / a_end;
  }
  const double n = static_cast<double>(records.size());
  j_tip = std::clamp(j_tip / n, settings.j_tip_min, settings.j_tip_max);
  const double area = std::max(g_end / n - j_tip, 0.5 * j_tip);
  const double dc = std::clamp(dc_factor * root_opening / n, settings.delta_c_min * 1.01,
                               settings.delta_c_max * 0.99);
  const double d1 = 0.05 * dc, d2 = d1 + 0.3 * (dc - d1), ratio = 0.3;
  const double s1 = std::clamp(2 * area / (d2 + ratio * (dc - d1)), settings.stress_max * 1.1e-3,
                               settings.stress_max * 0.99);
  return {d1, s1, d2, ratio * s1, dc, j_tip};
}

struct ObjectiveData {
  Misfit* misfit;
  const Mapping* mapping;
  int evaluations = 0;
  double best = std::numeric_limits<double>::infinity();
  const std::function<void(const std::string&)>* progress;
  std::string label; ///< which optimizer run, for the progress lines
};

double objective(const std::vector<double>& u, std::vector<double>&, void* data) {
  auto& d = *static_cast<ObjectiveData*>(data);
  const double f = d.misfit->chi2(d.mapping->physical(u));
  ++d.evaluations;
  d.best = std::min(d.best, f);
  if (*d.progress && d.evaluations % 50 == 0)
    (*d.progress)("identify: " + d.label + ": " + std::to_string(d.evaluations) +
                  " evaluations, best chi^2 " + fmt(d.best));
  return f;
}

/// A bounded NLopt run on [0,1]^6 from `u` (updated), returning the misfit reached.
double run_optimizer(const IdentifySettings& settings, ObjectiveData& data, double tolerance,
                     double initial_step, std::vector<double>& u, nlopt::result& code) {
  nlopt::opt opt(settings.algorithm == "bobyqa" ? nlopt::LN_BOBYQA : nlopt::LN_SBPLX, n_parameters);
  opt.set_lower_bounds(std::vector<double>(n_parameters, 0.0));
  opt.set_upper_bounds(std::vector<double>(n_parameters, 1.0));
  opt.set_min_objective(objective, &data);
  opt.set_maxeval(settings.max_evaluations);
  opt.set_ftol_rel(tolerance);
  opt.set_initial_step(initial_step);
  double f = 0;
  try {
    code = opt.optimize(u, f);
  } catch (const nlopt::roundoff_limited&) {
    code = nlopt::ROUNDOFF_LIMITED;
    f = data.misfit->chi2(data.mapping->physical(u));
  }
  return f;
}

/// The forward-run bookkeeping of one job (its own Misfit), summed over the jobs in job order:
/// the totals and the last failure are those of the serial run.
struct RunCounts {
  int evaluations = 0;
  int forward_runs = 0;
  double forward_time_s = 0;
  std::string last_failure;

  /// A job's part: its own Misfit's counts and `evals` optimizer evaluations.
  static void write(ByteWriter& w, const Misfit& m, int evals) {
    w.integer(evals);
    w.integer(m.forward_runs);
    w.number(m.forward_time_s);
    w.text(m.last_failure);
  }
  void add(ByteReader& r) {
    evaluations += static_cast<int>(r.integer());
    forward_runs += static_cast<int>(r.integer());
    forward_time_s += r.number();
    const std::string failure = r.text();
    if (!failure.empty())
      last_failure = failure;
  }
};

/// One optimizer run (a start or a polish round) as a job: its misfit reached, NLopt's code and
/// its end point.
struct OptimizerRun {
  double f = 0;
  int code = 0;
  std::vector<double> u;
};

std::string optimizer_job(const std::vector<PreparedRecord>& prepared,
                          const IdentifySettings& settings, const Mapping& mapping,
                          const std::function<void(const std::string&)>& progress,
                          const std::string& label, std::vector<double> u, double tolerance,
                          double initial_step) {
  Misfit misfit(prepared, settings);
  ObjectiveData data{&misfit,   &mapping, 0, std::numeric_limits<double>::infinity(),
                     &progress, label};
  nlopt::result code{};
  const double f = run_optimizer(settings, data, tolerance, initial_step, u, code);
  ByteWriter w;
  w.number(f);
  w.integer(static_cast<int>(code));
  w.numbers(u);
  RunCounts::write(w, misfit, data.evaluations);
  return w.bytes;
}

OptimizerRun read_optimizer_run(const std::string& bytes, RunCounts& counts) {
  ByteReader r(bytes);
  OptimizerRun run;
  run.f = r.number();
  run.code = static_cast<int>(r.integer());
  run.u = r.numbers();
  counts.add(r);
  return run;
}

std::vector<std::string> run_batch(const IdentifyJobRunner& run_jobs, const std::string& what,
                                   std::size_t n, const IdentifyJob& job) {
  auto out = run_jobs ? run_jobs(what, n, job) : serial_jobs(what, n, job);
  if (out.size() != n)
    throw std::logic_error("identify: the job runner returned " + std::to_string(out.size()) +
                           " results for " + std::to_string(n) + " " + what + " jobs");
  return out;
}

} // namespace

std::vector<std::string> serial_jobs(const std::string&, std::size_t n, const IdentifyJob& job) {
  std::vector<std::string> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(job(i));
  return out;
}

void IdentifySettings::validate(const std::string& c) const {
  if (!(delta_c_min > 0 && delta_c_max > delta_c_min))
    throw InputError(c + "/Delta c range: need 0 < min < max (mm)");
  if (!(stress_max > 0))
    throw InputError(c + "/Stress max: must be positive (kPa)");
  if (!(j_tip_min > 0 && j_tip_max > j_tip_min))
    throw InputError(c + "/J tip range: need 0 < min < max (J/m^2)");
  if (!(load_scatter > 0))
    throw InputError(c + "/Load scatter: must be positive (fraction of the peak load)");
  if (!(crack_scatter > 0))
    throw InputError(c + "/Crack scatter: must be positive (mm)");
  if (!(compliance_low >= 0 && compliance_high > compliance_low && compliance_high <= 1))
    throw InputError(c + "/Compliance window: need 0 <= low < high <= 1 (fractions of the peak)");
  if (algorithm != "bobyqa" && algorithm != "sbplx")
    throw InputError(c + "/Algorithm: expected bobyqa or sbplx, got '" + algorithm + "'");
  if (max_evaluations < 10)
    throw InputError(c + "/Max evaluations: need at least 10");
  if (starts < 1)
    throw InputError(c + "/Starts: need at least 1");
  if (!(relative_tolerance > 0 && relative_tolerance < 1))
    throw InputError(c + "/Tolerance: must be in (0, 1)");
  beam.validate(c);
}

double initial_compliance(const analysis::TestRecord& rec, const IdentifySettings& s) {
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

void model_at_openings(const result::SimulationResult& run, const std::vector<double>& opening,
                       std::vector<double>& load, std::vector<double>& crack_length) {
  const auto& rc = run.rcurve;
  std::vector<const result::RCurvePoint*> path;
  for (const auto& p : rc)
    if (path.empty() || p.load_point_opening > path.back()->load_point_opening)
      path.push_back(&p);
  load.resize(opening.size());
  crack_length.resize(opening.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < opening.size(); ++i) {
    const double d = opening[i];
    const auto& first = *path.front();
    if (d <= first.load_point_opening) {
      load[i] = first.load * d / first.load_point_opening;
      crack_length[i] = first.a;
      continue;
    }
    while (k + 1 < path.size() && path[k + 1]->load_point_opening < d)
      ++k;
    if (k + 1 >= path.size()) {
      load[i] = path.back()->load;
      crack_length[i] = path.back()->a;
      continue;
    }
    const auto &p = *path[k], &q = *path[k + 1];
    const double w = (d - p.load_point_opening) / (q.load_point_opening - p.load_point_opening);
    load[i] = p.load + w * (q.load - p.load);
    crack_length[i] = p.a + w * (q.a - p.a);
  }
}

double with_large_displacements(result::SimulationResult& run, double arm_thickness) {
  const double l1 = 0.5 * arm_thickness; // hinges on the arms' surfaces, no end blocks (l2 = 0)
  double min_F = 1;
  for (auto& p : run.rcurve) {
    const double a = p.a, d_small = p.load_point_opening;
    if (!(a > 0) || !(d_small > 0))
      continue;
    // F and N at the large-displacement opening, which depends on them: two fixed-point passes
    // from the small one (the change is O((delta/a)^2), the second pass leaves O((delta/a)^4)).
    double d = d_small, F = 1;
    for (int pass = 0; pass < 2; ++pass) {
      F = specimen::large_displacement_F(d, a, l1);
      const double N = specimen::end_block_N(d, a, l1, 0.0);
      d = d_small * N / std::sqrt(F);
    }
    p.load_point_opening = d;
    p.load /= std::sqrt(F);
    min_F = std::min(min_F, F);
  }
  return min_F;
}

Identification identify_law(const std::vector<analysis::TestRecord>& records,
                            const specimen::Specimen& specimen, const specimen::Material& quoted,
                            const IdentifySettings& settings,
                            const std::function<void(const std::string&)>& progress,
                            const IdentifyJobRunner& run_jobs) {
  const auto t0 = std::chrono::steady_clock::now();
  settings.validate();
  if (records.empty())
    throw InputError("Identify: no records to identify from");
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
    if (settings.calibrate_modulus)
      pr.material.E_L = modulus_for_compliance(pr.specimen, quoted, pr.compliance);
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

  const Mapping mapping(settings);
  Identification out;
  RunCounts counts; // over every job, in the serial order
  std::vector<double> best_u;
  double best_f = std::numeric_limits<double>::infinity();
  // Starts differ in delta_c (the parameter the record constrains least directly). They are
  // independent: one job each.
  const double dc_factors[] = {0.5, 1.5, 0.2, 3.0};
  const auto starts = run_batch(run_jobs, "starts", settings.starts, [&](std::size_t s) {
    const Parameters p0 =
        start_value(prepared, settings, dc_factors[s % 4] * (1 + static_cast<int>(s) / 4));
    return optimizer_job(prepared, settings, mapping, progress, "start " + std::to_string(s + 1),
                         mapping.normalized(p0), settings.relative_tolerance, 0.1);
  });
  for (int s = 0; s < settings.starts; ++s) {
    const OptimizerRun run = read_optimizer_run(starts[s], counts);
    out.notes.push_back("start " + std::to_string(s + 1) + ": NLopt " + settings.algorithm +
                        " stopped with code " + std::to_string(run.code) + " at chi^2 " +
                        fmt(run.f));
    if (run.f < best_f) {
      best_f = run.f;
      best_u = run.u;
    }
  }
  // Polish: BOBYQA again from the best point with a small trust region (the first runs stop on
  // the relative tolerance while the d2-s2 valley is still being followed). A restart rebuilds
  // the optimizer's quadratic model, which a long curved valley leaves stale, so the polish is
  // repeated while a round still lowers chi^2 by more than 1 % (at most kPolishRounds rounds).
  // Each round depends on the last: a batch of one job (one process runs it, the others wait).
  constexpr int kPolishRounds = 4;
  for (int round = 0; round < kPolishRounds; ++round) {
    const auto polished = run_batch(run_jobs, "polish", 1, [&](std::size_t) {
      return optimizer_job(prepared, settings, mapping, progress,
                           "polish " + std::to_string(round + 1), best_u,
                           0.1 * settings.relative_tolerance, 0.02);
    });
    const OptimizerRun run = read_optimizer_run(polished[0], counts);
    const double f = run.f;
    out.notes.push_back("polish " + std::to_string(round + 1) + " from the best point: chi^2 " +
                        fmt(best_f) + " -> " + fmt(f));
    const bool improved_enough = f < 0.99 * best_f;
    if (f < best_f) {
      best_f = f;
      best_u = run.u;
    }
    if (!improved_enough)
      break;
  }
  out.evaluations = counts.evaluations;
  const Parameters best = mapping.physical(best_u);

  // Uncertainty: Jacobian of the weighted residuals by central differences (2 % steps: the
  // beam's discrete advances make the misfit piecewise smooth below about 1 %). Job 0 is the
  // optimum itself (with the model curves), jobs 2j+1 and 2j+2 parameter j up and down.
  const auto jacobian_runs =
      run_batch(run_jobs, "jacobian", 1 + 2 * n_parameters, [&](std::size_t k) {
        Misfit misfit(prepared, settings);
        ByteWriter w;
        if (k == 0) {
          std::vector<RecordFit> fits;
          w.numbers(misfit.residuals(best, &fits));
          w.integer(static_cast<std::int64_t>(fits.size()));
          for (const auto& f : fits)
            write_fit(w, f);
        } else {
          const int j = static_cast<int>(k - 1) / 2;
          Parameters p = best;
          const double step = 0.02 * best[j];
          if ((k - 1) % 2 == 0)
            p[j] += step;
          else
            p[j] -= step;
          w.numbers(misfit.residuals(p));
        }
        RunCounts::write(w, misfit, 0);
        return w.bytes;
      });
  std::vector<std::vector<double>> residuals_of(jacobian_runs.size());
  for (std::size_t k = 0; k < jacobian_runs.size(); ++k) {
    ByteReader r(jacobian_runs[k]);
    residuals_of[k] = r.numbers();
    if (k == 0)
      for (auto n = r.integer(); n > 0; --n)
        out.records.push_back(read_fit(r));
    counts.add(r);
  }
  const std::vector<double>& r0 = residuals_of[0];
  std::vector<std::vector<double>> jac(r0.size(), std::vector<double>(n_parameters));
  for (int j = 0; j < n_parameters; ++j) {
    const double step = 0.02 * best[j];
    const auto &rp = residuals_of[1 + 2 * j], &rm = residuals_of[2 + 2 * j];
    for (std::size_t i = 0; i < r0.size(); ++i)
      jac[i][j] = (rp[i] - rm[i]) / (2 * step);
  }
  out.chi2 = 0;
  for (double v : r0)
    out.chi2 += v * v;
  out.n_residuals = r0.size();
  const Covariance cov = covariance_from_jacobian(jac, out.chi2);
  out.law = trilinear_of(best);
  out.j_tip = best[5];
  out.g_ss = out.j_tip + out.law.area();
  for (int j = 0; j < n_parameters; ++j)
    out.parameters.push_back({parameter_names[j], best[j] / parameter_units[j],
                              std::sqrt(std::max(cov.matrix[j][j], 0.0)) / parameter_units[j]});
  out.correlation = cov.correlation;
  for (const auto& n : cov.notes)
    out.notes.push_back(n);
  for (int i = 0; i < n_parameters; ++i) {
    for (int j = i + 1; j < n_parameters; ++j)
      if (std::abs(cov.correlation[i][j]) > 0.95)
        out.notes.push_back(std::string(parameter_names[i]) + " and " + parameter_names[j] +
                            " are correlated at " + fmt(cov.correlation[i][j], 3) +
                            ": the records identify a combination of them, not each one");
    if (out.parameters[i].std_error > 0.5 * out.parameters[i].value)
      out.notes.push_back(std::string(parameter_names[i]) +
                          " is poorly identified (standard "
                          "error " +
                          fmt(100 * out.parameters[i].std_error / out.parameters[i].value, 3) +
                          " % of its value)");
  }
  // J_c and the law's band by linear propagation of the covariance (law parameters only).
  const auto& l = out.law;
  const double g_area[5] = {-0.5 * l.s2, 0.5 * l.d2, 0.5 * l.s1, 0.5 * (l.dc - l.d1), 0.5 * l.s2};
  double var_area = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      var_area += g_area[i] * cov.matrix[i][j] * g_area[j];
  out.j_c_std_error = std::sqrt(std::max(var_area, 0.0));
  const auto law = law::make_trilinear(l);
  for (int k = 0; k <= 100; ++k) {
    const double d = 1.1 * l.dc * k / 100.0;
    double g[5];
    for (int j = 0; j < 5; ++j) {
      Parameters p = best;
      const double h = 1e-4 * best[j];
      p[j] += h;
      const double sp = law::make_trilinear(trilinear_of(p)).envelope(d);
      p[j] -= 2 * h;
      const double sm = law::make_trilinear(trilinear_of(p)).envelope(d);
      g[j] = (sp - sm) / (2 * h);
    }
    double var = 0;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        var += g[i] * cov.matrix[i][j] * g[j];
    const double sigma = law.envelope(d), sd = std::sqrt(std::max(var, 0.0));
    out.band_delta.push_back(d);
    out.band_sigma.push_back(sigma);
    out.band_lo.push_back(std::max(0.0, sigma - sd));
    out.band_hi.push_back(sigma + sd);
  }
  double sp = 0, sa = 0;
  std::size_t np = 0, na = 0;
  for (const auto& f : out.records) {
    sp += std::pow(f.load_rms_rel, 2) * f.opening.size();
    np += f.opening.size();
    const std::size_t readings = analysis::crack_reading_rows(records[&f - &out.records[0]]).size();
    const std::size_t n = readings > 0 ? readings - 1 : 0;
    sa += std::pow(f.crack_rms, 2) * n;
    na += n;
  }
  out.load_rms_rel = std::sqrt(sp / np);
  out.crack_rms = na ? std::sqrt(sa / na) : 0;
  if (!counts.last_failure.empty())
    out.notes.push_back("some trial laws could not be simulated (last: " + counts.last_failure +
                        "); they were scored as carrying no load");
  out.forward_runs = counts.forward_runs;
  out.forward_time_s = counts.forward_time_s;
  out.wall_time_s = seconds_since(t0);
  return out;
}

} // namespace fiberbridge::identify
