#pragma once
// One DCB arm as a Timoshenko beam whose intact ligament rests on a Winkler foundation (Kanninen's
// augmented DCB, with shear): the closed-form pieces the beam model is built from and checked
// against. SI units; "per arm" quantities are for one arm of the whole specimen width B.
//
// Conventions (used throughout the beam library): x runs from the load line into the specimen,
// w is the deflection of one arm away from the crack plane (the opening is delta = 2 w), theta is
// the section rotation (theta = w' without shear). Section resultants follow the Lagrangian
// e = EI theta'^2/2 + S (w' - theta)^2/2 + interface energy: M = EI theta', Q = S (w' - theta),
// with M' + Q = 0 in an unloaded span.
#include "fiberbridge/specimen/specimen.h"

namespace fiberbridge::beam {

/// Section and foundation constants of one arm.
struct ArmConstants {
  double EI = 0;        ///< bending stiffness of one arm, E B h^3/12 [N m^2]
  double S = 0;         ///< shear stiffness of one arm, kappa G_LT B h [N]
  double width = 0;     ///< B [m]
  double thickness = 0; ///< h, one arm [m]
  /// Foundation modulus k on the opening: traction = k delta ahead of the tip [Pa/m]. One arm
  /// sees k_w = 2 k B per unit length on its own deflection w (the traction acts on w = delta/2).
  double foundation_modulus = 0;
  double k_w() const { return 2 * foundation_modulus * width; }
};

/// Bending modulus used for the arms: E_L in plane stress, E_L/(1 - nu_LT nu_TL) in plane strain.
double arm_bending_modulus(const specimen::Material& m);

/// EI and S of one arm for `kappa` (5/6 for a rectangular section) and foundation modulus k.
ArmConstants arm_constants(const specimen::Specimen& s, const specimen::Material& m, double kappa,
                           double foundation_modulus);

/// End flexibilities of a semi-infinite Timoshenko beam on a Winkler foundation loaded at its
/// left end x = 0 by the section resultants M(0) = M0 and Q(0) = Q0 (conventions above):
/// w(0) = w_M M0 + w_Q Q0, theta(0) = t_M M0 + t_Q Q0. Exact solution of
/// EI theta'' + S (w' - theta) = 0, S (w' - theta)' = k_w w with decaying exponentials.
struct EndFlexibility {
  double w_M = 0, w_Q = 0, t_M = 0, t_Q = 0;
};
EndFlexibility semi_infinite_end_flexibility(const ArmConstants& arm);

/// Root-rotation length c = EI |theta(0)/M0| (Q0 = 0): the crack-length correction that the
/// foundation adds to beam theory, a -> a + c in the a^2 term of the compliance. For an Euler
/// beam on k_w this is 1/lambda, lambda^4 = k_w/(4 EI) (Kanninen 1973).
double root_rotation_length(const ArmConstants& arm);

/// The foundation modulus k [Pa/m on the opening] for which the Timoshenko arm on its foundation
/// has the root rotation of corrected beam theory, c = chi h (specimen::cbt_chi): then the model's
/// compliance matches CBT's 8 (a + chi h)^3/(E B h^3) in its a^3 and a^2 terms. Throws InputError
/// when no foundation can do it (chi h <= sqrt(EI/S), the rotation a rigid foundation already
/// gives through shear alone).
double calibrated_foundation_modulus(const specimen::Specimen& s, const specimen::Material& m,
                                     double kappa);

/// LEFM limit of the beam model in closed form (semi-infinite ligament): the tip releases
/// G = k delta_tip^2/2 (the foundation energy per area at the tip), so at G = J_tip the tip
/// deflection is delta_0/2 with delta_0 = sqrt(2 J_tip/k). Returns the load for the whole width
/// and the total load-point opening at crack length a (from the load line).
struct LefmState {
  double load = 0;               ///< [N]
  double load_point_opening = 0; ///< total, both arms [m]
};
LefmState lefm_state(const ArmConstants& arm, double j_tip, double a);

} // namespace fiberbridge::beam
