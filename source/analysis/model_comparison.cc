#include "fiberbridge/analysis/model_comparison.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fiberbridge::analysis {

namespace {

/// Tip position where the notch root first moves (end of the developing part); +inf if never.
double end_of_development(const result::SimulationResult& r) {
  if (r.rcurve.empty())
    return 0;
  const double root0 = r.rcurve.front().root;
  for (const auto& p : r.rcurve)
    if (std::isfinite(p.root) && std::isfinite(root0) && p.root > root0 + 1e-9)
      return p.a;
  return std::numeric_limits<double>::infinity();
}

double peak_load(const result::SimulationResult& r) {
  double m = 0;
  for (const auto& p : r.rcurve)
    if (std::isfinite(p.load))
      m = std::max(m, p.load);
  return m;
}

double field(const result::RCurvePoint& p, const std::string& q) {
  if (q == "R_energy")
    return p.R_energy;
  if (q == "R_J")
    return p.R_J;
  if (q == "R_eq2")
    return p.R_eq2;
  return p.delta_root;
}

} // namespace

std::vector<PairwiseDifference> compare_models(const result::SimulationResult& a,
                                               const result::SimulationResult& b) {
  std::vector<PairwiseDifference> out;
  const double a_end = std::min(end_of_development(a), end_of_development(b));
  // R(a) curves depend on the specimen model (where each model puts the effective crack tip);
  // R_J(delta_root) does not (Eq. 2): it is the like-for-like comparison of the zone mechanics.
  for (const std::string q : {"R_energy", "R_J", "R_eq2", "delta_root", "R_J(delta_root)"}) {
    const bool vs_delta = q == "R_J(delta_root)";
    const std::string y_field = vs_delta ? "R_J" : q;
    const auto x_of = [&](const result::RCurvePoint& p) { return vs_delta ? p.delta_root : p.a; };
    // b's curve as a function of x (rows with increasing x, finite values).
    std::vector<double> xb, yb;
    for (const auto& p : b.rcurve) {
      const double v = field(p, y_field);
      if (std::isfinite(x_of(p)) && std::isfinite(v) && p.a <= a_end &&
          (xb.empty() || x_of(p) > xb.back())) {
        xb.push_back(x_of(p));
        yb.push_back(v);
      }
    }
    double num = 0, den = 0;
    int n = 0;
    for (const auto& p : a.rcurve) {
      const double va = field(p, y_field);
      if (!std::isfinite(x_of(p)) || !std::isfinite(va) || p.a > a_end)
        continue;
      const double vb = interpolate_within(xb, yb, x_of(p));
      if (!std::isfinite(vb))
        continue;
      num += (vb - va) * (vb - va);
      den += va * va;
      ++n;
    }
    PairwiseDifference d;
    d.model_a = a.model;
    d.model_b = b.model;
    d.quantity = q;
    d.n_points = n;
    d.rel_l2_developing = den > 0 ? std::sqrt(num / den) : result::not_available;
    d.plateau_rel_diff = (b.G_ss - a.G_ss) / a.G_ss;
    const double pa = peak_load(a), pb = peak_load(b);
    d.peak_load_rel_diff = pa > 0 ? (pb - pa) / pa : result::not_available;
    out.push_back(d);
  }
  return out;
}

std::vector<ClosedLoopRow> closed_loop(const result::SimulationResult& r,
                                       const law::TractionLaw& law, double j_tip, int n, int k) {
  const double dc = law.critical_opening();
  if (!(dc > 0))
    throw ComputationError("closed loop: the law has no bridging (delta_c = 0): nothing to "
                           "recover");
  // True law on the extraction grid.
  std::vector<double> grid(n + 1), truth(n + 1);
  for (int i = 0; i <= n; ++i) {
    grid[i] = dc * i / n;
    truth[i] = law.envelope(grid[i]);
  }
  const auto [true_peak, true_peak_delta] = law.peak();
  std::vector<ClosedLoopRow> rows;
  for (const std::string source : {"R_energy", "R_eq2"}) {
    RDeltaCurve c;
    c.n_replicates = 1;
    // R is flat at J_tip before the first advance (no zone yet): start the curve there.
    c.delta.push_back(0);
    c.R.push_back(j_tip);
    int below_dc = 0;
    for (const auto& p : r.rcurve) {
      const double R = source == "R_energy" ? p.R_energy : p.R_eq2;
      if (!std::isfinite(p.delta_root) || !std::isfinite(R) || !(p.delta_root > c.delta.back()))
        continue;
      c.delta.push_back(p.delta_root);
      c.R.push_back(R);
      below_dc += p.delta_root < dc;
    }
    if (below_dc < n / 4)
      throw ComputationError("closed loop for " + r.model + ": only " + std::to_string(below_dc) +
                             " distinct delta_root values below "
                             "delta_c; refine the tip advance or lower the Compare intervals (" +
                             std::to_string(n) + ")");
    if (c.delta.back() < dc) {
      // The run stopped at the plateau's onset: R' = 0 beyond delta_c is what Eq. 5 assumes.
      c.delta.push_back(dc * 1.05);
      c.R.push_back(c.R.back());
    }
    c.R_std.assign(c.R.size(), 0.0);
    const auto laws = extract_cohesive_laws(c, dc, n, k);
    for (const std::string method : {"eq6", "dRdd"}) {
      const auto& s = method == "eq6" ? laws.sigma_eq6 : laws.sigma_dRdd;
      ClosedLoopRow row;
      row.model = r.model;
      row.r_source = source;
      row.method = method;
      // The first point of the peak: a recovered law can have a flat top (dR/ddelta of a
      // smoothed curve, equal to 10 digits over several points), where max_element's choice
      // would follow the round-off of the run (a condensed FEM against a full one moved it by
      // a factor 2 in delta). Points within 1e-9 of the maximum count as the peak.
      const double top = *std::max_element(s.begin(), s.end());
      const auto it = std::find_if(s.begin(), s.end(),
                                   [top](double v) { return v >= top - 1e-9 * std::abs(top); });
      row.peak_kPa = *it / units::kPa;
      row.delta_at_peak_mm = laws.delta[static_cast<std::size_t>(it - s.begin())] / units::mm;
      row.peak_true_kPa = true_peak / units::kPa;
      row.delta_at_peak_true_mm = true_peak_delta / units::mm;
      row.area_J_m2 = method == "eq6" ? laws.area_eq6 : laws.area_dRdd;
      row.area_true_J_m2 = law.area();
      double num = 0, den = 0;
      for (int i = 0; i <= n; ++i) {
        num += (s[i] - truth[i]) * (s[i] - truth[i]);
        den += truth[i] * truth[i];
      }
      row.curve_rel_l2 = std::sqrt(num / den);
      row.laws = laws;
      rows.push_back(row);
    }
  }
  return rows;
}

ModelComparison compare_simulations(const std::vector<const result::SimulationResult*>& models,
                                    const law::TractionLaw& law, double j_tip, bool loop, int n,
                                    int k) {
  ModelComparison c;
  for (std::size_t i = 0; i < models.size(); ++i)
    for (std::size_t j = i + 1; j < models.size(); ++j)
      for (auto& d : compare_models(*models[i], *models[j]))
        c.pairs.push_back(std::move(d));
  if (!loop)
    return c;
  for (const auto* r : models) {
    ModelComparison::Loop l;
    l.model = r->model;
    try {
      l.rows = closed_loop(*r, law, j_tip, n, k);
    } catch (const ComputationError& e) {
      // A model too coarse for the loop does not invalidate the comparison: say so.
      l.diagnosis = e.what();
    }
    c.loops.push_back(std::move(l));
  }
  return c;
}

} // namespace fiberbridge::analysis
