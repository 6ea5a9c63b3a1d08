#include "fiberbridge/fem/dcb_common.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/fem/auto_mesh.h"
#include "fiberbridge/law/rigid_law.h"

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>

namespace fiberbridge::fem {

using namespace dealii;

template <>
SymmetricTensor<4, 2> orthotropic_stiffness<2>(const specimen::Material& m,
                                               const FemParameters& /* 3D shear moduli only */) {
  constexpr int dim = 2;
  const auto [q11, q22, q12] = specimen::in_plane_stiffness(m);
  SymmetricTensor<4, dim> C;
  C[0][0][0][0] = q11;
  C[1][1][1][1] = q22;
  C[0][0][1][1] = q12;
  C[1][1][0][0] = q12;
  C[0][1][0][1] = m.G_LT; // sigma_xy = 2 C_0101 eps_xy = G_LT gamma_xy
  return C;
}

template <>
SymmetricTensor<4, 3> orthotropic_stiffness<3>(const specimen::Material& m,
                                               const FemParameters& p) {
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
  if (!(m2 > 0 && m3 > 0) ||
      !(p.elasticity_3d.G_LR_over_E_L > 0 && p.elasticity_3d.G_RT_over_E_L > 0))
    throw InputError("Material/FEM: the 3D orthotropic compliance is not positive definite; "
                     "check nu_LT, nu_LR, nu_RT, E_R over E_L, G_LR over E_L, G_RT over E_L");
  C.invert(S);
  SymmetricTensor<4, 3> T;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j)
      T[i][i][j][j] = C(i, j);
  T[0][1][0][1] = m.G_LT;
  T[0][2][0][2] = p.elasticity_3d.G_LR_over_E_L * m.E_L;
  T[1][2][1][2] = p.elasticity_3d.G_RT_over_E_L * m.E_L;
  return T;
}

double crack_plane_step(const specimen::Specimen& specimen, const FemParameters& p) {
  const double a0 = specimen.initial_crack;
  // auto: the law-free part of the choice (fem::choose_mesh gives the engine a number).
  const unsigned n_a0 = std::max(1u, unsigned(std::lround(a0 / element_length(specimen, p))));
  if (n_a0 < std::max(5u, p.j_domain.half_width_elements + 1))
    throw InputError("Specimen/Initial crack: the notch must span at least " +
                     std::to_string(std::max(5u, p.j_domain.half_width_elements + 1)) +
                     " elements (the far-field J domain lies between load line and notch tip); "
                     "reduce FEM/Element size");
  return a0 / n_a0;
}

DcbMeshLines dcb_mesh_lines(const specimen::Specimen& specimen, const FemParameters& p) {
  const double L = specimen.length;
  const double h = specimen.arm_thickness();
  DcbMeshLines m;
  // Uniform elements along x with a mesh line at a0, so that every advance is one element.
  m.dx = crack_plane_step(specimen, p);
  const unsigned n_a0 = unsigned(std::lround(specimen.initial_crack / m.dx));
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
  const double cap = h / p.mesh.min_layers;
  double size = std::min(m.dx, cap);
  m.first_layer = size;
  if (m.dx > kMaxCrackPlaneAspect * size * (1 + 1e-9))
    throw InputError(
        "FEM/Element size: " + fmt(m.dx / units::mm) + " mm elements on arms " +
        fmt(h / units::mm) +
        " mm thick with Minimum layers per arm = " + std::to_string(p.mesh.min_layers) +
        " would be " + fmt(m.dx / size, 3) + " times longer than high at the crack plane (bound " +
        fmt(kMaxCrackPlaneAspect) + "); set FEM/Element size to at most " +
        fmt(kMaxCrackPlaneAspect * size / units::mm) + " mm or lower FEM/Minimum layers per arm");
  m.y = {0.0};
  while (m.y.back() + size < h - 1e-12 * h) {
    m.y.push_back(m.y.back() + size);
    size = std::min(size * p.mesh.grading, cap);
  }
  const double rest = h - m.y.back();
  if (rest < 0.5 * size && m.y.size() > 1)
    m.y.back() = h;
  else
    m.y.push_back(h);
  return m;
}

double q1_bending_indicator(const specimen::Material& material, double element_length,
                            double arm_thickness) {
  const double r = element_length / arm_thickness;
  return material.G_LT / material.E_L * r * r;
}

unsigned resolve_degree(const specimen::Specimen& specimen, const specimen::Material& material,
                        const FemParameters& p, std::vector<std::string>& notes) {
  const double h = specimen.arm_thickness();
  const double size = element_length(specimen, p);
  const double indicator = q1_bending_indicator(material, size, h);
  if (p.mesh.degree == 0) {
    const unsigned degree = indicator > kQ1BendingBound ? 2 : 1;
    if (degree == 2)
      notes.push_back("FEM/Polynomial degree = auto chose Q2: Q1 elements " +
                      fmt(size / units::mm) + " mm long on arms " + fmt(h / units::mm) +
                      " mm thick would bend too stiffly (parasitic shear " +
                      "(G_LT/E_L)(element/arm)^2 = " + fmt(indicator, 3) + " > " +
                      fmt(kQ1BendingBound) + ")");
    return degree;
  }
  if (p.mesh.degree == 1 && indicator > kQ1BendingBound)
    notes.push_back(
        "resolution: Q1 elements " + fmt(size / units::mm) + " mm long on arms " +
        fmt(h / units::mm) +
        " mm thick bend too stiffly (parasitic shear (G_LT/E_L)(element/arm)^2 = " +
        fmt(indicator, 3) + " > " + fmt(kQ1BendingBound) + ", a load about " +
        fmt(100 * kQ1LoadErrorPerIndicator * indicator, 2) +
        " % high at fixed J); set FEM/Polynomial degree = auto or 2, or FEM/Element "
        "size to at most " +
        fmt(h * std::sqrt(kQ1BendingBound * material.E_L / material.G_LT) / units::mm, 3) + " mm");
  return p.mesh.degree;
}

double note_small_strain_bound(result::SimulationResult& result) {
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
        "past the 1 % bound; set FEM/Kinematics = finite for this range");
  return worst;
}

result::SteadyStateRule steady_state_rule(const FemParameters& p,
                                          const specimen::Specimen& specimen) {
  result::SteadyStateRule rule;
  rule.window = p.steady_state.window;
  rule.tolerance = p.steady_state.plateau_tolerance;
  rule.root_move = 1e-9 * specimen.length;
  return rule;
}

} // namespace fiberbridge::fem
