// FEM/Element size = auto (auto_mesh.h; docs/design.md section 2, "The automatic mesh").
#include "fiberbridge/fem/auto_mesh.h"

#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/dcb_common.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fiberbridge::fem {

const double kAutoLargestElement = 2e-3;
// The cost bound of a default run. The model time grows with the dofs and with the advances
// (one per element): on the seed specimen the 20 MPa / 0.05 mm law took 5.1 s at 0.5 mm (24040
// dofs) and 31 s at 0.25 mm (62452 dofs) on one core of the 2-core machine (docs/verification.md,
// "The automatic mesh: the tip's share and finer where the zone needs it"). A default run is not
// to take much more than half a minute: finer than this, the user says so.
const double kAutoMostDofs = 65000;
// The zone rule asks for kMinZoneSpacings = 3 elements. Resolved zones measured over the estimate
// with the tip's share (estimated_zone_length): 0.66 and 0.88 (10 MPa / 0.1 mm, seed and
// composite), 0.75 (20 MPa / 0.05 mm, seed) and 0.54 (30 MPa / 0.02 mm, composite): 3 / 0.54 =
// 5.6, so 6 (docs/verification.md, "The automatic mesh: the tip's share and finer where the zone
// needs it"; without the tip's share the smallest ratio was 0.42 and this was 8).
const double kAutoElementsPerZoneEstimate = 6;

namespace {
constexpr double mm = units::mm;

/// The largest a0 / n not above `size`: the mesh snaps the element to a0 / round(a0 / size)
/// (crack_plane_step), which may round up past a bound; auto snaps down instead, so the snapped
/// element keeps every bound it was chosen under.
double snap_down(const specimen::Specimen& specimen, double size) {
  const double a0 = specimen.initial_crack;
  return a0 / std::ceil(a0 / size * (1 - 1e-12));
}

/// The finest a0 / n from `coarse` down to `wanted` (both a0 / n already) whose mesh stays within
/// kAutoMostDofs. The dofs grow with n (more columns, and more
/// layers as the first layer follows the element): bisection on n.
double finest_within_cost(const specimen::Specimen& specimen, const specimen::Material& material,
                          const FemParameters& p, double coarse, double wanted) {
  const double a0 = specimen.initial_crack;
  unsigned lo = unsigned(std::lround(a0 / coarse)), hi = unsigned(std::lround(a0 / wanted));
  if (estimated_dofs(specimen, material, p, wanted) <= kAutoMostDofs)
    return wanted;
  if (estimated_dofs(specimen, material, p, coarse) > kAutoMostDofs)
    return coarse;      // the arm's own limit already costs more: it is not coarsened past it
  while (hi - lo > 1) { // dofs(a0 / lo) within the bound, dofs(a0 / hi) not
    const unsigned mid = lo + (hi - lo) / 2;
    (estimated_dofs(specimen, material, p, a0 / mid) <= kAutoMostDofs ? lo : hi) = mid;
  }
  return a0 / lo;
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

namespace {
/// The law's peak traction [Pa].
double law_peak_traction(const law::TractionLaw& law) {
  // At sigma(0+), a kink, or (a smooth law) anywhere; 256 samples find a smooth peak to well
  // within the scatter of the zone estimate itself.
  const double dc = law.critical_opening();
  double peak = law.envelope(0);
  for (const double k : law.kinks())
    peak = std::max(peak, law.envelope(k));
  for (int i = 1; i < 256; ++i)
    peak = std::max(peak, law.envelope(dc * i / 256.0));
  return peak;
}

} // namespace

double bridging_zone_length(const specimen::Specimen& specimen, const specimen::Material& material,
                            const law::TractionLaw& law) {
  const double dc = law.critical_opening(), Gc = law.area();
  if (!(dc > 0) || !(Gc > 0))
    return 0;
  const double peak = law_peak_traction(law);
  if (!(peak > 0))
    return 0;
  const double r = Gc / (peak * peak);
  const double infinite_body = crack_modulus(material) * r;
  const double slender =
      std::pow(material.E_L * r, 0.25) * std::pow(specimen.arm_thickness(), 0.75);
  return std::min(infinite_body, slender);
}

double tip_opening_length(const specimen::Specimen& specimen, const specimen::Material& material,
                          double critical_opening, double j_tip) {
  if (!(critical_opening > 0))
    return 0;
  if (!(j_tip > 0))
    return std::numeric_limits<double>::infinity();
  // Near the tip (K = sqrt(E' J_tip)) the crack opens as delta(r) = sqrt(32 J_tip r / (pi E'))
  // (the two faces of the K_I field); behind a slender arm's tip each arm bends with curvature
  // kappa = sqrt(12 J_tip / (E_L h^3)) (J = 12 M^2 / (E_L h^3) per unit width), delta = kappa r^2.
  const double dc = critical_opening, h = specimen.arm_thickness();
  const double k_field = M_PI * crack_modulus(material) * dc * dc / (32 * j_tip);
  const double kappa = std::sqrt(12 * j_tip / (material.E_L * h * h * h));
  const double slender = std::sqrt(dc / kappa);
  return std::min(k_field, slender);
}

double estimated_zone_length(const specimen::Specimen& specimen, const specimen::Material& material,
                             const law::TractionLaw& law, double j_tip) {
  const double bridging = bridging_zone_length(specimen, material, law);
  if (!(bridging > 0))
    return 0;
  const double tip = tip_opening_length(specimen, material, law.critical_opening(), j_tip);
  // Both shorten the zone: its end opens to delta_c under the bridging's own closure (bridging
  // alone: the Hillerborg length) and under the tip's opening (J_tip alone, a law too weak to
  // matter: the tip's length). The harmonic mean of the two limits is the closed form between
  // them, an interpolation checked against measured zones (docs/verification.md, "The automatic
  // mesh: the tip's share"), not a solution.
  return 1 / (1 / bridging + 1 / tip);
}

double estimated_dofs(const specimen::Specimen& specimen, const specimen::Material& material,
                      const FemParameters& p, double element_size) {
  FemParameters sized = p;
  sized.mesh.element_size = element_size;
  const DcbMeshLines lines = dcb_mesh_lines(specimen, sized);
  std::vector<std::string> notes;
  const double q = resolve_degree(specimen, material, sized, notes);
  const double nx = double(lines.x.size() - 1), ny = double(lines.y.size() - 1);
  double nodes = (q * nx + 1) * (q * ny + 1); // per arm, one layer in z
  if (p.mesh.dimension == 3) {
    const double nz = p.mesh.width_elements > 0
                          ? p.mesh.width_elements
                          : std::max(1.0, std::round(specimen.width / lines.dx));
    nodes *= q * nz + 1;
  }
  return 2 * nodes * p.mesh.dimension; // both arms, one dof per component
}

MeshChoice choose_mesh(const specimen::Specimen& specimen, const specimen::Material& material,
                       const law::TractionLaw& law, double j_tip, const FemParameters& p) {
  MeshChoice c;
  c.automatic = p.mesh.automatic_size();
  c.arm_limit = arm_element_size(specimen, p);
  c.zone_estimate = estimated_zone_length(specimen, material, law, j_tip);
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
      if (for_zone < c.element_size) {
        const double wanted = snap_down(specimen, for_zone);
        c.element_size = finest_within_cost(specimen, material, p, c.element_size, wanted);
        c.reason = "auto: the estimated cohesive zone, " + fmt(c.zone_estimate / mm, 3) +
                   " mm (the law's own length, the smaller of E' G_c/sigma_max^2 and "
                   "(E_L G_c/sigma_max^2)^(1/4) h^(3/4), shortened by the tip's opening under "
                   "J_tip), over " +
                   fmt(kAutoElementsPerZoneEstimate) + " elements";
        if (c.element_size > wanted * (1 + 1e-12))
          c.reason += ", held at " + fmt(c.element_size / mm, 3) + " mm by the cost bound of " +
                      std::to_string(std::lround(kAutoMostDofs)) + " dofs (" + fmt(wanted / mm, 3) +
                      " mm would need " +
                      std::to_string(std::lround(estimated_dofs(specimen, material, p, wanted))) +
                      "; the zone may stay unresolved: the run says so)";
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
