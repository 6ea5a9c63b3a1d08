#include "fiberbridge/fem/dcb_common.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace fiberbridge::fem {

using namespace dealii;

std::string fmt(double v, int precision) {
  std::ostringstream s;
  s << std::setprecision(precision) << v;
  return s.str();
}

template <>
SymmetricTensor<4, 2> orthotropic_stiffness<2>(const law::Material& m,
                                               const FemParameters& /* 3D shear moduli only */) {
  constexpr int dim = 2;
  const auto [q11, q22, q12] = law::in_plane_stiffness(m);
  SymmetricTensor<4, dim> C;
  C[0][0][0][0] = q11;
  C[1][1][1][1] = q22;
  C[0][0][1][1] = q12;
  C[1][1][0][0] = q12;
  C[0][1][0][1] = m.G_LT; // sigma_xy = 2 C_0101 eps_xy = G_LT gamma_xy
  return C;
}

template <>
SymmetricTensor<4, 3> orthotropic_stiffness<3>(const law::Material& m, const FemParameters& p) {
  // Normal compliance in the material axes (L, T, R) = (x, y, z), the same constants and
  // conventions as the plane-strain reduction above (s23 = -nu_RT / E_R), so a thin 3D plate
  // (sigma_zz = 0) is the 2D plane-stress model and a fully restrained one the plane-strain one.
  const double E_R = m.E_R_over_E_L * m.E_L;
  FullMatrix<double> S(3, 3), C(3, 3);
  S(0, 0) = 1 / m.E_L;
  S(1, 1) = 1 / m.E_T;
  S(2, 2) = 1 / E_R;
  S(0, 1) = S(1, 0) = -m.nu_LT / m.E_L;
  S(0, 2) = S(2, 0) = -m.nu_LR / m.E_L;
  S(1, 2) = S(2, 1) = -m.nu_RT / E_R;
  // Positive definite iff the leading minors are positive.
  const double m2 = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
  const double m3 = S(0, 0) * (S(1, 1) * S(2, 2) - S(1, 2) * S(2, 1)) -
                    S(0, 1) * (S(1, 0) * S(2, 2) - S(1, 2) * S(2, 0)) +
                    S(0, 2) * (S(1, 0) * S(2, 1) - S(1, 1) * S(2, 0));
  if (!(m2 > 0 && m3 > 0) || !(p.G_LR_over_E_L > 0 && p.G_RT_over_E_L > 0))
    throw InputError("Material/FEM: the 3D orthotropic compliance is not positive definite; "
                     "check nu_LT, nu_LR, nu_RT, E_R over E_L, G_LR over E_L, G_RT over E_L");
  C.invert(S);
  SymmetricTensor<4, 3> T;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j)
      T[i][i][j][j] = C(i, j);
  T[0][1][0][1] = m.G_LT;
  T[0][2][0][2] = p.G_LR_over_E_L * m.E_L;
  T[1][2][1][2] = p.G_RT_over_E_L * m.E_L;
  return T;
}

const law::TractionLaw* insertable_law(const law::TractionLaw& law, const law::Material& material,
                                       const FemParameters& p,
                                       std::unique_ptr<law::ElasticRiseLaw>& holder,
                                       std::vector<std::string>& notes) {
  if (!(law.critical_opening() > 0 && law.rigid_at_zero_opening()))
    return &law;
  const double delta_e = law::ElasticRiseLaw::rise_end_for_slope(
      law, p.rigid_law_stiffness_factor * material.E_T / p.element_size);
  const auto kinks = law.kinks();
  const double first = kinks.size() > 1 ? kinks[1] : law.critical_opening();
  if (!(delta_e > 0 && delta_e < 0.5 * first))
    throw InputError("FEM/Rigid law stiffness factor: the elastic rise of the " + law.name() +
                     " law would reach " + fmt(delta_e / units::mm) +
                     " mm, not small against its first kink; raise the factor");
  holder = std::make_unique<law::ElasticRiseLaw>(law, delta_e);
  notes.push_back("rigid " + law.name() + " law regularized with an elastic rise to " +
                  fmt(holder->delta_e() / units::mm) + " mm (area " +
                  fmt(100 * (holder->area() / law.area() - 1), 3) + " %)");
  return holder.get();
}

DcbMeshLines dcb_mesh_lines(const law::Specimen& specimen, const FemParameters& p) {
  const double L = specimen.length, a0 = specimen.initial_crack;
  const double h = specimen.arm_thickness();
  DcbMeshLines m;
  // Uniform elements along x with a mesh line at a0, so that every advance is one element.
  const unsigned n_a0 = std::max(1u, unsigned(std::lround(a0 / p.element_size)));
  m.dx = a0 / n_a0;
  if (n_a0 < std::max(5u, p.tip_domain_elements + 1))
    throw InputError("Specimen/Initial crack: the notch must span at least " +
                     std::to_string(std::max(5u, p.tip_domain_elements + 1)) +
                     " elements (the far-field J domain lies between load line and notch tip); "
                     "reduce FEM/Element size");
  const unsigned n_x = std::max(n_a0 + 1, unsigned(std::floor(L / m.dx + 1e-9)));
  for (unsigned i = 0; i <= n_x; ++i)
    m.x.push_back(std::min(L, i * m.dx));
  if (L - m.x.back() > 0.5 * m.dx)
    m.x.push_back(L);
  else
    m.x.back() = L;

  // Heights: the first layer at the crack plane is min(dx, h / min_layers), so that every arm
  // gets at least min_layers layers (an arm thinner than min_layers elements gets uniform layers
  // of h / min_layers), graded towards the face and capped at h / min_layers. The crack-plane
  // elements are then dx / y1 = max(1, min_layers dx / h) times longer than high; above
  // kMaxCrackPlaneAspect the element length is not tied to the arm any more: refused.
  const double cap = h / p.min_layers;
  double size = std::min(m.dx, cap);
  m.first_layer = size;
  if (m.dx > kMaxCrackPlaneAspect * size * (1 + 1e-9))
    throw InputError(
        "FEM/Element size: " + fmt(m.dx / units::mm) + " mm elements on arms " +
        fmt(h / units::mm) +
        " mm thick with Minimum layers per arm = " + std::to_string(p.min_layers) + " would be " +
        fmt(m.dx / size, 3) + " times longer than high at the crack plane (bound " +
        fmt(kMaxCrackPlaneAspect) + "); set FEM/Element size to at most " +
        fmt(kMaxCrackPlaneAspect * size / units::mm) + " mm or lower FEM/Minimum layers per arm");
  m.y = {0.0};
  while (m.y.back() + size < h - 1e-12 * h) {
    m.y.push_back(m.y.back() + size);
    size = std::min(size * p.grading, cap);
  }
  const double rest = h - m.y.back();
  if (rest < 0.5 * size && m.y.size() > 1)
    m.y.back() = h;
  else
    m.y.push_back(h);
  return m;
}

double q1_bending_indicator(const law::Material& material, double element_length,
                            double arm_thickness) {
  const double r = element_length / arm_thickness;
  return material.G_LT / material.E_L * r * r;
}

unsigned resolve_degree(const law::Specimen& specimen, const law::Material& material,
                        const FemParameters& p, std::vector<std::string>& notes) {
  const double h = specimen.arm_thickness();
  const double indicator = q1_bending_indicator(material, p.element_size, h);
  if (p.degree == 0) {
    const unsigned degree = indicator > kQ1BendingBound ? 2 : 1;
    if (degree == 2)
      notes.push_back("FEM/Polynomial degree = auto chose Q2: Q1 elements " +
                      fmt(p.element_size / units::mm) + " mm long on arms " + fmt(h / units::mm) +
                      " mm thick would bend too stiffly (parasitic shear " +
                      "(G_LT/E_L)(element/arm)^2 = " + fmt(indicator, 3) + " > " +
                      fmt(kQ1BendingBound) + ")");
    return degree;
  }
  if (p.degree == 1 && indicator > kQ1BendingBound)
    notes.push_back(
        "resolution: Q1 elements " + fmt(p.element_size / units::mm) + " mm long on arms " +
        fmt(h / units::mm) +
        " mm thick bend too stiffly (parasitic shear (G_LT/E_L)(element/arm)^2 = " +
        fmt(indicator, 3) + " > " + fmt(kQ1BendingBound) + ", a load about " +
        fmt(100 * kQ1LoadErrorPerIndicator * indicator, 2) +
        " % high at fixed J); set FEM/Polynomial degree = auto or 2, or FEM/Element "
        "size to at most " +
        fmt(h * std::sqrt(kQ1BendingBound * material.E_L / material.G_LT) / units::mm, 3) + " mm");
  return p.degree;
}

double note_small_strain_bound(law::SimulationResult& result) {
  double worst = 0, worst_a = 0;
  for (const auto& pt : result.rcurve)
    if (pt.a > 0 && pt.load_point_opening / pt.a > worst) {
      worst = pt.load_point_opening / pt.a;
      worst_a = pt.a;
    }
  const double error = kSmallRotationLoadError * worst * worst;
  if (error > kSmallRotationBound)
    result.notes.push_back(
        "small strain: at a = " + fmt(worst_a / units::mm) + " mm the load-point opening is " +
        fmt(worst, 3) +
        " of the crack length, where small-rotation kinematics put the load about " +
        fmt(100 * error, 2) +
        " % low (the beam model's elastica comparison, 0.13 (opening/a)^2), "
        "past the 1 % bound; the FEM has small-strain kinematics only: run the beam model with "
        "Beam/Kinematics = finite for this range");
  return worst;
}

bool check_steady_state(law::SimulationResult& result, const std::vector<double>& dissipated,
                        double first_root_move, const FemParameters& p) {
  const auto& rc = result.rcurve;
  const auto& pt = rc.back();
  if (pt.a - first_root_move < p.steady_state_window)
    return false;
  double lo = pt.R_J, hi = pt.R_J;
  std::size_t i0 = rc.size() - 1;
  while (i0 > 0 && pt.a - rc[i0 - 1].a <= p.steady_state_window * (1 + 1e-9)) {
    --i0;
    lo = std::min(lo, rc[i0].R_J);
    hi = std::max(hi, rc[i0].R_J);
  }
  if (hi - lo > p.plateau_tolerance * std::abs(pt.R_J))
    return false;
  result.reached_steady_state = true;
  // G_ss from R_J: every record is a state with tip J = J_tip. R_energy over the same window
  // carries the sawtooth of discrete advances (each release happens at fixed opening; in the
  // LEFM limit the energy per advance is J_tip (1 - 2 da/(a + chi h))) and the discreteness of
  // the root failures; it is reported beside.
  double sum = 0;
  for (std::size_t i = i0; i < rc.size(); ++i)
    sum += rc[i].R_J;
  result.G_ss = sum / double(rc.size() - i0);
  const double g_energy = (dissipated.back() - dissipated[i0]) / (pt.a - rc[i0].a);
  result.notes.push_back("steady state at a = " + fmt(pt.a / units::mm) + " mm: R_J spread " +
                         fmt(100 * (hi - lo) / pt.R_J, 3) + " % over the last " +
                         fmt((pt.a - rc[i0].a) / units::mm) +
                         " mm; G_ss = mean R_J there; R_energy over the window (dissipation "
                         "per growth) " +
                         fmt(g_energy) + " J/m^2");
  return true;
}

} // namespace fiberbridge::fem
