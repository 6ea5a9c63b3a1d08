// FEM/Element size = auto (auto_mesh.h; docs/design.md section 2, "The automatic mesh").
#include "fiberbridge/fem/auto_mesh.h"

#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_common.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::fem {

const double kAutoLargestElement = 2e-3;
// 0.5 mm on the seed specimen (300 mm). What finer elements cost on the strong short laws:
// docs/verification.md, "Strong short laws" and "The automatic mesh". A default run is not to
// take minutes: finer than this, the user says so.
const double kAutoMostElementsAlongLength = 600;
// The zone rule asks for kMinZoneSpacings = 3 elements. The smallest ratio of a measured,
// resolved zone to the estimate was 0.42 (10 MPa / 0.1 mm on the seed specimen: 2.78 mm at 0.5 mm
// elements against 6.56 mm; docs/verification.md, "The automatic mesh"): 3 / 0.42 = 7.1, so 8.
const double kAutoElementsPerZoneEstimate = 8;

namespace {
constexpr double mm = units::mm;

/// The largest a0 / n not above `size`: the mesh snaps the element to a0 / round(a0 / size)
/// (crack_plane_step), which may round up past a bound; auto snaps down instead, so the snapped
/// element keeps every bound it was chosen under.
double snap_down(const specimen::Specimen& specimen, double size) {
  const double a0 = specimen.initial_crack;
  return a0 / std::ceil(a0 / size * (1 - 1e-12));
}
} // namespace

double arm_element_size(const specimen::Specimen& specimen, const FemParameters& p) {
  const double h = specimen.arm_thickness(), a0 = specimen.initial_crack;
  const unsigned hw = p.j_domain.half_width_elements;
  double size = std::min(kAutoLargestElement, kMaxCrackPlaneAspect * h / p.mesh.min_layers);
  size = std::min(size, a0 / std::max(5u, hw + 1));
  const double ligament = specimen.length - a0 - h;
  if (ligament > 0 && hw > 0)
    size = std::min(size, ligament / hw);
  return snap_down(specimen, size);
}

double element_length(const specimen::Specimen& specimen, const FemParameters& p) {
  return p.mesh.automatic_size() ? arm_element_size(specimen, p) : p.mesh.element_size;
}

double crack_modulus(const specimen::Material& material) {
  const auto s = specimen::in_plane_compliance(material);
  const double s66 = 1 / material.G_LT;
  return 1 / (std::sqrt(s.s11 * s.s22 / 2) *
              std::sqrt(std::sqrt(s.s22 / s.s11) + (2 * s.s12 + s66) / (2 * s.s11)));
}

double estimated_zone_length(const specimen::Specimen& specimen, const specimen::Material& material,
                             const law::TractionLaw& law) {
  const double dc = law.critical_opening(), Gc = law.area();
  if (!(dc > 0) || !(Gc > 0))
    return 0;
  // The peak traction: at sigma(0+), a kink, or (a smooth law) anywhere; 256 samples find a
  // smooth peak to well within the factor-of-three scatter of the estimate itself.
  double peak = law.envelope(0);
  for (const double k : law.kinks())
    peak = std::max(peak, law.envelope(k));
  for (int i = 1; i < 256; ++i)
    peak = std::max(peak, law.envelope(dc * i / 256.0));
  if (!(peak > 0))
    return 0;
  const double r = Gc / (peak * peak);
  const double infinite_body = crack_modulus(material) * r;
  const double slender =
      std::pow(material.E_L * r, 0.25) * std::pow(specimen.arm_thickness(), 0.75);
  return std::min(infinite_body, slender);
}

MeshChoice choose_mesh(const specimen::Specimen& specimen, const specimen::Material& material,
                       const law::TractionLaw& law, const FemParameters& p) {
  MeshChoice c;
  c.automatic = p.mesh.automatic_size();
  c.arm_limit = arm_element_size(specimen, p);
  c.zone_estimate = estimated_zone_length(specimen, material, law);
  const double h = specimen.arm_thickness();
  if (!c.automatic) {
    c.element_size = p.mesh.element_size;
    c.reason = "given (FEM/Element size = " + fmt(c.element_size / mm) + " mm)";
  } else {
    c.element_size = c.arm_limit;
    if (c.arm_limit < kAutoLargestElement * (1 - 1e-12))
      c.reason = "auto: the arm (" + fmt(h / mm) + " mm thick, " +
                 std::to_string(p.mesh.min_layers) + " layers, crack-plane elements at most " +
                 fmt(kMaxCrackPlaneAspect) +
                 " times longer than high), the notch and the ligament admit " +
                 fmt(c.arm_limit / mm, 3) + " mm";
    else
      c.reason = "auto: the largest auto element, " + fmt(kAutoLargestElement / mm) +
                 " mm (the verified default of the seed figures)";
    if (c.zone_estimate > 0) {
      const double for_zone = c.zone_estimate / kAutoElementsPerZoneEstimate;
      const double floor = specimen.length / kAutoMostElementsAlongLength;
      if (for_zone < c.element_size) {
        c.element_size = snap_down(specimen, std::max(for_zone, floor));
        c.reason = "auto: the estimated cohesive zone, " + fmt(c.zone_estimate / mm, 3) +
                   " mm (the smaller of E' G_c/sigma_max^2 and (E_L G_c/sigma_max^2)^(1/4) "
                   "h^(3/4)), over " +
                   fmt(kAutoElementsPerZoneEstimate) + " elements";
        if (for_zone < floor)
          c.reason += ", held at the cost floor Length/" + fmt(kAutoMostElementsAlongLength) +
                      " = " + fmt(floor / mm, 3) +
                      " mm (the zone may stay unresolved: the run says so)";
      } else {
        c.reason += "; the estimated cohesive zone, " + fmt(c.zone_estimate / mm, 3) +
                    " mm, spans " + fmt(c.zone_estimate / c.element_size, 3) + " of them";
      }
    }
  }
  if (p.mesh.file.empty()) {
    const FemParameters chosen = with_mesh(p, c);
    c.layers_per_arm = unsigned(dcb_mesh_lines(specimen, chosen).y.size() - 1);
  }
  return c;
}

FemParameters with_mesh(const FemParameters& parameters, const MeshChoice& choice) {
  FemParameters p = parameters;
  p.mesh.element_size = choice.element_size;
  return p;
}

} // namespace fiberbridge::fem
