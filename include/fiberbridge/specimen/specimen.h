#pragma once
// The DCB specimen and its orthotropic material as plain structs shared by fem, mpm and beam.
// Defaults: the seed's specimen (section 2.2) and coast Douglas-fir at 12 % MC (USDA Wood Handbook,
// Ch. 5: E_L = 13.4 GPa, E_T/E_L = 0.050, G_LT/E_L = 0.078, nu_LT = 0.449).
//
// One specimen type for the simulations and for the reduction of test records (it replaced
// analysis::TestSpecimen, issue 30): a record's geometry starts from Specimen::unknown(), every
// length NaN ("not given"), and is filled from the scene, the command line or a manifest row.
#include <cmath>
#include <string>

namespace fiberbridge::specimen {

struct Specimen {
  double length = 0.300;        ///< beam length along the grain [m]
  double width = 0.035;         ///< B, out of plane [m]
  double height = 0.035;        ///< both arms together, 2h [m]
  double initial_crack = 0.100; ///< a0, measured from the load line [m]
  /// l1 of ASTM D5528 / ISO 15024: load-pin axis to the arm's mid-plane [m]; NaN: h/2 (a hinge
  /// on the arm's surface). Used by the reduction of test records (large_displacement.h).
  double pin_to_arm_midplane = NAN;
  /// l2 of ASTM D5528 / ISO 15024: load-pin axis to the end block's inner edge [m]; NaN: no end
  /// blocks (hinges): l2 = 0 in N.
  double pin_to_block_edge = NAN;
  double arm_thickness() const { return 0.5 * height; }
  void validate(const std::string& context = "Specimen") const;

  /// A test record's specimen before anything is known: every length NaN. In the reduction a NaN
  /// initial crack means each record's first crack reading, a NaN length is not used.
  static Specimen unknown();
  /// The checks of a test record's geometry (analysis::reduce_record): throws InputError naming
  /// `where` when the width or the arm thickness is missing or not positive, or a given length,
  /// initial crack or pin distance is not positive.
  void check_test_geometry(const std::string& where) const;
};

struct Material {
  double E_L = 13.4e9;          ///< along the beam [Pa]
  double E_T = 0.050 * 13.4e9;  ///< normal to the crack plane [Pa]
  double G_LT = 0.078 * 13.4e9; ///< in-plane shear [Pa]
  double nu_LT = 0.449;         ///< major Poisson ratio (nu_TL = nu_LT E_T / E_L)
  bool plane_stress = true;     ///< else plane strain (out-of-plane constants then matter)
  double density = 530;         ///< [kg/m^3], Douglas-fir at 12 % MC (dynamic models only)
  /// Out-of-plane (radial, z) constants: plane strain and 3D only (USDA Wood Handbook,
  /// Douglas-fir: E_R/E_L = 0.068, nu_LR = 0.292, nu_RT = 0.390).
  double E_R_over_E_L = 0.068;
  double nu_LR = 0.292;
  double nu_RT = 0.390;
  void validate(const std::string& context = "Material") const;
  double nu_TL() const { return nu_LT * E_T / E_L; }
};

/// In-plane compliance (x = L along the beam, y = T across the crack plane) of the 2D models,
/// eps = S sigma with eps_xx = s11 sig_xx + s12 sig_yy: plane stress, or plane strain
/// (eps_zz = 0, so s_ij - s_i3 s_j3 / s33 with the radial constants). Shared by the FEM and the
/// MPM so that both discretize the same continuum. Throws InputError when it is not positive
/// definite.
struct InPlaneCompliance {
  double s11 = 0, s22 = 0, s12 = 0;
};
InPlaneCompliance in_plane_compliance(const Material& m);
/// Its inverse, sigma = Q eps (reduced stiffness: sig_xx = q11 eps_xx + q12 eps_yy; the shear
/// modulus G_LT is unaffected by the reduction).
struct InPlaneStiffness {
  double q11 = 0, q22 = 0, q12 = 0;
};
InPlaneStiffness in_plane_stiffness(const Material& m);

/// Corrected-beam-theory length correction chi (docs/design.md section 3, "Reference formulas";
/// Hashemi, Kinloch, Williams 1990): a -> a + chi h,
/// chi = sqrt((E11/(11 G13)) (3 - 2 (Gamma/(1+Gamma))^2)), Gamma = 1.18 sqrt(E11 E22)/G13,
/// with E11 = E_L, E22 = E_T, G13 = G_LT.
double cbt_chi(const Material& m);

/// LEFM DCB under displacement control with G = J_tip (plane stress, E = E_L): load for the whole
/// width at crack length a (from the load line), corrected beam theory.
double cbt_load_at_crack_length(const Specimen& s, const Material& m, double j_tip, double a);
/// Total load-point opening for load P at crack length a, corrected beam theory.
double cbt_opening(const Specimen& s, const Material& m, double load, double a);

} // namespace fiberbridge::specimen
