#include "fiberbridge/specimen/specimen.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <cmath>
#include <utility>

namespace fiberbridge::specimen {

Specimen Specimen::unknown() {
  Specimen s;
  s.length = s.width = s.height = s.initial_crack = NAN;
  return s;
}

void Specimen::check_test_geometry(const std::string& where_) const {
  if (std::isnan(width))
    throw InputError(where_ + ": the specimen width is missing; give Specimen/Width (mm) or "
                              "--width MM");
  if (std::isnan(height))
    throw InputError(where_ + ": the arm thickness is missing; give Specimen/Height (mm, both "
                              "arms) or --arm-thickness MM");
  const std::pair<const char*, double> values[] = {{"width", width},
                                                   {"arm thickness", arm_thickness()},
                                                   {"length", length},
                                                   {"initial crack", initial_crack},
                                                   {"pin to arm mid-plane", pin_to_arm_midplane},
                                                   {"pin to block edge", pin_to_block_edge}};
  for (const auto& [name, v] : values)
    if (!std::isnan(v) && !(v > 0))
      throw InputError(where_ + ": the specimen " + name + " is " + num(v / units::mm) +
                       " mm; expected a positive length");
}

void Specimen::validate(const std::string& c) const {
  if (!(length > 0 && width > 0 && height > 0 && initial_crack > 0))
    throw InputError(c + ": Length, Width, Height and Initial crack must be positive (mm)");
  if (!(initial_crack < length))
    throw InputError(c + "/Initial crack: must be shorter than Length");
}

void Material::validate(const std::string& c) const {
  if (!(E_L > 0 && E_T > 0 && G_LT > 0))
    throw InputError(c + ": E_L, E_T and G_LT must be positive (MPa)");
  // Positive-definite orthotropic compliance in the plane: 1 - nu_LT nu_TL > 0.
  if (!(nu_LT >= 0) || !(1 - nu_LT * nu_TL() > 0))
    throw InputError(c + "/nu_LT: must be >= 0 with nu_LT^2 E_T/E_L < 1");
  if (!(density > 0))
    throw InputError(c + "/Density: must be positive (kg/m^3)");
  if (!(E_R_over_E_L > 0))
    throw InputError(c + "/E_R over E_L: must be positive");
  if (!(nu_LR >= 0 && nu_RT >= 0))
    throw InputError(c + "/nu_LR, nu_RT: must be >= 0");
}

InPlaneCompliance in_plane_compliance(const Material& m) {
  InPlaneCompliance s;
  s.s11 = 1 / m.E_L;
  s.s22 = 1 / m.E_T;
  s.s12 = -m.nu_LT / m.E_L;
  if (!m.plane_stress) {
    const double E_R = m.E_R_over_E_L * m.E_L;
    const double s33 = 1 / E_R, s13 = -m.nu_LR / m.E_L, s23 = -m.nu_RT / E_R;
    s.s11 -= s13 * s13 / s33;
    s.s22 -= s23 * s23 / s33;
    s.s12 -= s13 * s23 / s33;
  }
  if (!(s.s11 > 0 && s.s22 > 0 && s.s11 * s.s22 - s.s12 * s.s12 > 0))
    throw InputError("Material: the in-plane orthotropic compliance is not positive definite; "
                     "check nu_LT" +
                     std::string(m.plane_stress ? "" : ", nu_LR, nu_RT and E_R over E_L"));
  return s;
}

InPlaneStiffness in_plane_stiffness(const Material& m) {
  const InPlaneCompliance s = in_plane_compliance(m);
  const double det = s.s11 * s.s22 - s.s12 * s.s12;
  return {s.s22 / det, s.s11 / det, -s.s12 / det};
}

double cbt_chi(const Material& m) {
  const double gamma = 1.18 * std::sqrt(m.E_L * m.E_T) / m.G_LT;
  const double g = gamma / (1 + gamma);
  return std::sqrt(m.E_L / (11 * m.G_LT) * (3 - 2 * g * g));
}

double cbt_load_at_crack_length(const Specimen& s, const Material& m, double j_tip, double a) {
  const double h = s.arm_thickness();
  const double B = s.width;
  return std::sqrt(j_tip * B * B * h * h * h * m.E_L / 12) / (a + cbt_chi(m) * h);
}

double cbt_opening(const Specimen& s, const Material& m, double load, double a) {
  const double h = s.arm_thickness();
  const double ae = a + cbt_chi(m) * h;
  return load * 8 * ae * ae * ae / (m.E_L * s.width * h * h * h);
}

} // namespace fiberbridge::specimen
