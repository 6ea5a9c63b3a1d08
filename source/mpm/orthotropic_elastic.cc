#include "fiberbridge/mpm/orthotropic_elastic.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::mpm {

OrthotropicElastic::OrthotropicElastic(const specimen::Material& m) {
  m.validate("Material");
  // Reduced in-plane stiffness (grain along x), the inverse of the compliance the FEM uses:
  // plane stress, or plane strain with the radial constants (sigma_zz does no work there).
  const specimen::InPlaneStiffness q = specimen::in_plane_stiffness(m);
  q11_ = q.q11;
  q22_ = q.q22;
  q12_ = q.q12;
  q66_ = m.G_LT;
  density_ = m.density;
}

double OrthotropicElastic::max_wave_speed() const {
  // Dilatational speeds along the axes bound the shear speed (Q66 < Q11 for wood) and the
  // off-axis speeds closely enough for a CFL factor below one.
  return std::sqrt(std::max(q11_, q22_) / density_);
}

} // namespace fiberbridge::mpm
