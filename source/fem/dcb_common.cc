#include "fiberbridge/fem/dcb_common.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <deal.II/lac/full_matrix.h>

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
SymmetricTensor<4, 2> orthotropic_stiffness<2>(const law::Material& m, const FemParameters& p) {
  constexpr int dim = 2;
  double s11 = 1 / m.E_L, s22 = 1 / m.E_T, s12 = -m.nu_LT / m.E_L;
  if (!m.plane_stress) {
    const double E_R = p.E_R_over_E_L * m.E_L;
    const double s33 = 1 / E_R, s13 = -p.nu_LR / m.E_L, s23 = -p.nu_RT / E_R;
    s11 -= s13 * s13 / s33;
    s22 -= s23 * s23 / s33;
    s12 -= s13 * s23 / s33;
  }
  const double det = s11 * s22 - s12 * s12;
  if (!(det > 0))
    throw InputError("Material/FEM: the in-plane orthotropic compliance is not positive "
                     "definite; check nu_LT, nu_LR, nu_RT and E_R over E_L");
  SymmetricTensor<4, dim> C;
  C[0][0][0][0] = s22 / det;
  C[1][1][1][1] = s11 / det;
  C[0][0][1][1] = -s12 / det;
  C[1][1][0][0] = -s12 / det;
  C[0][1][0][1] = m.G_LT; // sigma_xy = 2 C_0101 eps_xy = G_LT gamma_xy
  return C;
}

template <>
SymmetricTensor<4, 3> orthotropic_stiffness<3>(const law::Material& m, const FemParameters& p) {
  // Normal compliance in the material axes (L, T, R) = (x, y, z), the same constants and
  // conventions as the plane-strain reduction above (s23 = -nu_RT / E_R), so a thin 3D plate
  // (sigma_zz = 0) is the 2D plane-stress model and a fully restrained one the plane-strain one.
  const double E_R = p.E_R_over_E_L * m.E_L;
  FullMatrix<double> S(3, 3), C(3, 3);
  S(0, 0) = 1 / m.E_L;
  S(1, 1) = 1 / m.E_T;
  S(2, 2) = 1 / E_R;
  S(0, 1) = S(1, 0) = -m.nu_LT / m.E_L;
  S(0, 2) = S(2, 0) = -p.nu_LR / m.E_L;
  S(1, 2) = S(2, 1) = -p.nu_RT / E_R;
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

ElasticRiseLaw::ElasticRiseLaw(const law::TractionLaw& base, double k) : base_(base) {
  delta_e_ = base.envelope(0) / k;
  for (int i = 0; i < 20; ++i) // fixed point of delta_e = sigma(delta_e)/k (sigma decreasing)
    delta_e_ = base.envelope(delta_e_) / k;
  sigma_e_ = base.envelope(delta_e_);
  const auto kinks = base.kinks();
  const double first = kinks.size() > 1 ? kinks[1] : base.critical_opening();
  if (!(delta_e_ > 0 && delta_e_ < 0.5 * first))
    throw InputError("FEM/Rigid law stiffness factor: the elastic rise of the " + base.name() +
                     " law would reach " + fmt(delta_e_ / units::mm) +
                     " mm, not small against its first kink; raise the factor");
}

double ElasticRiseLaw::envelope_integral(double d) const {
  if (d <= delta_e_)
    return 0.5 * sigma_e_ / delta_e_ * d * d;
  return 0.5 * sigma_e_ * delta_e_ + base_.envelope_integral(d) - base_.envelope_integral(delta_e_);
}

std::vector<double> ElasticRiseLaw::kinks() const {
  std::vector<double> k{0.0, delta_e_};
  for (double b : base_.kinks())
    if (b > delta_e_)
      k.push_back(b);
  return k;
}

} // namespace fiberbridge::fem
