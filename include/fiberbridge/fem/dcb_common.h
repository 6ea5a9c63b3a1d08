#pragma once
// Pieces of the DCB finite-element model shared by the serial engine (dcb_simulation.cc) and the
// MPI-distributed engine (distributed_dcb.templates.h): the orthotropic stiffness, the elastic
// rise that makes rigid laws insertable, the J-integral weight and number formatting. Keeping one
// copy is what makes "the distributed engine solves the same discrete problem" checkable.
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/specimen.h"
#include "fiberbridge/law/traction_law.h"

#include <deal.II/base/symmetric_tensor.h>

#include <string>

namespace fiberbridge::fem {

std::string fmt(double v, int precision = 4);

/// Stiffness of the orthotropic wood with 1 = L along x, 2 = T along y (normal to the crack
/// plane), 3 = R along z (out of plane in 2D, across the width in 3D).
/// dim = 2: plane stress, or plane strain through the reduced compliance S_ij - S_i3 S_j3 / S_33.
/// dim = 3: the full orthotropic solid (E_R, nu_LR, nu_RT, G_LR, G_RT from FemParameters; the
/// Material section gives E_L, E_T, G_LT, nu_LT). Throws InputError if not positive definite.
template <int dim>
dealii::SymmetricTensor<4, dim> orthotropic_stiffness(const law::Material& m,
                                                      const FemParameters& p);

/// A law with sigma(0) > 0 cannot be inserted at a tied (zero-opening) node: it would pull with
/// sigma(0) at no opening. It gets an elastic rise from the origin to the envelope with slope k.
class ElasticRiseLaw : public law::TractionLaw {
public:
  ElasticRiseLaw(const law::TractionLaw& base, double k);
  std::string name() const override { return base_.name(); }
  double envelope(double d) const override {
    return d < delta_e_ ? sigma_e_ * d / delta_e_ : base_.envelope(d);
  }
  double envelope_slope(double d) const override {
    return d < delta_e_ ? sigma_e_ / delta_e_ : base_.envelope_slope(d);
  }
  double envelope_integral(double d) const override;
  double critical_opening() const override { return base_.critical_opening(); }
  std::vector<double> kinks() const override;
  double delta_e() const { return delta_e_; }

private:
  const law::TractionLaw& base_;
  double delta_e_ = 0, sigma_e_ = 0;
};

/// Weight q(x) of the domain J integral: 0 outside [x0, x3], 1 on [x1, x2], linear between.
/// q depends on x only, so the strip spans both arms (and the whole width in 3D) and the top,
/// bottom and side faces (n_x = 0, traction-free) add nothing; its kinks sit on mesh lines, so
/// Gauss quadrature is exact.
struct Ramp {
  double x0, x1, x2, x3;
  double value(double x) const {
    if (x <= x0 || x >= x3)
      return 0;
    if (x < x1)
      return (x - x0) / (x1 - x0);
    if (x <= x2)
      return 1;
    return (x3 - x) / (x3 - x2);
  }
  double slope(double x) const {
    if (x <= x0 || x >= x3)
      return 0;
    if (x < x1)
      return 1 / (x1 - x0);
    if (x <= x2)
      return 0;
    return -1 / (x3 - x2);
  }
};

} // namespace fiberbridge::fem
