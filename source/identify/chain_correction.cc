// The chain corrected by simulating the test it measured (identify/chain_correction.h).
#include "fiberbridge/identify/chain_correction.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

namespace fiberbridge::identify {

namespace {

/// One state of the machine's path: where the test is when the load line is opened this far.
struct PathState {
  double opening, load, a, delta_root;
};

/// The simulation as the machine sees it: the unloaded specimen, then the critical states in
/// order while the opening grows. A state whose opening falls below the largest so far (snap-back)
/// is passed at constant opening: the machine holds that opening while the load drops, so the path
/// goes straight down from the state at the maximum to the returning branch's state at the same
/// opening (interpolated between the states that bracket it), and on from there.
std::vector<PathState> machine_path(const result::SimulationResult& sim) {
  std::vector<PathState> path;
  bool falling_back = false;
  PathState previous{};
  for (const auto& p : sim.rcurve) {
    if (!std::isfinite(p.load_point_opening) || !std::isfinite(p.load) || !std::isfinite(p.a))
      continue;
    const PathState s{p.load_point_opening, p.load, p.a,
                      std::isfinite(p.delta_root) ? p.delta_root : 0.0};
    if (path.empty())
      path.push_back({0.0, 0.0, p.a, 0.0}); // elastic from the origin to initiation
    const double top = path.back().opening;
    if (s.opening > top) {
      if (falling_back) {
        // Back past the maximum: the returning branch's state at it, at the same opening as the
        // state before the jump (state_at takes the latter at that opening, the former above).
        const double w = (top - previous.opening) / (s.opening - previous.opening);
        const auto mix = [w](double x, double y) { return x + w * (y - x); };
        path.push_back({top, mix(previous.load, s.load), mix(previous.a, s.a),
                        mix(previous.delta_root, s.delta_root)});
        falling_back = false;
      }
      path.push_back(s);
    } else if (path.size() > 1) {
      falling_back = true;
    }
    previous = s;
  }
  return path;
}

/// The state at `u` linear between the two path states that bracket it; the last state's
/// opening must not be exceeded (the caller drops those rows).
PathState state_at(const std::vector<PathState>& path, double u) {
  const auto hi = std::lower_bound(path.begin(), path.end(), u,
                                   [](const PathState& s, double x) { return s.opening < x; });
  if (hi == path.begin())
    return path.front();
  const PathState &b = *hi, &a = *(hi - 1);
  if (!(b.opening > a.opening))
    return b; // u at a jump: the state before it (the first entry at that opening)
  const double w = (u - a.opening) / (b.opening - a.opening);
  const auto mix = [w](double x, double y) { return x + w * (y - x); };
  return {u, mix(a.load, b.load), mix(a.a, b.a), mix(a.delta_root, b.delta_root)};
}

/// The parameters the correction moves, as one vector: J_tip, d1, s1, d2, s2, dc.
using Vec = std::array<double, 6>;

Vec to_vec(const ChainEstimate& e) {
  return {e.j_tip, e.law.d1, e.law.s1, e.law.d2, e.law.s2, e.law.dc};
}

ChainEstimate from_vec(const Vec& v) {
  ChainEstimate e;
  e.j_tip = v[0];
  e.law = {v[1], v[2], v[3], v[4], v[5]};
  return e;
}

/// A law the simulation can take: positive stresses and toughness, 0 < d1 < d2 < dc.
bool admissible(const Vec& v) {
  for (double x : v)
    if (!std::isfinite(x))
      return false;
  return v[0] > 0 && v[2] > 0 && v[4] > 0 && v[1] > 0 && v[1] < v[3] && v[3] < v[5];
}

/// Largest difference between two estimates, each parameter on its own scale: J_tip relative to
/// the measured J_tip, stresses to the measured law's larger stress, openings to its delta_c (a
/// small sigma2 or d1 is not held to a relative tolerance it cannot have).
double mismatch(const Vec& x, const Vec& ref) {
  const double s_scale = std::max(ref[2], ref[4]), d_scale = ref[5];
  const std::array<double, 6> scale = {ref[0], d_scale, s_scale, d_scale, s_scale, d_scale};
  double m = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    m = std::max(m, std::abs(x[i] - ref[i]) / scale[i]);
  return m;
}

std::string describe(const ChainEstimate& e) {
  return "J_tip " + fmt(e.j_tip) + " J/m^2, sigma1 " + fmt(e.law.s1 / units::kPa) + " kPa at " +
         fmt(e.law.d1 / units::mm) + " mm, sigma2 " + fmt(e.law.s2 / units::kPa) + " kPa at " +
         fmt(e.law.d2 / units::mm) + " mm, delta_c " + fmt(e.law.dc / units::mm) + " mm";
}

} // namespace

analysis::TestRecord simulated_record(const analysis::TestRecord& measured,
                                      const result::SimulationResult& sim,
                                      std::vector<std::string>& notes) {
  const std::vector<PathState> path = machine_path(sim);
  analysis::TestRecord r;
  r.name = measured.name;
  r.source = measured.source + " (simulated)";
  if (path.size() < 2)
    throw ComputationError("the forward model gave no critical state for record '" + measured.name +
                           "' (the crack did not start)");
  // The crack column as the record has it: a new value on the rows where the record makes a
  // new reading, the last one repeated where the record repeats its own, none where it has none
  // (the reduction's windows see the same readings).
  const auto readings = analysis::crack_reading_rows(measured);
  std::vector<char> new_reading(measured.opening.size(), 0);
  for (auto i : readings)
    new_reading[i] = 1;
  const bool has_crack = !measured.crack_length.empty();
  const bool has_root = !measured.delta_root.empty();
  const double last_opening = path.back().opening;
  std::size_t dropped = 0;
  double last_a = std::numeric_limits<double>::quiet_NaN();
  double widest = 0;
  for (std::size_t i = 0; i < measured.opening.size(); ++i) {
    const double u = measured.opening[i];
    if (!(u <= last_opening)) {
      ++dropped;
      continue;
    }
    const PathState s = state_at(path, std::max(u, 0.0));
    if (!measured.time.empty())
      r.time.push_back(measured.time[i]);
    r.opening.push_back(u);
    r.load.push_back(u > 0 ? s.load : 0.0);
    r.line.push_back(i < measured.line.size() ? measured.line[i] : i + 1);
    // The crack never heals: its length follows the largest opening so far, so a record whose
    // opening dips with noise (or a zero offset) still reads a crack that does not shorten.
    widest = std::max(widest, u);
    if (has_crack) {
      const double m = measured.crack_length[i];
      // max: also against the last ulp of the interpolation (a + w (b - a) on a flat stretch).
      if (new_reading[i])
        last_a = std::isfinite(last_a) ? std::max(last_a, state_at(path, widest).a)
                                       : state_at(path, widest).a;
      r.crack_length.push_back(std::isfinite(m) ? last_a : m);
    }
    if (has_root)
      r.delta_root.push_back(std::isfinite(measured.delta_root[i]) ? s.delta_root
                                                                   : measured.delta_root[i]);
  }
  if (dropped > 0)
    notes.push_back("record '" + measured.name + "': " + std::to_string(dropped) +
                    " rows past the simulation's last opening (" + fmt(last_opening / units::mm) +
                    " mm) left out of its simulated record");
  r.cleaning.push_back("simulated by the correction's forward model at the record's openings");
  return r;
}

ChainCorrection correct_chain(const std::vector<analysis::TestRecord>& records,
                              const std::vector<specimen::Specimen>& specimens,
                              const specimen::Material& material, const ChainEstimate& measured,
                              const MeasuringChain& chain, const ForwardModel& model,
                              const ChainCorrectionSettings& settings) {
  ChainCorrection out;
  out.forward_model = model.name;
  out.measured = measured;
  const Vec m = to_vec(measured);
  if (specimens.size() != records.size())
    throw std::logic_error("correct_chain: one specimen per record");
  if (!admissible(m)) {
    out.notes.push_back("not corrected: the measured law is not a trilinear law the forward model "
                        "can run (" +
                        describe(measured) + ")");
    return out;
  }
  // The chain on the records that law `p` would have written.
  const auto chain_on_simulation = [&](const Vec& p, std::vector<std::string>& notes) {
    const ChainEstimate e = from_vec(p);
    const law::PiecewiseLinearLaw trial = law::make_trilinear(e.law);
    std::vector<analysis::TestRecord> simulated;
    for (std::size_t k = 0; k < records.size(); ++k) {
      const analysis::TestRecord& rec = records[k];
      specimen::Specimen s = specimens[k];
      double reach = s.length;
      const auto rows = analysis::crack_reading_rows(rec);
      if (!rows.empty()) {
        s.initial_crack = rec.crack_length[rows.front()];
        double last = s.initial_crack;
        for (auto i : rows)
          last = std::max(last, rec.crack_length[i]);
        // A little past the last reading: the model may lag the record.
        reach = last + 0.1 * (last - s.initial_crack);
      }
      const auto t0 = std::chrono::steady_clock::now();
      const result::SimulationResult sim = model.run(s, material, trial, e.j_tip, reach);
      out.forward_time_s +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ++out.forward_runs;
      simulated.push_back(simulated_record(rec, sim, notes));
    }
    return to_vec(chain(simulated));
  };

  if (settings.max_iterations < 1) {
    out.notes.push_back("not corrected: Correction iterations must be at least 1");
    return out;
  }
  // One simulation of p and the chain on it, recorded as a step; false (with the reason in the
  // notes, and the step's own notes before it) when the forward model or the chain fails.
  const auto step = [&](const Vec& p, Vec& c) {
    std::vector<std::string> step_notes;
    try {
      c = chain_on_simulation(p, step_notes);
    } catch (const std::exception& e) {
      out.notes.insert(out.notes.end(), step_notes.begin(), step_notes.end());
      out.notes.push_back("not corrected: the simulation of " + describe(from_vec(p)) +
                          " or the chain on its records failed: " + e.what());
      return false;
    }
    // A step's notes (rows past the simulation's end) are said once, as they first appear.
    for (const auto& n : step_notes)
      if (std::find(out.notes.begin(), out.notes.end(), n) == out.notes.end())
        out.notes.push_back(n);
    out.steps.push_back({from_vec(p), from_vec(c), mismatch(c, m)});
    return true;
  };

  Vec p = m;
  int worse = 0;
  for (int k = 0; k < settings.max_iterations; ++k) {
    Vec c;
    if (!step(p, c))
      return out;
    const double mis = out.steps.back().mismatch;
    if (mis <= settings.tolerance) {
      out.converged = true;
      out.corrected = from_vec(p);
      return out;
    }
    // A law that the chain measures further from the records than the records' own estimate was
    // is a step away from the fixed point; twice, and the iteration is not attracted to one.
    worse = k > 0 && mis > out.steps.front().mismatch ? worse + 1 : 0;
    if (worse >= 2) {
      out.notes.push_back("not corrected: the iteration moves away from a fixed point (mismatch " +
                          fmt(mis) + " after " + std::to_string(k + 1) + " simulations, " +
                          fmt(out.steps.front().mismatch) + " at the first)");
      return out;
    }
    // p + (measured - C(p)); a step that leaves the admissible laws is halved until it does not.
    Vec next = p;
    double step = 1;
    for (int h = 0; h < 6; ++h, step *= 0.5) {
      for (std::size_t i = 0; i < p.size(); ++i)
        next[i] = p[i] + step * (m[i] - c[i]);
      if (admissible(next))
        break;
    }
    if (!admissible(next)) {
      out.notes.push_back("not corrected: every step from " + describe(from_vec(p)) +
                          " leaves the trilinear laws the forward model can run");
      return out;
    }
    p = next;
  }
  // The chain's automatic choices (windows, hinge, delta_c) move in steps as the law changes, so
  // C(p) is piecewise smooth and the iterates can alternate about a fixed point that no single
  // law hits within the tolerance. The mean of the trailing iterates (from the third on) whose
  // chain results average to the records' estimate then stands for it, if the chain run on that
  // mean law itself lands within the chain's own steps there (its spread over those iterates,
  // not above 5 tolerances): the law is found to the chain's resolution, and the note says how
  // fine that is.
  const std::size_t n = out.steps.size();
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_from = n;
  Vec best_p{}, best_c{};
  for (std::size_t from = 2; from + 2 <= n; ++from) {
    Vec pm{}, cm{};
    for (std::size_t j = from; j < n; ++j)
      for (std::size_t i = 0; i < pm.size(); ++i) {
        pm[i] += to_vec(out.steps[j].simulated)[i] / double(n - from);
        cm[i] += to_vec(out.steps[j].measured)[i] / double(n - from);
      }
    const double mis = mismatch(cm, m);
    if (mis < best && admissible(pm)) {
      best = mis;
      best_from = from;
      best_p = pm;
      best_c = cm;
    }
  }
  if (best <= settings.tolerance) {
    double jitter = 0;
    for (std::size_t j = best_from; j < n; ++j)
      jitter = std::max(jitter, mismatch(to_vec(out.steps[j].measured), best_c));
    Vec c;
    if (!step(best_p, c))
      return out;
    const double mis = out.steps.back().mismatch;
    if (mis <= std::max(settings.tolerance, jitter) && jitter <= 5 * settings.tolerance) {
      out.converged = true;
      out.corrected = from_vec(best_p);
      out.notes.push_back(
          "the chain's estimate moves in steps of up to " + fmt(jitter) +
          " near the fixed point (its automatic windows and delta_c), more than the tolerance " +
          fmt(settings.tolerance) + ": the corrected law is the mean of the last " +
          std::to_string(n - best_from) + " laws simulated, on which the chain gives " + fmt(mis) +
          " from the records' estimate; the law is found to that resolution");
      return out;
    }
    out.notes.push_back("not corrected: the chain's steps near the fixed point (" + fmt(jitter) +
                        ") leave the mean of the last laws simulated at " + fmt(mis) +
                        " from the records' estimate");
    return out;
  }
  out.notes.push_back("not corrected: no fixed point within " +
                      std::to_string(settings.max_iterations) + " simulations (last mismatch " +
                      fmt(out.steps.back().mismatch) + ", tolerance " + fmt(settings.tolerance) +
                      ")");
  return out;
}

} // namespace fiberbridge::identify
