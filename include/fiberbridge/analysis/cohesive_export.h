#pragma once
// A bridging law written as the FE codes take it (issue 33 item 7; docs/design.md section 1,
// "Durability campaign"): LS-DYNA's general cohesive material (*MAT_COHESIVE_GENERAL, MAT_186)
// with a normalised traction-separation load curve, and Abaqus cohesive elements (*ELASTIC,
// TYPE=TRACTION; *DAMAGE INITIATION, CRITERION=MAXS; *DAMAGE EVOLUTION, TYPE=DISPLACEMENT,
// SOFTENING=TABULAR). Both files use the consistent unit set mm, N, MPa, s, tonne: traction in
// MPa, separation in mm, energy per area in N/mm (= kJ/m^2), stiffness in N/mm^3. Mode I only:
// the law is a mode I measurement; the shear entries repeat the normal ones and say so.
#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::analysis {

/// A polyline law (delta [m], sigma [Pa]) from (0, 0) to (delta_c, 0), sigma > 0 inside.
struct PolylineLaw {
  std::vector<double> delta, sigma;
  /// Trapezoid area [J/m^2] and the largest traction [Pa].
  double area() const;
  double peak() const;
};

/// The trilinear law (0,0) (d1,s1) (d2,s2) (dc,0) as a polyline.
PolylineLaw trilinear_polyline(double d1, double s1, double d2, double s2, double dc);

/// *MAT_COHESIVE_GENERAL with TSLC = `curve_id`: the curve is the law normalised by its peak
/// traction (ordinate) and by delta_c (abscissa); T = the peak [MPa], GIC = the law's area
/// [N/mm], so that LS-DYNA's ultimate separation GIC / (T x area of the normalised curve) is
/// delta_c. Free (comma-separated) fields. Throws InputError for a polyline that is not a law.
std::string lsdyna_mat_cohesive_general(const PolylineLaw& law, int material_id, int curve_id,
                                        const std::string& title);

/// The normalised curve of lsdyna_mat_cohesive_general (lambda, traction / peak) and the
/// ultimate separation LS-DYNA derives from T and GIC [m] (for the tests).
struct LsDynaCurve {
  std::vector<double> lambda, t_over_T;
  double T = 0, GIC = 0; ///< [Pa], [J/m^2]
  double area_normalised = 0;
  double ultimate_separation() const { return GIC / (T * area_normalised); }
};
LsDynaCurve lsdyna_normalised_curve(const PolylineLaw& law);

/// The Abaqus cohesive material: K = sigma_1 / delta_1 of the first (elastic) segment, damage
/// initiation at the first breakpoint (MAXS with the traction there), and the tabular damage
/// D(u) = 1 - sigma(delta) / (K delta) against u = delta - delta_1, sampled at
/// `points_per_segment` points on every segment beyond delta_1 (Abaqus interpolates D linearly
/// in u, so the traction between samples differs slightly from the polyline: the sampling is
/// chosen so that the area and peak hold to 0.1 %, tests/analysis/campaign_tests.cc).
/// Requires the law to stay below its elastic line beyond delta_1 (D non-decreasing).
struct AbaqusDamageTable {
  double K = 0;             ///< [Pa/m]
  double delta0 = 0;        ///< damage initiation [m]
  double t0 = 0;            ///< traction at initiation [Pa]
  std::vector<double> D, u; ///< damage and separation after initiation [m]
  /// Traction the table gives at separation delta [Pa] (linear D between the samples).
  double traction(double delta) const;
};
AbaqusDamageTable abaqus_damage_table(const PolylineLaw& law, int points_per_segment = 200);
std::string abaqus_cohesive_material(const PolylineLaw& law, const std::string& name,
                                     int points_per_segment = 200);

} // namespace fiberbridge::analysis
