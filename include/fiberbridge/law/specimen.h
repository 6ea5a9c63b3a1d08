#pragma once
// The DCB specimen and its orthotropic material as plain structs shared by fem, mpm and beam.
// Defaults: the seed's specimen (section 2.2) and coast Douglas-fir at 12 % MC (USDA Wood Handbook,
// Ch. 5: E_L = 13.4 GPa, E_T/E_L = 0.050, G_LT/E_L = 0.078, nu_LT = 0.449).
#include <string>

namespace fiberbridge::law {

struct Specimen {
  double length = 0.300;        ///< beam length along the grain [m]
  double width = 0.035;         ///< B, out of plane [m]
  double height = 0.035;        ///< both arms together, 2h [m]
  double initial_crack = 0.100; ///< a0, measured from the load line [m]
  double arm_thickness() const { return 0.5 * height; }
  void validate(const std::string& context = "Specimen") const;
};

struct Material {
  double E_L = 13.4e9;          ///< along the beam [Pa]
  double E_T = 0.050 * 13.4e9;  ///< normal to the crack plane [Pa]
  double G_LT = 0.078 * 13.4e9; ///< in-plane shear [Pa]
  double nu_LT = 0.449;         ///< major Poisson ratio (nu_TL = nu_LT E_T / E_L)
  bool plane_stress = true;     ///< else plane strain (out-of-plane constants then matter)
  double density = 530;         ///< [kg/m^3], Douglas-fir at 12 % MC (dynamic models only)
  void validate(const std::string& context = "Material") const;
  double nu_TL() const { return nu_LT * E_T / E_L; }
};

/// Corrected-beam-theory length correction chi (notes/verification.md; Hashemi, Kinloch, Williams
/// 1990): a -> a + chi h, chi = sqrt((E11/(11 G13)) (3 - 2 (Gamma/(1+Gamma))^2)),
/// Gamma = 1.18 sqrt(E11 E22)/G13, with E11 = E_L, E22 = E_T, G13 = G_LT.
double cbt_chi(const Material& m);

/// LEFM DCB under displacement control with G = J_tip (plane stress, E = E_L): load for the whole
/// width at crack length a (from the load line), corrected beam theory.
double cbt_load_at_crack_length(const Specimen& s, const Material& m, double j_tip, double a);
/// Total load-point opening for load P at crack length a, corrected beam theory.
double cbt_opening(const Specimen& s, const Material& m, double load, double a);

} // namespace fiberbridge::law
