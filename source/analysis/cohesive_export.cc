// Bridging laws as LS-DYNA and Abaqus take them (cohesive_export.h).
#include "fiberbridge/analysis/cohesive_export.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::analysis {

namespace {

// The files' unit set: mm, N, MPa (docs/design.md section 1, "Durability campaign").
constexpr double to_mm = 1e3;     // m -> mm
constexpr double to_MPa = 1e-6;   // Pa -> MPa
constexpr double to_N_mm = 1e-3;  // J/m^2 -> N/mm
constexpr double to_N_mm3 = 1e-9; // Pa/m -> N/mm^3

void check_law(const PolylineLaw& l) {
  const std::size_t n = l.delta.size();
  if (n < 3 || l.sigma.size() != n || l.delta.front() != 0 || l.sigma.front() != 0 ||
      l.sigma.back() != 0)
    throw InputError("cohesive law export: the law must run from (0, 0) to (delta_c, 0) with at "
                     "least one point between");
  for (std::size_t i = 1; i < n; ++i)
    if (!(l.delta[i] > l.delta[i - 1]) || !std::isfinite(l.sigma[i]) || l.sigma[i] < 0)
      throw InputError("cohesive law export: openings must increase and tractions be >= 0");
  if (!(l.sigma[1] > 0))
    throw InputError("cohesive law export: the first breakpoint carries no traction (no elastic "
                     "segment to start from)");
}

} // namespace

double PolylineLaw::area() const {
  double a = 0;
  for (std::size_t i = 1; i < delta.size(); ++i)
    a += 0.5 * (sigma[i] + sigma[i - 1]) * (delta[i] - delta[i - 1]);
  return a;
}

double PolylineLaw::peak() const {
  return sigma.empty() ? 0 : *std::max_element(sigma.begin(), sigma.end());
}

PolylineLaw trilinear_polyline(double d1, double s1, double d2, double s2, double dc) {
  return {{0, d1, d2, dc}, {0, s1, s2, 0}};
}

LsDynaCurve lsdyna_normalised_curve(const PolylineLaw& law) {
  check_law(law);
  LsDynaCurve c;
  c.T = law.peak();
  c.GIC = law.area();
  const double dc = law.delta.back();
  for (std::size_t i = 0; i < law.delta.size(); ++i) {
    c.lambda.push_back(law.delta[i] / dc);
    c.t_over_T.push_back(law.sigma[i] / c.T);
  }
  for (std::size_t i = 1; i < c.lambda.size(); ++i)
    c.area_normalised +=
        0.5 * (c.t_over_T[i] + c.t_over_T[i - 1]) * (c.lambda[i] - c.lambda[i - 1]);
  return c;
}

std::string lsdyna_mat_cohesive_general(const PolylineLaw& law, int material_id, int curve_id,
                                        const std::string& title) {
  const LsDynaCurve c = lsdyna_normalised_curve(law);
  std::string s;
  s += "$ fiberbridge: " + title + "\n";
  s += "$ Units: mm, N, MPa, s, tonne (traction MPa, GIC N/mm = kJ/m^2).\n";
  s += "$ Mode I bridging law measured by the DCB (seed Eq. 6, trilinear fit): the load curve is\n";
  s += "$ the law normalised by T (ordinate) and delta_c (abscissa); LS-DYNA's ultimate\n";
  s += "$ separation GIC/(T*area of the curve) = delta_c = " + fmt(law.delta.back() * to_mm, 7) +
       " mm.\n";
  s += "$ Mode II was not measured: S and GIIC repeat T and GIC (replace them if you know "
       "better).\n";
  s += "$ RO: 1000 kg/m^3 (1e-9 tonne/mm^3) assumed for the cohesive layer; set yours.\n";
  s += "*MAT_COHESIVE_GENERAL_TITLE\n" + title + "\n";
  s += "$      MID,       RO,    ROFLG,  INTFAIL,      TES,     TSLC,      GIC,     GIIC\n";
  s += std::to_string(material_id) + ",1.0e-9,0,1,0," + std::to_string(curve_id) + "," +
       fmt(c.GIC * to_N_mm, 7) + "," + fmt(c.GIC * to_N_mm, 7) + "\n";
  s += "$      XMU,        T,        S,    STFSF\n";
  s += "1.0," + fmt(c.T * to_MPa, 7) + "," + fmt(c.T * to_MPa, 7) + ",0.0\n";
  s += "*DEFINE_CURVE_TITLE\n" + title + " normalised traction-separation\n";
  s += "$     LCID,     SIDR,      SFA,      SFO\n";
  s += std::to_string(curve_id) + ",0,1.0,1.0\n";
  s += "$   lambda = delta/delta_c, traction/T\n";
  for (std::size_t i = 0; i < c.lambda.size(); ++i)
    s += fmt(c.lambda[i], 7) + "," + fmt(c.t_over_T[i], 7) + "\n";
  return s;
}

double AbaqusDamageTable::traction(double delta) const {
  if (delta <= delta0)
    return K * delta;
  const double uu = delta - delta0;
  if (uu >= u.back())
    return 0;
  const auto it = std::upper_bound(u.begin(), u.end(), uu);
  const std::size_t i = static_cast<std::size_t>(it - u.begin());
  const double w = (uu - u[i - 1]) / (u[i] - u[i - 1]);
  const double d = D[i - 1] + w * (D[i] - D[i - 1]);
  return (1 - d) * K * delta;
}

AbaqusDamageTable abaqus_damage_table(const PolylineLaw& law, int points_per_segment) {
  check_law(law);
  if (points_per_segment < 2)
    throw InputError("cohesive law export: need at least 2 points per segment");
  AbaqusDamageTable t;
  t.delta0 = law.delta[1];
  t.t0 = law.sigma[1];
  t.K = t.t0 / t.delta0;
  t.D.push_back(0);
  t.u.push_back(0);
  for (std::size_t s = 2; s < law.delta.size(); ++s)
    for (int k = 1; k <= points_per_segment; ++k) {
      const double w = static_cast<double>(k) / points_per_segment;
      const double d = law.delta[s - 1] + w * (law.delta[s] - law.delta[s - 1]);
      const double sig = law.sigma[s - 1] + w * (law.sigma[s] - law.sigma[s - 1]);
      const double D = std::clamp(1 - sig / (t.K * d), 0.0, 1.0);
      if (D < t.D.back() - 1e-12)
        throw InputError("cohesive law export: the law rises above its elastic line (K = sigma1 "
                         "/ delta1) beyond delta1; Abaqus' damage would have to decrease");
      t.D.push_back(s + 1 == law.delta.size() && k == points_per_segment ? 1.0 : D);
      t.u.push_back(d - t.delta0);
    }
  return t;
}

std::string abaqus_cohesive_material(const PolylineLaw& law, const std::string& name,
                                     int points_per_segment) {
  const AbaqusDamageTable t = abaqus_damage_table(law, points_per_segment);
  std::string s;
  s += "** fiberbridge: " + name + "\n";
  s += "** Units: mm, N, MPa (traction MPa, separation mm, stiffness N/mm^3). Use with\n";
  s += "** *COHESIVE SECTION, RESPONSE=TRACTION SEPARATION and constitutive thickness 1.\n";
  s += "** Elastic up to the first breakpoint (K = sigma1/delta1), damage from there:\n";
  s += "** D(u) = 1 - sigma(delta)/(K delta), u = delta - delta1, linear in u between rows.\n";
  s += "** Law area " + fmt(law.area() * to_N_mm, 7) + " N/mm, peak " +
       fmt(law.peak() * to_MPa, 7) + " MPa, delta_c " + fmt(law.delta.back() * to_mm, 7) +
       " mm. Mode II not measured: the shear\n";
  s += "** entries repeat the normal ones.\n";
  s += "*MATERIAL, NAME=" + name + "\n";
  s += "*ELASTIC, TYPE=TRACTION\n";
  s +=
      fmt(t.K * to_N_mm3, 7) + ", " + fmt(t.K * to_N_mm3, 7) + ", " + fmt(t.K * to_N_mm3, 7) + "\n";
  s += "*DAMAGE INITIATION, CRITERION=MAXS\n";
  s += fmt(t.t0 * to_MPa, 7) + ", " + fmt(t.t0 * to_MPa, 7) + ", " + fmt(t.t0 * to_MPa, 7) + "\n";
  s += "*DAMAGE EVOLUTION, TYPE=DISPLACEMENT, SOFTENING=TABULAR\n";
  for (std::size_t i = 0; i < t.D.size(); ++i)
    s += fmt(t.D[i], 7) + ", " + fmt(t.u[i] * to_mm, 7) + "\n";
  return s;
}

} // namespace fiberbridge::analysis
