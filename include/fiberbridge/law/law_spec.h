#pragma once
// The scene's "Cohesive law" section as a plain struct, and the factory that turns it into a law.
// Kept free of deal.II so that mpm and beam can use it without the FEM classes.
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/law/traction_law.h"

#include <string>
#include <vector>

namespace fiberbridge::law {

struct LawSpec {
  /// none | linear | bilinear | trilinear | exponential | table
  std::string type = "trilinear";
  double peak_stress = 0; ///< [Pa] for linear and exponential
  double delta_c = 0;     ///< [m]
  /// Interior points (delta, sigma) for bilinear (1 point) and trilinear (2 points); for table the
  /// whole polyline. The end points (0,0) and (delta_c, 0) are added where the type implies them.
  std::vector<LawPoint> points;
  std::string table_file;               ///< CSV for type = table when `points` is empty
  double j_tip = 200;                   ///< crack-tip (initiation) toughness [J/m^2]
  std::string context = "Cohesive law"; ///< where it came from, for messages
};

/// Builds and validates the law; throws InputError naming spec.context and the offending value.
TractionLawPtr make_law(const LawSpec& spec);

/// Parses "d1:s1, d2:s2" (delta in mm, sigma in kPa) into SI points; throws naming `context`.
std::vector<LawPoint> parse_points_mm_kPa(const std::string& text, const std::string& context);

} // namespace fiberbridge::law
