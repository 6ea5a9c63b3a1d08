#include "fiberbridge/mpm/orthotropic_elastic.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::mpm {

OrthotropicElastic::OrthotropicElastic(const law::Material& m) {
  m.validate("Material");
  if (!m.plane_stress)
    throw InputError("Material/Plane: the MPM model supports plane stress only; plane strain "
                     "needs the out-of-plane constants (E_R, nu_LR, nu_TR) that the Material "
                     "section does not define");
  // Plane-stress reduced stiffness of an orthotropic lamina (grain along x).
  const double d = 1 - m.nu_LT * m.nu_TL();
  q11_ = m.E_L / d;
  q22_ = m.E_T / d;
  q12_ = m.nu_LT * m.E_T / d;
  q66_ = m.G_LT;
  density_ = m.density;
}

double OrthotropicElastic::max_wave_speed() const {
  // Dilatational speeds along the axes bound the shear speed (Q66 < Q11 for wood) and the
  // off-axis speeds closely enough for a CFL factor below one.
  return std::sqrt(std::max(q11_, q22_) / density_);
}

} // namespace fiberbridge::mpm
