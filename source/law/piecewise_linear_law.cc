#include "fiberbridge/law/piecewise_linear_law.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fiberbridge::law {

namespace {
std::string fmt_point(const LawPoint& p) {
  std::ostringstream s;
  s << "(" << p.delta / units::mm << " mm, " << p.sigma / units::kPa << " kPa)";
  return s.str();
}
} // namespace

PiecewiseLinearLaw::PiecewiseLinearLaw(std::vector<LawPoint> points, std::string name,
                                       const std::string& context)
    : points_(std::move(points)), name_(std::move(name)) {
  if (points_.size() < 2)
    throw InputError(context + ": a traction law needs at least two points, got " +
                     std::to_string(points_.size()));
  bool any_positive = false;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const auto& p = points_[i];
    if (!std::isfinite(p.delta) || !std::isfinite(p.sigma))
      throw InputError(context + ": point " + std::to_string(i + 1) + " is not finite");
    if (p.sigma < 0)
      throw InputError(context + ": point " + std::to_string(i + 1) + " " + fmt_point(p) +
                       " has negative traction; bridging tractions must be >= 0");
    if (i == 0 && p.delta != 0)
      throw InputError(context + ": the first point must be at zero opening, got " + fmt_point(p));
    if (i > 0 && !(p.delta > points_[i - 1].delta))
      throw InputError(context + ": openings must increase strictly; point " +
                       std::to_string(i + 1) + " " + fmt_point(p) + " follows " +
                       fmt_point(points_[i - 1]));
    any_positive = any_positive || p.sigma > 0;
  }
  if (points_.back().sigma != 0)
    throw InputError(context + ": the last point " + fmt_point(points_.back()) +
                     " must have zero traction (it defines delta_c)");
  if (!any_positive)
    throw InputError(context + ": all tractions are zero; use law type 'none' for no bridging");
  cumulative_area_.assign(points_.size(), 0.0);
  for (std::size_t i = 1; i < points_.size(); ++i)
    cumulative_area_[i] = cumulative_area_[i - 1] + 0.5 *
                                                        (points_[i].sigma + points_[i - 1].sigma) *
                                                        (points_[i].delta - points_[i - 1].delta);
}

std::size_t PiecewiseLinearLaw::segment(double delta) const {
  // Index i of the segment [points_[i], points_[i+1]) containing delta (right-continuous).
  const auto it = std::upper_bound(points_.begin(), points_.end(), delta,
                                   [](double d, const LawPoint& p) { return d < p.delta; });
  const std::size_t i = static_cast<std::size_t>(it - points_.begin());
  return i == 0 ? 0 : i - 1;
}

double PiecewiseLinearLaw::envelope(double delta) const {
  if (delta < 0 || delta >= critical_opening())
    return delta < 0 ? points_.front().sigma : 0.0;
  const std::size_t i = segment(delta);
  const auto& p = points_[i];
  const auto& q = points_[i + 1];
  return p.sigma + (q.sigma - p.sigma) * (delta - p.delta) / (q.delta - p.delta);
}

double PiecewiseLinearLaw::envelope_slope(double delta) const {
  if (delta < 0 || delta >= critical_opening())
    return 0.0;
  const std::size_t i = segment(delta);
  return (points_[i + 1].sigma - points_[i].sigma) / (points_[i + 1].delta - points_[i].delta);
}

double PiecewiseLinearLaw::envelope_integral(double delta) const {
  if (delta <= 0)
    return 0.0;
  if (delta >= critical_opening())
    return cumulative_area_.back();
  const std::size_t i = segment(delta);
  return cumulative_area_[i] +
         0.5 * (points_[i].sigma + envelope(delta)) * (delta - points_[i].delta);
}

std::vector<double> PiecewiseLinearLaw::kinks() const {
  std::vector<double> k;
  for (const auto& p : points_)
    k.push_back(p.delta);
  return k;
}

PiecewiseLinearLaw PiecewiseLinearLaw::with_elastic_rise(double delta_e) const {
  if (!rigid_at_zero_opening())
    return *this;
  if (!(delta_e > 0 && delta_e < points_[1].delta))
    throw InputError(name_ + " law: elastic rise opening must lie in (0, first kink)");
  std::vector<LawPoint> p{{0.0, 0.0}, {delta_e, envelope(delta_e)}};
  p.insert(p.end(), points_.begin() + 1, points_.end());
  return PiecewiseLinearLaw(p, name_);
}

PiecewiseLinearLaw make_linear_softening(double sigma_c, double delta_c) {
  if (!(sigma_c > 0) || !(delta_c > 0))
    throw InputError("linear softening law: peak stress and delta_c must be positive");
  return PiecewiseLinearLaw({{0.0, sigma_c}, {delta_c, 0.0}}, "linear");
}

PiecewiseLinearLaw make_bilinear(double d1, double s1, double dc) {
  if (!(s1 > 0))
    throw InputError("bilinear law: peak stress must be positive");
  return PiecewiseLinearLaw({{0.0, 0.0}, {d1, s1}, {dc, 0.0}}, "bilinear", "bilinear law");
}

PiecewiseLinearLaw make_trilinear(const TrilinearParameters& t) {
  if (!(t.s1 > 0) && !(t.s2 > 0))
    throw InputError("trilinear law: sigma1 and sigma2 are both zero");
  return PiecewiseLinearLaw({{0.0, 0.0}, {t.d1, t.s1}, {t.d2, t.s2}, {t.dc, 0.0}}, "trilinear",
                            "trilinear law");
}

PiecewiseLinearLaw read_law_table_csv(const std::string& path) {
  const auto table = CsvTable::read(path);
  const auto d = table.numeric("delta_mm");
  const auto s = table.numeric("sigma_kPa");
  std::vector<LawPoint> p(d.size());
  for (std::size_t i = 0; i < d.size(); ++i)
    p[i] = {d[i] * units::mm, s[i] * units::kPa};
  return PiecewiseLinearLaw(p, "table", path);
}

} // namespace fiberbridge::law
