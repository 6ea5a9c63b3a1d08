// The search over trial laws: bounds as a map onto the unit cube, start values from corrected
// beam theory, NLopt runs as independent jobs (docs/design.md section 6, "identify").
#include "optimizer.h"

#include "fiberbridge/core/format.h"

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <utility>

namespace fiberbridge::identify::detail {

namespace {

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
  /// What the objective threw, kept across NLopt: its C++ wrapper catches every exception of an
  /// objective and throws "nlopt failure" instead, which would lose a ComputationError's message
  /// and turn a caller's stop (RunInterrupted, a Python KeyboardInterrupt from the progress
  /// callback) into a failed start.
  std::exception_ptr thrown;
};

double objective(const std::vector<double>& u, std::vector<double>&, void* data) {
  auto& d = *static_cast<ObjectiveData*>(data);
  try {
    const double f = d.misfit->chi2(d.mapping->physical(u));
    ++d.evaluations;
    d.best = std::min(d.best, f);
    if (*d.progress && d.evaluations % 50 == 0)
      (*d.progress)("identify: " + d.label + ": " + std::to_string(d.evaluations) +
                    " evaluations, best chi^2 " + fmt(d.best));
    return f;
  } catch (...) {
    d.thrown = std::current_exception();
    throw nlopt::forced_stop(); // NLopt stops and optimize() throws forced_stop
  }
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
  } catch (const nlopt::forced_stop&) {
    if (data.thrown) // the objective's own exception, as it was thrown
      std::rethrow_exception(std::exchange(data.thrown, nullptr));
    throw;
  }
  return f;
}

/// One optimizer run (a start or a polish round) as a job: its misfit reached, NLopt's code and
/// its end point.
struct OptimizerRun {
  double f = 0;
  int code = 0;
  std::vector<double> u;
};

std::string optimizer_job(const std::vector<PreparedRecord>& prepared,
                          const IdentifySettings& settings, const ForwardModel& forward,
                          const Mapping& mapping,
                          const std::function<void(const std::string&)>& progress,
                          const std::string& label, std::vector<double> u, double tolerance,
                          double initial_step) {
  Misfit misfit(prepared, settings, forward);
  ObjectiveData data{&misfit,   &mapping, 0,      std::numeric_limits<double>::infinity(),
                     &progress, label,    nullptr};
  nlopt::result code{};
  const double f = run_optimizer(settings, data, tolerance, initial_step, u, code);
  ByteWriter w;
  w.number(f);
  w.integer(static_cast<int>(code));
  w.numbers(u);
  RunCounts::write(w, misfit, data.evaluations);
  return w.bytes();
}

OptimizerRun read_optimizer_run(const std::string& bytes, RunCounts& counts) {
  ByteReader r(bytes);
  OptimizerRun run;
  run.f = r.number();
  run.code = static_cast<int>(r.integer());
  run.u = r.numbers();
  counts.add(r);
  r.expect_end();
  return run;
}

} // namespace

Parameters optimize(const std::vector<PreparedRecord>& prepared, const IdentifySettings& settings,
                    const ForwardModel& forward,
                    const std::function<void(const std::string&)>& progress,
                    const IdentifyJobRunner& run_jobs, RunCounts& counts,
                    std::vector<std::string>& notes) {
  const Mapping mapping(settings);
  std::vector<double> best_u;
  double best_f = std::numeric_limits<double>::infinity();
  // Starts differ in delta_c (the parameter the record constrains least directly). They are
  // independent: one job each. A given start (IdentifySettings::start_law, near the optimum, e.g.
  // the beam's for the FEM) is one start with the polish's small first step.
  const bool given = settings.start_j_tip > 0;
  const int n_starts = given ? 1 : settings.starts;
  const double dc_factors[] = {0.5, 1.5, 0.2, 3.0};
  const auto starts = run_batch(run_jobs, "starts", n_starts, [&](std::size_t s) {
    const Parameters p0 =
        given ? Parameters{settings.start_law.d1, settings.start_law.s1, settings.start_law.d2,
                           settings.start_law.s2, settings.start_law.dc, settings.start_j_tip}
              : start_value(prepared, settings, dc_factors[s % 4] * (1 + static_cast<int>(s) / 4));
    return optimizer_job(prepared, settings, forward, mapping, progress,
                         "start " + std::to_string(s + 1), mapping.normalized(p0),
                         settings.relative_tolerance, given ? 0.02 : 0.1);
  });
  for (int s = 0; s < n_starts; ++s) {
    const OptimizerRun run = read_optimizer_run(starts[s], counts);
    notes.push_back("start " + std::to_string(s + 1) + ": NLopt " + settings.algorithm +
                    " stopped with code " + std::to_string(run.code) + " at chi^2 " + fmt(run.f));
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
      return optimizer_job(prepared, settings, forward, mapping, progress,
                           "polish " + std::to_string(round + 1), best_u,
                           0.1 * settings.relative_tolerance, 0.02);
    });
    const OptimizerRun run = read_optimizer_run(polished[0], counts);
    const double f = run.f;
    notes.push_back("polish " + std::to_string(round + 1) + " from the best point: chi^2 " +
                    fmt(best_f) + " -> " + fmt(f));
    const bool improved_enough = f < 0.99 * best_f;
    if (f < best_f) {
      best_f = f;
      best_u = run.u;
    }
    if (!improved_enough)
      break;
  }
  return mapping.physical(best_u);
}

} // namespace fiberbridge::identify::detail
