#pragma once
// The equivalent crack length of the compliance-based beam method (CBBM; de Moura, Morais,
// Dourado, Eng. Fract. Mech. 75 (2008) 3852): R(a) from load and opening alone, for records
// without crack readings (docs/design.md section 6, "R without crack readings").
#include "fiberbridge/analysis/test_record.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

/// Timoshenko arms: C(a) = alpha a^3 + beta a, alpha = 8/(E_f B h^3), beta = 12/(5 B h G13),
/// with a measured from the load line plus the root-rotation correction |Delta|.
struct CbbmBeam {
  double width = NAN, arm_thickness = NAN; ///< B, h of one arm [m]
  double shear_modulus = NAN;              ///< G13 [Pa]; NaN or inf: no shear term (beta = 0)
  double flexural_modulus = NAN;           ///< E_f [Pa]
  double delta = 0;                        ///< |Delta| [m]

  double alpha() const;
  double beta() const;
  /// C at the effective crack length a_e = a + |Delta| [m/N].
  double compliance(double a_e) const;
  /// The one real root a_e of alpha a^3 + beta a - C = 0 (Cardano; alpha, beta >= 0 make the
  /// cubic monotone, so the root is unique) [m].
  double effective_crack(double compliance) const;
  /// G = 6 P^2/(B^2 h) (2 a_e^2/(E_f h^2) + 1/(5 G13)) = P^2/(2B) dC/da [J/m^2].
  double energy_release_rate(double load, double a_e) const;
};

/// E_f from the initial compliance C0 at a0 + |Delta| (CBBM): the flexural modulus for which
/// CbbmBeam::compliance(a0 + |Delta|) = C0. Throws InputError naming `where` when the shear term
/// alone exceeds C0 (G13 too small for this specimen's compliance).
double cbbm_flexural_modulus(double width, double arm_thickness, double shear_modulus, double delta,
                             double a0, double c0, const std::string& where);

/// |Delta| = chi h of corrected beam theory (Hashemi, Kinloch, Williams 1990; the formula of
/// specimen::cbt_chi, which analysis cannot link): chi = sqrt(E11/(11 G13) (3 - 2 (G/(1+G))^2)),
/// G = 1.18 sqrt(E11 E22)/G13 [m].
double corrected_beam_delta(double e11, double e22, double g13, double arm_thickness);

/// The initial linear part of a record: opening against load over the rows before the load first
/// reaches `high` x its peak whose load is at least `low` x the peak, least squares with an
/// intercept (which takes up a zero offset or toe of the opening).
struct InitialCompliance {
  double compliance = NAN; ///< slope [m/N]
  double offset = NAN;     ///< opening at zero load [m]
  std::size_t rows = 0;    ///< rows fitted
  std::size_t end = 0;     ///< first row past the fitted part
};
/// Throws InputError naming the record when fewer than 3 rows qualify or the slope is not > 0.
InitialCompliance initial_linear_part(const TestRecord& record, double low = 0.1,
                                      double high = 0.5);

} // namespace fiberbridge::analysis
