#include "fiberbridge/mpm/orthotropic_elastic.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::mpm {

OrthotropicElastic::OrthotropicElastic(const law::Material& m) {
  m.validate("Material");
  // Reduced in-plane stiffness (grain along x), the inverse of the compliance the FEM uses:
  // plane stress, or plane strain with the radial constants (sigma_zz does no work there).
  const law::InPlaneCompliance s = law::in_plane_compliance(m);
  const double det = s.s11 * s.s22 - s.s12 * s.s12;
  q11_ = s.s22 / det;
  q22_ = s.s11 / det;
  q12_ = -s.s12 / det;
  q66_ = m.G_LT;
  density_ = m.density;
}

double OrthotropicElastic::max_wave_speed() const {
  // Dilatational speeds along the axes bound the shear speed (Q66 < Q11 for wood) and the
  // off-axis speeds closely enough for a CFL factor below one.
  return std::sqrt(std::max(q11_, q22_) / density_);
}

} // namespace fiberbridge::mpm
