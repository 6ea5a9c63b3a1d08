#pragma once
// Finite-strain kinematics of the FEM bulk (FEM/Kinematics = finite; docs/design.md section 2,
// "Kinematics"): total Lagrangian, St Venant-Kirchhoff with the orthotropic stiffness of
// the small-strain model, in the style of deal.II's step-44 (which uses a neo-Hookean law; a
// DCB arm rotates far at small strain, where St Venant-Kirchhoff is the natural extension of
// the orthotropic Hooke law the small-strain model uses). Everything is per unit reference
// volume and in the reference configuration.
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/physics/elasticity/kinematics.h>

namespace fiberbridge::fem {

/// The state at a quadrature point from the displacement gradient H = grad_X u.
template <int dim>
struct SvkPoint {
  dealii::Tensor<2, dim> F;          ///< deformation gradient I + H
  dealii::SymmetricTensor<2, dim> E; ///< Green-Lagrange strain (F^T F - I)/2
  dealii::SymmetricTensor<2, dim> S; ///< second Piola-Kirchhoff stress C : E
  dealii::Tensor<2, dim> P;          ///< first Piola-Kirchhoff stress F S
  double W = 0;                      ///< strain energy density S : E / 2

  SvkPoint(const dealii::SymmetricTensor<4, dim>& C, const dealii::Tensor<2, dim>& H)
      : F(dealii::Physics::Elasticity::Kinematics::F(H)),
        E(dealii::Physics::Elasticity::Kinematics::E(F)), S(C * E),
        P(F * dealii::Tensor<2, dim>(S)), W(0.5 * (S * E)) {}

  /// The work-conjugate strain variation of a shape-function gradient G: sym(F^T G).
  dealii::SymmetricTensor<2, dim> strain_variation(const dealii::Tensor<2, dim>& G) const {
    return dealii::symmetrize(dealii::transpose(F) * G);
  }
  /// Cauchy stress F S F^T / det F, for output.
  dealii::SymmetricTensor<2, dim> cauchy() const {
    return dealii::symmetrize(F * dealii::Tensor<2, dim>(S) * dealii::transpose(F)) /
           dealii::determinant(F);
  }
};

} // namespace fiberbridge::fem
