#pragma once
// Orthotropic linear elasticity in the L-T plane (grain along x), in the material frame. Large
// rotations are handled by the caller (corotational: strain = U - I of F = R U, stress rotated
// by R), so the arms can swing open without spurious rotational strain.
#include "fiberbridge/specimen/specimen.h"

namespace fiberbridge::mpm {

class OrthotropicElastic {
public:
  /// Plane stress or plane strain (specimen::in_plane_stiffness); a compliance that is not positive
  /// definite throws InputError.
  explicit OrthotropicElastic(const specimen::Material& m);

  /// Stress (xx, yy, xy) from strain (xx, yy, xy) with the tensor shear strain eps_xy.
  void stress(const double eps[3], double sig[3]) const {
    sig[0] = q11_ * eps[0] + q12_ * eps[1];
    sig[1] = q12_ * eps[0] + q22_ * eps[1];
    sig[2] = 2 * q66_ * eps[2];
  }
  /// Strain energy density 0.5 eps : C : eps [J/m^3].
  double energy_density(const double eps[3]) const {
    double s[3];
    stress(eps, s);
    return 0.5 * (s[0] * eps[0] + s[1] * eps[1] + 2 * s[2] * eps[2]);
  }
  /// Largest dilatational wave speed sqrt(max(Q11, Q22)/rho) [m/s]: sets the CFL time step.
  double max_wave_speed() const;
  double density() const { return density_; }

private:
  double q11_, q12_, q22_, q66_, density_;
};

} // namespace fiberbridge::mpm
