#include "fiberbridge/law/law_spec.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/exponential_law.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace fiberbridge::law {

std::vector<LawPoint> parse_points_mm_kPa(const std::string& text, const std::string& context) {
  std::vector<LawPoint> points;
  for (const auto& item : split_list(text, ',')) {
    const auto colon = item.find(':');
    char* e1 = nullptr;
    char* e2 = nullptr;
    const std::string ds = colon == std::string::npos ? "" : item.substr(0, colon);
    const std::string ss = colon == std::string::npos ? "" : item.substr(colon + 1);
    const double d = std::strtod(ds.c_str(), &e1);
    const double s = std::strtod(ss.c_str(), &e2);
    if (colon == std::string::npos || ds.empty() || ss.empty() || *e1 != '\0' || *e2 != '\0' ||
        !std::isfinite(d) || !std::isfinite(s))
      throw InputError(context + ": cannot read point '" + item +
                       "', expected delta_mm:sigma_kPa such as 0.1:661");
    points.push_back({d * units::mm, s * units::kPa});
  }
  return points;
}

TractionLawPtr make_law(const LawSpec& spec) {
  const std::string& c = spec.context;
  if (!(spec.j_tip > 0) || !std::isfinite(spec.j_tip))
    throw InputError(c + "/J tip: must be a positive toughness in J/m^2");
  const auto need_dc = [&] {
    if (!(spec.delta_c > 0))
      throw InputError(c + "/Delta c: must be a positive opening in mm for law type '" + spec.type +
                       "'");
  };
  const auto need_points = [&](std::size_t n) {
    if (spec.points.size() != n)
      throw InputError(c + "/Points: law type '" + spec.type + "' needs " + std::to_string(n) +
                       " point(s) delta_mm:sigma_kPa, got " + std::to_string(spec.points.size()));
  };
  if (spec.type == "none")
    return std::make_shared<NoBridgingLaw>();
  if (spec.type == "linear") {
    need_dc();
    if (!(spec.peak_stress > 0))
      throw InputError(c + "/Peak stress: must be positive (kPa) for a linear law");
    return std::make_shared<PiecewiseLinearLaw>(
        std::vector<LawPoint>{{0.0, spec.peak_stress}, {spec.delta_c, 0.0}}, "linear", c);
  }
  if (spec.type == "exponential") {
    need_dc();
    if (!(spec.peak_stress > 0))
      throw InputError(c + "/Peak stress: must be positive (kPa) for an exponential law");
    return std::make_shared<ExponentialLaw>(spec.peak_stress, spec.delta_c);
  }
  if (spec.type == "bilinear" || spec.type == "trilinear") {
    need_dc();
    need_points(spec.type == "bilinear" ? 1 : 2);
    std::vector<LawPoint> p{{0.0, 0.0}};
    p.insert(p.end(), spec.points.begin(), spec.points.end());
    if (!(spec.delta_c > p.back().delta))
      throw InputError(c + "/Delta c: must lie beyond the last point (" +
                       std::to_string(p.back().delta / units::mm) + " mm)");
    p.push_back({spec.delta_c, 0.0});
    return std::make_shared<PiecewiseLinearLaw>(p, spec.type, c);
  }
  if (spec.type == "table") {
    if (!spec.points.empty())
      return std::make_shared<PiecewiseLinearLaw>(spec.points, "table", c + "/Points");
    if (spec.table_file.empty())
      throw InputError(c + ": law type 'table' needs Points or a Table file");
    return std::make_shared<PiecewiseLinearLaw>(read_law_table_csv(spec.table_file));
  }
  throw InputError(c + "/Type: unknown law type '" + spec.type +
                   "', expected none|linear|bilinear|trilinear|exponential|table");
}

} // namespace fiberbridge::law
