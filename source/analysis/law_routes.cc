// The three routes to the bridging law on one grid (law_routes.h).
#include "fiberbridge/analysis/law_routes.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace fiberbridge::analysis {

namespace {

/// Critical opening of a tabulated law: the last grid point with a positive stress.
double tabulated_critical_opening(const std::vector<double>& delta,
                                  const std::vector<double>& sigma) {
  for (std::size_t i = sigma.size(); i-- > 0;)
    if (sigma[i] > 0)
      return delta[std::min(i + 1, delta.size() - 1)];
  return 0;
}

/// A tabulated law on the extraction grid, linear in between, zero beyond its last point.
std::vector<double> resample_or_zero(const std::vector<double>& x, const std::vector<double>& y,
                                     const std::vector<double>& at) {
  std::vector<double> inside, out(at.size(), 0.0);
  for (double d : at)
    inside.push_back(std::min(d, x.back()));
  const auto v = resample_linear(x, y, inside);
  for (std::size_t i = 0; i < at.size(); ++i)
    out[i] = at[i] <= x.back() ? v[i] : 0.0;
  return out;
}

/// Peak and trapezoid area of a tabulated law on its own grid (exact for the table).
void summarize_table(RouteLaw& r, const std::vector<double>& delta,
                     const std::vector<double>& sigma) {
  r.peak = -INFINITY;
  r.area = 0;
  for (std::size_t i = 0; i < delta.size(); ++i) {
    if (sigma[i] > r.peak) {
      r.peak = sigma[i];
      r.delta_at_peak = delta[i];
    }
    if (i)
      r.area += 0.5 * (sigma[i] + sigma[i - 1]) * (delta[i] - delta[i - 1]);
  }
}

void compare(RouteLaw& r, const RouteLaw& ref, const std::vector<double>& delta, double dc_r,
             double dc_ref) {
  r.peak_ratio = r.peak / ref.peak;
  r.area_ratio = r.area / ref.area;
  const double end = std::max(dc_r, dc_ref);
  double ss = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < delta.size() && delta[i] <= end; ++i, ++n)
    ss += std::pow(r.sigma[i] - ref.sigma[i], 2);
  r.rms_rel = n ? std::sqrt(ss / static_cast<double>(n)) / ref.peak : NAN;
}

} // namespace

LawRoutes compare_law_routes(const ExtractedLaws& e, const law::TractionLaw& identified,
                             const law::TractionLaw* input, int n_grid) {
  if (e.delta.size() < 2 || e.sigma_eq6.size() != e.delta.size() ||
      e.sigma_dRdd.size() != e.delta.size())
    throw InputError("law routes: the extracted laws hold fewer than 2 points");
  if (n_grid < 3)
    throw InputError("law routes: the comparison grid needs at least 3 points");
  const double dc_eq6 = tabulated_critical_opening(e.delta, e.sigma_eq6);
  const double dc_dRdd = tabulated_critical_opening(e.delta, e.sigma_dRdd);
  const double dc_id = identified.critical_opening();
  const double dc_in = input ? input->critical_opening() : 0.0;
  const double end = 1.05 * std::max({e.delta.back(), dc_id, dc_in});

  LawRoutes out;
  for (int i = 0; i < n_grid; ++i)
    out.delta.push_back(end * i / (n_grid - 1));
  auto of_law = [&](const std::string& name, const law::TractionLaw& l) {
    RouteLaw r;
    r.name = name;
    for (double d : out.delta)
      r.sigma.push_back(l.envelope(d));
    // From the law itself, not the grid: a kink between two grid points would cut the peak.
    std::tie(r.peak, r.delta_at_peak) = l.peak();
    r.area = l.area();
    return r;
  };
  RouteLaw eq6{"eq6", resample_or_zero(e.delta, e.sigma_eq6, out.delta)};
  RouteLaw dRdd{"dRdd", resample_or_zero(e.delta, e.sigma_dRdd, out.delta)};
  summarize_table(eq6, e.delta, e.sigma_eq6);
  summarize_table(dRdd, e.delta, e.sigma_dRdd);
  out.routes = {eq6, dRdd, of_law("identified", identified)};
  std::vector<double> dc = {dc_eq6, dc_dRdd, dc_id};
  if (input) {
    out.routes.push_back(of_law("input", *input));
    dc.push_back(dc_in);
  }
  const std::size_t ref = input ? 3 : 0;
  out.reference = out.routes[ref].name;
  for (std::size_t k = 0; k < out.routes.size(); ++k)
    compare(out.routes[k], out.routes[ref], out.delta, dc[k], dc[ref]);
  if (input) {
    // Eq. 4 from the input law itself: what an exact dR/d delta would give. Sampled just right
    // of each grid point and each kink, where envelope_slope is the right derivative.
    double best = 0;
    auto at = [&](double d) {
      best = std::max(best, 0.5 * (input->envelope(d) - d * input->envelope_slope(d)));
    };
    for (double d : out.delta)
      at(d);
    for (double d : input->kinks())
      at(d);
    out.dRdd_peak_ratio_eq4 = best / out.routes[ref].peak;
  }
  return out;
}

} // namespace fiberbridge::analysis
