#include "fiberbridge/result/steady_state.h"

#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::result {

double released_energy(const RCurvePoint& p) {
  const double ke = std::isfinite(p.kinetic_energy) ? p.kinetic_energy : 0.0;
  return p.external_work - p.strain_energy - p.zone_recoverable - ke;
}

void fill_r_energy(std::vector<RCurvePoint>& rc, double width) {
  const std::size_t n = rc.size();
  for (std::size_t k = 0; n > 1 && k < n; ++k) {
    const std::size_t i = k == 0 ? 0 : k - 1;
    const std::size_t j = k + 1 < n ? k + 1 : k;
    rc[k].R_energy =
        (released_energy(rc[j]) - released_energy(rc[i])) / (width * (rc[j].a - rc[i].a));
  }
}

namespace {
bool is_excluded(const std::vector<bool>& excluded, std::size_t i) {
  return i < excluded.size() && excluded[i];
}
} // namespace

SteadyState find_steady_state(const std::vector<RCurvePoint>& rc, double a0, double width,
                              bool bridging, const SteadyStateRule& rule,
                              const std::vector<bool>& excluded) {
  SteadyState s;
  s.bridging = bridging;
  if (rc.empty())
    return s;
  const std::size_t n = rc.size();
  if (!bridging) {
    s.root_moved = true;
    s.moved = 0;
  } else {
    for (std::size_t i = 0; i < n && !s.root_moved; ++i)
      if (rc[i].root > a0 + rule.root_move) {
        s.root_moved = true;
        s.moved = i;
      }
  }
  if (!s.root_moved)
    return s;
  s.last = n - 1;
  auto usable = [&](std::size_t i) {
    return !is_excluded(excluded, i) && std::isfinite(rc[i].R_J);
  };

  // The longest flat stretch ending at the last row: walk back while the spread of the used
  // rows stays within the tolerance of their mean.
  double lo = INFINITY, hi = -INFINITY, sum = 0;
  std::size_t used = 0, left_out = 0, first = n;
  for (std::size_t i = n; i-- > s.moved;) {
    if (!usable(i)) {
      ++left_out;
      first = i;
      continue;
    }
    const double l = std::min(lo, rc[i].R_J), h = std::max(hi, rc[i].R_J);
    const double mean = (sum + rc[i].R_J) / double(used + 1);
    if (h - l > rule.tolerance * std::abs(mean))
      break;
    lo = l, hi = h, sum += rc[i].R_J, ++used, first = i;
  }
  // Rows excluded at the start of the stretch do not lengthen it.
  while (first < n && !usable(first)) {
    ++first;
    --left_out;
  }
  if (used > 0 && first < n && rc[s.last].a - rc[first].a >= rule.window * (1 - 1e-9)) {
    s.reached = true;
    s.first = first;
    s.used = used;
    s.left_out = left_out;
    s.G_ss = sum / double(used);
    s.spread = (hi - lo) / std::abs(s.G_ss);
    if (s.last > s.first)
      s.R_energy = (released_energy(rc[s.last]) - released_energy(rc[s.first])) /
                   (width * (rc[s.last].a - rc[s.first].a));
    return s;
  }
  // Not reached: the mean R_J after the root moved (flag false).
  s.first = s.moved;
  sum = 0;
  s.used = s.left_out = 0;
  for (std::size_t i = s.moved; i < n; ++i) {
    if (!usable(i)) {
      ++s.left_out;
      continue;
    }
    sum += rc[i].R_J;
    ++s.used;
  }
  if (s.used > 0)
    s.G_ss = sum / double(s.used);
  return s;
}

void report_steady_state(SimulationResult& result, const SteadyState& s,
                         const SteadyStateRule& rule, const std::string& section) {
  using units::mm;
  result.reached_steady_state = s.reached;
  result.steady_state_status =
      s.reached ? SteadyStateStatus::resolved : SteadyStateStatus::not_reached;
  result.G_ss = s.G_ss;
  const auto& rc = result.rcurve;
  const std::string left_out =
      s.left_out > 0 ? " (" + std::to_string(s.left_out) + " advance(s) left out by the model)"
                     : std::string();
  if (s.reached) {
    result.notes.push_back(
        "steady state: R_J within " + fmt(100 * s.spread, 3) + " % (" + section +
        "/Plateau tolerance " + fmt(100 * rule.tolerance, 3) + " %) over the last " +
        fmt((rc[s.last].a - rc[s.first].a) / mm) + " mm of growth (" + section +
        "/Steady state window " + fmt(rule.window / mm) + " mm) " +
        (s.bridging ? "after the notch root moved at a = " + fmt(rc[s.moved].a / mm) + " mm"
                    : std::string("(no bridging zone: every advance counts)")) +
        "; G_ss = mean R_J of " + std::to_string(s.used) + " advances there" + left_out +
        "; R_energy over them (released energy per growth) " + fmt(s.R_energy) + " J/m^2");
  } else if (s.root_moved && std::isfinite(s.G_ss)) {
    result.notes.push_back(
        "no steady state: after the notch root moved at a = " + fmt(rc[s.moved].a / mm) +
        " mm, R_J did not stay within " + section + "/Plateau tolerance " +
        fmt(100 * rule.tolerance, 3) + " % over " + section + "/Steady state window " +
        fmt(rule.window / mm) + " mm of growth before the run stopped; G_ss = " + fmt(s.G_ss) +
        " J/m^2 is the mean R_J after the root moved" + left_out + ", not a plateau");
  } else if (!s.root_moved) {
    result.notes.push_back("no steady state: the notch root did not move before the run stopped "
                           "(G_ss not available)");
  }
}

SteadyState finish_rcurve(SimulationResult& result, const law::TractionLaw& law, double j_tip,
                          double initial_crack, double width, const SteadyStateRule& rule,
                          const std::string& section, const std::vector<bool>& excluded) {
  fill_r_energy(result.rcurve, width);
  const SteadyState s = find_steady_state(result.rcurve, initial_crack, width,
                                          law.critical_opening() > 0, rule, excluded);
  report_steady_state(result, s, rule, section);
  result.rdelta_rel_error_vs_eq2 = rdelta_error_vs_eq2(result, law, j_tip);
  return s;
}

} // namespace fiberbridge::result
